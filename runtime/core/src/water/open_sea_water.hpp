// Open water at rest offsets from a batch of query points (private): every wave keeps
// its open-sea wavevector, amplitude and steepness. A provider for solve_rest_offset.
#pragma once

#include "tidewater/detail/water_point.hpp"
#include "water/prepared_waves.hpp"
#include "water/recorded_phases.hpp"

namespace tidewater::detail {

/// With kRecordPhases, full evaluations keep their sines in a RecordedPhases for `lagged`.
template <typename T, bool kRecordPhases = false>
class OpenSeaWater {
  public:
    using Ops = NumberOps<T>;
    using Scalar = typename Ops::Scalar;
    /// Every wave is the same everywhere: the sums' Jacobian is the map's (newton.hpp).
    static constexpr bool kSumsJacobianExact = true;

    /// `base` holds each wave's phase at the query points, [wave * kLanes + lane].
    OpenSeaWater(const PreparedWaves<Scalar>& waves, const Scalar* base) : w_(waves), base_(base) {}
    /// `phases` (kRecordPhases) outlives the water.
    OpenSeaWater(const PreparedWaves<Scalar>& waves, const Scalar* base, RecordedPhases<T>& phases)
        : w_(waves), base_(base), phases_(&phases) {}

    template <bool kVelocity>
    SurfaceSums<T> evaluate(const T& ex, const T& ez) const {
        SurfaceSums<T> s;
        if constexpr (kVelocity && kRecordPhases) {
            each_wave(ex, ez, [&](std::size_t i, const WaveTerm<T>& term, const T& theta) {
                Ops::sin_cos(theta, phases_->sin_last[i], phases_->cos_last[i]);
                add_wave<kVelocity>(s, term, phases_->sin_last[i], phases_->cos_last[i]);
            });
            phases_->ex_last = ex;
            phases_->ez_last = ez;
            return s;
        }
        each_wave(ex, ez,
                  [&](std::size_t, const WaveTerm<T>& term, const T& theta) { add_wave<kVelocity>(s, term, theta); });
        return s;
    }

    /// The compression of the particles at rest offset e earlier (LaggedCompression).
    LaggedCompression<T> lagged(const T& ex, const T& ez) const {
        LaggedCompression<T> c;
        if constexpr (kRecordPhases) {
            if (phases_->kept_at(ex, ez)) {  // as write_results asks: no second sine pass
                for (std::size_t i = 0; i < w_.count; ++i)
                    add_wave_lags(c, broadcast(w_.open_sea[i]), phases_->sin_kept[i], phases_->cos_kept[i],
                                  &w_.lag_sin[i * kFoamLags], &w_.lag_cos[i * kFoamLags]);
                return c;
            }
        }
        each_wave(ex, ez, [&](std::size_t i, const WaveTerm<T>& term, const T& theta) {
            add_wave_lags(c, term, theta, &w_.lag_sin[i * kFoamLags], &w_.lag_cos[i * kFoamLags]);
        });
        return c;
    }

    void record(typename Ops::Mask m) {
        if constexpr (kRecordPhases) phases_->keep(m, w_.count);
    }

  private:
    /// Calls add(i, wave i's term, its phase) for every wave at rest offset e.
    template <typename Add>
    void each_wave(const T& ex, const T& ez, Add&& add) const {
        for (std::size_t i = 0; i < w_.count; ++i) {
            const T theta =
                Ops::mul_add(T(w_.kx_s[i]), ex, Ops::mul_add(T(w_.kz_s[i]), ez, Ops::load(base_ + i * Ops::kLanes)));
            add(i, broadcast(w_.open_sea[i]), theta);
        }
    }

    static WaveTerm<T> broadcast(const WaveTerm<Scalar>& w) {
        return {T(w.a),      T(w.ak_x),   T(w.ak_z),  T(w.qa_x),  T(w.qa_z), T(w.qak_xx),
                T(w.qak_xz), T(w.qak_zz), T(w.qaw_x), T(w.qaw_z), T(w.aw)};
    }

    const PreparedWaves<Scalar>& w_;
    const Scalar* base_;
    RecordedPhases<T>* phases_ = nullptr;
};

}  // namespace tidewater::detail
