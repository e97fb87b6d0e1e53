// A lake's extent: the terrain below its level connected to its "at" point (private).
#pragma once

#include "tidewater/detail/water_bodies.hpp"

namespace tidewater::detail {

/// Heights of `terrain` at the centres of `grid`.
std::vector<float> sample_terrain(const Terrain& terrain, const FieldGrid& grid);

/// Floods from `lake.at` over `heights` (on `grid`) below the lake's level. `where` names
/// the lake in messages ("scene.json: /lakes/0"). Fails when `at` is not under the level
/// or the water would spill over the grid's edge.
Result<LakeBake> find_lake_extent(const SceneLake& lake, const FieldGrid& grid, const std::vector<float>& heights,
                                  const std::string& where);

}  // namespace tidewater::detail
