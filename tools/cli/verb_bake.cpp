// tidewater bake: the shore model and signed distance field of a scene as 16-bit
// PNGs with a JSON sidecar (save_shore_bake: whole or not at all). A scene loads it
// with "shore": {"bake": "folder"}.
#include <cstdio>
#include <memory>

#include "scene_option.hpp"
#include "tidewater/shore_bake.hpp"
#include "tidewater/shore_bake_folder.hpp"
#include "tidewater/shore_waves.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

struct BakeArgs {
    std::string scene;
    std::string out;
    int resolution = 1024;
    int model_resolution = 0;
    double tolerance = 0.0;
    unsigned threads = 0;
    bool quiet = false;
};

/// Progress lines every 10% of a stage.
class Progress {
public:
    Progress(bool quiet, const char* stage) : quiet_(quiet), stage_(stage) {}
    void operator()(double f) {
        const int percent = static_cast<int>(f * 100.0);
        if (!quiet_ && percent >= last_ + 10) {
            std::fprintf(stderr, "bake: %s %d%%\n", stage_, percent);
            last_ = percent;
        }
    }

private:
    bool quiet_;
    const char* stage_;
    int last_ = -10;
};

int run_bake(const BakeArgs& a) {
    constexpr const char* verb = "bake";
    if (a.out.empty()) return fail(verb, "give --out DIR");
    // The scene's own shore model is what this verb makes: don't bake it on load too.
    SceneLoadOptions load;
    load.shore_model = false;
    auto scene = load_scene_option(a.scene, load);
    if (!scene) return fail(verb, scene.error().message);

    ShoreWaveOptions model_options = scene->shore.options;
    if (a.model_resolution != 0) model_options.resolution = a.model_resolution;
    model_options.threads = a.threads;
    if (!a.quiet) std::fprintf(stderr, "bake: shore model %dx%d, %zu waves\n", model_options.resolution, model_options.resolution,
                               scene->ocean.waves().size());
    auto model = ShoreWaves::bake(scene->ocean.waves(), scene->terrain, scene->water_level(), model_options);
    if (!model) return fail(verb, model.error().message);

    BakeOptions options;
    options.resolution = a.resolution;
    options.simplify_tolerance = a.tolerance;
    options.threads = a.threads;
    Progress progress(a.quiet, "signed distance");
    options.progress = [&](double f) { progress(f); };
    auto field = bake_shore(scene->terrain, scene->water_level(), options);
    if (!field) return fail(verb, field.error().message);

    ShoreBakeContents contents;
    contents.model = model->get();
    contents.waves = &scene->ocean.waves();
    contents.water_level = scene->water_level();
    contents.breaking_index = model_options.breaking_index;
    contents.scene_name = scene->name;
    contents.distance_field = &*field;
    if (auto st = save_shore_bake(a.out, contents); !st) return fail(verb, st.error().message);
    std::printf("baked \"%s\": shore model %dx%d (%.2f m texels, %zu waves); signed distance %dx%d (%.2f m texels): %zu shoreline "
                "segments, %zu land polygons, %zu enclosed waters -> %s/\n",
                scene->name.c_str(), (*model)->resolution(), (*model)->resolution(), (*model)->texel(), (*model)->wave_count(),
                field->resolution, field->resolution, field->texel, field->segment_count, field->polygons, field->holes, a.out.c_str());
    return 0;
}

}  // namespace

Verb add_bake_verb(CLI::App& app) {
    auto args = std::make_shared<BakeArgs>();
    CLI::App* cmd = app.add_subcommand("bake", "Bake the shore model (per-wave fields), the shoreline, its signed distance and the depth "
                                                "to a folder a scene can load");
    cmd->add_option("--scene", args->scene, "Scene JSON (default: the bundled default scene)");
    cmd->add_option("--out", args->out, "Output folder (written whole or not at all)")->required();
    cmd->add_option("--resolution", args->resolution, "Texels per side of the signed distance field (8 to 8192)")->capture_default_str();
    cmd->add_option("--model-resolution", args->model_resolution,
                    "Texels per side of the per-wave shore model (16 to 4096; default: the scene's shore.resolution)");
    cmd->add_option("--tolerance", args->tolerance, "Shoreline simplification tolerance, m (0 = half a texel)");
    cmd->add_option("--threads", args->threads, "Worker threads (0 = all)");
    cmd->add_flag("--quiet", args->quiet, "No progress lines");
    return {cmd, [args] { return run_bake(*args); }};
}

}  // namespace tidewater::cli
