// The SIMD Eulerian query kernel: the one water evaluation (water_point.hpp) and the one
// Newton solver (tidewater/detail/newton.hpp) instantiated for xsimd float batches, whose lanes
// are query points. Included once per instruction set by kernel_<isa>.cpp, each
// compiled with its own flags and defining TIDEWATER_KERNEL_NS, so no inline function
// is shared between ISAs.
//
// Phases k D.p are formed and reduced in double, once per point; the iterations only
// add k D.e (|e| <= sum(Q A)) and the shore's residual in float, so float keeps
// micro-radian phase accuracy anywhere in the world.
#pragma once

#ifndef TIDEWATER_KERNEL_NS
#error "define TIDEWATER_KERNEL_NS before including eulerian_kernel_impl.hpp"
#endif

#include <immintrin.h>

#include <cstddef>
#include <type_traits>
#include <xsimd/xsimd.hpp>

#include "kernel/kernel_waves.hpp"
#include "tidewater/detail/newton.hpp"
#include "water/open_sea_water.hpp"
#include "water/point_lanes.hpp"
#include "water/river_solve.hpp"
#include "water/shore_water.hpp"

namespace tidewater::detail::TIDEWATER_KERNEL_NS {

using Arch = xsimd::default_arch;
using FloatBatch = xsimd::batch<float, Arch>;

/// Square transposes in registers, rows[l][c] -> rows[c][l], for the batch widths the
/// kernels are built for.
inline void transpose_registers(__m128 (&rows)[4]) {
    _MM_TRANSPOSE4_PS(rows[0], rows[1], rows[2], rows[3]);
}

#ifdef __AVX__
inline void transpose_registers(__m256 (&rows)[8]) {
    __m256 t[8], s[8];
    for (int i = 0; i < 4; ++i) {
        t[2 * i] = _mm256_unpacklo_ps(rows[2 * i], rows[2 * i + 1]);
        t[2 * i + 1] = _mm256_unpackhi_ps(rows[2 * i], rows[2 * i + 1]);
    }
    for (int h = 0; h < 8; h += 4) {
        s[h + 0] = _mm256_shuffle_ps(t[h + 0], t[h + 2], _MM_SHUFFLE(1, 0, 1, 0));
        s[h + 1] = _mm256_shuffle_ps(t[h + 0], t[h + 2], _MM_SHUFFLE(3, 2, 3, 2));
        s[h + 2] = _mm256_shuffle_ps(t[h + 1], t[h + 3], _MM_SHUFFLE(1, 0, 1, 0));
        s[h + 3] = _mm256_shuffle_ps(t[h + 1], t[h + 3], _MM_SHUFFLE(3, 2, 3, 2));
    }
    for (int c = 0; c < 4; ++c) {
        rows[c] = _mm256_permute2f128_ps(s[c], s[c + 4], 0x20);
        rows[c + 4] = _mm256_permute2f128_ps(s[c], s[c + 4], 0x31);
    }
}
#endif

}  // namespace tidewater::detail::TIDEWATER_KERNEL_NS

