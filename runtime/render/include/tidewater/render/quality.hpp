// Quality tiers: how much the renderer draws, chosen once when it is made
// (RendererInitInfo::quality) and tuned setting by setting (QualityOverrides).
//
// `high` is the default and draws the water's geometry as before the tiers; `ultra` is
// for stills; `low` and `medium` are for weaker GPUs and for several views at once.
// Each tier's cost: docs/PERFORMANCE.md ("Quality tiers"), `tidewater gpu-cost`.
//
// Lifetime and threading: plain values, copied by the renderer. Units: pixels of the
// host's target (a sample's footprint where the water shades every sample).
#pragma once

#include <optional>
#include <string_view>

#include "tidewater/result.hpp"

namespace tidewater::render {

enum class Quality { low, medium, high, ultra };

/// Every setting a tier fixes.
struct QualitySettings {
    /// The water's vertices are this many pixels apart on screen across the view. Waves
    /// too short for them are drawn in the shading instead. Fewer pixels: more vertices,
    /// more fragment invocations (small triangles shade whole 2x2 quads). 1 to 32.
    double water_pixels_per_vertex = 3.0;
    /// How many times further apart the water's vertices may be along the view than across
    /// it, following the screen's foreshortening at grazing angles. 1: as close along the
    /// view as across it, so that every wave a pixel resolves keeps its shape and the
    /// crests that hide the troughs (sub-pixel triangles at grazing angles); larger: fewer
    /// vertices and fragments, those waves only in the shading. 1 to 100.
    double water_max_foreshortening = 1.0;
};

/// Settings that replace a tier's own; unset ones keep the tier's.
struct QualityOverrides {
    std::optional<double> water_pixels_per_vertex;
    std::optional<double> water_max_foreshortening;
};

/// The tier's settings with `overrides` applied; an override out of its range is refused
/// with an error naming it.
Result<QualitySettings> quality_settings(Quality tier, const QualityOverrides& overrides = {});

/// "low", "medium", "high", "ultra".
std::string_view quality_name(Quality tier);
/// The tier of that name, or nothing.
std::optional<Quality> quality_from_name(std::string_view name);

}  // namespace tidewater::render
