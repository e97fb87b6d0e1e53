// Water near a shore at rest offsets from a batch of query points (private): each
// wave's wavevector, amplitude, steepness and phase come from the shore fields at
// the rest position, sampled bilinearly between texel centres and clamped at the
// edges (as ShoreWaves::sample does in double). A provider for solve_rest_offset.
//
// The fields come from ShoreWaves::tiles(): per texel, query_texel_stride(W) floats:
// W phase residuals, W amplitude factors, W wavevector x, W wavevector z, then depth,
// breaking, steepness scale and shore distance; a cell's four taps lie in one slot. The four texels around each
// lane's rest position are transposed once into lane-major rows, in the bilinear form
// c0 + c1 u + c2 v + c3 u v, and reused until the rest position leaves that cell
// (Newton moves it by far less than a texel).
#pragma once

#include <algorithm>
#include <array>

#include "host_device.h"
#include "tidewater/constants.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/water_point.hpp"
#include "water/prepared_waves.hpp"

namespace tidewater::detail {

template <typename T>
class ShoreWater {
  public:
    using Ops = NumberOps<T>;
    using Scalar = typename Ops::Scalar;
    using Mask = typename Ops::Mask;
    static constexpr std::size_t kLanes = Ops::kLanes;
    static constexpr std::size_t kMaxStride = 4 * kMaxWaves + 4;

    /// `base` holds each wave's open-sea phase at the query points, [wave * kLanes + lane];
    /// (px, pz) are the query points, world m.
    ShoreWater(const PreparedWaves<Scalar>& waves, const ShoreWaves& shore, const double* px, const double* pz,
               const Scalar* base)
        : w_(waves),
          tiles_(shore.tiles()),
          n_(shore.resolution()),
          inv_texel_(1.0 / shore.texel()),
          stride_(ShoreWaves::query_texel_stride(waves.count)),
          base_(base) {
        for (std::size_t l = 0; l < kLanes; ++l) {
            u_[l] = (px[l] - shore.corner().x) * inv_texel_ - 0.5;
            v_[l] = (pz[l] - shore.corner().y) * inv_texel_ - 0.5;
            cell_[l] = -1;
            edge_lane_[l] = true;
            cell_u_[l] = cell_v_[l] = Scalar(0);
        }
        // The still water at the query points themselves (rest offset 0, where Newton
        // starts: the taps fetched here serve its first evaluation).
        locate(T(0.0), T(0.0));
        depth_at_point = depth_;
        shore_distance_at_point = blend(4 * w_.count + 3);
    }

    template <bool kVelocity>
    SurfaceSums<T> evaluate(const T& ex, const T& ez) {
        SurfaceSums<T> s;
        each_wave(ex, ez,
                  [&](std::size_t, const WaveTerm<T>& term, const T& theta) { add_wave<kVelocity>(s, term, theta); });
        // A copy, not the named local: the sums stay in registers instead of the caller's
        // memory, which the row loads might alias.
        return SurfaceSums<T>(s);
    }

    /// The compression of the particles at rest offset e earlier (LaggedCompression): the
    /// shore fields are fixed in time, so only the phases turn back.
    LaggedCompression<T> lagged(const T& ex, const T& ez) {
        LaggedCompression<T> c;
        each_wave(ex, ez, [&](std::size_t i, const WaveTerm<T>& term, const T& theta) {
            add_wave_lags(c, term, theta, &w_.lag_sin[i * kFoamLags], &w_.lag_cos[i * kFoamLags]);
        });
        return c;
    }

    /// Keeps the breaking sampled by the last evaluation for the lanes in `m`.
    void record(Mask m) { breaking = Ops::select(m, blend(4 * w_.count + 1), breaking); }

    T breaking = T(0.0);  ///< at the recorded rest positions: the foam of the particle's wave
    /// Still-water depth (level - terrain) and signed shore distance at the query points, m.
    T depth_at_point = T(0.0), shore_distance_at_point = T(0.0);