namespace tidewater::detail {

/// This instruction set's float batch as a number type of the water templates.
template <>
struct NumberOps<TIDEWATER_KERNEL_NS::FloatBatch> {
    using T = TIDEWATER_KERNEL_NS::FloatBatch;
    using Mask = xsimd::batch_bool<float, TIDEWATER_KERNEL_NS::Arch>;
    using Scalar = float;
    static constexpr std::size_t kLanes = T::size;
    static T load(const float* p) { return T::load_aligned(p); }
    static void store(const T& v, float* p) { v.store_aligned(p); }
    static T mul_add(const T& a, const T& b, const T& c) { return xsimd::fma(a, b, c); }
    static void sin_cos(const T& x, T& s, T& c) {
        const auto sc = xsimd::sincos(x);
        s = sc.first;
        c = sc.second;
    }
    static T sqrt(const T& x) { return xsimd::sqrt(x); }
    static T exp(const T& x) { return xsimd::exp(x); }
    static T round(const T& x) { return xsimd::nearbyint(x); }
    /// The hardware estimate and one Newton step: about 2e-7 relative, without the
    /// latency of a square root and a division.
    static T inv_sqrt(const T& x) {
        const T y = xsimd::rsqrt(x);
        return y * xsimd::fnma(T(0.5f) * x, y * y, T(1.5f));
    }
    static void interleave(const float* const* src, std::size_t count, float* dst) {
        std::size_t f = 0;
        for (; f + kLanes <= count; f += kLanes) {
            typename T::register_type rows[kLanes];
            for (std::size_t l = 0; l < kLanes; ++l) rows[l] = T::load_unaligned(src[l] + f);
            TIDEWATER_KERNEL_NS::transpose_registers(rows);
            for (std::size_t c = 0; c < kLanes; ++c) T(rows[c]).store_aligned(dst + (f + c) * kLanes);
        }
        for (; f < count; ++f)
            for (std::size_t l = 0; l < kLanes; ++l) dst[f * kLanes + l] = src[l][f];
    }
    static T select(const Mask& m, const T& a, const T& b) { return xsimd::select(m, a, b); }
    static bool any(const Mask& m) { return xsimd::any(m); }
    static bool all(const Mask& m) { return xsimd::all(m); }
};

}  // namespace tidewater::detail

