// Wakes at one instant laid out for evaluation, and the water with them (private).
// The formula is detail/wake_point.hpp; this walks the chains and lone points.
#pragma once

#include <algorithm>
#include <cstddef>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

#include "tidewater/detail/wake_point.hpp"
#include "tidewater/wakes.hpp"

namespace tidewater::detail {

/// `Scalar` is float for the SIMD kernel and double for one-off evaluations. Positions
/// are relative to `origin` (near the wakes), ages are reduced in double: float keeps
/// sub-millimetre positions and micro-radian phases over kilometres of wake.
template <typename Scalar>
struct PreparedWakes {
    glm::dvec2 origin{0.0};
    /// Points in chain order, oldest first. linked[i]: point i + 1 continues i's chain.
    std::vector<Scalar> x, z, age, strength, size, steepness, turbulence;
    std::vector<unsigned char> linked;
    /// Where point i's waves can be felt: with the next point's, if linked, else its own
    /// (centre relative to `origin`, squared radius; wake_reach_disc). Farther away the
    /// walk skips them (their contributions cancel along the chain) unless `cull` is off.
    std::vector<Scalar> reach_x, reach_z, reach2;
    /// Discs holding the reach of points b * kWakeBlockPoints onward (wake_block_discs).
    std::vector<glm::dvec3> blocks;
    bool cull = true;
    /// How far the wakes can move a particle sideways (an estimate, m): widens the
    /// Eulerian solve's search radius.
    double displacement_bound = 0.0;
    /// Where each chain's waves (and all the splashes') can be felt, relative to `origin`:
    /// (min x, min z, max x, max z). Outside, a chain's contributions cancel (wake_reach).
    std::vector<glm::dvec4> boxes;
    bool empty() const { return x.empty(); }
};

/// How far from a disturbance its chain's waves can be felt `age` seconds on (m): a
/// straight chain's Kelvin waves travel at half its speed `speed` (m/s), but a turn and
/// the chain's start shed faster ones, so 1.25 times it (kWakeReachSpeedShare), with two
/// source sizes and 60 m to spare for the cusp's Airy tail and the near field (summing
/// only segments within reach changes a tug's wake with a 45 degree turn by under 1 mm);
/// a splash's waves (speed 0) at the group speed of the longest it makes with any height,
/// 1/20 of its peak wavenumber.
double wake_reach(double age, double speed, double size);

/// The disc (centre x, z, squared radius) where a chain's segment from disturbance a
/// (the older) to b can be felt: wake_reach of its older end at the segment's own speed
/// (its length over the ages' difference; 0 for a lone point, a = b), round its middle,
/// widened by half its length. A test of position alone, so that the renderer's patches
/// agree on shared vertices.
glm::dvec3 wake_reach_disc(glm::dvec2 a, double age_a, double size_a, glm::dvec2 b, double age_b, double size_b);

/// The share of its strength (and turbulence) a point keeps at `age`: all until the last
/// fifth of `max_age`, then a smoothstep to none.
double wake_age_fade(double age, double max_age);

/// The wakes at clock time `time`, leaving out emitter `exclude` (-1: none). Points not
/// yet made are left out; chains keep their order.
template <typename Scalar>
PreparedWakes<Scalar> prepare_wakes(const Wakes& wakes, double time, int exclude = -1);

/// For each run of kWakeBlockPoints consecutive points (b * kWakeBlockPoints onward), a
/// disc (centre x, z, squared radius) holding the reach discs of the terms their walk
/// adds (a segment's, from the point before, or a lone point's), widened by 1 m: where
/// it is not felt, the whole run is skipped. (x, z, r2, linked) as PreparedWakes' reach
/// discs; relative to whatever origin they are.
template <typename Scalar>
std::vector<glm::dvec3> wake_block_discs(const std::vector<Scalar>& x, const std::vector<Scalar>& z,
                                         const std::vector<Scalar>& r2, const std::vector<unsigned char>& linked);

/// How much of a segment's (or lone point's) waves is summed at squared distance `d2`
/// from the middle of its reach disc of squared radius `r2`: all within
/// kWakeReachFullShare of the radius, none beyond it, a smoothstep in d^2 between, so
/// that the sum has no edge and grows smoothly as the disc does (shaders/wake_point.glsl: wake_reach_share).
template <typename T>
T wake_reach_share(const T& d2, const T& r2) {
    using Ops = NumberOps<T>;
    const double full = static_cast<double>(gpu::kWakeReachFullShare);
    T x = (r2 - d2) / (r2 * constant<T>(1.0 - full * full));
    x = Ops::select(x < T(0.0), T(0.0), Ops::select(x > T(1.0), T(1.0), x));
    return x * x * (T(3.0) - T(2.0) * x);
}

/// Adds every chain segment and lone point of `w` at rest position (x, z) (relative to
/// w.origin) to `s`.
template <bool kVelocity, typename T, typename Scalar>
void add_wakes(SurfaceSums<T>& s, const PreparedWakes<Scalar>& w, const T& x, const T& z) {
    using Ops = NumberOps<T>;
    const std::size_t n = w.x.size();
    auto wave = [&](std::size_t i) { return wake_wave(x - T(w.x[i]), z - T(w.z[i]), T(w.age[i]), T(w.size[i])); };
    WakeWave<T> last{};
    bool last_made = false;  // `last` holds point i - 1's wave
    for (std::size_t begin = 0, block = 0; begin < n; begin += gpu::kWakeBlockPoints, ++block) {
        const std::size_t end = std::min(n, begin + gpu::kWakeBlockPoints);
        if (w.cull) {
            const glm::dvec3& disc = w.blocks[block];
            const T bx = x - T(Scalar(disc.x)), bz = z - T(Scalar(disc.y));
            if (!Ops::any(bx * bx + bz * bz <= T(Scalar(disc.z)))) {  // none of this block is felt here
                last_made = false;
                continue;
            }
        }
        for (std::size_t i = begin; i < end; ++i) {
            const bool after = i > 0 && w.linked[i - 1];  // i closes a segment from i - 1
            const bool before = w.linked[i] != 0;         // i opens a segment to i + 1
            if (!after && before) {                       // a chain's first point: no term of its own
                last_made = false;
                continue;
            }
            const std::size_t disc = after ? i - 1 : i;
            const T rx = x - T(w.reach_x[disc]), rz = z - T(w.reach_z[disc]);
            const T share = w.cull ? wake_reach_share(rx * rx + rz * rz, T(w.reach2[disc])) : T(1.0);
            if (!Ops::any(share > T(0.0))) {
                last_made = false;
                continue;
            }
            const WakeWave<T> here = wave(i);
            if (after) {
                if (!last_made) last = wave(i - 1);
                add_wake_segment<kVelocity>(s, last, here, share * T(w.strength[i - 1]), share * T(w.strength[i]),
                                            T(w.steepness[i - 1]), T(w.steepness[i]), T(w.age[i - 1] - w.age[i]));
            } else {
                add_wake_point<kVelocity>(s, here, share * T(w.strength[i]), T(w.steepness[i]));
            }
            last = here;
            last_made = true;
        }
    }
}

/// The foam the wakes' turbulence leaves at (x, z): the most of any segment's (its
/// turbulence, age and size interpolated at the nearest point) or lone point's.
template <typename T, typename Scalar>
T wakes_foam(const PreparedWakes<Scalar>& w, const T& x, const T& z) {
    using Ops = NumberOps<T>;
    T foam(0.0);
    const std::size_t n = w.x.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (w.turbulence[i] <= Scalar(0) && (i + 1 >= n || !w.linked[i] || w.turbulence[i + 1] <= Scalar(0))) continue;
        const bool before = w.linked[i] != 0 && i + 1 < n;
        const Scalar bx = before ? w.x[i + 1] - w.x[i] : Scalar(0), bz = before ? w.z[i + 1] - w.z[i] : Scalar(0);
        const Scalar len2 = bx * bx + bz * bz;
        const T px = x - T(w.x[i]), pz = z - T(w.z[i]);
        T f(0.0);
        if (len2 > Scalar(0)) {
            T t = (px * T(bx) + pz * T(bz)) * T(Scalar(1) / len2);
            t = Ops::select(t < T(0.0), T(0.0), Ops::select(t > T(1.0), T(1.0), t));
            const T dx = px - t * T(bx), dz = pz - t * T(bz);
            const T d = Ops::sqrt(dx * dx + dz * dz);
            const T age = T(w.age[i]) + t * T(w.age[i + 1] - w.age[i]);
            const T size = T(w.size[i]) + t * T(w.size[i + 1] - w.size[i]);
            const T turbulence = T(w.turbulence[i]) + t * T(w.turbulence[i + 1] - w.turbulence[i]);
            f = wake_foam(d, age, size, turbulence);
        } else if (!(i > 0 && w.linked[i - 1])) {
            f = wake_foam(Ops::sqrt(px * px + pz * pz), T(w.age[i]), T(w.size[i]), T(w.turbulence[i]));
        }
        foam = Ops::select(f > foam, f, foam);
    }
    return foam;
}

