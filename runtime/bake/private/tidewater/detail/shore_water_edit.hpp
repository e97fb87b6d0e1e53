// A terrain edit under the water, re-baked where it reaches (private to Tidewater::bake).
// When an edit changes the seabed only where the water stays (every texel under it and a
// step round it wet before and after, on every grid of the model and the shoreline's),
// the shoreline keeps its contour and its distances, and the waves their sources. An
// edit across the waterline is given the distance field after it: where its normals
// moved under water the rows are baked again too, and where its distances alone moved,
// the shared layer's distance. What
// changes is each wave's phase round the edit and downstream of it, toward the shore, and
// with it the waves' amplitudes and the breaking cap. Each wave is marched again in a
// window that grows until the phase along its sides moved by under
// kOpenSeaPhaseTolerance (detail::remarch, the tolerance the model already leaves the
// open sea out at); the texels under the windows, and the cap's reach round them, are
// baked again with the bake's own rows (shore/shore_rows.hpp). Every other slot stays the
// previous bake's, shared: a stroke on the seabed costs its windows, not every wave's
// full march. With the parabolic march, each wave's march is taken up again the same way
// (shore/shore_diffraction.hpp, rediffract_wave).
#pragma once

#include <memory>
#include <optional>
#include <span>

#include "tidewater/detail/heightmap_change.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/terrain.hpp"
#include "tidewater/waves.hpp"

namespace tidewater::detail {

struct ShoreMarches;

struct WaterEdit {
    std::shared_ptr<const ShoreField> shoreline;
    std::shared_ptr<const ShoreWaves> model;
    std::shared_ptr<const ShoreMarches> marches;  ///< with `marches` given: what they keep after the edit
};

/// `shoreline` and `model` (non-null, baked over `before` at `water_level` for `waves`
/// with `breaking_index`) for `after`, when the two terrains' heights differ (`change`:
/// heightmap_change of the two) only where the water stays, or `shoreline_after` (the
/// distance field baked over `after`, on the model's grid) is given; no tile of the model
/// turns from open sea to stored or back or from dry land to stored or back, and no wave
/// gains or loses deep water on its grid. Otherwise nullopt: the caller bakes in full.
/// Within the windows the values are a full bake's to the tolerance; outside them, the
/// previous bake's. A model baked with the parabolic march (diffraction) needs what its
/// march kept (`marches`, baked with it): each wave's march is then taken up again round
/// the edit and downstream of it (the random sea's first);
/// where its amplitude moved by over kMarchAmplitudeTolerance, the march's blend, its
/// energy and the foam are made again from what the model holds (the rays and the cap do
/// not depend on the march), or, where that cannot be told, the texels are baked again.
std::optional<WaterEdit> rebake_water_edit(const HeightmapChange& change, const Terrain& before, const Terrain& after,
                                           double water_level, std::span<const Wave> waves, double breaking_index,
                                           const std::shared_ptr<const ShoreField>& shoreline,
                                           const std::shared_ptr<const ShoreWaves>& model, unsigned threads,
                                           const std::shared_ptr<const ShoreMarches>& marches = nullptr,
                                           const std::shared_ptr<const ShoreField>& shoreline_after = nullptr);

}  // namespace tidewater::detail