  private:
    /// Calls add(i, wave i's term, its phase) for every wave as the shore shapes it at
    /// rest offset e.
    template <typename Add>
    void each_wave(const T& ex, const T& ez, Add&& add) {
        locate(ex, ez);
        const std::size_t nw = w_.count;
        // Waves die out over the last kWaterlineRampDepth of water: continuous, and zero on land.
        const T ramp =
            Ops::select(depth_ > T(0.0), Ops::select(depth_ < ramp_depth_, depth_ * inv_ramp_depth_, T(1.0)), T(0.0));
        const T steepness_scale = blend(4 * nw + 2);
        for (std::size_t i = 0; i < nw; ++i) {
            const T residual = blend(i), amplitude = blend(nw + i);
            const T kx = blend(2 * nw + i), kz = blend(3 * nw + i);
            // The phase follows the shore: open-sea phase at p, k0 D.e, and the marched residual.
            const T theta =
                Ops::mul_add(T(w_.kx_s[i]), ex, Ops::mul_add(T(w_.kz_s[i]), ez, Ops::load(base_ + i * kLanes))) +
                residual;
            const T a = amplitude * ramp;
            add(i, wave_term<T>(kx, kz, a, T(w_.steepness[i]) * steepness_scale, T(w_.omega[i])), theta);
        }
    }

    /// Finds each lane's place in its cell at rest offset e. Newton moves the rest position
    /// by far less than a texel, so a lane's cached cell nearly always still holds it: the
    /// place is then cell_u + e / texel in float, checked for all lanes in one SIMD pass.
    /// A lane that left its cell, or lies on the grid's edge, is placed in double and its
    /// taps are fetched again. Every choice depends on the lane alone, never on its batch
    /// neighbours, so a point's answer does not depend on how points are batched.
    void locate(const T& ex, const T& ez) {
        const T u = Ops::mul_add(ex, inv_texel_t_, Ops::load(cell_u_)),
                v = Ops::mul_add(ez, inv_texel_t_, Ops::load(cell_v_));
        const T zero(0.0), one(1.0);
        const auto inside = u >= zero && u <= one && v >= zero && v <= one;
        if (!edge_ && Ops::all(inside)) {
            u_frac_ = u;
            v_frac_ = v;
            depth_ = blend(4 * w_.count);
            return;
        }
        alignas(64) Scalar exs[kLanes], ezs[kLanes], fu[kLanes], fv[kLanes];
        Ops::store(ex, exs);
        Ops::store(ez, ezs);
        Ops::store(u, fu);
        Ops::store(v, fv);
        long cells[kLanes];
        const float* firsts[kLanes];
        bool moved = false;
        const double top = n_ - 1.0;
        edge_ = false;
        for (std::size_t l = 0; l < kLanes; ++l) {
            cells[l] = cell_[l];
            firsts[l] = first_[l];
            const bool keep =
                !edge_lane_[l] && fu[l] >= Scalar(0) && fu[l] <= Scalar(1) && fv[l] >= Scalar(0) && fv[l] <= Scalar(1);
            if (keep) continue;
            const double u_raw = u_[l] + static_cast<double>(exs[l]) * inv_texel_;
            const double v_raw = v_[l] + static_cast<double>(ezs[l]) * inv_texel_;
            const double uc = clamp_texel(u_raw, top), vc = clamp_texel(v_raw, top);
            // NaN never equals itself: a NaN point is an edge lane too.
            edge_lane_[l] = uc != u_raw || vc != v_raw;
            edge_ = edge_ || edge_lane_[l];
            const int i = std::min(static_cast<int>(uc), n_ - 2), j = std::min(static_cast<int>(vc), n_ - 2);
            fu[l] = static_cast<Scalar>(uc - i);
            fv[l] = static_cast<Scalar>(vc - j);
            cell_u_[l] = static_cast<Scalar>(u_[l] - i);
            cell_v_[l] = static_cast<Scalar>(v_[l] - j);
            cells[l] = static_cast<long>(j) * n_ + i;
            firsts[l] = tiles_.cell(i, j);
            moved = moved || cells[l] != cell_[l];
        }
        if (moved) fetch(cells, firsts);
        u_frac_ = Ops::load(fu);
        v_frac_ = Ops::load(fv);
        depth_ = blend(4 * w_.count);
    }

    /// Clamps to [0, top]; a non-finite coordinate (a NaN query point) maps to 0, never to
    /// an out-of-range cell.
    static double clamp_texel(double u, double top) { return u >= 0.0 ? (u <= top ? u : top) : 0.0; }