namespace tidewater::detail::TIDEWATER_KERNEL_NS {

using Ops = NumberOps<FloatBatch>;
inline constexpr std::size_t kLanes = Ops::kLanes;

/// What the wakes left at the finished lanes: their share of the height and their foam.
struct WakeLanes {
    double eta[kLanes] = {}, foam[kLanes] = {};
};

template <typename Water>
WakeLanes wake_lanes(const Water& water, const PreparedWakes<float>& wakes) {
    WakeLanes out;
    store_lanes(water.eta, out.eta);
    store_lanes(wakes_foam(wakes, water.rest_x, water.rest_z), out.foam);
    return out;
}

/// Writes the first `used` lanes of a solve of `water`. Full results also carry the foam
/// the particles remember, from the waves' earlier compression at their rest positions.
template <bool kFull, typename Water>
void write_results(const KernelInput& in, const NewtonResult<FloatBatch>& r, Water& water,
                   const ShoreWater<FloatBatch>* shore, std::size_t used, SurfacePoint* full, double* heights,
                   const WakeLanes* wakes) {
    if constexpr (!kFull) {
        double eta[kLanes];
        store_lanes(point_state(r).eta, eta);
        for (std::size_t l = 0; l < used; ++l) heights[l] = in.waves->level + eta[l];
        (void)water;
        (void)shore;
        (void)full;
    } else {
        const PointLanes<FloatBatch> lanes(r);
        const LagLanes<FloatBatch> lags(water.lagged(r.ex, r.ez));
        double depth[kLanes], breaking[kLanes], distance[kLanes];
        if (shore) {
            store_lanes(shore->depth_at_point, depth);
            store_lanes(shore->breaking, breaking);
            store_lanes(shore->shore_distance_at_point, distance);
        }
        for (std::size_t l = 0; l < used; ++l) {
            SurfacePoint& o = full[l];
            lanes.fill(l, in.waves->level, o);
            o.depth = shore ? shore_far_to_infinite(depth[l]) : kDeepWater;
            o.shore_distance = shore ? shore_far_to_infinite(distance[l]) : kDeepWater;
            o.wet = surface_wet(o.height, in.waves->level, o.depth);
            o.foam =
                surface_foam(shore ? breaking[l] : 0.0, lanes.jacobian[l], lags.lane(l), in.waves->whitecap_jacobian);
            if (wakes) {
                o.wake = wakes->eta[l];
                o.foam = o.foam > wakes->foam[l] ? o.foam : wakes->foam[l];
            }
        }
    }
}

/// Open water over a batch; full queries record their phases in `phases`.
template <bool kFull, typename Phases>
OpenSeaWater<FloatBatch, kFull> make_open_water(const PreparedWaves<float>& w, const float* base, Phases& phases) {
    if constexpr (kFull) {
        return OpenSeaWater<FloatBatch, true>(w, base, phases);
    } else {
        (void)phases;
        return OpenSeaWater<FloatBatch, false>(w, base);
    }
}

template <bool kFull>
void solve_points(const KernelInput& in, const glm::dvec2* points, std::size_t n, SurfacePoint* full, double* heights) {
    const PreparedWaves<float>& w = *in.waves;
    alignas(64) double px[kLanes], pz[kLanes];
    alignas(64) float base[kMaxWaves * kLanes];
    // Full queries: the lagged sums reuse the solve's sines (heights-only queries keep no
    // such buffer: even unused, it cost them 7% of their speed).
    [[maybe_unused]] std::conditional_t<kFull, RecordedPhases<FloatBatch>, char> phases;
    using OpenWater = OpenSeaWater<FloatBatch, kFull>;
    for (std::size_t start = 0; start < n; start += kLanes) {
        const std::size_t used = n - start < kLanes ? n - start : kLanes;
        for (std::size_t l = 0; l < kLanes; ++l) {
            // Spare lanes repeat the last point; lanes never interact.
            const glm::dvec2& p = points[start + (l < used ? l : used - 1)];
            px[l] = p.x;
            pz[l] = p.y;
            base_phases(w, p.x, p.y, base + l, kLanes);
        }
        SurfacePoint* out_full = full ? full + start : nullptr;
        double* out_heights = heights ? heights + start : nullptr;
        if (in.wakes && !in.wakes->empty()) {
            // The wakes join whichever water this is, at the same rest positions.
            alignas(64) float wx[kLanes], wz[kLanes];
            for (std::size_t l = 0; l < kLanes; ++l) {
                wx[l] = static_cast<float>(px[l] - in.wakes->origin.x);
                wz[l] = static_cast<float>(pz[l] - in.wakes->origin.y);
            }
            const double radius = w.radius + in.wakes->displacement_bound;
            if (in.shore) {
                ShoreWater<FloatBatch> shore(w, *in.shore, px, pz, base);
                WakeWater<ShoreWater<FloatBatch>, FloatBatch, float> water(shore, *in.wakes, Ops::load(wx),
                                                                           Ops::load(wz));
                const auto r = solve_rest_offset<kFull, FloatBatch>(water, w.tolerance, radius);
                const WakeLanes lanes = wake_lanes(water, *in.wakes);
                write_results<kFull>(in, r, water, &shore, used, out_full, out_heights, &lanes);
            } else {
                OpenWater open = make_open_water<kFull>(w, base, phases);
                WakeWater<OpenWater, FloatBatch, float> water(open, *in.wakes, Ops::load(wx), Ops::load(wz));
                const auto r = solve_rest_offset<kFull, FloatBatch>(water, w.tolerance, radius);
                const WakeLanes lanes = wake_lanes(water, *in.wakes);
                write_results<kFull>(in, r, water, nullptr, used, out_full, out_heights, &lanes);
            }
        } else if (in.shore) {
            ShoreWater<FloatBatch> water(w, *in.shore, px, pz, base);
            const auto r = solve_rest_offset<kFull, FloatBatch>(water, w.tolerance, w.radius);
            write_results<kFull>(in, r, water, &water, used, out_full, out_heights, nullptr);
        } else {
            OpenWater water = make_open_water<kFull>(w, base, phases);
            const auto r = solve_rest_offset<kFull, FloatBatch>(water, w.tolerance, w.radius);
            write_results<kFull>(in, r, water, nullptr, used, out_full, out_heights, nullptr);
        }
    }
}

void solve_river(const RiverInput<float>& in, const glm::dvec2* points, std::size_t n, SurfacePoint* out) {
    for (std::size_t start = 0; start < n; start += kLanes)
        solve_river_batch<FloatBatch>(in, points + start, n - start < kLanes ? n - start : kLanes, out + start);
}

void solve(const KernelInput& in, const glm::dvec2* points, std::size_t n, SurfacePoint* full, double* heights) {
    if (full != nullptr) {
        solve_points<true>(in, points, n, full, nullptr);
    } else {
        solve_points<false>(in, points, n, nullptr, heights);
    }
}

}  // namespace tidewater::detail::TIDEWATER_KERNEL_NS
