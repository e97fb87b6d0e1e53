// tidewater demo: the main job on a scene (the bundled default unless --scene):
// a summary of the water, a CSV of its surface over a grid and a few times,
// and, with the renderer, a rendered still and a short sequence.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "atomic_file.hpp"
#if defined(TIDEWATER_HAVE_RENDER)
#include "render_job.hpp"
#endif
#include "scene_option.hpp"
#include "tidewater/body_summary.hpp"
#include "tidewater/query.hpp"
#include "tidewater/version.hpp"
#include "tidewater/world_query.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

struct DemoArgs {
    std::string scene;
    std::string out_dir = "tidewater-demo";
    int grid = 64;
    double extent = 200.0;
    std::vector<double> center;  // x z; default: under the scene's camera
    bool no_render = false;
};

int run_demo(const DemoArgs& a) {
    constexpr const char* verb = "demo";
    if (a.grid < 2 || a.grid > 2048) return fail(verb, "--grid: must be in 2..2048");
    if (!std::isfinite(a.extent) || a.extent <= 0.0 || a.extent > 1e6)
        return fail(verb, "--extent: must be in (0, 1e6] m");
    auto loaded = load_scene_option(a.scene);
    if (!loaded) return fail(verb, loaded.error().message);
    const std::shared_ptr<const Scene> scene = std::move(loaded).value();
    std::error_code ec;
    std::filesystem::create_directories(a.out_dir, ec);
    if (ec) return fail(verb, fmt::format("{}: cannot create folder: {}", a.out_dir, ec.message()));

    const WaterBody& ocean = scene->ocean;
    const WaveSet& waves = ocean.waves();
    // Energy-weighted mean period: sum(A^2 T) / sum(A^2).
    double energy = 0.0, weighted_period = 0.0;
    for (const Wave& w : waves.waves()) {
        energy += w.amplitude * w.amplitude;
        weighted_period += w.amplitude * w.amplitude * w.period();
    }
    const double mean_period = energy > 0.0 ? weighted_period / energy : 0.0;

    // Surface over a grid at a few times, centred under the scene's camera (on the
    // default island that is open water in front of the beach) unless --center says.
    glm::dvec2 centre = scene->camera ? glm::dvec2(scene->camera->position.x, scene->camera->position.z)
                                      : scene->terrain.extent_center();
    if (a.center.size() == 2) centre = {a.center[0], a.center[1]};
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y)) return fail(verb, "--center: must be finite");
    const int n = a.grid;
    std::vector<glm::dvec2> pts;
    pts.reserve(static_cast<std::size_t>(n * n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            pts.push_back(centre +
                          glm::dvec2(a.extent * (i / double(n - 1) - 0.5), a.extent * (j / double(n - 1) - 0.5)));
    std::vector<WorldPoint> surf(pts.size());
    const std::filesystem::path csv_path = std::filesystem::path(a.out_dir) / "surface.csv";
    AtomicFile csv(csv_path);
    if (!csv.status()) return fail(verb, csv.status().error().message);
    csv.stream() << "t,x,z,height,nx,ny,nz,vx,vy,vz,jacobian,depth,wet,foam,body,flow_x,flow_z\n";
    double min_h = 1e300, max_h = -1e300, min_jac = 1e300;
    QueryOptions opt;
    opt.threads = 0;
    for (double t : {0.0, 2.0, 4.0, 6.0}) {
        if (auto st = query_world(*scene, t, pts, surf, opt); !st) return fail(verb, st.error().message);
        for (std::size_t k = 0; k < pts.size(); ++k) {
            const SurfacePoint& s = surf[k].surface;
            csv.stream() << fmt::format(
                "{},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{:.5f},{:.5f},{:.5f},{:.6f},{:.3f},{},{:.3f},{},{:.5f},{:.5f}\n",
                t, pts[k].x, pts[k].y, s.height, s.normal.x, s.normal.y, s.normal.z, s.velocity.x, s.velocity.y,
                s.velocity.z, s.jacobian, s.depth, s.wet ? 1 : 0, s.foam, body_name(*scene, surf[k].body),
                surf[k].flow.x, surf[k].flow.y);
            min_h = std::min(min_h, s.height);
            max_h = std::max(max_h, s.height);
            min_jac = std::min(min_jac, s.jacobian);
        }
    }
    if (auto st = csv.commit(); !st) return fail(verb, st.error().message);

    const BodySummary bodies = summarize_bodies(*scene);
    nlohmann::json lakes = nlohmann::json::array(), rivers = nlohmann::json::array();
    for (const LakeSummary& l : bodies.lakes)
        lakes.push_back({{"name", l.name}, {"level_m", l.level}, {"area_m2", l.area}});
    for (const RiverSummary& r : bodies.rivers)
        rivers.push_back({{"name", r.name},
                          {"ends_in", r.ends_in},
                          {"receiver", r.receiver},
                          {"length_m", r.length},
                          {"discharge_m3_s", r.discharge},
                          {"mean_speed_m_s", r.mean_speed},
                          {"source_level_m", r.source_level},
                          {"mouth_level_m", r.mouth_level},
                          {"islands", r.islands}});
    nlohmann::json summary = {{"tidewater_version", TIDEWATER_VERSION_STRING},
                              {"scene", scene->name},
                              {"water_level_m", scene->water_level()},
                              {"terrain", scene->terrain.kind_name()},
                              {"terrain_height_at_origin_m", scene->terrain.height_at({0.0, 0.0})},
                              {"ocean", ocean.profile().name},
                              {"waves", waves.size()},
                              {"significant_wave_height_m", waves.significant_wave_height()},
                              {"mean_period_s", mean_period},
                              {"fold_measure_sum_QkA", waves.fold_measure()},
                              {"max_horizontal_displacement_m", waves.max_horizontal_displacement()},
                              {"grid",
                               {{"points", pts.size()},
                                {"center_m", {centre.x, centre.y}},
                                {"extent_m", a.extent},
                                {"times_s", {0.0, 2.0, 4.0, 6.0}}}},
                              {"surface_height_range_m", {min_h, max_h}},
                              {"min_jacobian", min_jac},
                              {"query_kernel", query_kernel_name()},
                              {"lakes", lakes},
                              {"rivers", rivers},
                              {"warnings", scene->warnings}};
    const std::filesystem::path summary_path = std::filesystem::path(a.out_dir) / "summary.json";
    AtomicFile sum_file(summary_path);
    if (auto st = sum_file.write_and_commit(summary.dump(2) + "\n"); !st) return fail(verb, st.error().message);

    std::printf("Tidewater %s demo: scene \"%s\", ocean \"%s\"\n", TIDEWATER_VERSION_STRING, scene->name.c_str(),
                ocean.profile().name.c_str());
    std::printf("  %zu Gerstner waves, Hs = %.2f m, mean period %.1f s, sum(QkA) = %.3f\n", waves.size(),
                waves.significant_wave_height(), mean_period, waves.fold_measure());
    std::printf("  terrain: %s; surface height %.2f .. %.2f m over the grid; min Jacobian %.3f\n",
                scene->terrain.kind_name(), min_h, max_h, min_jac);
    for (const LakeSummary& l : bodies.lakes)
        std::printf("  lake \"%s\": level %.1f m, %.0f m^2\n", l.name.c_str(), l.level, l.area);
    for (const SceneBoat& b : scene->boats)
        std::printf("  boat \"%s\": %.0f m hull at %.1f m/s along %.0f m of path\n", b.name.c_str(), b.hull.length,
                    b.speed, b.path_length());
    if (!scene->floats.empty()) std::printf("  %zu floats (barrels, crates, buoys) afloat\n", scene->floats.size());
    for (const RiverSummary& r : bodies.rivers)
        std::printf(
            "  river \"%s\": %.0f m from %.1f m to %s%s%s at %.1f m, %.1f m^3/s at a mean %.2f m/s, %d island%s\n",
            r.name.c_str(), r.length, r.source_level, r.ends_in.c_str(), r.receiver.empty() ? "" : " ",
            r.receiver.c_str(), r.mouth_level, r.discharge, r.mean_speed, r.islands, r.islands == 1 ? "" : "s");
    for (const std::string& w : scene->warnings) std::printf("  warning: %s\n", w.c_str());
    std::printf("  wrote %s\n  wrote %s\n", summary_path.string().c_str(), csv_path.string().c_str());
#if defined(TIDEWATER_HAVE_RENDER)
    if (!a.no_render) {
        // A still and a short sequence of the scene.
        RenderJob still;
        still.extent = {1280, 720};
        still.start_time = 3.0;
        still.single_output = (std::filesystem::path(a.out_dir) / "still.png").string();
        auto shot = run_render_job(*scene, still);
        if (!shot) return fail(verb, shot.error().message);
        // The first boat, followed from astern and above, with what floats round it.
        std::string boat_still;
        if (!scene->boats.empty()) {
            glm::dvec2 at;
            double heading = 0.0;
            scene->boats.front().pose_at(still.start_time, at, heading);
            const glm::dvec2 forward{std::cos(heading), std::sin(heading)}, starboard{-forward.y, forward.x};
            const glm::dvec2 eye = at - 45.0 * forward - 28.0 * starboard, look = at + 25.0 * forward;
            RenderJob boat = still;
            boat.camera = render::Camera{};
            boat.camera->position = {eye.x, scene->water_level() + 14.0, eye.y};
            boat.camera->target = {look.x, scene->water_level(), look.y};
            boat.camera->fov_y_deg = 45.0;
            boat.single_output = boat_still = (std::filesystem::path(a.out_dir) / "boat.png").string();
            auto shot_boat = run_render_job(*scene, boat);
            if (!shot_boat) return fail(verb, shot_boat.error().message);
        }
        RenderJob sequence = still;
        sequence.extent = {640, 360};
        sequence.frames = 24;
        sequence.fps = 12.0;
        sequence.single_output.clear();
        sequence.output_dir = (std::filesystem::path(a.out_dir) / "sequence").string();
        auto seq = run_render_job(*scene, sequence);
        if (!seq) return fail(verb, seq.error().message);
        std::printf("  rendered on %s:\n  wrote %s\n", shot->device.c_str(), shot->files.front().c_str());
        if (!boat_still.empty())
            std::printf("  wrote %s (the boat \"%s\")\n", boat_still.c_str(), scene->boats.front().name.c_str());
        std::printf("  wrote %zu frames in %s/\n", seq->files.size(), sequence.output_dir.c_str());
    }
#endif
    return 0;
}

}  // namespace

Verb add_demo_verb(CLI::App& app) {
    auto args = std::make_shared<DemoArgs>();
    CLI::App* cmd = app.add_subcommand("demo", "Run the main job on a scene: a summary and a surface CSV");
    cmd->add_option("--scene", args->scene, "Scene JSON (default: the bundled default scene)");
    cmd->add_option("--out-dir", args->out_dir, "Folder for summary.json and surface.csv")->capture_default_str();
    cmd->add_option("--grid", args->grid, "Grid points per side")->capture_default_str();
    cmd->add_option("--extent", args->extent, "Grid side length, m")->capture_default_str();
    cmd->add_option("--center", args->center, "Grid centre x z, m (default: under the scene's camera)")->expected(2);
    cmd->add_flag("--no-render", args->no_render, "Skip the rendered still and sequence");
    return {cmd, [args] { return run_demo(*args); }};
}

}  // namespace tidewater::cli
