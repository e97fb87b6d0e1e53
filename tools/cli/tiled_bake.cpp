#include "tiled_bake.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "farm_job.hpp"
#include "scene_option.hpp"
#include "tidewater/detail/tiled_shore.hpp"
#include "tidewater/scene_bake.hpp"
#include "tiled_bake_files.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

namespace fs = std::filesystem;

constexpr const char* kVerb = "bake";

/// A tiled bake's job: its scene, tiling and folders (DIR.job/contours, shoreline.bin,
/// DIR.job/distances), and the carved terrain once a step needs it.
class TiledJob {
  public:
    TiledJob(Scene scene, tiled::ShoreTiling tiling, const BakeArgs& a)
        : scene_(std::move(scene)), tiling_(tiling), args_(a), root_(a.out + ".job") {}

    std::size_t units() const { return static_cast<std::size_t>(tiling_.count()); }
    farm::JobFolder root() const { return farm::JobFolder(root_); }
    farm::JobFolder contours() const { return farm::JobFolder(root_ / "contours"); }
    farm::JobFolder distances() const { return farm::JobFolder(root_ / "distances"); }
    fs::path shoreline_file() const { return root_ / "shoreline.bin"; }
    std::string describe(std::size_t t) const {
        return fmt::format("column {}, row {}", t % static_cast<std::size_t>(tiling_.tiles),
                           t / static_cast<std::size_t>(tiling_.tiles));
    }

    Status contour_unit(std::size_t task) {
        bool skipped = false;
        std::size_t pieces = 0;
        const Status st = contours().run_unit(
            task,
            [&](const fs::path& temp) -> Status {
                auto terrain = carved();
                if (!terrain) return terrain.error();
                auto c = tiled::extract_tile_contour(**terrain, scene_.water_level(), tiling_, static_cast<int>(task),
                                                     args_.threads);
                if (!c) return c.error();
                pieces = c->cells.size();
                return tiled_files::write_contour(temp / "contour.bin", *c);
            },
            skipped);
        if (st && !args_.quiet)
            std::printf("contours: tile %zu (%s): %s\n", task, describe(task).c_str(),
                        skipped ? "done already" : fmt::format("{} pieces of shoreline", pieces).c_str());
        return st;
    }

    Status stitch() {
        std::error_code ec;
        if (fs::exists(shoreline_file(), ec)) {
            if (!args_.quiet) std::printf("stitch: done already (%s)\n", shoreline_file().c_str());
            return {};
        }
        if (auto st = farm::require_all_done(contours(), units(), [&](std::size_t t) { return describe(t); }); !st)
            return st;
        std::vector<tiled::TileContour> all;
        for (std::size_t t = 0; t < units(); ++t) {
            auto c = tiled_files::read_contour(contours().unit_folder(t) / "contour.bin", tiling_, static_cast<int>(t));
            if (!c) return c.error();
            all.push_back(std::move(c).value());
        }
        auto stitched = tiled::stitch_shoreline(tiling_, std::move(all), args_.tolerance, args_.threads);
        if (!stitched) return stitched.error();
        if (auto st = tiled_files::write_shoreline(shoreline_file(), *stitched); !st) return st;
        if (!args_.quiet)
            std::printf("stitch: %zu shoreline segments, %zu land polygons, %zu enclosed waters\n",
                        stitched->segment_count, stitched->polygons, stitched->holes);
        return {};
    }

    Status distance_unit(std::size_t task) {
        bool skipped = false;
        const Status st = distances().run_unit(
            task,
            [&](const fs::path& temp) -> Status {
                auto stitched = shoreline();
                if (!stitched) return stitched.error();
                auto terrain = carved();
                if (!terrain) return terrain.error();
                auto d = tiled::bake_tile_distances(**terrain, scene_.water_level(), tiling_, static_cast<int>(task),
                                                    **stitched, args_.threads);
                if (!d) return d.error();
                return tiled_files::write_distances(temp / "distances.bin", *d);
            },
            skipped);
        if (st && !args_.quiet)
            std::printf("distances: tile %zu (%s): %s\n", task, describe(task).c_str(),
                        skipped ? "done already" : "baked");
        return st;
    }

    Status merge() {
        const auto start = std::chrono::steady_clock::now();
        if (auto st = farm::require_all_done(distances(), units(), [&](std::size_t t) { return describe(t); }); !st)
            return st;
        auto stitched = shoreline();
        if (!stitched) return stitched.error();
        auto field = tiled::assemble_shore_field(tiling_, **stitched, [&](int t) {
            return tiled_files::read_distances(distances().unit_folder(static_cast<std::size_t>(t)) / "distances.bin",
                                               tiling_, t);
        });
        if (!field) return field.error();
        SceneBakeOptions options;
        options.distance_resolution = tiling_.resolution;
        options.threads = args_.threads;
        auto baked = tiled::bake_scene_on_shoreline(scene_, options,
                                                    std::make_shared<const ShoreField>(std::move(field).value()));
        if (!baked) return baked.error();
        if (auto st = save_scene_bake(args_.out, **baked); !st) return st;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("baked \"%s\" from %zu tiles (merge %.2f s) -> %s/\n", (*baked)->name.c_str(), units(), seconds,
                    args_.out.c_str());
        return {};
    }

