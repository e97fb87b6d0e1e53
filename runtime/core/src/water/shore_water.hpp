// Water near a shore at rest offsets from a batch of query points (private): each
// wave's wavevector, amplitude, steepness and phase come from the shore fields at
// the rest position, sampled bilinearly between texel centres and clamped at the
// edges (as ShoreWaves::sample does in double). A provider for solve_rest_offset.
//
// The fields come from ShoreWaves' layers (shore_waves.hpp): the shared layer (depth,
// breaking, steepness scale, shore distance per texel) and each run of waves on its own
// grid (per texel the run's phase residuals, amplitude factors, wavevectors x and z); a
// cell's four taps lie in one slot. For each layer the four texels around each lane's
// rest position are transposed once into lane-major rows, in the bilinear form
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
    static constexpr std::size_t kMaxRows = 4 * kMaxWaves + kShoreSharedRows;

    /// `base` holds each wave's open-sea phase at the query points, [wave * kLanes + lane];
    /// (px, pz) are the query points, world m.
    ShoreWater(const PreparedWaves<Scalar>& waves, const ShoreWaves& shore, const double* px, const double* pz,
               const Scalar* base)
        : w_(waves), base_(base) {
        // The shared layer's rows first, then each run's: the rows of wave i's run start at
        // kShoreSharedRows + 4 * (its first wave).
        cursors_[0].start(shore.grid(), shore.shared(), 0, 0, 0, px, pz);
        for (const ShoreWaveLayer& layer : shore.layers())
            cursors_[1 + layers_++].start(layer.grid, layer.tiles, layer.first, layer.count,
                                          kShoreSharedRows + 4 * layer.first, px, pz);
        // The still water at the query points themselves (rest offset 0, where Newton
        // starts: the taps fetched here serve its first evaluation).
        locate(T(0.0), T(0.0));
        depth_at_point = depth_;
        shore_distance_at_point = blend(cursors_[0], 3);
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
    void record(Mask m) { breaking = Ops::select(m, blend(cursors_[0], 1), breaking); }

    T breaking = T(0.0);  ///< at the recorded rest positions: the foam of the particle's wave
    /// Still-water depth (level - terrain) and signed shore distance at the query points, m.
    T depth_at_point = T(0.0), shore_distance_at_point = T(0.0);

  private:
    /// One layer's cell for each lane, its place in it, and where its rows start.
    struct Cursor {
        const ShoreTiles* tiles = nullptr;
        int n = 0;
        double inv_texel = 1.0;
        std::size_t first_wave = 0, waves = 0;  // the run's waves (0: the shared layer)
        std::size_t row = 0;                    // its first field's row
        double u[kLanes], v[kLanes];            // query points in texel units from the first texel centre
        long cell[kLanes];
        const float* first[kLanes] = {};                    // the floats of each lane's cached cell's first tap
        alignas(64) Scalar cell_u[kLanes], cell_v[kLanes];  // query points relative to their cached cell, texels
        bool edge_lane[kLanes];  // the lane was clamped at the grid's edge (or nothing is cached yet)
        bool edge = true;        // any lane is
        T inv_texel_t = T(0.0);
        T u_frac = T(0.0), v_frac = T(0.0);  // position in the cell, 0..1

        void start(const ShoreGrid& grid, const ShoreTiles& t, std::size_t first_wave_of_run, std::size_t run_waves,
                   std::size_t first_row, const double* px, const double* pz) {
            tiles = &t;
            n = grid.resolution;
            inv_texel = 1.0 / grid.texel;
            inv_texel_t = constant<T>(inv_texel);
            first_wave = first_wave_of_run;
            waves = run_waves;
            row = first_row;
            for (std::size_t l = 0; l < kLanes; ++l) {
                u[l] = (px[l] - grid.corner.x) * inv_texel - 0.5;
                v[l] = (pz[l] - grid.corner.y) * inv_texel - 0.5;
                cell[l] = -1;
                edge_lane[l] = true;
                cell_u[l] = cell_v[l] = Scalar(0);
            }
        }
    };

    /// Calls add(i, wave i's term, its phase) for every wave as the shore shapes it at
    /// rest offset e.
    template <typename Add>
    void each_wave(const T& ex, const T& ez, Add&& add) {
        locate(ex, ez);
        // Waves die out over the last texel of water (host_device.h): continuous, and zero on land.
        const T shore_texels = blend(cursors_[0], 3) * cursors_[0].inv_texel_t;
        const T ramp = Ops::select(depth_ > T(0.0) && shore_texels > T(0.0),
                                   Ops::select(shore_texels < T(1.0), shore_texels, T(1.0)), T(0.0));
        const T steepness_scale = blend(cursors_[0], 2);
        for (std::size_t l = 1; l <= layers_; ++l) {
            const Cursor& c = cursors_[l];
            const std::size_t nw = c.waves;
            for (std::size_t k = 0; k < nw; ++k) {
                const std::size_t i = c.first_wave + k;
                const T residual = blend(c, k), amplitude = blend(c, nw + k);
                const T kx = blend(c, 2 * nw + k), kz = blend(c, 3 * nw + k);
                // The phase follows the shore: open-sea phase at p, k0 D.e, and the marched residual.
                const T theta =
                    Ops::mul_add(T(w_.kx_s[i]), ex, Ops::mul_add(T(w_.kz_s[i]), ez, Ops::load(base_ + i * kLanes))) +
                    residual;
                const T a = amplitude * ramp;
                add(i, wave_term<T>(kx, kz, a, T(w_.steepness[i]) * steepness_scale, T(w_.omega[i])), theta);
            }
        }
    }

    void locate(const T& ex, const T& ez) {
        for (std::size_t l = 0; l <= layers_; ++l) locate(cursors_[l], ex, ez);
        depth_ = blend(cursors_[0], 0);
    }

    /// Finds each lane's place in its cell of c's layer at rest offset e. Newton moves the
    /// rest position by far less than a texel, so a lane's cached cell nearly always still
    /// holds it: the place is then cell_u + e / texel in float, checked for all lanes in one
    /// SIMD pass. A lane that left its cell, or lies on the grid's edge, is placed in double
    /// and its taps are fetched again. Every choice depends on the lane alone, never on its
    /// batch neighbours, so a point's answer does not depend on how points are batched.
    void locate(Cursor& c, const T& ex, const T& ez) {
        const T u = Ops::mul_add(ex, c.inv_texel_t, Ops::load(c.cell_u)),
                v = Ops::mul_add(ez, c.inv_texel_t, Ops::load(c.cell_v));
        const T zero(0.0), one(1.0);
        const auto inside = u >= zero && u <= one && v >= zero && v <= one;
        if (!c.edge && Ops::all(inside)) {
            c.u_frac = u;
            c.v_frac = v;
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
        const double top = c.n - 1.0;
        c.edge = false;
        for (std::size_t l = 0; l < kLanes; ++l) {
            cells[l] = c.cell[l];
            firsts[l] = c.first[l];
            const bool keep =
                !c.edge_lane[l] && fu[l] >= Scalar(0) && fu[l] <= Scalar(1) && fv[l] >= Scalar(0) && fv[l] <= Scalar(1);
            if (keep) continue;
            const double u_raw = c.u[l] + static_cast<double>(exs[l]) * c.inv_texel;
            const double v_raw = c.v[l] + static_cast<double>(ezs[l]) * c.inv_texel;
            const double uc = clamp_texel(u_raw, top), vc = clamp_texel(v_raw, top);
            // NaN never equals itself: a NaN point is an edge lane too.
            c.edge_lane[l] = uc != u_raw || vc != v_raw;
            c.edge = c.edge || c.edge_lane[l];
            const int i = std::min(static_cast<int>(uc), c.n - 2), j = std::min(static_cast<int>(vc), c.n - 2);
            fu[l] = static_cast<Scalar>(uc - i);
            fv[l] = static_cast<Scalar>(vc - j);
            c.cell_u[l] = static_cast<Scalar>(c.u[l] - i);
            c.cell_v[l] = static_cast<Scalar>(c.v[l] - j);
            cells[l] = static_cast<long>(j) * c.n + i;
            firsts[l] = c.tiles->cell(i, j);
            moved = moved || cells[l] != c.cell[l];
        }
        if (moved) fetch(c, cells, firsts);
        c.u_frac = Ops::load(fu);
        c.v_frac = Ops::load(fv);
    }

    /// Clamps to [0, top]; a non-finite coordinate (a NaN query point) maps to 0, never to
    /// an out-of-range cell.
    static double clamp_texel(double u, double top) { return u >= 0.0 ? (u <= top ? u : top) : 0.0; }

    /// Copies the four taps of every lane's cell of c's layer (whose first tap's floats are
    /// `firsts`) into its lane-major rows (all lanes at once: a transpose costs about what two
    /// single-lane copies do).
    void fetch(Cursor& c, const long* cells, const float* const* firsts) {
        constexpr std::size_t side = ShoreTiles::kSide;
        const std::array<std::size_t, 4> offsets{0, 1, side, side + 1};
        const std::size_t stride = c.tiles->stride, first = c.row * kLanes;
        for (std::size_t t = 0; t < 4; ++t) {
            const float* src[kLanes];
            for (std::size_t l = 0; l < kLanes; ++l) src[l] = firsts[l] + offsets[t] * stride;
            Ops::interleave(src, stride, rows_[t].data() + first);
        }
        // Taps to the bilinear form c0 + c1 u + c2 v + c3 u v: three multiply-adds a value.
        for (std::size_t at = first; at < first + stride * kLanes; at += kLanes) {
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
        for (std::size_t at = first; at < first + c.waves * kLanes; at += kLanes) {
            const T c0 = Ops::load(rows_[0].data() + at);
            const T turns = Ops::round(c0 * turns_per_rad);
            Ops::store((c0 - turns * two_pi_hi) - turns * two_pi_lo, rows_[0].data() + at);
        }
        // Amplitude factors to amplitudes (the form is linear in its coefficients).
        for (std::size_t k = 0; k < c.waves; ++k) {
            const T a0(w_.amplitude[c.first_wave + k]);
            for (auto& row : rows_) {
                Scalar* at = row.data() + first + (c.waves + k) * kLanes;
                Ops::store(a0 * Ops::load(at), at);
            }
        }
        std::copy(cells, cells + kLanes, c.cell);
        std::copy(firsts, firsts + kLanes, c.first);
    }

    /// Field `field` of c's layer at each lane's place.
    T blend(const Cursor& c, std::size_t field) const {
        const std::size_t at = (c.row + field) * kLanes;
        const T c2_uc3 = Ops::mul_add(c.u_frac, Ops::load(rows_[3].data() + at), Ops::load(rows_[2].data() + at));
        return Ops::mul_add(c.v_frac, c2_uc3,
                            Ops::mul_add(c.u_frac, Ops::load(rows_[1].data() + at), Ops::load(rows_[0].data() + at)));
    }

    const PreparedWaves<Scalar>& w_;
    const Scalar* base_;
    std::array<Cursor, 1 + gpu::kShoreMaxLayers> cursors_;  // the shared layer's, then each run's
    std::size_t layers_ = 0;                                // runs of waves
    T depth_ = T(0.0);
    alignas(64) std::array<std::array<Scalar, kMaxRows * kLanes>, 4> rows_;
};

}  // namespace tidewater::detail
