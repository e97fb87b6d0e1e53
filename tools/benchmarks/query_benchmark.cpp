// Google Benchmark: Eulerian height queries (SIMD Newton) against the seed
// project's fixed-point loop, and the full surface query, for 8/32/64 waves; and
// the harbour frame near the default island's shore (100 boats, 4 hull corners each);
// the island's shore band with and without its shore model, on one thread;
// whole-scene queries in a river's channel and at its mouth.
// Run: build/bin/tidewater_query_benchmark [--benchmark_filter=...]
// `tidewater bench` measures the same with accuracy figures, as JSON.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tidewater/detail/reference.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/scene_bake.hpp"
#include "tidewater/tidewater.hpp"

namespace {

using namespace tidewater;

constexpr std::size_t kPoints = 4096;
constexpr double kTime = 1000.25;

WaterBody make_sea(int waves) {
    SpectrumSpec spec;
    spec.wave_count = waves;
    spec.steepness = 0.7;
    spec.seed = 42;
    spec.wind_speed = 12.0;
    spec.spreading = 4.0;
    WaterProfile profile;
    profile.waves = generate_waves(spec, "benchmark").value();
    return WaterBody::create(profile, 0.0, "benchmark").value();
}

std::vector<glm::dvec2> make_points() {
    std::mt19937_64 rng(7);
    std::vector<glm::dvec2> pts(kPoints);
    for (auto& p : pts) {
        p = {static_cast<double>(rng() % 2000000) * 1e-3 - 1000.0,
             static_cast<double>(rng() % 2000000) * 1e-3 - 1000.0};
    }
    return pts;
}

void BM_NewtonHeights(benchmark::State& state) {
    const WaterBody sea = make_sea(static_cast<int>(state.range(0)));
    const auto pts = make_points();
    std::vector<double> h(pts.size());
    for (auto _ : state) {
        benchmark::DoNotOptimize(query_heights(sea, kTime, pts, h).ok());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
    state.SetLabel(query_kernel_name());
}

void BM_NewtonSurface(benchmark::State& state) {
    const WaterBody sea = make_sea(static_cast<int>(state.range(0)));
    const auto pts = make_points();
    std::vector<SurfacePoint> out(pts.size());
    for (auto _ : state) {
        benchmark::DoNotOptimize(query_surface(sea, kTime, pts, out).ok());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}

void BM_FixedPointReference(benchmark::State& state) {
    const WaterBody sea = make_sea(static_cast<int>(state.range(0)));
    const auto pts = make_points();
    std::vector<double> h(pts.size());
    for (auto _ : state) {
        reference::fixed_point_heights(sea.waves(), kTime, pts, h);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}

/// 400 points of 100 boats moored 2 to 120 m off the default island's shore.
std::vector<glm::dvec2> harbour_points(const ShoreWaves& shore) {
    std::vector<glm::dvec2> centres;
    const int n = shore.resolution();
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double d = shore.texel_values(i, j).shore_distance();
            if (d >= 2.0 && d <= 120.0)
                centres.push_back(shore.corner() + shore.texel() * glm::dvec2(i + 0.5, j + 0.5));
        }
    std::mt19937_64 rng(9);
    std::vector<glm::dvec2> pts;
    for (int boat = 0; boat < 100; ++boat) {
        const glm::dvec2 c = centres[rng() % centres.size()];
        for (const glm::dvec2 corner : {glm::dvec2(2, 1), glm::dvec2(2, -1), glm::dvec2(-2, 1), glm::dvec2(-2, -1)})
            pts.push_back(c + corner);
    }
    return pts;
}

void BM_ShoreHarbour(benchmark::State& state) {
    static const Scene scene = *bake_scene(default_scene().value()).value();
    const auto pts = harbour_points(*scene.ocean.shore());
    std::vector<double> h(pts.size());
    std::vector<SurfacePoint> out(pts.size());
    const bool full = state.range(0) != 0;
    double t = kTime;
    for (auto _ : state) {
        t += 1.0 / 60.0;
        benchmark::DoNotOptimize(full ? query_surface(scene.ocean, t, pts, out).ok()
                                      : query_heights(scene.ocean, t, pts, h).ok());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
    state.SetLabel(full ? "surface" : "heights");
}

/// 65536 points in the default island's shore band (signed shore distance -5 to 120 m,
/// as `tidewater bench` draws them), jittered within their texels, queried on one thread.
/// Arg 0: heights (0) or the full surface (1). Arg 1: the island's ocean (0) or the same
/// body without its shore model (1): open water at the same points.
void BM_ShoreBand(benchmark::State& state) {
    static const Scene scene = *bake_scene(default_scene().value()).value();
    static const WaterBody open = scene.ocean.with_shore(nullptr).value();
    static const auto pts = [] {
        const ShoreWaves& shore = *scene.ocean.shore();
        std::vector<glm::dvec2> centres;
        const int n = shore.resolution();
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double d = shore.texel_values(i, j).shore_distance();
                if (d >= -5.0 && d <= 120.0)
                    centres.push_back(shore.corner() + shore.texel() * glm::dvec2(i + 0.5, j + 0.5));
            }
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> jitter(-0.5, 0.5);
        std::vector<glm::dvec2> band(65536);
        for (auto& p : band) p = centres[rng() % centres.size()] + shore.texel() * glm::dvec2(jitter(rng), jitter(rng));
        return band;
    }();
    const bool full = state.range(0) != 0, without_shore = state.range(1) != 0;
    const WaterBody& body = without_shore ? open : scene.ocean;
    std::vector<double> h(pts.size());
    std::vector<SurfacePoint> out(pts.size());
    QueryOptions one_thread;
    one_thread.threads = 1;
    for (auto _ : state) {
        benchmark::DoNotOptimize(full ? query_surface(body, kTime, pts, out, one_thread).ok()
                                      : query_heights(body, kTime, pts, h, one_thread).ok());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
    state.SetLabel(std::string(full ? "surface" : "heights") + (without_shore ? ", no shore model" : ", shore"));
    if (full) {
        // Newton's evaluations: per point, and per batch of 8 lanes grouped by 4x4-texel
        // tile (about as the kernel orders them), where the slowest lane sets the batch's.
        const ShoreWaves& shore = *scene.ocean.shore();
        std::vector<std::size_t> order(pts.size());
        std::vector<long> tile(pts.size());
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const glm::dvec2 t = (pts[i] - shore.corner()) / (4.0 * shore.texel());
            tile[i] = static_cast<long>(std::floor(t.y)) * 4096 + static_cast<long>(std::floor(t.x));
            order[i] = i;
        }
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return tile[a] < tile[b]; });
        double per_point = 0.0, per_batch = 0.0, unconverged = 0.0;
        for (std::size_t b = 0; b < order.size(); b += 8) {
            int most = 0;
            for (std::size_t l = b; l < b + 8 && l < order.size(); ++l) {
                const SurfacePoint& o = out[order[l]];
                per_point += o.iterations;
                most = std::max(most, o.iterations);
                unconverged += o.converged ? 0.0 : 1.0;
            }
            per_batch += most;
        }
        state.counters["evals_per_point"] = per_point / static_cast<double>(pts.size());
        state.counters["evals_per_batch"] = per_batch / std::ceil(static_cast<double>(pts.size()) / 8.0);
        state.counters["unconverged"] = unconverged;
    }
}

/// 4096 points scattered over a 24 m river's channel (and, with Arg 1, its mouth and the
/// sea beside it), queried through query_world: body lookup, river surface, waves riding
/// the current, the blend into still water.
void BM_RiverWorld(benchmark::State& state) {
    static const auto scene = [] {
        auto parsed = parse_scene(R"({ "version": 1, "name": "reach", "water_level": 0.0, "shore": { "enabled": false },
          "terrain": { "plane": { "height": 10.0, "slope": [-0.004, 0.0] } }, "ocean": "ocean_rolling",
          "rivers": [ { "name": "reach", "path": [[-2000, 30], [2900, 30]], "width": 24, "discharge": 40.0 } ] })",
                                  "benchmark");
        return bake_scene(parsed.value()).value();
    }();
    const bool mouth = state.range(0) != 0;
    std::mt19937_64 rng(11);
    std::vector<glm::dvec2> pts(kPoints);
    for (auto& p : pts) {
        const double u = static_cast<double>(rng() % 1000000) * 1e-6, v = static_cast<double>(rng() % 1000000) * 1e-6;
        p = mouth ? glm::dvec2(2460.0 + 120.0 * u, 30.0 + 40.0 * (v - 0.5))
                  : glm::dvec2(-1800.0 + 4000.0 * u, 30.0 + 20.0 * (v - 0.5));
    }
    std::vector<WorldPoint> out(pts.size());
    double t = kTime;
    for (auto _ : state) {
        t += 1.0 / 60.0;
        benchmark::DoNotOptimize(query_world(*scene, t, pts, out).ok());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
    state.SetLabel(mouth ? "mouth" : "channel");
}

