// A water body: a validated wave set, ripples, a rest level and a clock offset.
//
// WaterProfile is what a preset file or a scene's "ocean" entry holds
// (authoring data); WaterBody is the validated, ready-to-evaluate form.
// Threading: WaterBody is immutable and safe to share between threads.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tidewater/flow_detail.hpp"
#include "tidewater/ripples.hpp"
#include "tidewater/spectrum.hpp"
#include "tidewater/water_optics.hpp"
#include "tidewater/waves.hpp"
#include "tidewater/whitecaps.hpp"

namespace tidewater {

class ShoreWaves;

struct WaterProfile {
    std::string name;
    std::string description;
    /// The waves; when `spectrum` is set they were generated from it.
    std::vector<WaveSpec> waves;
    std::optional<SpectrumSpec> spectrum;
    RippleSpec ripples;
    FlowDetailSpec flow;  ///< detail a current carries (rivers); strength 0 = none
    FoldPolicy fold_policy = FoldPolicy::reject;
    double time_offset = 0.0;  ///< s, added to the clock time for this body.
    /// How light travels through the water; absent, the body's kind decides
    /// (kDefaultOceanWaterType, kDefaultInlandWaterType: optics_of in world_query.hpp).
    std::optional<WaterOptics> optics;
};

class WaterBody {
  public:
    WaterBody() = default;

    /// Validates the profile (see WaveSet::create). `context` prefixes messages.
    static Result<WaterBody> create(const WaterProfile& profile, double level, const std::string& context,
                                    std::vector<std::string>* warnings = nullptr);

    const WaterProfile& profile() const { return profile_; }
    const WaveSet& waves() const { return waves_; }
    const RippleField& ripples() const { return ripples_; }
    double level() const { return level_; }  ///< Rest water level (world y), m.
    /// The Jacobian below which crests turn to whitecaps (tidewater/whitecaps.hpp): from
    /// the spectrum's wind by Monahan's coverage when the waves come from a spectrum,
    /// kDefaultWhitecapJacobian when they were authored one by one.
    double whitecap_jacobian() const { return whitecap_jacobian_; }
    double time_offset() const { return profile_.time_offset; }
    /// The time the waves see for a given clock time.
    double local_time(double clock_time) const { return clock_time + profile_.time_offset; }

    /// The shore model the waves feel (null: open water everywhere).
    const std::shared_ptr<const ShoreWaves>& shore() const { return shore_; }
    /// A copy of this body whose waves feel `shore`, which must have been baked for this
    /// body's waves (the same count); null gives open water.
    Result<WaterBody> with_shore(std::shared_ptr<const ShoreWaves> shore) const;

  private:
    WaterProfile profile_;
    WaveSet waves_;
    RippleField ripples_;
    double level_ = 0.0;
    double whitecap_jacobian_ = kDefaultWhitecapJacobian;
    std::shared_ptr<const ShoreWaves> shore_;
};

}  // namespace tidewater
