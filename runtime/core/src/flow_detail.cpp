#include "tidewater/flow_detail.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "host_device.h"
#include "tidewater/ripples.hpp"

namespace tidewater {

namespace {

double positive_mod(double v, double m) {
    const double r = std::fmod(v, m);
    return r < 0.0 ? r + m : r;
}

/// One layer: the noise at the advected, jumped coordinates, as a world slope. The
/// second layer has a noise of its own (seed + 1), half a cell over, so the two are
/// uncorrelated.
glm::dvec2 layer_slope(const FlowDetailSpec& s, glm::dvec2 p, glm::dvec2 flow, double progress, glm::dvec2 jump_uv,
                       int layer) {
    const glm::dvec2 travelled = flow * (s.speed * s.period * (progress + s.offset));
    const glm::dvec2 uv = (p - travelled) * s.tiling + jump_uv + glm::dvec2(0.5 * layer);
    return gradient_noise(uv, s.seed + static_cast<std::uint32_t>(layer)).gradient * (s.tiling * s.strength);
}

}  // namespace

Status validate(const FlowDetailSpec& s, const std::string& context) {
    auto bad = [&](const char* field, double v, const char* range) {
        return Error{ErrorCode::schema_error,
                     fmt::format("{}/{}: {} is out of range (allowed: {})", context, field, v, range)};
    };
    if (!std::isfinite(s.tiling) || s.tiling < 0.01 || s.tiling > 20.0)
        return bad("tiling", s.tiling, "0.01 <= tiling <= 20 per m");
    if (!std::isfinite(s.speed) || s.speed < 0.0 || s.speed > 4.0) return bad("speed", s.speed, "0 <= speed <= 4");
    if (!std::isfinite(s.strength) || s.strength < 0.0 || s.strength > 1.0)
        return bad("strength", s.strength, "0 <= strength <= 1");
    if (!std::isfinite(s.offset) || s.offset < -1.0 || s.offset > 0.0)
        return bad("offset", s.offset, "-1 <= offset <= 0");
    if (!std::isfinite(s.period) || s.period < 0.1 || s.period > 60.0)
        return bad("period", s.period, "0.1 <= period <= 60 s");
    for (int i = 0; i < 2; ++i) {
        const double j = s.jump[i];
        if (!std::isfinite(j) || std::abs(j) > 0.5)
            return Error{ErrorCode::schema_error,
                         fmt::format("{}/jump/{}: {} is out of range (allowed: -0.5 <= jump <= 0.5 noise cells)",
                                     context, i, j)};
    }
    return {};
}

FlowDetailClock flow_detail_clock(const FlowDetailSpec& s, double time) {
    const double cycles = time / s.period;
    const double whole = std::floor(cycles);
    FlowDetailClock c;
    c.cycle_fraction = cycles - whole;
    if (c.cycle_fraction >= 1.0) c.cycle_fraction = 0.0;  // rounding just below a whole cycle
    c.jump_base = {positive_mod(whole * s.jump.x, static_cast<double>(gpu::kFlowNoisePeriod)),
                   positive_mod(whole * s.jump.y, static_cast<double>(gpu::kFlowNoisePeriod))};
    return c;
}

FlowDetailSample flow_detail(const FlowDetailSpec& s, glm::dvec2 p, glm::dvec2 flow, double time) {
    FlowDetailSample out;
    const FlowDetailClock clock = flow_detail_clock(s, time);
    // The per-texel time offset in [0, 1): a coarse noise, smooth in space.
    const double stagger = 0.5 + 0.5 * gradient_noise(p * (s.tiling * static_cast<double>(gpu::kFlowOffsetScale)),
                                                      s.seed + gpu::kFlowStaggerSeed)
                                           .value;
    glm::dvec2 slopes[2];
    double weights[2];
    for (int layer = 0; layer < 2; ++layer) {
        const double c = clock.cycle_fraction + std::clamp(stagger, 0.0, 1.0) + 0.5 * layer;
        const double restarts = std::floor(c);
        const double progress = c - restarts;
        weights[layer] = 1.0 - std::abs(1.0 - 2.0 * progress);
        slopes[layer] = layer_slope(s, p, flow, progress, clock.jump_base + restarts * s.jump, layer);
    }
    out.weight_a = weights[0];
    out.weight_b = weights[1];
    out.slope_a = slopes[0];
    out.slope_b = slopes[1];
    const double norm = std::sqrt(weights[0] * weights[0] + weights[1] * weights[1]);  // >= sqrt(0.5)
    out.slope = (weights[0] * slopes[0] + weights[1] * slopes[1]) / norm;
    return out;
}

}  // namespace tidewater
