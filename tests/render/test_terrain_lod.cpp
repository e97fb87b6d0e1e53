// The terrain's level of detail without a device: the CDLOD selection covers what is in
// view once, neighbours meet without cracks (their shared edges morph to the same grid),
// quads stay under kTerrainQuadPixels at the end of their range, and an 8 km world at
// 1 m texels stays within the node budget at 1080p.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <numbers>
#include <random>
#include <tuple>

#include "frame_constants.hpp"
#include "terrain_lod.hpp"
#include "terrain_mesh.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater::render::detail {
namespace {

struct Drawn {
    glm::dvec2 lo, hi;  // world xz
    int level;
    double quad;  // m
    double morph_start, morph_scale;
};

TerrainLodView view_of(glm::dvec3 eye, glm::dvec3 at, double fov_deg, int width, int height) {
    TerrainLodView v;
    v.camera = eye;
    v.origin = {std::floor(eye.x / 64.0) * 64.0, std::floor(eye.z / 64.0) * 64.0};
    const glm::dvec3 o{v.origin.x, 0.0, v.origin.y};
    const glm::mat4 view = glm::lookAt(glm::vec3(eye - o), glm::vec3(at - o), glm::vec3(0, 1, 0));
    v.view_proj = reversed_z_projection(fov_deg, double(width) / height, 0.5) * view;
    v.pixel_angle = 2.0 * std::tan(0.5 * fov_deg * std::numbers::pi / 180.0) / height;
    return v;
}

std::vector<Drawn> drawn_of(const TerrainSelection& s, const TerrainLodView& v) {
    std::vector<Drawn> out;
    for (std::size_t g = 0; g < 5; ++g)
        for (std::uint32_t k = 0; k < s.count[g]; ++k) {
            const gpu::GpuTerrainNode& n = s.nodes[s.first[g] + k];
            Drawn d;
            const glm::dvec2 side(n.rect.z, n.morph.w);
            d.lo = v.origin + glm::dvec2(n.rect.x, n.rect.y);
            d.hi = d.lo + side;
            if (g > 0) {  // one quadrant of the node
                const int q = static_cast<int>(g) - 1;
                d.lo += glm::dvec2((q & 1) * side.x / 2, (q >> 1) * side.y / 2);
                d.hi = d.lo + side / 2.0;
            }
            d.level = static_cast<int>(n.rect.w);
            d.quad = side.x / gpu::kTerrainPatchQuads;
            d.morph_start = n.morph.x;
            d.morph_scale = n.morph.y;
            out.push_back(d);
        }
    return out;
}

double morph_of(const Drawn& d, const TerrainLodGrid& grid, const TerrainLodView& v, glm::dvec2 p) {
    return std::clamp((terrain_lod_distance(grid, v, p) - d.morph_start) * d.morph_scale, 0.0, 1.0);
}

/// A square region of half side `half` (m) at 1 m texels, the first texel centre at
/// `first_centre`, the ground between `lowest` and `highest` (m).
TerrainLodGrid metre_grid(double half, double lowest, double highest, double first_centre = 0.0) {
    TerrainLodGrid g;
    g.finest_quad = glm::dvec2(1.0);
    g.region_min = glm::dvec2(-half);
    g.region_max = glm::dvec2(half);
    g.grid_origin = glm::dvec2(first_centre);
    g.lowest = lowest;
    g.highest = highest;
    return g;
}

TerrainLodGrid island_grid() {
    return metre_grid(3000.0, -40.0, 120.0);
}

// No two drawn rectangles overlap, levels of neighbours differ by at most one, and along
// every edge two neighbours share, the vertices of the finer one have fully morphed onto
// the coarser grid while the coarser one's have not started to morph: no crack can open.
TEST(TerrainLod, NeighboursMeetWithoutCracks) {
    const TerrainLodGrid grid = island_grid();
    for (const auto& [eye, at] : {std::pair{glm::dvec3(0, 30, 0), glm::dvec3(500, 0, 200)},
                                  std::pair{glm::dvec3(-1200, 300, 900), glm::dvec3(0, 0, 0)},
                                  std::pair{glm::dvec3(400, 8, -700), glm::dvec3(420, 5, -600)}}) {
        const TerrainLodView v = view_of(eye, at, 55.0, 640, 360);
        const TerrainSelection s = select_terrain_nodes(grid, v);
        ASSERT_FALSE(s.truncated);
        const std::vector<Drawn> d = drawn_of(s, v);
        ASSERT_GT(d.size(), 10u);
        int shared_edges = 0, level_steps = 0;
        for (std::size_t a = 0; a < d.size(); ++a)
            for (std::size_t b = a + 1; b < d.size(); ++b) {
                const glm::dvec2 lo = glm::max(d[a].lo, d[b].lo), hi = glm::min(d[a].hi, d[b].hi);
                const double ox = hi.x - lo.x, oz = hi.y - lo.y;
                ASSERT_FALSE(ox > 1e-6 && oz > 1e-6) << "overlap";
                if (!((std::abs(ox) < 1e-6 && oz > 1e-6) || (std::abs(oz) < 1e-6 && ox > 1e-6))) continue;
                ++shared_edges;
                ASSERT_LE(std::abs(d[a].level - d[b].level), 1);
                if (d[a].level == d[b].level) continue;
                ++level_steps;
                const Drawn& fine = d[a].level < d[b].level ? d[a] : d[b];
                const Drawn& coarse = d[a].level < d[b].level ? d[b] : d[a];
                const glm::dvec2 along = ox > 1e-6 ? glm::dvec2(1, 0) : glm::dvec2(0, 1);
                const double length = std::max(ox, oz);
                for (double t = 0.0; t <= length + 1e-9; t += fine.quad) {
                    const glm::dvec2 p = lo + along * t;
                    EXPECT_NEAR(morph_of(fine, grid, v, p), 1.0, 1e-9)
                        << "finer side not morphed at " << p.x << "," << p.y;
                    EXPECT_NEAR(morph_of(coarse, grid, v, p), 0.0, 1e-9)
                        << "coarser side morphing at " << p.x << "," << p.y;
                }
            }
        EXPECT_GT(shared_edges, 10);
        EXPECT_GT(level_steps, 0) << "the view spans several levels";
    }
}

// At the end of its range a level's quad spans at most kTerrainQuadPixels on screen, and a
// level's range covers at least kTerrainRangeOverNode of its nodes.
TEST(TerrainLod, QuadsStaySmallOnScreen) {
    const TerrainLodGrid grid = island_grid();
    const double pixel_angle = 2.0 * std::tan(0.5 * 55.0 * std::numbers::pi / 180.0) / 1080.0;
    for (int level = 0; level < 12; ++level) {
        const double quad = std::ldexp(grid.finest_quad.x, level);
        const double range = terrain_lod_range(grid, pixel_angle, level);
        EXPECT_LE(quad / (range * pixel_angle), kTerrainQuadPixels * (1 + 1e-12));
        EXPECT_GE(range, kTerrainRangeOverNode * gpu::kTerrainPatchQuads * quad);
    }
}

// An 8 km world at 1 m texels, seen at 1080p from low and from high up, stays within the
// node budget and draws under 2 million vertices.
TEST(TerrainLod, ARealSizedWorldFitsTheNodeBudget) {
    const TerrainLodGrid grid = metre_grid(6000.0, -60.0, 100.0);
    for (const auto& [eye, at] : {std::pair{glm::dvec3(0, 5, 0), glm::dvec3(1000, 0, 0)},
                                  std::pair{glm::dvec3(-3000, 1500, -3000), glm::dvec3(0, 0, 0)},
                                  std::pair{glm::dvec3(0, 120, 0), glm::dvec3(0, 0, 1)}}) {
        const TerrainSelection s = select_terrain_nodes(grid, view_of(eye, at, 55.0, 1920, 1080));
        EXPECT_FALSE(s.truncated);
        std::size_t nodes = 0;
        for (std::uint32_t c : s.count) nodes += c;
        EXPECT_LT(nodes * (gpu::kTerrainPatchQuads + 1) * (gpu::kTerrainPatchQuads + 1), 2'000'000u)
            << nodes << " nodes";
        EXPECT_GE(s.levels, 3);
    }
}

/// A 4 km plain at 1 m with 2 m wide, 1.5 m deep ditches every 40 m and rolling hills to
/// the north (the GPU tests' terrain, test_render_terrain_lod.cpp).
Terrain ditch_terrain() {
    constexpr int n = 4096;
    auto image = std::make_shared<Gray16Image>();
    image->width = image->height = n;
    image->pixels.resize(static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = i - 0.5 * (n - 1), z = j - 0.5 * (n - 1);
            double h = 5.0;
            const double along = std::abs(std::remainder(x - 20.0, 40.0));
            if (along < 1.0) h -= 1.5 * 0.5 * (1.0 + std::cos(M_PI * along));
            if (z < -300.0)
                h += 12.0 * std::min(1.0, (-300.0 - z) / 400.0) * (1.0 + std::sin(x / 90.0) * std::cos(z / 70.0));
            image->pixels[static_cast<std::size_t>(j) * n + i] =
                static_cast<std::uint16_t>(std::lround((h + 5.0) / 50.0 * 65535.0));
        }
    HeightmapTerrain map;
    map.size = glm::dvec2(n - 1);
    map.min_height = -5.0;
    map.max_height = 45.0;
    map.image = image;
    return Terrain(map);
}

// The drawn surface against the heightmap in screen space: at random points of every
// node's triangles (vertices where terrain.vert puts them, heights from the terrain), the
// mesh's point and the terrain's point at the same x, z project within kMaxError pixels of
// each other, over views low along the ditches, across them, over the hills and from high.
TEST(TerrainLod, TheDrawnSurfaceIsWithinAPixelOfTheHeightmap) {
    const Terrain terrain = ditch_terrain();
    // The ditch terrain's pixel centres, with its fade to the seabed.
    const TerrainLodGrid grid = metre_grid(2047.5 + 255.9375, -5.0, 29.0, -2047.5);
    constexpr int width = 960, height = 540;  // 1080p's pixel angle halved: the same ranges in pixels
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& [eye, at] : {std::pair{glm::dvec3(3, 7, 0), glm::dvec3(300, 4, 10)},
                                  std::pair{glm::dvec3(0, 3, 5), glm::dvec3(10, 4, 300)},
                                  std::pair{glm::dvec3(0, 40, 200), glm::dvec3(0, 10, -600)},
                                  std::pair{glm::dvec3(-300, 400, 300), glm::dvec3(0, 0, 0)}}) {
        const TerrainLodView v = view_of(eye, at, 55.0, width, height);
        const TerrainSelection s = select_terrain_nodes(grid, v);
        const glm::dvec2 cam = glm::dvec2(eye.x, eye.z) - v.origin;
        auto vertex = [&](const gpu::GpuTerrainNode& node, glm::dvec2 g) {
            const glm::dvec2 xz = terrain_vertex_xz(node, g, cam);
            return glm::dvec3(xz.x, terrain.height_at(v.origin + xz), xz.y);
        };
        auto screen = [&](glm::dvec3 p) {
            const glm::dvec4 c = glm::dmat4(v.view_proj) * glm::dvec4(p, 1.0);
            return std::pair{c.w > 0.1, glm::dvec2(c.x / c.w * 0.5 * width, c.y / c.w * 0.5 * height)};
        };
        std::vector<double> errors;
        for (const gpu::GpuTerrainNode& node : s.nodes)
            for (int k = 0; k < 24; ++k) {
                const double gi = std::floor(unit(rng) * gpu::kTerrainPatchQuads),
                             gj = std::floor(unit(rng) * gpu::kTerrainPatchQuads);
                double u = unit(rng), w = unit(rng);
                glm::dvec3 a = vertex(node, {gi, gj}), b = vertex(node, {gi + 1, gj}), c = vertex(node, {gi, gj + 1});
                if (u + w > 1.0) {  // the quad's other triangle (b, c, d)
                    a = vertex(node, {gi + 1, gj + 1});
                    u = 1.0 - u;
                    w = 1.0 - w;
                }
                const glm::dvec3 drawn = a + u * (b - a) + w * (c - a);
                const glm::dvec3 truth(drawn.x, terrain.height_at(v.origin + glm::dvec2(drawn.x, drawn.z)), drawn.z);
                const auto [front_d, pd] = screen(drawn);
                const auto [front_t, pt] = screen(truth);
                if (!front_d || !front_t || std::abs(pd.x) > width / 2 || std::abs(pd.y) > height / 2) continue;
                errors.push_back(glm::length(pd - pt));
            }
        ASSERT_GT(errors.size(), 1000u);
        std::sort(errors.begin(), errors.end());
        const double p99 = errors[errors.size() * 99 / 100], worst = errors.back();
        std::printf("view from (%.0f, %.0f, %.0f): %zu points, screen error 99%% %.3f px, worst %.3f px\n", eye.x,
                    eye.y, eye.z, errors.size(), p99, worst);
        EXPECT_LT(worst, 1.0);
    }
}

