// What a baked scene's lakes and rivers came out as: for an editor's outliner, a
// demo's summary or a check that a river reaches where it was meant to.
//
// Lifetime: plain values, copied out of the scene's bake.
// Threading: reads an immutable baked scene; safe beside queries and rendering.
// Units: metres, seconds, m^2 and m^3/s.
#pragma once

#include <string>
#include <vector>

#include "tidewater/scene.hpp"

namespace tidewater {

struct LakeSummary {
    std::string name;
    double level = 0.0;  ///< m
    double area = 0.0;   ///< its extent's area, m^2
};

struct RiverSummary {
    std::string name;
    /// Where it ends: "ocean", "lake", "river" (a confluence) or "domain_edge".
    std::string ends_in;
    std::string receiver;          ///< the lake's or river's name it runs into ("" for the ocean or the edge)
    double length = 0.0;           ///< along its centreline to the mouth, m
    double discharge = 0.0;        ///< below its tributaries, m^3/s
    double mean_speed = 0.0;       ///< discharge over the mean wetted section, m/s
    double source_level = 0.0;     ///< its surface at the source, m
    double mouth_level = 0.0;      ///< the surface it meets, m
    int islands = 0;               ///< knolls it flows round
    int grid_nx = 0, grid_nz = 0;  ///< texels of its fields
    double texel = 0.0;            ///< m
};

struct BodySummary {
    std::vector<LakeSummary> lakes;    ///< in the scene's order
    std::vector<RiverSummary> rivers;  ///< in the scene's order
};

/// The lakes and rivers of a baked scene (empty lists when it has none or is not baked).
BodySummary summarize_bodies(const Scene& scene);

}  // namespace tidewater