/// Height queries on the open sea (ocean_rolling) with a boat's wake of N disturbance
/// points (0, 1024, 4096): 4096 points scattered over the wake.
void BM_WakeQueries(benchmark::State& state) {
    const WaterBody sea = make_sea(24);
    const auto points = static_cast<std::size_t>(state.range(0));
    // Two bow chains of N/2 points each, as a tug lays them (every 1.25 m) on a straight track.
    Wakes wakes;
    for (int side = 0; side < 2 && points > 0; ++side) {
        WakeChain chain;
        for (std::size_t i = 0; i < points / 2; ++i) {
            DisturbancePoint p;
            p.position = {1.25 * static_cast<double>(i), side ? 1.5 : -1.5};
            p.emitted = kTime - 0.25 * static_cast<double>(points / 2 - i);
            p.strength = 117.0;
            p.source_size = 10.0;
            p.steepness = 0.6;
            chain.points.push_back(p);
        }
        wakes.chains.push_back(chain);
    }
    std::mt19937_64 rng(5);
    std::vector<glm::dvec2> pts(kPoints);
    for (auto& p : pts)
        p = {static_cast<double>(rng() % 1000000) * 1.3e-3, static_cast<double>(rng() % 1000000) * 4e-4 - 200.0};
    std::vector<double> h(pts.size());
    QueryOptions options;
    options.wakes = points > 0 ? &wakes : nullptr;
    for (auto _ : state) {
        benchmark::DoNotOptimize(query_heights(sea, kTime, pts, h, options).ok());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pts.size()));
}

