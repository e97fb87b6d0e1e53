// tidewater drift: a floating tracer carried by the scene's currents, as a CSV track.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "atomic_file.hpp"
#include "scene_option.hpp"
#include "tidewater/drift.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

struct DriftArgs {
    std::string scene;
    std::string start;
    double duration = 0.0;
    double dt = 1.0 / 60.0;
    double time = 0.0;
    std::string out;
};

/// "x,z" in metres.
Result<glm::dvec2> parse_start(const std::string& text) {
    const auto comma = text.find(',');
    const auto bad = [&] {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("--start \"{}\" must be x,z in metres (two finite numbers)", text)};
    };
    if (comma == std::string::npos) return bad();
    try {
        std::size_t used_x = 0, used_z = 0;
        const std::string xs = text.substr(0, comma), zs = text.substr(comma + 1);
        const double x = std::stod(xs, &used_x), z = std::stod(zs, &used_z);
        if (used_x != xs.size() || used_z != zs.size() || !std::isfinite(x) || !std::isfinite(z)) return bad();
        return glm::dvec2(x, z);
    } catch (const std::exception&) {
        return bad();
    }
}

int run_drift(const DriftArgs& a) {
    constexpr const char* verb = "drift";
    auto start = parse_start(a.start);
    if (!start) return fail(verb, start.error().message);
    auto loaded = load_scene_option(a.scene, OceanNeed::optional);
    if (!loaded) return fail(verb, loaded.error().message);
    const std::shared_ptr<const Scene> scene = std::move(loaded).value();
    for (const std::string& w : scene->warnings) std::fprintf(stderr, "tidewater drift: warning: %s\n", w.c_str());
    DriftOptions options;
    options.start_time = a.time;
    options.duration = a.duration;
    options.dt = a.dt;
    auto track = drift(*scene, *start, options);
    if (!track) return fail(verb, track.error().message);

    std::string text = "t,x,z,height,body\n";
    for (const DriftSample& s : *track)
        fmt::format_to(std::back_inserter(text), "{:.6f},{:.6f},{:.6f},{:.6f},{}\n", s.time, s.position.x, s.position.y,
                       s.height, body_name(*scene, s.body));
    // Written whole or not at all.
    AtomicFile file(a.out);
    if (!file.status()) return fail(verb, file.status().error().message);
    file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
    if (auto st = file.commit(); !st) return fail(verb, st.error().message);
    const double travelled = track->back().time - track->front().time;
    std::fprintf(stderr, "tidewater drift: %zu samples over %.3f s, from %s to %s\n", track->size(), travelled,
                 std::string(body_name(*scene, track->front().body)).c_str(),
                 std::string(body_name(*scene, track->back().body)).c_str());
    return 0;
}

}  // namespace

Verb add_drift_verb(CLI::App& app) {
    auto args = std::make_shared<DriftArgs>();
    CLI::App* cmd =
        app.add_subcommand("drift", "A floating tracer carried by the currents (RK4 on the baked river current)");
    cmd->add_option("--scene", args->scene, "Scene JSON (default: the bundled default scene)");
    cmd->add_option("--start", args->start, "Start point x,z, m (in water)")->required();
    cmd->add_option("--duration", args->duration, "How long to drift, s (> 0)")->required();
    cmd->add_option("--dt", args->dt, "Integration step, s")->capture_default_str();
    cmd->add_option("--time", args->time, "Clock time at the start, s")->capture_default_str();
    cmd->add_option("--out", args->out, "Output CSV; written whole or not at all")->required();
    cmd->footer(
        "Output columns: t,x,z,height,body (s, m, m, world y in m, the body's name).\n"
        "The track stops at the duration or where the next step would leave the water.");
    return {cmd, [args] { return run_drift(*args); }};
}

}  // namespace tidewater::cli
