// Minimal host: load the bundled ocean preset, ask the water height under a
// buoy over a few seconds, and float a small boat on it.
#include <cstdio>
#include <tidewater/tidewater.hpp>
#if defined(CONSUMER_HAS_RENDER)
#include <tidewater/render/gpu_query.hpp>
#endif

int main() {
    auto preset = tidewater::load_preset("ocean_rolling");
    if (!preset) {
        std::fprintf(stderr, "%s\n", preset.error().message.c_str());
        return 1;
    }
    auto ocean = tidewater::WaterBody::create(*preset, /*level=*/0.0, "consumer");
    if (!ocean) {
        std::fprintf(stderr, "%s\n", ocean.error().message.c_str());
        return 1;
    }
    tidewater::Clock clock;
    for (int frame = 0; frame < 5; ++frame) {
        const tidewater::SurfacePoint s = tidewater::query_point(*ocean, clock.now(), {10.0, 5.0});
        std::printf("t=%.2f s height=%.3f m jacobian=%.3f\n", clock.now(), s.height, s.jacobian);
        clock.advance(0.5);
    }
    const auto boat = tidewater::FloatingBody::four_point(8.0, 3.0);
    auto attitude = tidewater::hull_attitude(*ocean, boat, clock.now());
    if (!attitude) return 1;
#if defined(CONSUMER_HAS_RENDER)
    std::printf("renderer linked: %s\n", &tidewater::render::GpuQuery::create != nullptr ? "yes" : "no");
#endif
    std::printf("boat heave=%.3f m pitch=%.4f rad roll=%.4f rad (Tidewater %s)\n", attitude->heave, attitude->pitch,
                attitude->roll, TIDEWATER_VERSION_STRING);
    return 0;
}