    /// Copies the four taps of every lane's cell (whose first tap's floats are `firsts`)
    /// into the lane-major rows (all lanes at once: a transpose costs about what two
    /// single-lane copies do).
    void fetch(const long* cells, const float* const* firsts) {
        constexpr std::size_t side = ShoreTiles::kSide;
        const std::array<std::size_t, 4> offsets{0, 1, side, side + 1};
        for (std::size_t t = 0; t < 4; ++t) {
            const float* src[kLanes];
            for (std::size_t l = 0; l < kLanes; ++l) src[l] = firsts[l] + offsets[t] * stride_;
            Ops::interleave(src, stride_, rows_[t].data());
        }
        // Taps to the bilinear form c0 + c1 u + c2 v + c3 u v: three multiply-adds a value.
        for (std::size_t at = 0; at < stride_ * kLanes; at += kLanes) {
            const T t00 = Ops::load(rows_[0].data() + at), t10 = Ops::load(rows_[1].data() + at);
            const T t01 = Ops::load(rows_[2].data() + at), t11 = Ops::load(rows_[3].data() + at);
            Ops::store(t10 - t00, rows_[1].data() + at);
            Ops::store(t01 - t00, rows_[2].data() + at);
            Ops::store((t11 - t10) - (t01 - t00), rows_[3].data() + at);
        }
        // Phase residuals grow to hundreds of radians inshore; taking whole turns out of the
        // cell's base value keeps the phase sums small and float-exact. 2 pi in two parts
        // (Cody-Waite): the turns come off exactly.
        const T turns_per_rad = constant<T>(1.0 / kTwoPi), two_pi_hi = T(Scalar(6.28125)),
                two_pi_lo = constant<T>(kTwoPi - 6.28125);
        for (std::size_t at = 0; at < w_.count * kLanes; at += kLanes) {
            const T c0 = Ops::load(rows_[0].data() + at);
            const T turns = Ops::round(c0 * turns_per_rad);
            Ops::store((c0 - turns * two_pi_hi) - turns * two_pi_lo, rows_[0].data() + at);
        }
        // Amplitude factors to amplitudes (the form is linear in its coefficients).
        for (std::size_t i = 0; i < w_.count; ++i) {
            const T a0(w_.amplitude[i]);
            for (auto& row : rows_) {
                Scalar* at = row.data() + (w_.count + i) * kLanes;
                Ops::store(a0 * Ops::load(at), at);
            }
        }
        std::copy(cells, cells + kLanes, cell_);
        std::copy(firsts, firsts + kLanes, first_);
    }

    T blend(std::size_t field) const {
        const std::size_t at = field * kLanes;
        const T c2_uc3 = Ops::mul_add(u_frac_, Ops::load(rows_[3].data() + at), Ops::load(rows_[2].data() + at));
        return Ops::mul_add(v_frac_, c2_uc3,
                            Ops::mul_add(u_frac_, Ops::load(rows_[1].data() + at), Ops::load(rows_[0].data() + at)));
    }

    const T ramp_depth_ = constant<T>(static_cast<double>(gpu::kWaterlineRampDepth));
    const T inv_ramp_depth_ = constant<T>(1.0 / static_cast<double>(gpu::kWaterlineRampDepth));
    const PreparedWaves<Scalar>& w_;
    const ShoreTiles& tiles_;
    int n_;
    double inv_texel_;
    std::size_t stride_;
    const Scalar* base_;
    double u_[kLanes], v_[kLanes];  // query points in texel units from the first texel centre
    long cell_[kLanes];
    const float* first_[kLanes] = {};                     // the floats of each lane's cached cell's first tap
    alignas(64) Scalar cell_u_[kLanes], cell_v_[kLanes];  // query points relative to their cached cell, texels
    bool edge_lane_[kLanes];  // the lane was clamped at the grid's edge (or nothing is cached yet)
    bool edge_ = true;        // any lane is
    const T inv_texel_t_ = constant<T>(inv_texel_);
    T u_frac_ = T(0.0), v_frac_ = T(0.0), depth_ = T(0.0);  // position in the cell, 0..1
    alignas(64) std::array<std::array<Scalar, kMaxStride * kLanes>, 4> rows_;
};

}  // namespace tidewater::detail