/// Some water (an OpenSeaWater, a ShoreWater) with the wakes added at the same rest
/// position: a provider for solve_rest_offset. (x, z): the query points relative to the
/// wakes' origin. It keeps, for the lanes that finish, the wakes' share of the height and
/// the rest position (for their foam).
template <typename Inner, typename T, typename Scalar>
class WakeWater {
  public:
    using Ops = NumberOps<T>;
    WakeWater(Inner& inner, const PreparedWakes<Scalar>& wakes, const T& x, const T& z)
        : inner_(inner), wakes_(wakes), x_(x), z_(z) {}

    template <bool kVelocity>
    SurfaceSums<T> evaluate(const T& ex, const T& ez) {
        SurfaceSums<T> s = inner_.template evaluate<kVelocity>(ex, ez);
        SurfaceSums<T> wake;
        add_wakes<kVelocity>(wake, wakes_, x_ + ex, z_ + ez);
        add_scaled(s, wake, T(1.0));
        last_eta_ = wake.eta;
        last_ex_ = ex;
        last_ez_ = ez;
        return s;
    }

    /// The waves' earlier compression (the wakes' own foam is their turbulence).
    LaggedCompression<T> lagged(const T& ex, const T& ez) { return inner_.lagged(ex, ez); }

    void record(typename Ops::Mask m) {
        inner_.record(m);
        eta = Ops::select(m, last_eta_, eta);
        rest_x = Ops::select(m, x_ + last_ex_, rest_x);
        rest_z = Ops::select(m, z_ + last_ez_, rest_z);
    }

    T eta = T(0.0);                      ///< the wakes' share of the height at the finish, m
    T rest_x = T(0.0), rest_z = T(0.0);  ///< the rest position there, relative to the origin

  private:
    Inner& inner_;
    const PreparedWakes<Scalar>& wakes_;
    T x_, z_;
    T last_eta_ = T(0.0), last_ex_ = T(0.0), last_ez_ = T(0.0);
};

}  // namespace tidewater::detail
