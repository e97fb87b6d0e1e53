// The quality tiers' settings (quality.hpp); docs/PERFORMANCE.md gives each tier's cost.
#include "tidewater/render/quality.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "host_device.h"

namespace tidewater::render {

namespace {

struct Tier {
    Quality quality;
    std::string_view name;
    QualitySettings settings;
};

// `medium` and `low` let the water's vertices follow the screen at grazing angles and
// shade less (`low` reflects only the sky and draws no caustics); `high` spaces them 4
// pixels apart and half as much again along the view, where the far field stays within
// its bound of the supersampled picture (0.0396 of 0.04 from 12 m); `ultra` shades the
// water of multisampled targets at every sample, and otherwise draws as every tier did
// before them (docs/PERFORMANCE.md, "Quality tiers"). No tier caps the waves drawn: at
// `low` a cap of 8 took the far whitecaps and the surf's streaks away and saved nothing
// measurable (docs/PERFORMANCE.md, "How many waves are drawn").
constexpr std::array<Tier, 4> kTiers{{
    {Quality::low,
     "low",
     {.water_pixels_per_vertex = 12.0,
      .water_max_foreshortening = 100.0,
      .foam_lags = 0,
      .reflection_facets = 1,
      .reflection_march_steps = 6,
      .far_field_ring_patches = 16,
      .scene_reflection = false,
      .caustics = false}},
    {Quality::medium,
     "medium",
     {.water_pixels_per_vertex = 5.0,
      .water_max_foreshortening = 8.0,
      .foam_lags = 2,
      .reflection_facets = 4,
      .reflection_march_steps = 8}},
    {Quality::high,
     "high",
     {.water_pixels_per_vertex = 4.0,
      .water_max_foreshortening = 1.5,
      .foam_lags = 4,
      .reflection_facets = 4,
      .reflection_march_steps = 12}},
    {Quality::ultra,
     "ultra",
     {.water_pixels_per_vertex = 2.0,
      .water_max_foreshortening = 1.0,
      .foam_lags = 4,
      .reflection_facets = 4,
      .reflection_march_steps = 24,
      .water_per_sample = true}},
}};

template <typename T>
Status check_override(const std::optional<T>& value, const char* name, T lo, T hi) {
    if (!value || (std::isfinite(static_cast<double>(*value)) && *value >= lo && *value <= hi)) return {};
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
    if (auto st = check_override(overrides.foam_lags, "foam_lags", 0, static_cast<int>(gpu::kFoamLags)); !st)
        return st.error();
    if (overrides.reflection_facets && *overrides.reflection_facets != 1 && *overrides.reflection_facets != 4)
        return Error{ErrorCode::invalid_argument, fmt::format("quality override reflection_facets = {}: must be 1 or 4",
                                                              *overrides.reflection_facets)};
    if (auto st = check_override(overrides.reflection_march_steps, "reflection_march_steps", 4, 64); !st)
        return st.error();
    s.water_pixels_per_vertex = overrides.water_pixels_per_vertex.value_or(s.water_pixels_per_vertex);
    s.water_max_foreshortening = overrides.water_max_foreshortening.value_or(s.water_max_foreshortening);
    s.foam_lags = overrides.foam_lags.value_or(s.foam_lags);
    s.reflection_facets = overrides.reflection_facets.value_or(s.reflection_facets);
    s.reflection_march_steps = overrides.reflection_march_steps.value_or(s.reflection_march_steps);
    if (auto st = check_override(overrides.far_field_ring_patches, "far_field_ring_patches", 8, 64); !st)
        return st.error();
    if (overrides.far_field_ring_patches && *overrides.far_field_ring_patches % 2 != 0)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("quality override far_field_ring_patches = {}: must be even",
                                 *overrides.far_field_ring_patches)};
    s.far_field_ring_patches = overrides.far_field_ring_patches.value_or(s.far_field_ring_patches);
    if (auto st = check_override(overrides.waves_drawn, "waves_drawn", 0, 1024); !st) return st.error();
    s.waves_drawn = overrides.waves_drawn.value_or(s.waves_drawn);
    s.scene_reflection = overrides.scene_reflection.value_or(s.scene_reflection);
    s.water_per_sample = overrides.water_per_sample.value_or(s.water_per_sample);
    s.caustics = overrides.caustics.value_or(s.caustics);
    return s;
}

double reflection_step_growth(int steps) {
    // The reach in first steps: sum of g^i, i < n = (g^n - 1) / (g - 1), increasing in g.
    const auto reach = [](double g, int n) { return (std::pow(g, n) - 1.0) / (g - 1.0); };
    const double wanted = reach(1.25, 24);
    if (steps == 24) return 1.25;
    double lo = 1.0 + 1e-9, hi = 16.0;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (reach(mid, steps) < wanted ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
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
