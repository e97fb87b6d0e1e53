#include "tidewater/body_summary.hpp"

#include "tidewater/baked_scene.hpp"
#include "tidewater/detail/water_bodies.hpp"

namespace tidewater {

BodySummary summarize_bodies(const Scene& scene) {
    BodySummary out;
    if (!scene.bake || !scene.bake->bodies) return out;
    const detail::WaterBodiesBake& bodies = *scene.bake->bodies;
    for (const detail::LakeBake& lake : bodies.lakes)
        out.lakes.push_back(
            {lake.name, lake.level, static_cast<double>(lake.texels) * lake.grid.texel * lake.grid.texel});
    for (std::size_t k = 0; k < bodies.rivers.size(); ++k) {
        const detail::RiverBake& river = bodies.rivers[k];
        RiverSummary r;
        r.name = river.name;
        const detail::RiverEnd end = river.end;
        r.ends_in = detail::river_end_name(end);
        if (river.receiver >= 0) {
            const auto at = static_cast<std::size_t>(river.receiver);
            if (end == detail::RiverEnd::lake && at < bodies.lakes.size()) r.receiver = bodies.lakes[at].name;
            if (end == detail::RiverEnd::river && at < bodies.rivers.size()) r.receiver = bodies.rivers[at].name;
        }
        r.length = river.along.empty() ? 0.0 : river.along.back();
        r.discharge = river.discharge;
        r.mean_speed = river.mean_speed;
        r.source_level = river.surface.empty() ? 0.0 : river.surface.front();
        r.mouth_level = river.mouth_level;
        r.islands = static_cast<int>(river.islands);
        r.grid_nx = river.grid.nx;
        r.grid_nz = river.grid.nz;
        r.texel = river.grid.texel;
        out.rivers.push_back(std::move(r));
    }
    return out;
}

}  // namespace tidewater
