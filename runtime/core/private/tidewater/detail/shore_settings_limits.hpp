// The ranges a scene's shore settings may take, checked alike where a scene file gives
// them (scene_json.cpp) and where a saved bake records them (shore_bake_folder.cpp).
// Private to Tidewater.
#pragma once

namespace tidewater::detail {

/// SceneShore::breaking_index: breaker height over depth.
inline constexpr double kLowestBreakingIndex = 0.3, kHighestBreakingIndex = 1.2;
/// SceneShore::texels_per_wavelength: 0 (every wave on the model's grid) or within these.
inline constexpr double kFewestTexelsPerWavelength = 4.0, kMostTexelsPerWavelength = 64.0;

}  // namespace tidewater::detail
