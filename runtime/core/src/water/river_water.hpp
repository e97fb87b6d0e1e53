// A river's water at rest offsets from a batch of query points (private): a provider
// for solve_rest_offset, written once over the number type like the open-sea and shore
// providers.
//
// The river's preset gives its waves with directions relative to downstream. At the rest
// position x0 a wave with channel-frame wavevector (k_s, k_n) has the world wavevector
// K = k_s t + k_n n, with t the downstream tangent there and n = (-t_z, t_x) the left
// normal; its phase is the one formed at the query point (in channel coordinates, with
// the Doppler shift of the river's mean speed, see prepare_river_waves) plus K . e.
// Its amplitude dies out over the last PreparedWaves::bank_ramp_depth of water, like the shore's,
// and over a blend width of the still water it runs into, whose own waves take over.
// The river's falling surface is one more term of the sums: its height above the mouth
// level adds to eta and its gradient to the slope (0 through the plume, whose still
// water is at the mouth level).
//
// Fields: RiverBake::query_texels, kRiverQueryStride floats per texel (host_device.h),
// sampled bilinearly between texel centres, clamped at the grid's edges.
#pragma once

#include <algorithm>
#include <cmath>

#include "host_device.h"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/detail/water_point.hpp"
#include "water/prepared_waves.hpp"

namespace tidewater::detail {

template <typename T>
class RiverWater {
  public:
    using Ops = NumberOps<T>;
    using Scalar = typename Ops::Scalar;
    using Mask = typename Ops::Mask;
    static constexpr std::size_t kLanes = Ops::kLanes;

    /// `waves` from prepare_river_waves; `base` holds each wave's phase at the query points,
    /// [wave * kLanes + lane]; (px, pz) are the query points, world m.
    RiverWater(const PreparedWaves<Scalar>& waves, const RiverBake& river, const double* px, const double* pz,
               const Scalar* base)
        : ramp_depth_(constant<T>(waves.bank_ramp_depth)),
          inv_ramp_depth_(constant<T>(waves.bank_ramp_depth > 0.0 ? 1.0 / waves.bank_ramp_depth : 0.0)),
          w_(waves),
          river_(river),
          px_(px),
          pz_(pz),
          base_(base) {}

    template <bool kVelocity>
    SurfaceSums<T> evaluate(const T& ex, const T& ez) {
        sample(ex, ez);
        const T zero(0.0), one(1.0);
        const T len2 = tx_ * tx_ + tz_ * tz_;
        const T inv_len = Ops::inv_sqrt(Ops::select(len2 > constant<T>(kVanishingSquare), len2, one));
        const T tx = tx_ * inv_len, tz = tz_ * inv_len;
        const T depth_ramp =
            Ops::select(depth_ > zero, Ops::select(depth_ < ramp_depth_, depth_ * inv_ramp_depth_, one), zero);
        const T ramp = depth_ramp * weight_;
        SurfaceSums<T> s;
        for (std::size_t i = 0; i < w_.count; ++i) {
            const T ks(w_.kx_s[i]), kn(w_.kz_s[i]);
            const T kx = ks * tx - kn * tz, kz = ks * tz + kn * tx;
            const T theta = Ops::mul_add(kx, ex, Ops::mul_add(kz, ez, Ops::load(base_ + i * kLanes)));
            add_wave<kVelocity>(s, wave_term<T>(kx, kz, T(w_.amplitude[i]) * ramp, T(w_.steepness[i]), T(w_.omega[i])),
                                theta);
        }
        // The surface above the mouth level: it reaches 0 at the mouth and stays 0 through
        // the plume, whose still water is at that level.
        s.eta = s.eta + surface_;
        s.sx = s.sx + surface_dx_;
        s.sz = s.sz + surface_dz_;
        return SurfaceSums<T>(s);
    }

    /// A river's waves ride its current, so its particles do not keep their rest
    /// positions: they remember no compression (lagged Jacobians of 1, no foam).
    LaggedCompression<T> lagged(const T&, const T&) const { return {}; }

    /// The still water's weight at rest offset e (still_weight, sampled there).
    const T& still_weight_at(const T& ex, const T& ez) {
        sample(ex, ez);
        return still_weight_;
    }

    void record(Mask) {}

    /// The weight of the still water's waves at the last rest position, 0..1: 0 in the
    /// river and on land, rising to 1 over the blend width of still water.
    const T& still_weight() const { return still_weight_; }