/// One buoyancy step of 100 barrels (64 triangles each) on ocean_rolling, one core.
void BM_BuoyancyStep(benchmark::State& state) {
    const WaterBody sea = make_sea(24);
    BuoyancyWorld world;
    for (int i = 0; i < 100; ++i) {
        RigidBodyState s;
        s.position = {7.0 * (i % 10), -0.2, 7.0 * (i / 10)};
        RigidBodyProps barrel = RigidBodyProps::barrel(0.4, 1.0, 250.0);
        barrel.hull = HullMesh::cylinder(0.4, 1.0, 16);  // 64 triangles
        (void)world.add(barrel, s);
    }
    world.set_time(kTime);
    for (auto _ : state) benchmark::DoNotOptimize(world.step({nullptr, &sea, nullptr}).ok());
    state.SetItemsProcessed(state.iterations() * 100);
    state.SetLabel("100 bodies x 64 triangles");
}

BENCHMARK(BM_WakeQueries)->Arg(0)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuoyancyStep)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ShoreHarbour)->Arg(0)->Arg(1);
BENCHMARK(BM_ShoreBand)->ArgsProduct({{0, 1}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RiverWorld)->Arg(0)->Arg(1);
BENCHMARK(BM_NewtonHeights)->Arg(8)->Arg(32)->Arg(64);
BENCHMARK(BM_NewtonSurface)->Arg(8)->Arg(32)->Arg(64);
BENCHMARK(BM_FixedPointReference)->Arg(8)->Arg(32)->Arg(64);

}  // namespace

BENCHMARK_MAIN();
