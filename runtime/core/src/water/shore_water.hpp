// Water near a shore at rest offsets from a batch of query points (private): each
// wave's wavevector, amplitude, steepness and phase come from the shore fields at
// the rest position, sampled bilinearly between texel centres and clamped at the
// edges (ShoreWaves::sample in the same arithmetic). A provider for solve_rest_offset.
//
// The fields come from ShoreWaves::query_texels(): per texel, kQueryTexelStride(W)
// floats: W phase residuals, W amplitude factors, W wavevector x, W wavevector z, then
// depth, breaking, steepness scale and shore distance. The four texels around each
// lane's rest position are copied once into lane-major rows and reused until the rest
// position leaves that cell (Newton moves it by far less than a texel).
#pragma once

#include <algorithm>
#include <array>

#include "host_device.h"
#include "tidewater/constants.hpp"
#include "tidewater/detail/water_point.hpp"
#include "tidewater/shore_waves.hpp"
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
        : w_(waves), texels_(shore.query_texels().data()), n_(shore.resolution()), inv_texel_(1.0 / shore.texel()),
          stride_(ShoreWaves::query_texel_stride(waves.count)), base_(base) {
        for (std::size_t l = 0; l < kLanes; ++l) {
            u_[l] = (px[l] - shore.corner().x) * inv_texel_ - 0.5;
            v_[l] = (pz[l] - shore.corner().y) * inv_texel_ - 0.5;
            cell_[l] = -1;
        }
    }

    template <bool kVelocity>
    SurfaceSums<T> evaluate(const T& ex, const T& ez) {
        locate(ex, ez);
        const std::size_t nw = w_.count;
        // Waves die out over the last kWaterlineRampDepth of water: continuous, and zero on land.
        const T ramp = Ops::select(depth_ > T(0.0), Ops::select(depth_ < ramp_depth_, depth_ / ramp_depth_, T(1.0)), T(0.0));
        const T steepness_scale = blend(4 * nw + 2);
        SurfaceSums<T> s;
        for (std::size_t i = 0; i < nw; ++i) {
            const T residual = blend(i), amplitude_factor = blend(nw + i);
            const T kx = blend(2 * nw + i), kz = blend(3 * nw + i);
            // The phase follows the shore: open-sea phase at p, k0 D.e, and the marched residual.
            const T theta = Ops::mul_add(T(w_.kx_s[i]), ex, Ops::mul_add(T(w_.kz_s[i]), ez, Ops::load(base_ + i * kLanes))) + residual;
            const T a = T(w_.amplitude[i]) * amplitude_factor * ramp;
            add_wave<kVelocity>(s, wave_term<T>(kx, kz, a, T(w_.steepness[i]) * steepness_scale, T(w_.omega[i])), theta);
        }
        return s;
    }

    /// Keeps the shore values sampled by the last evaluation for the lanes in `m`.
    void record(Mask m) {
        depth = Ops::select(m, depth_, depth);
        breaking = Ops::select(m, blend(4 * w_.count + 1), breaking);
        shore_distance = Ops::select(m, blend(4 * w_.count + 3), shore_distance);
    }

    T depth = T(0.0), breaking = T(0.0), shore_distance = T(0.0);  ///< at the recorded rest positions

private:
    /// Finds each lane's cell and bilinear weights at rest offset e; refreshes the cached taps.
    void locate(const T& ex, const T& ez) {
        alignas(64) Scalar exs[kLanes], ezs[kLanes];
        Ops::store(ex, exs);
        Ops::store(ez, ezs);
        alignas(64) Scalar fu[kLanes], fv[kLanes];
        const double top = n_ - 1.0;
        for (std::size_t l = 0; l < kLanes; ++l) {
            const double u = clamp_texel(u_[l] + static_cast<double>(exs[l]) * inv_texel_, top);
            const double v = clamp_texel(v_[l] + static_cast<double>(ezs[l]) * inv_texel_, top);
            const int i = std::min(static_cast<int>(u), n_ - 2), j = std::min(static_cast<int>(v), n_ - 2);
            fu[l] = static_cast<Scalar>(u - i);
            fv[l] = static_cast<Scalar>(v - j);
            const long cell = static_cast<long>(j) * n_ + i;
            if (cell != cell_[l]) fetch(l, cell);
        }
        const T one(1.0), u = Ops::load(fu), v = Ops::load(fv);
        w00_ = (one - u) * (one - v);
        w10_ = u * (one - v);
        w01_ = (one - u) * v;
        w11_ = u * v;
        depth_ = blend(4 * w_.count);
    }

    /// Clamps to [0, top]; a non-finite coordinate (a NaN query point) maps to 0, never to
    /// an out-of-range cell.
    static double clamp_texel(double u, double top) { return u >= 0.0 ? (u <= top ? u : top) : 0.0; }

    void fetch(std::size_t lane, long cell) {
        cell_[lane] = cell;
        const std::size_t k00 = static_cast<std::size_t>(cell), n = static_cast<std::size_t>(n_);
        const std::array<std::size_t, 4> taps{k00, k00 + 1, k00 + n, k00 + n + 1};
        for (std::size_t t = 0; t < 4; ++t) {
            const float* src = texels_ + taps[t] * stride_;
            Scalar* dst = rows_[t].data() + lane;
            for (std::size_t f = 0; f < stride_; ++f) dst[f * kLanes] = static_cast<Scalar>(src[f]);
        }
    }

    T blend(std::size_t field) const {
        const std::size_t at = field * kLanes;
        return Ops::mul_add(w00_, Ops::load(rows_[0].data() + at),
                            Ops::mul_add(w10_, Ops::load(rows_[1].data() + at),
                                         Ops::mul_add(w01_, Ops::load(rows_[2].data() + at), w11_ * Ops::load(rows_[3].data() + at))));
    }

    const T ramp_depth_ = constant<T>(static_cast<double>(gpu::kWaterlineRampDepth));
    const PreparedWaves<Scalar>& w_;
    const float* texels_;
    int n_;
    double inv_texel_;
    std::size_t stride_;
    const Scalar* base_;
    double u_[kLanes], v_[kLanes];  // query points in texel units from the first texel centre
    long cell_[kLanes];
    T w00_ = T(0.0), w10_ = T(0.0), w01_ = T(0.0), w11_ = T(0.0), depth_ = T(0.0);
    alignas(64) std::array<std::array<Scalar, kMaxStride * kLanes>, 4> rows_;
};

}  // namespace tidewater::detail
