#include "water/body_at.hpp"

#include <cmath>

#include "tidewater/baked_scene.hpp"
#include "tidewater/detail/shore_waves.hpp"

namespace tidewater::detail {

PointBody BodyFinder::find(glm::dvec2 p) const {
    int plume_river = -1;
    if (bodies_ != nullptr) {
        for (std::size_t r = 0; r < bodies_->rivers.size(); ++r) {
            const RiverBake& river = bodies_->rivers[r];
            if (!river.grid.contains(p)) continue;
            int i = 0, j = 0;
            river.grid.texel_of(p, i, j);
            const std::size_t t = river.grid.index(i, j);
            const std::uint8_t texel = river.texel[t];
            const int index = static_cast<int>(r);
            if (river_water(texel)) {
                const RiverSample at = sample_river(river, p);
                // A dry texel beside the water (a bank) is the river's out to its waterline.
                if (!(river.depth[t] > 0.0f) && !(at.depth > 0.0)) continue;
                // Mouth texels blend with the still water: the plume's evaluation answers them.
                const bool blends = texel == static_cast<std::uint8_t>(RiverTexel::mouth);
                return {
                    {BodyKind::river, index}, {at.flow_x, at.flow_z}, std::nan(""), river_evaluation(index, blends)};
            }
            if (texel == static_cast<std::uint8_t>(RiverTexel::plume) && plume_river < 0) plume_river = index;
        }
    }
    if (plume_river >= 0) {
        const RiverBake& river = bodies_->rivers[static_cast<std::size_t>(plume_river)];
        const RiverSample at = sample_river(river, p);
        const BodyRef still =
            river.end == RiverEnd::lake ? BodyRef{BodyKind::lake, river.receiver} : BodyRef{BodyKind::ocean, -1};
        return {still, {at.flow_x, at.flow_z}, std::nan(""), river_evaluation(plume_river, true)};
    }
    const double ground = (bodies_ != nullptr ? bodies_->terrain : scene_.terrain).height_at(p);
    if (bodies_ != nullptr) {
        for (std::size_t l = 0; l < bodies_->lakes.size(); ++l) {
            if (!bodies_->lakes[l].holds(p, ground)) continue;
            const int index = static_cast<int>(l);
            return {{BodyKind::lake, index}, {0.0, 0.0}, ground, lake_evaluation(index)};
        }
    }
    if (!scene_.has_ocean) return {{}, {0.0, 0.0}, ground, 0};
    const BodyRef ocean = ground < scene_.water_level() ? BodyRef{BodyKind::ocean, -1} : BodyRef{};
    return {ocean, {0.0, 0.0}, ground, 1};
}

EvaluationKey BodyFinder::evaluation_key(std::size_t evaluation) const {
    EvaluationKey key;
    if (evaluation == 0) return key;
    if (evaluation == 1) {
        key.kind = EvaluationKind::ocean;
        return key;
    }
    std::size_t k = evaluation - 2;
    if (k < scene_.lakes.size()) {
        key.kind = EvaluationKind::lake;
        key.lake = static_cast<int>(k);
        return key;
    }
    k -= scene_.lakes.size();
    key.kind = EvaluationKind::river;
    key.river = static_cast<int>(k / 2);
    key.plume = k % 2 == 1;
    return key;
}

SurfacePoint land_surface(const Scene& scene, glm::dvec2 p) {
    const Terrain& terrain = scene.bake ? scene.bake->terrain : scene.terrain;
    SurfacePoint o;
    o.height = terrain.height_at(p);
    o.depth = 0.0;
    o.wet = false;
    return o;
}

WorldPoint world_point(const Scene& scene, const EvaluationKey& key, const PointBody& at, const SurfacePoint& surface,
                       glm::dvec2 flow) {
    WorldPoint out;
    out.surface = surface;
    out.body = at.body;
    out.flow = flow;
    const bool still = key.kind == EvaluationKind::ocean || key.kind == EvaluationKind::lake;
    if (still && !std::isfinite(surface.depth) && !std::isnan(at.ground)) {
        const double level = key.kind == EvaluationKind::ocean
                                 ? scene.water_level()
                                 : scene.lakes[static_cast<std::size_t>(key.lake)].body.level();
        out.surface.depth = level - at.ground;
        out.surface.wet = surface_wet(out.surface.height, level, out.surface.depth);
    }
    return out;
}

const WaterBody& still_body(const Scene& scene, const RiverBake& river) {
    if (river.end == RiverEnd::lake) return scene.lakes[static_cast<std::size_t>(river.receiver)].body;
    return scene.ocean;
}

template <typename Scalar>
RiverInput<Scalar> prepare_river_input(const Scene& scene, const WaterBodiesBake& bodies, const EvaluationKey& key,
                                       double time, PreparedWaves<Scalar>& river_waves,
                                       PreparedWaves<Scalar>& still_waves) {
    const SceneRiver& river = scene.rivers[static_cast<std::size_t>(key.river)];
    const RiverBake& baked = bodies.rivers[static_cast<std::size_t>(key.river)];
    river_waves = prepare_river_waves<Scalar>(river.body.waves(), river.body.local_time(time), baked.mouth_level,
                                              baked.mean_speed);
    river_waves.whitecap_jacobian = river.body.whitecap_jacobian();
    RiverInput<Scalar> in;
    in.river = &baked;
    in.river_waves = &river_waves;
    if (key.plume) {
        const WaterBody& still = still_body(scene, baked);
        still_waves = prepare_body_waves<Scalar>(still, time);
        in.still_waves = &still_waves;
        if (const auto& shore = still.shore(); shore && !shore->trivial()) in.still_shore = shore.get();
    }
    return in;
}

template RiverInput<float> prepare_river_input<float>(const Scene&, const WaterBodiesBake&, const EvaluationKey&,
                                                      double, PreparedWaves<float>&, PreparedWaves<float>&);
template RiverInput<double> prepare_river_input<double>(const Scene&, const WaterBodiesBake&, const EvaluationKey&,
                                                        double, PreparedWaves<double>&, PreparedWaves<double>&);

}  // namespace tidewater::detail
