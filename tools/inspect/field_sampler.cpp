#include "field_sampler.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "tidewater/query.hpp"
#include "tidewater/world_query.hpp"

namespace tidewater::inspect {

Status validate_grid(const SampleGrid& g) {
    if (g.is_piece() ? g.nx < 1 || g.nz < 1 || g.whole_nx < 2 || g.whole_nz < 2 || g.first_i < 0 || g.first_j < 0 ||
                           g.first_i + g.nx > g.whole_nx || g.first_j + g.nz > g.whole_nz
                     : g.nx < 2 || g.nz < 2)
        return Error{ErrorCode::invalid_argument, fmt::format("grid {}x{}: at least 2x2 points", g.nx, g.nz)};
    const double points = static_cast<double>(g.nx) * static_cast<double>(g.nz);
    if (points > static_cast<double>(kMaxGridPoints))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("grid {}x{} is {:.3g} points, more than the {} one sample holds: "
                                 "lower the resolution or split the extent",
                                 g.nx, g.nz, points, kMaxGridPoints)};
    if (!std::isfinite(g.min.x) || !std::isfinite(g.min.y) || !std::isfinite(g.max.x) || !std::isfinite(g.max.y) ||
        !(g.max.x > g.min.x) || !(g.max.y > g.min.y))
        return Error{ErrorCode::invalid_argument, "grid extent: need finite x0 < x1 and z0 < z1"};
    return {};
}

const std::vector<FieldInfo>& field_infos() {
    static const std::vector<FieldInfo> infos = {
        {"height", 1, "m", "world y of the surface"},
        {"displacement", 3, "m", "particle offset from its rest position (x, y, z)"},
        {"normal", 3, "1", "unit normal of the displaced surface"},
        {"velocity", 3, "m/s", "water particle velocity"},
        {"jacobian", 1, "1", "horizontal-map determinant: 1 flat, toward 0 where crests fold"},
        {"foam", 1, "1", "0..1 foam the physics makes (breaking or folding crests)"},
        {"depth", 1, "m", "still-water depth at the point: level - terrain (inf without a shore model)"},
        {"shore_distance", 1, "m", "signed distance to the shoreline (+ over water; inf without a shore model)"},
        {"wet", 1, "1", "1 where the surface stands above the terrain"},
        {"flow", 3, "m/s", "depth-averaged current alone (x, 0, z): rivers and their plumes, 0 elsewhere"},
        {"body", 1, "1",
         "water body id: 0 land, 1 ocean, then the lakes and the rivers in the scene's order (names in body_names)"},
        {"wake", 1, "m", "the boats' wakes' share of the height (the scene's boats)"},
    };
    return infos;
}

const FieldInfo* find_field(const std::string& name) {
    for (const FieldInfo& f : field_infos())
        if (name == f.name) return &f;
    return nullptr;
}

double FieldSample::value(const std::string& field, std::size_t k, int c) const {
    const auto pick = [&](const glm::dvec3& v) { return c == 0 ? v.x : c == 1 ? v.y : v.z; };
    if (field == "height") return height[k];
    if (field == "displacement") return pick(displacement[k]);
    if (field == "normal") return pick(normal[k]);
    if (field == "velocity") return pick(velocity[k]);
    if (field == "jacobian") return jacobian[k];
    if (field == "foam") return foam[k];
    if (field == "depth") return depth[k];
    if (field == "shore_distance") return shore_distance[k];
    if (field == "wet") return wet[k];
    if (field == "flow") return pick(flow[k]);
    if (field == "body") return body[k];
    if (field == "wake") return wake[k];
    return std::numeric_limits<double>::quiet_NaN();
}

Result<FieldSample> sample_field(const Scene& scene, const SampleGrid& grid, double time, unsigned threads) {
    if (auto st = validate_grid(grid); !st) return st.error();
    if (!std::isfinite(time)) return Error{ErrorCode::invalid_argument, "time must be finite"};
    const std::size_t n = grid.points();
    std::vector<glm::dvec2> where(n);
    for (int j = 0; j < grid.nz; ++j)
        for (int i = 0; i < grid.nx; ++i) where[grid.index(i, j)] = grid.point(i, j);
    std::vector<WorldPoint> out(n);
    QueryOptions options;
    options.threads = threads;
    if (auto st = query_world(scene, time, where, out, options); !st) return st.error();
    FieldSample s;
    s.grid = grid;
    s.time = time;
    s.has_shore = scene.ocean.shore() != nullptr || !scene.lakes.empty() || !scene.rivers.empty();
    s.body_names = body_names(scene);
    s.surface.resize(n), s.height.resize(n), s.jacobian.resize(n), s.foam.resize(n), s.depth.resize(n),
        s.shore_distance.resize(n);
    s.wet.resize(n), s.displacement.resize(n), s.normal.resize(n), s.velocity.resize(n), s.flow.resize(n),
        s.body.resize(n);
    s.wake.resize(n);
    const double lakes = static_cast<double>(scene.lakes.size());
    for (std::size_t k = 0; k < n; ++k) {
        const SurfacePoint& p = out[k].surface;
        // The body's rest level: the displacement is measured from it.
        const double level = out[k].body.kind == BodyKind::lake
                                 ? scene.lakes[static_cast<std::size_t>(out[k].body.index)].body.level()
                                 : scene.water_level();
        s.surface[k] = {where[k].x, p.height, where[k].y};
        s.height[k] = p.height;
        // A river's rest surface falls: the terrain (carved) plus its still water column.
        const double rest = out[k].body.kind == BodyKind::river ? scene.terrain.height_at(where[k]) + p.depth : level;
        s.displacement[k] = {p.displacement.x, p.height - rest, p.displacement.y};
        s.normal[k] = p.normal;
        s.velocity[k] = p.velocity;
        s.jacobian[k] = p.jacobian;
        s.foam[k] = p.foam;
        s.wake[k] = p.wake;
        s.depth[k] = p.depth;
        s.shore_distance[k] = p.shore_distance;
        s.wet[k] = p.wet ? 1.0 : 0.0;
        s.flow[k] = {out[k].flow.x, 0.0, out[k].flow.y};
        const BodyRef b = out[k].body;
        s.body[k] = b.kind == BodyKind::none    ? 0.0
                    : b.kind == BodyKind::ocean ? 1.0
                    : b.kind == BodyKind::lake  ? 2.0 + b.index
                                                : 2.0 + lakes + b.index;
    }
    return s;
}

std::vector<std::string> body_names(const Scene& scene) {
    std::vector<std::string> names = {"", "ocean"};
    for (const SceneLake& l : scene.lakes) names.push_back(l.name);
    for (const SceneRiver& r : scene.rivers) names.push_back(r.name);
    return names;
}

std::vector<double> sample_terrain(const Scene& scene, const SampleGrid& grid) {
    std::vector<double> h(grid.points());
    for (int j = 0; j < grid.nz; ++j)
        for (int i = 0; i < grid.nx; ++i) h[grid.index(i, j)] = scene.terrain.height_at(grid.point(i, j));
    return h;
}

}  // namespace tidewater::inspect
