// The editor's terrain brush: raises or lowers the ground round a point with a smooth
// falloff, on a 16-bit heightmap. A procedural terrain is first sampled into one
// (1024 x 1024 over its extent); the height range is re-fitted so nothing clips.
// Units: metres.
#pragma once

#include <glm/vec2.hpp>
#include <tidewater/terrain.hpp>

namespace tidewater::editor {

/// `terrain`'s shape with `height` m added at `at`, falling smoothly to 0 at `radius`.
Terrain brush_terrain(const Terrain& terrain, glm::dvec2 at, double radius, double height);

}  // namespace tidewater::editor
