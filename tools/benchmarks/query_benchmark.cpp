// Google Benchmark: Eulerian height queries (SIMD Newton) against the seed
// project's fixed-point loop, and the full surface query, for 8/32/64 waves.
// Run: build/bin/tidewater_query_benchmark [--benchmark_filter=...]
// `tidewater bench` measures the same with accuracy figures, as JSON.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

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
        p = {static_cast<double>(rng() % 2000000) * 1e-3 - 1000.0, static_cast<double>(rng() % 2000000) * 1e-3 - 1000.0};
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

BENCHMARK(BM_NewtonHeights)->Arg(8)->Arg(32)->Arg(64);
BENCHMARK(BM_NewtonSurface)->Arg(8)->Arg(32)->Arg(64);
BENCHMARK(BM_FixedPointReference)->Arg(8)->Arg(32)->Arg(64);

}  // namespace

BENCHMARK_MAIN();
