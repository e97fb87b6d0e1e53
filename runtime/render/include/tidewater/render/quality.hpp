// Quality tiers: how much the renderer draws, chosen once when it is made
// (RendererInitInfo::quality) and tuned setting by setting (QualityOverrides).
//
// `high` is the default; `ultra` is for stills; `low` and `medium` are for weaker GPUs
// and for several views at once. The tiers change what is drawn, never what the CPU
// queries answer (a query's foam remembers every lag at every tier).
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

/// Every setting a tier fixes; the defaults are `high`'s.
struct QualitySettings {
    /// The water's vertices are this many pixels apart on screen across the view. Waves
    /// too short for them are drawn in the shading instead. Fewer pixels: more vertices,
    /// more fragment invocations (small triangles shade whole 2x2 quads). 1 to 32.
    double water_pixels_per_vertex = 4.0;
    /// How many times further apart the water's vertices may be along the view than across
    /// it, following the screen's foreshortening at grazing angles. 1: as close along the
    /// view as across it, so that every wave a pixel resolves keeps its shape and the
    /// crests that hide the troughs (sub-pixel triangles at grazing angles); larger: fewer
    /// vertices and fragments, those waves only in the shading. 1 to 100.
    double water_max_foreshortening = 1.5;
    /// How far back the foam on the crests remembers (whitecaps linger as they fade): the
    /// first this many of the lags of the crests' compression (kFoamLags, 0.5 s apart;
    /// tidewater::detail::surface_foam). 0: only the fresh foam. 0 to 4.
    int foam_lags = 4;
    /// The facets a pixel of water reflects the sky and the scene over: 4 (two along the
    /// view, two across it, where its waves are not all resolved) or 1, at their mean slope
    /// (a far field's reflection less spread).
    int reflection_facets = 4;
    /// Steps of the march that finds the terrain a reflection meets; fewer steps grow
    /// faster, to reach as far, and place a far hill's silhouette less closely. 4 to 64.
    int reflection_march_steps = 12;
    /// Patches per side of each of the rings of coarser water round the patch grid, out to
    /// the horizon (each ring twice as wide as the one inside): fewer, larger patches cost
    /// fewer patch invocations, and their vertices keep the spacing above up to 64 per
    /// patch edge. Even, 8 to 64.
    int far_field_ring_patches = 32;
    /// The most waves of a body (the ocean's, each lake's) that the water draws one by one,
    /// in its mesh and its normals: its largest in amplitude. The others reach the pixels
    /// as the waves too short for a pixel do, as statistics: their slope variance (a
    /// rougher surface, a wider glitter) and their share of the crest foam's spread. A
    /// river's waves ride its current and are always drawn. 0: every wave (every tier's
    /// choice); else 1 to 1024.
    int waves_drawn = 0;
    /// The water reflects the terrain and the host's opaque geometry where its reflections
    /// meet them (a march over the terrain's heights into the copy of the opaque scene).
    /// Off: it reflects the sky alone, and reflection_march_steps does not matter.
    bool scene_reflection = true;
    /// Shade the water at every sample of multisampled targets, its waves drawn and filtered
    /// for a sample's footprint (RendererInitInfo::shade_water_per_sample): `ultra`'s, for
    /// stills. The tier's wish applies where the targets are multisampled and the host
    /// enabled sampleRateShading (Renderer::quality() says whether it did); asked for by an
    /// override, it is refused where it cannot apply.
    bool water_per_sample = false;
    /// Caustics on the ground under shallow water (the waves focusing the sun). Off: the
    /// ground there shows their mean brightness.
    bool caustics = true;
};

/// Settings that replace a tier's own; unset ones keep the tier's.
struct QualityOverrides {
    std::optional<double> water_pixels_per_vertex;
    std::optional<double> water_max_foreshortening;
    std::optional<int> foam_lags;
    std::optional<int> reflection_facets;
    std::optional<int> reflection_march_steps;
    std::optional<int> far_field_ring_patches;
    std::optional<int> waves_drawn;
    std::optional<bool> scene_reflection;
    std::optional<bool> water_per_sample;
    std::optional<bool> caustics;
};

/// The tier's settings with `overrides` applied; an override out of its range is refused
/// with an error naming it.
Result<QualitySettings> quality_settings(Quality tier, const QualityOverrides& overrides = {});

/// How much each step of the reflection's march grows on the last so that `steps` steps
/// reach as far as `ultra`'s 24 steps growing by 1.25 (1054.8 first steps).
double reflection_step_growth(int steps);

/// "low", "medium", "high", "ultra".
std::string_view quality_name(Quality tier);
/// The tier of that name, or nothing.
std::optional<Quality> quality_from_name(std::string_view name);

}  // namespace tidewater::render