  private:
    /// Samples the fields at every lane's rest position (p + e), in double per lane.
    void sample(const T& ex, const T& ez) {
        alignas(64) Scalar exs[kLanes], ezs[kLanes];
        alignas(64) Scalar out[kFields][kLanes];
        Ops::store(ex, exs);
        Ops::store(ez, ezs);
        const FieldGrid& g = river_.grid;
        const float* texels = river_.query_texels.data();
        constexpr std::size_t stride = gpu::kRiverQueryStride;
        for (std::size_t l = 0; l < kLanes; ++l) {
            const glm::dvec2 x0{px_[l] + static_cast<double>(exs[l]), pz_[l] + static_cast<double>(ezs[l])};
            const GridTaps t = grid_taps(g.corner, g.texel, g.nx, g.nz, x0);
            const float* a = texels + t.k00 * stride;
            const float* b = texels + t.k10 * stride;
            const float* c = texels + t.k01 * stride;
            const float* d = texels + t.k11 * stride;
            for (std::size_t f = 0; f < stride; ++f)
                out[f][l] = static_cast<Scalar>(t.w00 * static_cast<double>(a[f]) + t.w10 * static_cast<double>(b[f]) +
                                                t.w01 * static_cast<double>(c[f]) + t.w11 * static_cast<double>(d[f]));
            // The surface's gradient: the bilinear form's derivatives in the cell.
            const double fu = t.w10 + t.w11, fv = t.w01 + t.w11;
            const double s00 = a[0], s10 = b[0], s01 = c[0], s11 = d[0];
            out[kFields - 2][l] = static_cast<Scalar>(((1.0 - fv) * (s10 - s00) + fv * (s11 - s01)) / g.texel);
            out[kFields - 1][l] = static_cast<Scalar>(((1.0 - fu) * (s01 - s00) + fu * (s11 - s10)) / g.texel);
        }
        surface_ = Ops::load(out[gpu::kRiverQuerySurface]);
        depth_ = Ops::load(out[gpu::kRiverQueryDepth]);
        tx_ = Ops::load(out[gpu::kRiverQueryTangentX]);
        tz_ = Ops::load(out[gpu::kRiverQueryTangentZ]);
        weight_ = Ops::load(out[gpu::kRiverQueryWaveWeight]);
        still_weight_ = Ops::load(out[gpu::kRiverQueryStillWeight]);
        surface_dx_ = Ops::load(out[kFields - 2]);
        surface_dz_ = Ops::load(out[kFields - 1]);
    }

    static constexpr std::size_t kFields = gpu::kRiverQueryStride + 2;
    const T ramp_depth_, inv_ramp_depth_;
    const PreparedWaves<Scalar>& w_;
    const RiverBake& river_;
    const double* px_;
    const double* pz_;
    const Scalar* base_;
    T surface_ = T(0.0), depth_ = T(0.0), tx_ = T(1.0), tz_ = T(0.0), weight_ = T(0.0), still_weight_ = T(0.0);
    T surface_dx_ = T(0.0), surface_dz_ = T(0.0);
};

/// Where a river meets still water (a lake's or the ocean's, with or without its shore):
/// the still water's waves fade in as the river's fade out, so the surface is continuous
/// across the mouth and the shore beside it. A provider for solve_rest_offset.
template <typename T, typename Still>
class PlumeWater {
  public:
    using Mask = typename NumberOps<T>::Mask;

    PlumeWater(RiverWater<T>& river, Still& still) : river_(river), still_(still) {}

    template <bool kVelocity>
    SurfaceSums<T> evaluate(const T& ex, const T& ez) {
        SurfaceSums<T> s = river_.template evaluate<kVelocity>(ex, ez);
        add_scaled(s, still_.template evaluate<kVelocity>(ex, ez), river_.still_weight());
        return s;
    }

    /// The still water's earlier compression, faded in as at rest offset e (the river's
    /// own waves remember none).
    LaggedCompression<T> lagged(const T& ex, const T& ez) {
        LaggedCompression<T> c;
        const T weight = river_.still_weight_at(ex, ez);
        add_scaled(c, still_.lagged(ex, ez), weight);
        return c;
    }

    void record(Mask m) { still_.record(m); }

  private:
    RiverWater<T>& river_;
    Still& still_;
};

}  // namespace tidewater::detail
