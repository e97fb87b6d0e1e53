// What the quality tier chooses for the water's (and the terrain's) shaders (tidewater::render::QualitySettings),
// as specialization constants set at pipeline creation; the defaults are `ultra`'s (the
// shaders as they were before the tiers).
#ifndef TIDEWATER_WATER_QUALITY_GLSL
#define TIDEWATER_WATER_QUALITY_GLSL

// The crest foam's memory the pixels show: the first this many of the kFoamLags lags.
layout(constant_id = kSpecFoamLags) const uint kFoamLagsShown = 4u;
// The visible facets the sky's and the scene's reflection average over (visible_facets.glsl):
// 4, or 1 at the facets' mean slope.
layout(constant_id = kSpecReflectionFacets) const uint kReflectionFacets = 4u;
// The march toward the terrain a reflection may meet (scene_reflection.glsl): its steps,
// each this many times the last; fewer steps grow faster to reach as far.
layout(constant_id = kSpecReflectionSteps) const int kReflectionSteps = 24;
layout(constant_id = kSpecReflectionStepGrowth) const float kReflectionStepGrowth = 1.25;
// The water reflects the opaque scene where its reflections meet it (scene_reflection.glsl);
// without, the sky alone.
layout(constant_id = kSpecSceneReflection) const bool kSceneReflection = true;
// Caustics on the ground under the water (terrain.frag); without them, their mean.
layout(constant_id = kSpecCaustics) const bool kCaustics = true;
// The tier draws only a body's largest waves one by one (QualitySettings::waves_drawn);
// without a cap the flag is not read.
layout(constant_id = kSpecWavesCapped) const bool kWavesCapped = false;

// Whether the tier leaves wave `w` to the slope variance instead of drawing it.
bool wave_left_to_variance(GpuWave w) { return kWavesCapped && w.steep_omega.w == 0.0; }

#endif
