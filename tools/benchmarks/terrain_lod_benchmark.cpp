// The terrain's per-frame level-of-detail selection (CPU) on an 8 km world at 1 m texels
// at 1080p, from three cameras; the counters give the nodes and vertices drawn.
// docs/PERFORMANCE.md ("Worlds at real scale") quotes it.
#include <benchmark/benchmark.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

#include "frame_constants.hpp"
#include "terrain_lod.hpp"

namespace {

using namespace tidewater::render::detail;

struct Camera {
    glm::dvec3 eye, at;
};
constexpr Camera kCameras[] = {{{0, 5, 0}, {1000, 0, 0}},          // 5 m above the ground, along it
                               {{-3000, 1500, -3000}, {0, 0, 0}},  // 1.5 km up, across the world
                               {{0, 120, 0}, {0, 0, 1}}};          // 120 m up, looking down

void select_nodes(benchmark::State& state) {
    TerrainLodGrid grid;
    grid.finest_quad = glm::dvec2(1.0);
    grid.region_min = glm::dvec2(-4096.0 - 512.0);
    grid.region_max = glm::dvec2(4096.0 + 512.0);
    grid.grid_origin = glm::dvec2(-4095.5);
    grid.lowest = -60.0;
    grid.highest = 100.0;
    const Camera& c = kCameras[state.range(0)];
    TerrainLodView view;
    view.camera = c.eye;
    view.view_proj = reversed_z_projection(55.0, 16.0 / 9.0, 0.5) *
                     glm::lookAt(glm::vec3(c.eye), glm::vec3(c.at), glm::vec3(0.0f, 1.0f, 0.0f));
    view.pixel_angle = 2.0 * std::tan(27.5 * std::numbers::pi / 180.0) / 1080.0;
    TerrainSelection s;
    for (auto _ : state) {
        s = select_terrain_nodes(grid, view);
        benchmark::DoNotOptimize(s.nodes.data());
    }
    double nodes = 0.0;
    for (std::uint32_t n : s.count) nodes += n;
    state.counters["levels"] = s.levels;
    state.counters["nodes"] = nodes;
    state.counters["vertices"] =
        nodes * (tidewater::gpu::kTerrainPatchQuads + 1) * (tidewater::gpu::kTerrainPatchQuads + 1);
}
BENCHMARK(select_nodes)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
