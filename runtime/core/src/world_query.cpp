#include "tidewater/world_query.hpp"

#include <fmt/format.h>

#include <exception>
#include <vector>

#include "kernel/kernel_select.hpp"
#include "tidewater/baked_scene.hpp"
#include "tidewater/detail/parallel.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/wakes.hpp"
#include "water/body_at.hpp"
#include "water/prepared_waves.hpp"

namespace tidewater {

namespace {

/// Points per scheduled chunk of river points (a multiple of every kernel's lane count).
constexpr std::size_t kRiverPointsPerChunk = 256;

/// The points of one evaluation: one body's water, or one river's plume.
struct Group {
    std::vector<std::size_t> members;  ///< indices into the caller's points
    std::vector<glm::dvec2> points;
    std::vector<SurfacePoint> results;

    void add(std::size_t i, glm::dvec2 p) {
        members.push_back(i);
        points.push_back(p);
    }
};

Status run_river_group(const Scene& scene, const detail::WaterBodiesBake& bodies, const detail::EvaluationKey& key,
                       double time, Group& group, const QueryOptions& options) {
    detail::PreparedWaves<float> river_waves, still_waves;
    const detail::RiverInput<float> in =
        detail::prepare_river_input<float>(scene, bodies, key, time, river_waves, still_waves);
    const detail::RiverSolveFn solve = detail::query_kernel().solve_river;
    detail::parallel_chunks(group.points.size(), kRiverPointsPerChunk, options.threads,
                            [&](std::size_t begin, std::size_t end) {
                                solve(in, group.points.data() + begin, end - begin, group.results.data() + begin);
                            });
    // A saved bake's tile that could not be read (it was read as zeros) fails the query.
    return in.still_shore ? in.still_shore->status() : Status();
}

Status run_world(const Scene& scene, double time, std::span<const glm::dvec2> points, std::span<WorldPoint> out,
                 const QueryOptions& caller_options) {
    // The scene's boats (emitter i for boat i) join the caller's wakes on the still water.
    QueryOptions options = caller_options;
    Wakes wakes;
    if (!scene.boats.empty()) {
        if (caller_options.wakes != nullptr) wakes = *caller_options.wakes;
        scene_boat_wakes(scene.boats, time, wakes);
        options.wakes = &wakes;
    }
    const detail::WaterBodiesBake* bodies = scene.bake ? scene.bake->bodies.get() : nullptr;
    const detail::BodyFinder finder(scene, bodies);
    std::vector<detail::PointBody> where(points.size());
    detail::parallel_chunks(points.size(), 1024, options.threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) where[i] = finder.find(points[i]);
    });
    std::vector<Group> groups(finder.evaluation_count());
    for (std::size_t i = 0; i < points.size(); ++i) groups[where[i].evaluation].add(i, points[i]);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        Group& group = groups[g];
        if (group.points.empty()) continue;
        group.results.resize(group.points.size());
        const detail::EvaluationKey key = finder.evaluation_key(g);
        Status st;
        switch (key.kind) {
            case detail::EvaluationKind::land:
                for (std::size_t k = 0; k < group.points.size(); ++k)
                    group.results[k] = detail::land_surface(scene, group.points[k]);
                break;
            case detail::EvaluationKind::ocean:
                st = query_surface(scene.ocean, time, group.points, group.results, options);
                break;
            case detail::EvaluationKind::lake:
                st = query_surface(scene.lakes[static_cast<std::size_t>(key.lake)].body, time, group.points,
                                   group.results, options);
                break;
            case detail::EvaluationKind::river:
                st = run_river_group(scene, *bodies, key, time, group, options);
                break;
        }
        if (!st) return st;
        for (std::size_t k = 0; k < group.members.size(); ++k) {
            const std::size_t i = group.members[k];
            out[i] = detail::world_point(scene, key, where[i], group.results[k], where[i].flow);
        }
    }
    // Inside a clip volume the surface is dry: the renderer draws no water there.
    if (!scene.clip_volumes.empty() || !options.clip_volumes.empty()) {
        for (std::size_t i = 0; i < points.size(); ++i) {
            SurfacePoint& s = out[i].surface;
            const glm::dvec3 p(points[i].x, s.height, points[i].y);
            if (inside_any(scene.clip_volumes, p) || inside_any(options.clip_volumes, p)) s.wet = false;
        }
    }
    return {};
}

}  // namespace

std::string_view body_name(const Scene& scene, BodyRef body) {
    const auto index = static_cast<std::size_t>(body.index);
    switch (body.kind) {
        case BodyKind::ocean:
            return "ocean";
        case BodyKind::lake:
            return body.index >= 0 && index < scene.lakes.size() ? std::string_view(scene.lakes[index].name) : "";
        case BodyKind::river:
            return body.index >= 0 && index < scene.rivers.size() ? std::string_view(scene.rivers[index].name) : "";
        case BodyKind::none:
            break;
    }
    return "";
}

WaterOptics optics_of(const Scene& scene, BodyRef body) {
    const auto index = static_cast<std::size_t>(body.index);
    const WaterProfile* profile = &scene.ocean.profile();
    JerlovType fallback = kDefaultOceanWaterType;
    if (body.kind == BodyKind::lake && body.index >= 0 && index < scene.lakes.size()) {
        profile = &scene.lakes[index].body.profile();
        fallback = kDefaultInlandWaterType;
    } else if (body.kind == BodyKind::river && body.index >= 0 && index < scene.rivers.size()) {
        profile = &scene.rivers[index].body.profile();
        fallback = kDefaultInlandWaterType;
    }
    return profile->optics ? *profile->optics : jerlov_optics(fallback);
}

Status query_world(const Scene& scene, double time, std::span<const glm::dvec2> points, std::span<WorldPoint> out,
                   const QueryOptions& options) {
    if (points.size() != out.size())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("query_world: {} points but room for {} results", points.size(), out.size())};
    const bool has_bodies = !scene.lakes.empty() || !scene.rivers.empty();
    if (has_bodies && (!scene.bake || !scene.bake->bodies || !scene.baked()))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("query_world: {} has lakes or rivers but is not baked (or was edited since): pass it "
                                 "through bake_scene first",
                                 scene_label(scene))};
    if (points.empty()) return {};
    try {
        return run_world(scene, time, points, out, options);
    } catch (const std::exception& e) {
        return Error{ErrorCode::internal, fmt::format("query_world: could not run: {}", e.what())};
    }
}

WorldPoint query_world_point(const Scene& scene, double time, glm::dvec2 point) {
    WorldPoint out;
    if (!query_world(scene, time, std::span<const glm::dvec2>(&point, 1), std::span<WorldPoint>(&out, 1)))
        return WorldPoint{};
    return out;
}

Status query_submersion(const Scene& scene, double time, std::span<const glm::dvec3> points, std::span<Submersion> out,
                        const QueryOptions& options) {
    if (points.size() != out.size())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("query_submersion: {} points but room for {} results", points.size(), out.size())};
    std::vector<glm::dvec2> xz(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) xz[i] = {points[i].x, points[i].z};
    std::vector<WorldPoint> water(points.size());
    if (auto st = query_world(scene, time, xz, water, options); !st) return st;
    for (std::size_t i = 0; i < points.size(); ++i) {
        Submersion& s = out[i];
        s.body = water[i].body;
        s.depth = water[i].surface.height - points[i].y;
        s.under = s.body.kind != BodyKind::none && water[i].surface.wet && s.depth > 0.0;
    }
    return {};
}

}  // namespace tidewater
