// How the inspector colours a field, as ParaView does: a perceptually uniform map
// (viridis) for one-signed fields (foam, speeds, depth, the Jacobian) and a diverging
// map centred on zero (Moreland's cool to warm) for signed ones (height about the water
// level, shore distance, the wakes' share). Never the rainbow: its hue bands invent
// edges that the field does not have. No VTK here.
#pragma once

#include <glm/vec3.hpp>
#include <utility>

#include "field_sampler.hpp"

namespace tidewater::inspect {

enum class ColourMap { sequential, diverging };

struct FieldColouring {
    ColourMap map = ColourMap::sequential;
    double centre = 0.0;  ///< the value drawn in the diverging map's neutral middle
};

/// The map for `field` as the viewer draws it (a vector field by its magnitude). Heights
/// are centred on `water_level`.
FieldColouring colouring_for(const FieldInfo& field, double water_level);

/// The range the map spans for sampled values in [lo, hi]: as sampled for a sequential
/// map, symmetric about the centre for a diverging one (so the centre stays neutral).
std::pair<double, double> colour_range(const FieldColouring& colouring, double lo, double hi);

/// The map's sRGB colour (0..1, as displayed) at t in [0, 1] (clamped).
glm::dvec3 map_colour(ColourMap map, double t);

}  // namespace tidewater::inspect
