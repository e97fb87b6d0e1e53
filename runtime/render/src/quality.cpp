// The quality tiers' settings (quality.hpp); docs/PERFORMANCE.md gives each tier's cost.
#include "tidewater/render/quality.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

namespace tidewater::render {

namespace {

struct Tier {
    Quality quality;
    std::string_view name;
    QualitySettings settings;
};

// `high` keeps the water's geometry as it was drawn before the tiers; `medium` and `low`
// let the vertices follow the screen at grazing angles (docs/PERFORMANCE.md, "Quality tiers").
constexpr std::array<Tier, 4> kTiers{{
    {Quality::low, "low", {.water_pixels_per_vertex = 8.0, .water_max_foreshortening = 100.0}},
    {Quality::medium, "medium", {.water_pixels_per_vertex = 4.0, .water_max_foreshortening = 8.0}},
    {Quality::high, "high", {.water_pixels_per_vertex = 3.0, .water_max_foreshortening = 1.0}},
    {Quality::ultra, "ultra", {.water_pixels_per_vertex = 2.0, .water_max_foreshortening = 1.0}},
}};

Status check_override(const std::optional<double>& value, const char* name, double lo, double hi) {
    if (!value || (std::isfinite(*value) && *value >= lo && *value <= hi)) return {};
    return Error{ErrorCode::invalid_argument,
                 fmt::format("quality override {} = {}: must be in [{}, {}]", name, *value, lo, hi)};
}

const Tier& tier_of(Quality q) {
    for (const Tier& t : kTiers)
        if (t.quality == q) return t;
    return kTiers[2];
}

}  // namespace

Result<QualitySettings> quality_settings(Quality tier, const QualityOverrides& overrides) {
    QualitySettings s = tier_of(tier).settings;
    if (auto st = check_override(overrides.water_pixels_per_vertex, "water_pixels_per_vertex", 1.0, 32.0); !st)
        return st.error();
    if (auto st = check_override(overrides.water_max_foreshortening, "water_max_foreshortening", 1.0, 100.0); !st)
        return st.error();
    s.water_pixels_per_vertex = overrides.water_pixels_per_vertex.value_or(s.water_pixels_per_vertex);
    s.water_max_foreshortening = overrides.water_max_foreshortening.value_or(s.water_max_foreshortening);
    return s;
}

std::string_view quality_name(Quality tier) {
    return tier_of(tier).name;
}

std::optional<Quality> quality_from_name(std::string_view name) {
    for (const Tier& t : kTiers)
        if (t.name == name) return t.quality;
    return std::nullopt;
}

}  // namespace tidewater::render