// No popping: as the camera moves 0.5 m (1/60 s at 30 m/s), every vertex of the nodes
// drawn in both frames moves, by the level of detail alone (both seen through the first
// frame's view), less than a pixel. The morph spreads each level's switch over the last
// third of its range; a switch without it moves odd vertices a whole quad (2 px).
TEST(TerrainLod, VerticesGlideAsTheCameraMoves) {
    const Terrain terrain = ditch_terrain();
    // The ditch terrain's pixel centres, with its fade to the seabed.
    const TerrainLodGrid grid = metre_grid(2047.5 + 255.9375, -5.0, 29.0, -2047.5);
    constexpr int width = 960, height = 540;
    const glm::dvec3 eye(0, 20, 500), step(0, 0, -0.5), ahead(0, -15, -1000);
    const TerrainLodView a = view_of(eye, eye + ahead, 55.0, width, height);
    TerrainLodView b = view_of(eye + step, eye + step + ahead, 55.0, width, height);
    b.origin = a.origin;  // the same frame of reference for both
    b.view_proj = a.view_proj;
    const TerrainSelection sa = select_terrain_nodes(grid, a), sb = select_terrain_nodes(grid, b);
    auto key = [](const gpu::GpuTerrainNode& n) { return std::tuple(n.rect.x, n.rect.y, n.rect.z, n.rect.w); };
    std::map<std::tuple<float, float, float, float>, const gpu::GpuTerrainNode*> in_b;
    for (const auto& n : sb.nodes) in_b[key(n)] = &n;
    double worst = 0.0;
    int compared = 0;
    for (const auto& na : sa.nodes) {
        const auto found = in_b.find(key(na));
        if (found == in_b.end()) continue;
        for (int j = 0; j <= static_cast<int>(gpu::kTerrainPatchQuads); ++j)
            for (int i = 0; i <= static_cast<int>(gpu::kTerrainPatchQuads); ++i) {
                auto place = [&](const gpu::GpuTerrainNode& n, const TerrainLodView& v) {
                    const glm::dvec2 xz = terrain_vertex_xz(n, {i, j}, glm::dvec2(v.camera.x, v.camera.z) - v.origin);
                    const glm::dvec4 c =
                        glm::dmat4(a.view_proj) * glm::dvec4(xz.x, terrain.height_at(a.origin + xz), xz.y, 1.0);
                    return std::pair{c.w > 1.0, glm::dvec2(c.x / c.w * 0.5 * width, c.y / c.w * 0.5 * height)};
                };
                const auto [front_a, pa] = place(na, a);
                const auto [front_b, pb] = place(*found->second, b);
                if (!front_a || !front_b || std::abs(pa.x) > width / 2 || std::abs(pa.y) > height / 2) continue;
                worst = std::max(worst, glm::length(pb - pa));
                ++compared;
            }
    }
    std::printf("%d vertices in both frames: the level of detail moves them at most %.3f px\n", compared, worst);
    EXPECT_GT(compared, 10000);
    EXPECT_LT(worst, 1.0);
}

// The patch lists its triangles quadrant by quadrant: a quarter draw covers exactly its
// quarter of the grid.
TEST(TerrainLod, ThePatchDrawsByQuadrant) {
    const TerrainPatch patch = build_terrain_patch();
    constexpr std::uint32_t p = gpu::kTerrainPatchQuads;
    ASSERT_EQ(patch.vertices.size(), std::size_t{(p + 1) * (p + 1)});
    ASSERT_EQ(patch.indices.size(), std::size_t{6 * p * p});
    ASSERT_EQ(patch.quadrant_indices * 4, patch.indices.size());
    for (std::uint32_t q = 0; q < 4; ++q)
        for (std::uint32_t k = q * patch.quadrant_indices; k < (q + 1) * patch.quadrant_indices; ++k) {
            const glm::vec2 g = patch.vertices[patch.indices[k]];
            EXPECT_GE(g.x, (q & 1) * p / 2.0f);
            EXPECT_LE(g.x, ((q & 1) + 1) * p / 2.0f);
            EXPECT_GE(g.y, (q >> 1) * p / 2.0f);
            EXPECT_LE(g.y, ((q >> 1) + 1) * p / 2.0f);
        }
}

}  // namespace
}  // namespace tidewater::render::detail
