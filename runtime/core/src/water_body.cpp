#include "tidewater/water_body.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/whitecaps.hpp"

namespace tidewater {

Result<WaterBody> WaterBody::create(const WaterProfile& profile, double level, const std::string& context,
                                    std::vector<std::string>* warnings) {
    if (!std::isfinite(level) || std::abs(level) > 1e5) {
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: water level {} is out of range (allowed: |level| <= 100000 m)", context, level)};
    }
    if (!std::isfinite(profile.time_offset) || std::abs(profile.time_offset) > 1e9) {
        return Error{ErrorCode::schema_error,
                     fmt::format("{}/time_offset: {} is out of range (allowed: |offset| <= 1e9 s)", context,
                                 profile.time_offset)};
    }
    auto waves = WaveSet::create(profile.waves, profile.fold_policy, context + "/waves", warnings);
    if (!waves) return std::move(waves).error();
    if (auto st = validate(profile.ripples, context + "/ripples"); !st) return st.error();
    if (auto st = validate(profile.flow, context + "/flow"); !st) return st.error();
    if (profile.optics)
        if (auto st = validate(*profile.optics, context + "/optics"); !st) return st.error();
    WaterBody body;
    body.profile_ = profile;
    body.waves_ = std::move(waves).value();
    body.ripples_ = RippleField(profile.ripples);
    body.level_ = level;
    body.whitecap_jacobian_ =
        profile.spectrum
            ? tidewater::whitecap_jacobian(body.waves_, monahan_whitecap_fraction(profile.spectrum->wind_speed))
            : kDefaultWhitecapJacobian;
    return body;
}

Result<WaterBody> WaterBody::with_shore(std::shared_ptr<const ShoreWaves> shore) const {
    if (shore && shore->wave_count() != waves_.size()) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("water body: the shore model was baked for {} waves, the body has {}",
                                 shore->wave_count(), waves_.size())};
    }
    WaterBody copy = *this;
    copy.shore_ = std::move(shore);
    return copy;
}

}  // namespace tidewater