  private:
    Result<const Terrain*> carved() {
        if (!terrain_) {
            auto t = tiled::shore_terrain(scene_);
            if (!t) return t.error();
            terrain_ = std::move(t).value();
        }
        return &*terrain_;
    }
    Result<const ShoreField*> shoreline() {
        if (!stitched_) {
            std::error_code ec;
            if (!fs::exists(shoreline_file(), ec))
                return Error{ErrorCode::invalid_argument,
                             fmt::format("{}: the shoreline is not stitched yet: run --step stitch first",
                                         shoreline_file().string())};
            auto s = tiled_files::read_shoreline(shoreline_file(), tiling_);
            if (!s) return s.error();
            stitched_ = std::move(s).value();
        }
        return &*stitched_;
    }

    Scene scene_;
    tiled::ShoreTiling tiling_;
    const BakeArgs& args_;
    fs::path root_;
    std::optional<Terrain> terrain_;
    std::optional<ShoreField> stitched_;
};

/// Runs unit `task` of a step, or every unit (each keeps its failure in its failure file).
Status run_units(std::size_t units, int task, const std::function<Status(std::size_t)>& unit) {
    if (task >= 0 && static_cast<std::size_t>(task) >= units)
        return Error{ErrorCode::invalid_argument, fmt::format("--task {}: the job has tiles 0 to {}", task, units - 1)};
    const std::size_t first = task >= 0 ? static_cast<std::size_t>(task) : 0;
    const std::size_t last = task >= 0 ? first + 1 : units;
    Status worst;
    for (std::size_t t = first; t < last; ++t) {
        const Status outcome = unit(t);
        if (!outcome) {
            std::fprintf(stderr, "tidewater %s: %s\n", kVerb, outcome.error().message.c_str());
            if (worst) worst = outcome;
        }
    }
    return worst;
}

}  // namespace

int run_tiled_bake(const BakeArgs& a) {
    if (a.out.empty()) return fail(kVerb, "give --out DIR");
    const bool array_step = a.step == "contours" || a.step == "distances";
    if (!a.step.empty() && !array_step && a.step != "stitch")
        return fail(kVerb, fmt::format("--step {}: give contours, stitch or distances", a.step));
    if ((a.task >= 0 || a.status) && !array_step)
        return fail(kVerb, "--task and --status go with --step contours or --step distances");
    if (a.task >= 0 && a.status) return fail(kVerb, "give --task or --status, not both");
    if (a.merge && !a.step.empty()) return fail(kVerb, "give --merge or --step, not both");
    auto scene = parse_scene_option(a.scene);
    if (!scene) return fail(kVerb, scene.error().message);
    if (!scene->shore.enabled || !scene->has_ocean)
        return fail(
            kVerb, fmt::format("{} has no ocean shore: a tiled bake tiles the ocean's shoreline", scene_label(*scene)));
    scene->shore.bake_folder.clear();
    if (a.model_resolution != 0) scene->shore.resolution = a.model_resolution;
    if (a.resolution != 0) scene->shore.distance_resolution = a.resolution;
    const int distance =
        scene->shore.distance_resolution != 0 ? scene->shore.distance_resolution : scene->shore.resolution;
    auto tiling = tiled::ShoreTiling::over(scene->terrain, distance, a.tiles);
    if (!tiling) return fail(kVerb, tiling.error().message);
    TiledJob job(*scene, *tiling, a);
    std::error_code ec;
    const std::string scene_path = a.scene.empty() ? "<default scene>" : fs::absolute(a.scene, ec).string();
    const std::string options =
        fmt::format("scene {}\ntiles {}\ndistance resolution {}\nmodel resolution {}\nsimplify tolerance {}\n",
                    scene_path, a.tiles, distance, scene->shore.resolution, a.tolerance);
    if (auto st = farm::check_job_options(job.root(), options, "another --out folder"); !st)
        return fail(kVerb, st.error().message);
    auto describe = [&](std::size_t t) { return job.describe(t); };
    if (a.status) {
        std::printf("%s",
                    farm::status_report(a.step == "contours" ? job.contours() : job.distances(), job.units(), describe)
                        .c_str());
        return 0;
    }
    auto step_ok = [](const Status& st) { return st ? 0 : 1; };
    if (a.step == "contours")
        return step_ok(run_units(job.units(), a.task, [&](std::size_t t) { return job.contour_unit(t); }));
    if (a.step == "distances")
        return step_ok(run_units(job.units(), a.task, [&](std::size_t t) { return job.distance_unit(t); }));
    if (a.step == "stitch") {
        if (auto st = job.stitch(); !st) return fail(kVerb, st.error().message);
        return 0;
    }
    if (!a.merge) {
        // Every step here, in turn.
        if (!run_units(job.units(), -1, [&](std::size_t t) { return job.contour_unit(t); })) return 1;
        if (auto st = job.stitch(); !st) return fail(kVerb, st.error().message);
        if (!run_units(job.units(), -1, [&](std::size_t t) { return job.distance_unit(t); })) return 1;
    }
    if (auto st = job.merge(); !st) return fail(kVerb, st.error().message);
    return 0;
}

}  // namespace tidewater::cli
