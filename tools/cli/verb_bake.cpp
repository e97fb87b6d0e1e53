// tidewater bake: a scene's bake (bake_scene: one shoreline bake, the shore model
// sampling it, the lakes and rivers and the lakes' shore models) saved as 16-bit PNGs
// with JSON sidecars, whole or not at all. A scene loads it with "shore": {"bake": "folder"}.
#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <string_view>

#include "scene_option.hpp"
#include "tidewater/body_summary.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/scene_bake.hpp"
#include "tiled_bake.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

/// A progress line every 10% of the whole bake, naming the stage.
class Progress {
  public:
    explicit Progress(bool quiet) : quiet_(quiet) {}
    void operator()(std::string_view stage, double f) {
        const int percent = static_cast<int>(f * 100.0);
        if (!quiet_ && percent >= last_ + 10) {
            std::fprintf(stderr, "bake: %3d%% (%.*s)\n", percent, static_cast<int>(stage.size()), stage.data());
            last_ = percent;
        }
    }

  private:
    bool quiet_;
    int last_ = -10;
};

int run_bake(const BakeArgs& a) {
    constexpr const char* verb = "bake";
    if (a.tiles > 0) return run_tiled_bake(a);
    if (!a.step.empty() || a.task >= 0 || a.status || a.merge)
        return fail(verb, "--step, --task, --status and --merge are a tiled bake's: give --tiles T");
    if (a.out.empty()) return fail(verb, "give --out DIR");
    auto scene = parse_scene_option(a.scene);
    if (!scene) return fail(verb, scene.error().message);
    const bool bodies = !scene->lakes.empty() || !scene->rivers.empty();
    const bool ocean_shore = scene->shore.enabled && scene->has_ocean;
    if (!ocean_shore && !bodies)
        return fail(verb, fmt::format("{} has its shore disabled and no lakes or rivers: there is nothing to bake",
                                      scene_label(*scene)));
    // This verb makes the scene's bake: a saved one it names is not loaded but redone.
    scene->shore.bake_folder.clear();
    // The scene's resolutions unless the command line overrides them.
    if (a.model_resolution != 0) scene->shore.resolution = a.model_resolution;
    if (a.resolution != 0) scene->shore.distance_resolution = a.resolution;
    const int distance =
        scene->shore.distance_resolution != 0 ? scene->shore.distance_resolution : scene->shore.resolution;
    if (!a.quiet)
        std::fprintf(stderr, "bake: shore model %dx%d over a %dx%d shoreline, %zu waves\n", scene->shore.resolution,
                     scene->shore.resolution, distance, distance, scene->ocean.waves().size());
    SceneBakeOptions options;
    options.distance_resolution = distance;
    options.threads = a.threads;
    Progress progress(a.quiet);
    options.progress = [&](std::string_view stage, double f) { progress(stage, f); };
    auto baked = bake_scene(*scene, options);
    if (!baked) return fail(verb, baked.error().message);
    if (auto st = save_scene_bake(a.out, **baked); !st) return fail(verb, st.error().message);
    std::printf("baked \"%s\" in %.2f s -> %s/\n", (*baked)->name.c_str(), (*baked)->bake->seconds, a.out.c_str());
    if (ocean_shore) {
        const ShoreWaves& model = *(*baked)->bake->ocean_shore;
        const ShoreField& field = *(*baked)->bake->shoreline;
        std::printf(
            "  ocean: shore model %dx%d (%.2f m texels, %zu waves); signed distance %dx%d (%.2f m texels): %zu "
            "shoreline "
            "segments, %zu land polygons, %zu enclosed waters\n",
            model.resolution(), model.resolution(), model.texel(), model.wave_count(), field.resolution,
            field.resolution, field.texel, field.segment_count, field.polygons, field.holes);
        std::printf("    shared fields: %zu of %zu tiles stored\n", model.shared().stored_tiles(),
                    model.shared().pages.size());
        for (const ShoreWaveLayer& run : model.layers())
            std::printf("    waves %zu to %zu: %dx%d at %.2f m texels, %zu of %zu tiles stored\n", run.first,
                        run.first + run.count - 1, run.grid.resolution, run.grid.resolution, run.grid.texel,
                        run.tiles.stored_tiles(), run.tiles.pages.size());
        std::printf("    %.1f MB of tiles\n", static_cast<double>(model.bytes()) / 1e6);
    }
    const BodySummary summary = summarize_bodies(**baked);
    for (const LakeSummary& l : summary.lakes)
        std::printf("  lake \"%s\": level %.2f m, %.0f m^2\n", l.name.c_str(), l.level, l.area);
    for (const RiverSummary& r : summary.rivers)
        std::printf("  river \"%s\": %.0f m to %s%s%s, %.2f m^3/s, grid %dx%d at %.2f m, %d island%s\n", r.name.c_str(),
                    r.length, r.ends_in.c_str(), r.receiver.empty() ? "" : " ", r.receiver.c_str(), r.discharge,
                    r.grid_nx, r.grid_nz, r.texel, r.islands, r.islands == 1 ? "" : "s");
    return 0;
}

}  // namespace

Verb add_bake_verb(CLI::App& app) {
    auto args = std::make_shared<BakeArgs>();
    CLI::App* cmd =
        app.add_subcommand("bake",
                           "Bake the shore model (per-wave fields), the shoreline, its signed distance and the depth "
                           "to a folder a scene can load");
    cmd->add_option("--scene", args->scene, "Scene JSON (default: the bundled default scene)");
    cmd->add_option("--out", args->out, "Output folder (written whole or not at all)")->required();
    cmd->add_option("--resolution", args->resolution,
                    "Texels per side of the signed distance field (8 to 8192; default: the scene's "
                    "shore.distance_resolution, else its shore.resolution)");
    cmd->add_option("--model-resolution", args->model_resolution,
                    "Texels per side of the per-wave shore model (16 to 8192; default: the scene's shore.resolution)");
    cmd->add_option("--tolerance", args->tolerance, "Shoreline simplification tolerance, m (0 = half a texel)");
    cmd->add_option("--threads", args->threads, "Worker threads (0 = all)");
    cmd->add_flag("--quiet", args->quiet, "No progress lines");
    cmd->add_option("--tiles", args->tiles,
                    "Bake as a farmed job over T x T tiles of the distance field (docs/scale-out.md); its steps' "
                    "files go to OUT.job/")
        ->check(CLI::Range(1, 256));
    cmd->add_option("--step", args->step,
                    "With --tiles: run one step, contours (an array), stitch or distances (an array)");
    cmd->add_option("--task", args->task, "With --step contours or distances: the tile to run, 0 to T*T-1")
        ->check(CLI::Range(0, 65535));
    cmd->add_flag(
        "--status", args->status,
        "With --step contours or distances: list the tiles missing or failed (todo: in sbatch --array's form)");
    cmd->add_flag("--merge", args->merge,
                  "With --tiles: once every tile's distances are done, march the shore model and write OUT");
    return {cmd, [args] { return run_bake(*args); }};
}

}  // namespace tidewater::cli
