// A camera flight across a scene, drawn headless at 1080p (or the size given): the time
// of set_scene and of every frame (submitted, drawn and read back), their median and
// worst, and what is resident on the device. One JSON object on standard output:
//   tidewater_flight_benchmark SCENE.json [FRAMES=60] [WIDTH=1920] [HEIGHT=1080] [BUDGET_MIB=1024]
// The scene is baked, or loaded from the saved bake it names. The camera flies 150 m up
// along the terrain's diagonal, from one corner of its extent to the other, looking ahead
// and down; frames are 1/60 s apart in the water's time. docs/PERFORMANCE.md ("Worlds at
// real scale") quotes it: the issue's "no frame takes longer than twice the median".
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tidewater/render/offscreen.hpp"
#include "tidewater/render/renderer.hpp"
#include "tidewater/render/standalone.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

int fail(const std::string& what) {
    std::fprintf(stderr, "tidewater_flight_benchmark: %s\n", what.c_str());
    return 1;
}

double percentile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

/// The process's resident memory now and its peak, MiB (Linux: /proc/self/status).
std::pair<double, double> resident_mib() {
    std::ifstream status("/proc/self/status");
    double now = 0.0, peak = 0.0;
    for (std::string line; std::getline(status, line);) {
        std::istringstream fields(line);
        std::string key;
        double kib = 0.0;
        fields >> key >> kib;
        if (key == "VmRSS:") now = kib / 1024.0;
        if (key == "VmHWM:") peak = kib / 1024.0;
    }
    return {now, peak};
}

}  // namespace

int main(int argc, char** argv) {
    using namespace tidewater;
    if (argc < 2) return fail("usage: SCENE.json [FRAMES=60] [WIDTH=1920] [HEIGHT=1080] [BUDGET_MIB=1024]");
    const int frames = argc > 2 ? std::atoi(argv[2]) : 60;
    const int width = argc > 3 ? std::atoi(argv[3]) : 1920, height = argc > 4 ? std::atoi(argv[4]) : 1080;
    const long budget_mib = argc > 5 ? std::atol(argv[5]) : 1024;
    if (frames < 2 || frames > 100000 || width < 16 || width > 8192 || height < 16 || height > 8192 ||
        budget_mib < 16 || budget_mib > (1L << 20))
        return fail("FRAMES must be 2 to 100000, WIDTH and HEIGHT 16 to 8192, BUDGET_MIB 16 to 2^20");

    auto parsed = load_scene(argv[1]);
    if (!parsed) return fail(parsed.error().message);
    const auto t_bake = Clock::now();
    auto scene = bake_scene(*parsed);
    if (!scene) return fail(scene.error().message);
    const double bake_s = seconds_since(t_bake);

    auto device = render::StandaloneDevice::create({});
    if (!device) return fail(device.error().message);
    render::RendererInitInfo init;
    init.device = (*device)->context();
    init.color_format = render::OffscreenTarget::kColorFormat;
    init.depth_format = render::OffscreenTarget::kDepthFormat;
    init.gpu_memory_budget = static_cast<std::uint64_t>(budget_mib) << 20;
    auto renderer = render::Renderer::create(init);
    if (!renderer) return fail(renderer.error().message);
    auto target = render::OffscreenTarget::create((*device)->context(), static_cast<std::uint32_t>(width),
                                                  static_cast<std::uint32_t>(height));
    if (!target) return fail(target.error().message);
    const auto t_upload = Clock::now();
    if (auto st = (*renderer)->set_scene(**scene); !st) return fail(st.error().message);
    const double set_scene_s = seconds_since(t_upload);

    // Corner to corner, 150 m above the water, looking 400 m ahead and down to the water.
    const glm::dvec2 c = (*scene)->terrain.extent_center();
    const double half = (*scene)->terrain.extent_half_size(), level = (*scene)->water_level();
    const glm::dvec2 from = c - glm::dvec2(0.9 * half), to = c + glm::dvec2(0.9 * half);
    const glm::dvec2 ahead = glm::normalize(to - from) * 400.0;
    std::vector<double> frame_ms;
    std::uint64_t streamed_bytes = 0, most_streamed = 0;  // full-resolution shore tiles brought in
    render::FrameInfo frame;
    for (int i = 0; i < frames; ++i) {
        const glm::dvec2 at = from + (to - from) * (static_cast<double>(i) / (frames - 1));
        frame.camera.position = {at.x, level + 150.0, at.y};
        frame.camera.target = {at.x + ahead.x, level, at.y + ahead.y};
        frame.time = i / 60.0;
        frame.frame_index = static_cast<std::uint64_t>(i);
        const auto t0 = Clock::now();
        auto image = (*target)->render(**renderer, frame);
        if (!image) return fail(image.error().message);
        frame_ms.push_back(1e3 * seconds_since(t0));
        const std::uint64_t streamed = (*renderer)->stats().shore_streamed_bytes;
        streamed_bytes += streamed;
        most_streamed = std::max(most_streamed, streamed);
    }
    const double median = percentile(frame_ms, 0.5), worst = *std::max_element(frame_ms.begin(), frame_ms.end());
    const render::RendererStats s = (*renderer)->stats();
    const auto [rss_mib, peak_rss_mib] = resident_mib();
    std::printf(
        "{\"scene\": \"%s\", \"device\": \"%s\", \"width\": %d, \"height\": %d, \"frames\": %d, "
        "\"budget_mib\": %ld, \"bake_or_load_s\": %.2f, \"set_scene_s\": %.2f, \"first_frame_ms\": %.1f, "
        "\"median_ms\": %.1f, \"p95_ms\": %.1f, \"max_ms\": %.1f, \"max_over_median\": %.2f, "
        "\"terrain_mib\": %.1f, \"shore_mib\": %.1f, \"shore_stride\": %u, \"shore_tiles_streamed\": %llu, "
        "\"shore_tiles_streamable\": %llu, \"streamed_mib\": %.1f, \"most_streamed_in_a_frame_mib\": %.2f, "
        "\"host_rss_mib\": %.0f, \"host_peak_rss_mib\": %.0f}\n",
        argv[1], (*device)->device_name().c_str(), width, height, frames, budget_mib, bake_s, set_scene_s,
        frame_ms.front(), median, percentile(frame_ms, 0.95), worst, worst / median,
        static_cast<double>(s.terrain_bytes) / (1 << 20), static_cast<double>(s.shore_bytes) / (1 << 20),
        s.shore_stride, static_cast<unsigned long long>(s.shore_streamed_tiles),
        static_cast<unsigned long long>(s.shore_streamable_tiles), static_cast<double>(streamed_bytes) / (1 << 20),
        static_cast<double>(most_streamed) / (1 << 20), rss_mib, peak_rss_mib);
    return 0;
}
