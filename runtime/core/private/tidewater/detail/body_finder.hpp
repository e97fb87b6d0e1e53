// Which body's water is at a point, and so which evaluation answers it (internal):
// rivers first (their own channel texels), then a river's plume (the still water it
// runs into), then the lakes, then the ocean where the terrain is below its level.
// query_world and the GPU queries split their points with it.
// Threading: a BodyFinder only reads its scene and bake.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>

#include "tidewater/detail/water_bodies.hpp"
#include "tidewater/query.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater::detail {

enum class EvaluationKind : std::uint8_t { land, ocean, lake, river };

/// One evaluation of the water: a body's own, or (river with plume) a still body with a
/// river's waves fading out.
struct EvaluationKey {
    EvaluationKind kind = EvaluationKind::land;
    int lake = -1;
    int river = -1;
    bool plume = false;
};

struct PointBody {
    BodyRef body;
    glm::dvec2 flow{0.0};        ///< the river current at the point, m/s
    double ground = 0.0;         ///< the (carved) terrain's height at the point, m (NaN in a river: its depth is baked)
    std::size_t evaluation = 0;  ///< BodyFinder::evaluation_key(evaluation) answers the point
};

class BodyFinder {
  public:
    /// `bodies` may be null (a scene without lakes and rivers).
    BodyFinder(const Scene& scene, const WaterBodiesBake* bodies) : scene_(scene), bodies_(bodies) {}

    PointBody find(glm::dvec2 p) const;

    /// Evaluations: land, the ocean, each lake, then each river's own water and its plume.
    std::size_t evaluation_count() const { return 2 + scene_.lakes.size() + 2 * scene_.rivers.size(); }
    EvaluationKey evaluation_key(std::size_t evaluation) const;

  private:
    std::size_t lake_evaluation(int lake) const { return 2 + static_cast<std::size_t>(lake); }
    std::size_t river_evaluation(int river, bool plume) const {
        return 2 + scene_.lakes.size() + 2 * static_cast<std::size_t>(river) + (plume ? 1 : 0);
    }

    const Scene& scene_;
    const WaterBodiesBake* bodies_;
};

/// Land in a scene without an ocean (EvaluationKind::land): the (carved) terrain itself, dry.
SurfacePoint land_surface(const Scene& scene, glm::dvec2 p);

/// A point's answer from its evaluation `key`: the surface (still water without a shore
/// model knows no bottom, so its depth and wetness come from the terrain under the point),
/// the point's body and the current `flow` (m/s) there.
WorldPoint world_point(const Scene& scene, const EvaluationKey& key, const PointBody& at, const SurfacePoint& surface,
                       glm::dvec2 flow);

/// The still body a river's plume runs into (a lake or the ocean).
const WaterBody& still_body(const Scene& scene, const RiverBake& river);

}  // namespace tidewater::detail
