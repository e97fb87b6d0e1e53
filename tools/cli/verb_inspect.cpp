// tidewater inspect: sample the water the runtime draws over a grid and times, then
// export it for ParaView or render a picture of a field (VTK; optional at configure time).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "data_options.hpp"
#include "export_chunks.hpp"
#include "points_csv.hpp"
#include "scene_option.hpp"
#include "time_range.hpp"
#include "verbs.hpp"

#if defined(TIDEWATER_HAVE_INSPECT)
#include "tidewater/gerstner.hpp"
#include "tidewater/query.hpp"
#include "vtk_output.hpp"
#include "vtk_viewer.hpp"
#endif

namespace tidewater::cli {

namespace {

struct InspectArgs : DataOptions {
    std::string scene, extent, resolution = "128x128", times, field = "height", export_dir, screenshot,
                               size = "1280x720", probe, plot, preset, track;
    std::optional<double> time;
    ExportChunks chunks;
    unsigned threads = 0;
    std::size_t play = 0;
    bool quiet = false, view = false, glyphs = false;
};

#if defined(TIDEWATER_HAVE_INSPECT)
/// "x,z" in metres.
Result<glm::dvec2> parse_point(const std::string& text, const char* option) {
    glm::dvec2 at{0.0};
    char extra = 0;
    if (std::sscanf(text.c_str(), "%lf,%lf%c", &at.x, &at.y, &extra) != 2 || !std::isfinite(at.x) ||
        !std::isfinite(at.y))
        return Error{ErrorCode::invalid_argument, fmt::format("{} \"{}\": expected x,z in metres", option, text)};
    return at;
}

Result<std::pair<int, int>> parse_pair(const std::string& text, const char* option) {
    int a = 0, b = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &a, &x, &b, &extra) != 3 || (x != 'x' && x != 'X'))
        return Error{ErrorCode::invalid_argument, fmt::format("{} \"{}\": expected WxH", option, text)};
    return std::pair{a, b};
}

/// --data with --preset: the measured record and the preset's prediction at the probe
/// point (default 0,0) at the record's times (time 0 = its first sample, as `fit` writes).
int run_overlay(const InspectArgs& a) {
    constexpr const char* verb = "inspect";
#if defined(TIDEWATER_HAVE_CALIBRATION)
    if (a.preset.empty() || a.plot.empty()) return fail(verb, "--data needs --preset P and --plot PNG");
    auto kind = parse_kind(a.kind);
    if (!kind) return fail(verb, kind.error().message);
    if (*kind == calibration::RecordKind::profile)
        return fail(verb, "--data: a profile has no time series to overlay (use gauge or buoy)");
    auto record = read_data(a, *kind);
    if (!record) return fail(verb, record.error().message);
    auto profile = load_preset(a.preset);
    if (!profile) return fail(verb, profile.error().message);
    auto body = WaterBody::create(*profile, 0.0, a.preset);
    if (!body) return fail(verb, body.error().message);
    glm::dvec2 at{0.0};
    if (!a.probe.empty()) {
        auto parsed = parse_point(a.probe, "--probe");
        if (!parsed) return fail(verb, parsed.error().message);
        at = *parsed;
    }
    std::vector<double> model(record->size());
    const std::vector<glm::dvec2> where{at};
    std::vector<SurfacePoint> out(1);
    for (std::size_t k = 0; k < record->size(); ++k) {
        if (*kind == calibration::RecordKind::buoy) {
            model[k] =
                evaluate_lagrangian(body->waves(), at, record->axis[k]).displacement.y;  // the buoy rides the particle
        } else {
            if (auto st = query_surface(*body, record->axis[k], where, out); !st) return fail(verb, st.error().message);
            model[k] = out[0].height;
        }
    }
    double mean = 0.0, tss = 0.0, rss = 0.0;
    for (double v : record->z) mean += v;
    mean /= static_cast<double>(record->size());
    for (std::size_t k = 0; k < record->size(); ++k)
        tss += (record->z[k] - mean) * (record->z[k] - mean),
            rss += (record->z[k] - model[k]) * (record->z[k] - model[k]);
    const double r2 = tss > 0.0 ? 1.0 - rss / tss : 0.0;
    const std::string title = fmt::format("{} against {} at x = {:g}, z = {:g} m: R^2 {:.4f}",
                                          std::filesystem::path(record->source).filename().string(),
                                          std::filesystem::path(a.preset).filename().string(), at.x, at.y, r2);
    if (auto st = inspect::overlay_chart(record->axis, record->z, model, title, "t, s", a.plot); !st)
        return fail(verb, st.error().message);
    std::printf("%s -> %s\n", title.c_str(), a.plot.c_str());
    return 0;
#else
    (void)a;
    return fail(verb,
                "--data needs the calibration library (its readers): install libceres-dev and libnetcdf-dev and "
                "configure again");
#endif
}

/// The merge of a chunked export: DIR from DIR.job's chunks, once all are done.
bool merge_chunks(const InspectArgs& a, const std::vector<double>& times) {
    const ExportChunks& c = a.chunks;
    const farm::JobFolder job = c.job();
    const std::size_t count = c.chunks(times.size());
    auto describe = [&](std::size_t t) { return fmt::format("chunk {}", t); };
    if (auto st = farm::require_all_done(job, count, describe); !st) return fail("inspect", st.error().message), false;
    std::vector<std::filesystem::path> folders;
    for (std::size_t t = 0; t < count; ++t) folders.push_back(job.unit_folder(t));
    if (auto st = inspect::merge_export_chunks(c.dir, folders, times); !st)
        return fail("inspect", st.error().message), false;
    std::printf("merged %zu chunk(s) of %zu time step(s) into %s/ (surface.pvd opens in ParaView)\n", count,
                times.size(), c.dir.string().c_str());
    return true;
}

/// Chunk --task of a chunked export (or every chunk not done, then the merge), each into
/// its unit's folder; under mpirun every process takes part in each chunk.
int export_chunks(const InspectArgs& a, const Scene& scene, const inspect::SampleGrid& grid,
                  const std::vector<double>& times, const inspect::MpiProcesses* mpi) {
    const ExportChunks& c = a.chunks;
    const farm::JobFolder job = c.job();
    if (auto st = job.prepare(); !st) return fail("inspect", st.error().message);
    const std::size_t count = c.chunks(times.size());
    const std::size_t first = c.task >= 0 ? static_cast<std::size_t>(c.task) : 0;
    const std::size_t last = c.task >= 0 ? first + 1 : count;
    const int rank = mpi ? mpi->rank() : 0;
    int failed = 0;
    for (std::size_t t = first; t < last; ++t) {
        if (job.status(t).state == farm::UnitState::done) {
            if (rank == 0) std::printf("chunk %zu: done already\n", t);
            continue;
        }
        const std::size_t begin = t * c.chunk_steps, end = std::min(begin + c.chunk_steps, times.size());
        const std::vector<double> steps(times.begin() + static_cast<std::ptrdiff_t>(begin),
                                        times.begin() + static_cast<std::ptrdiff_t>(end));
        const inspect::ExportPart part{begin, t == 0, false};
        const Status st =
            mpi ? inspect::export_series_mpi(*mpi, job.unit_folder(t), scene, grid, steps, a.threads, {}, nullptr, part)
                : inspect::export_series(job.unit_folder(t), scene, grid, steps, a.threads, {}, nullptr, part);
        if (rank == 0) {
            if (auto kept = job.record_outcome(t, st); !kept) {
                fail("inspect", fmt::format("chunk {}: {}", t, kept.error().message));
                ++failed;
                continue;
            }
            std::printf("chunk %zu: steps %zu to %zu exported\n", t, begin, end - 1);
        } else if (!st) {
            fail("inspect",
                 fmt::format("chunk {}: MPI process {} of {}: {}", t, rank, mpi->ranks(), st.error().message));
            ++failed;
        }
    }
    if (failed > 0) return 1;
    if (c.task >= 0 || rank != 0) return 0;
    return merge_chunks(a, times) ? 0 : 1;
}

int run_inspect(const InspectArgs& a) {
    constexpr const char* verb = "inspect";
    if (!a.data.empty()) return run_overlay(a);
    if (a.export_dir.empty() && a.screenshot.empty() && a.plot.empty() && !a.view)
        return fail(verb, "give --view (interactive), --export DIR, --screenshot PNG and/or --plot PNG --probe x,z");
    if (a.plot.empty() != a.probe.empty())
        return fail(verb, "--plot and --probe go together: --plot probe.png --probe x,z");
    // Started among other MPI processes (mpirun -np N): they share the export; a picture or a
    // view would be made N times.
    const bool under_mpi = inspect::started_by_mpi();
    if (under_mpi && (a.export_dir.empty() || !a.screenshot.empty() || !a.plot.empty() || a.view))
        return fail(verb, "under MPI (mpirun) only --export runs: each process writes its band of the grid");
    if (!inspect::find_field(a.field)) {
        std::string names;
        for (const auto& f : inspect::field_infos()) names += (names.empty() ? "" : ", ") + std::string(f.name);
        return fail(verb, fmt::format("--field \"{}\" is unknown (fields: {})", a.field, names));
    }
    // Every option read before the scene's bake, which can take minutes.
    inspect::SampleGrid grid;
    auto res = parse_pair(a.resolution, "--resolution");
    if (!res) return fail(verb, res.error().message);
    grid.nx = res->first, grid.nz = res->second;
    if (!a.extent.empty()) {
        char extra = 0;
        if (std::sscanf(a.extent.c_str(), "%lf:%lf,%lf:%lf%c", &grid.min.x, &grid.max.x, &grid.min.y, &grid.max.y,
                        &extra) != 4)
            return fail(verb, fmt::format("--extent \"{}\": expected x0:x1,z0:z1 in metres", a.extent));
    } else {
        grid.min = glm::dvec2(0.0), grid.max = glm::dvec2(1.0);  // the resolution checked alone; the extent below
    }
    if (auto st = inspect::validate_grid(grid); !st) return fail(verb, "--resolution/--extent: " + st.error().message);
    auto parsed_times = times_from_options(a.time, a.times);
    if (!parsed_times) return fail(verb, parsed_times.error().message);
    const std::vector<double> times = std::move(parsed_times).value();
    const ExportChunks& chunked = a.chunks;
    if (chunked.chunk_steps == 0 && (chunked.task >= 0 || chunked.status || chunked.merge))
        return fail(verb, "--task, --status and --merge belong to a chunked export: give --chunk-steps K");
    if (chunked.chunk_steps > 0) {
        if (a.export_dir.empty()) return fail(verb, "--chunk-steps splits an export: give --export DIR");
        if ((chunked.task >= 0) + chunked.status + chunked.merge > 1)
            return fail(verb, "give one of --task, --status and --merge");
        if (under_mpi && (chunked.status || chunked.merge))
            return fail(verb, "--status and --merge run once, without mpirun");
        const std::size_t count = chunked.chunks(times.size());
        if (chunked.task >= static_cast<int>(count))
            return fail(verb, fmt::format("--task {}: the export has chunks 0 to {} ({} steps of --times, {} a chunk)",
                                          chunked.task, count - 1, times.size(), chunked.chunk_steps));
        const farm::JobFolder job = chunked.job();
        const std::string options = fmt::format(
            "--scene {}\n--extent {}\n--resolution {}\n--time {}\n--times {}\n--chunk-steps {}\n", a.scene, a.extent,
            a.resolution, a.time ? fmt::format("{:.17g}", *a.time) : "", a.times, chunked.chunk_steps);
        if (auto st = farm::check_job_options(job, options, "another --export folder"); !st)
            return fail(verb, st.error().message);
        auto describe = [&](std::size_t t) {
            const std::size_t first = t * chunked.chunk_steps;
            return fmt::format("steps {} to {}", first, std::min(first + chunked.chunk_steps, times.size()) - 1);
        };
        if (chunked.status) {
            std::fputs(farm::status_report(job, count, describe).c_str(), stdout);
            return 0;
        }
        if (chunked.merge) return merge_chunks(a, times) ? 0 : 1;
    }
    std::vector<glm::dvec2> track;
    if (!a.track.empty()) {
        auto read = read_points_csv(a.track);
        if (!read) return fail(verb, "--track: " + read.error().message);
        track = std::move(read).value();
    }
    auto loaded = load_scene_option(a.scene);
    if (!loaded) return fail(verb, loaded.error().message);
    const std::shared_ptr<const Scene> scene = std::move(loaded).value();
    if (a.extent.empty()) {
        const double half = scene->terrain.extent_half_size();
        grid.min = scene->terrain.extent_center() - glm::dvec2(half);
        grid.max = scene->terrain.extent_center() + glm::dvec2(half);
        if (auto st = inspect::validate_grid(grid); !st) return fail(verb, "--extent: " + st.error().message);
    }
    if (!a.export_dir.empty()) {
        int last = -10;
        auto progress = [&](double f) {
            const int percent = static_cast<int>(100.0 * f);
            if (!a.quiet && percent >= last + 10) std::fprintf(stderr, "inspect: export %d%%\n", last = percent);
        };
        // MPI lives from here to the end of the run: it cannot be initialised twice.
        std::unique_ptr<inspect::MpiProcesses> mpi;
        if (under_mpi) mpi = std::make_unique<inspect::MpiProcesses>();
        if (chunked.chunk_steps > 0) return export_chunks(a, *scene, grid, times, mpi.get());
        inspect::ExportStats stats;
        const Status st =
            mpi ? inspect::export_series_mpi(*mpi, a.export_dir, *scene, grid, times, a.threads, progress, &stats)
                : inspect::export_series(a.export_dir, *scene, grid, times, a.threads, progress, &stats);
        const int rank = mpi ? mpi->rank() : 0, ranks = mpi ? mpi->ranks() : 1;
        if (!st)
            return fail(verb, ranks > 1 ? fmt::format("MPI process {} of {}: {}", rank, ranks, st.error().message)
                                        : st.error().message);
        if (rank != 0) return 0;  // process 0 reports for all
        const double points = static_cast<double>(grid.points()) * static_cast<double>(times.size());
        const std::string by =
            ranks > 1 ? fmt::format(" by {} MPI processes (process 0's share of the time)", ranks) : std::string();
        std::printf(
            "exported %zu time step(s) of a %dx%d grid to %s/%s (surface.pvd opens in ParaView): sampling %.3g "
            "points/s (%.2f s), writing %.3g points/s (%.2f s, %.1f MB)\n",
            times.size(), grid.nx, grid.nz, a.export_dir.c_str(), by.c_str(),
            points / std::max(stats.sample_seconds, 1e-9), stats.sample_seconds,
            points / std::max(stats.write_seconds, 1e-9), stats.write_seconds, static_cast<double>(stats.bytes) / 1e6);
    }
    if (!a.plot.empty()) {
        auto parsed = parse_point(a.probe, "--probe");
        if (!parsed) return fail(verb, parsed.error().message);
        const glm::dvec2 at = *parsed;
        auto series = inspect::probe(*scene, at, times);
        if (!series) return fail(verb, "--probe: " + series.error().message);
        if (auto st = inspect::probe_chart(*series, a.plot); !st) return fail(verb, st.error().message);
        if (series->dominant_period > 0.0)
            std::printf("probe at x = %g, z = %g m: dominant period %.4f s -> %s\n", at.x, at.y,
                        series->dominant_period, a.plot.c_str());
        else
            std::printf("probe at x = %g, z = %g m: the height does not change (dry land or still water) -> %s\n", at.x,
                        at.y, a.plot.c_str());
    }
    if (a.view) {
        auto size = parse_pair(a.size, "--size");
        if (!size) return fail(verb, size.error().message);
        auto viewer = inspect::Viewer::create(*scene, grid, times, a.field, size->first, size->second, a.play > 0);
        if (!viewer) return fail(verb, viewer.error().message);
        if (a.play > 0) {
            // Playback as the time slider would, each step resampled and drawn: a benchmark.
            const auto t0 = std::chrono::steady_clock::now();
            for (std::size_t k = 0; k < a.play; ++k) {
                if (auto st = (*viewer)->set_time_index(k % times.size()); !st) return fail(verb, st.error().message);
                (*viewer)->render();
            }
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::printf("played %zu steps of a %dx%d grid in %.3f s: %.1f steps/s\n", a.play, grid.nx, grid.nz, s,
                        static_cast<double>(a.play) / s);
            return 0;
        }
        std::printf("viewer: space play/pause, f next field, g velocity glyphs, p probe under the mouse, q quit\n");
        (*viewer)->run();
    }
    if (!a.screenshot.empty()) {
        auto size = parse_pair(a.size, "--size");
        if (!size) return fail(verb, size.error().message);
        inspect::ScreenshotOptions o;
        o.field = a.field;
        o.width = size->first, o.height = size->second;
        o.glyphs = a.glyphs;
        o.track = std::move(track);
        if (auto st = inspect::screenshot(*scene, grid, times.front(), o, a.screenshot); !st)
            return fail(verb, st.error().message);
        std::printf("rendered %s at t = %g s to %s\n", a.field.c_str(), times.front(), a.screenshot.c_str());
    }
    return 0;
}
#endif

}  // namespace

Verb add_inspect_verb(CLI::App& app) {
    auto a = std::make_shared<InspectArgs>();
    CLI::App* cmd = app.add_subcommand(
        "inspect", "Sample the water over a grid and times: ParaView export or a picture of a field (VTK)");
    cmd->add_option("--scene", a->scene, "Scene JSON (default: the bundled default scene)");
    cmd->add_option("--extent", a->extent, "x0:x1,z0:z1, m (default: the terrain's extent)");
    cmd->add_option("--resolution", a->resolution, "Grid points NXxNZ")->capture_default_str();
    cmd->add_option("--time", a->time, "Clock time, s");
    cmd->add_option("--times", a->times, "Time range t0:t1:dt, s (export: one file per time)");
    cmd->add_option("--field", a->field,
                    "Field to colour: height, displacement, normal, velocity, jacobian, foam, depth, "
                    "shore_distance, wet, flow, body, wake")
        ->capture_default_str();
    cmd->add_option("--export", a->export_dir,
                    "Write .vts per time step, terrain.vts and surface.pvd to this folder (whole or not at all)");
    cmd->add_option("--chunk-steps", a->chunks.chunk_steps,
                    "Split the export into chunks of this many time steps, one unit each of a farmed job kept in "
                    "DIR.job/ (with --task, --status, --merge; docs/scale-out.md)");
    cmd->add_option("--task", a->chunks.task,
                    "With --chunk-steps: export chunk N only (for example $SLURM_ARRAY_TASK_ID)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("--status", a->chunks.status,
                  "With --chunk-steps: list the chunks not done and the tasks to run again");
    cmd->add_flag("--merge", a->chunks.merge,
                  "With --chunk-steps: once every chunk is done, write the export's folder");
    cmd->add_option("--screenshot", a->screenshot, "Render the field at the first time offscreen to this PNG");
    cmd->add_option("--size", a->size, "Screenshot size WxH")->capture_default_str();
    cmd->add_flag("--glyphs", a->glyphs,
                  "With --screenshot: arrows of the current (--field flow) or else of the velocity");
    cmd->add_option("--track", a->track,
                    "With --screenshot: a CSV with columns x and z (a drift track) drawn on the water");
    cmd->add_option("--probe", a->probe,
                    "x,z: a point whose height over --times is charted with its spectrum (--plot)");
    cmd->add_option("--plot", a->plot, "Write the probe chart (height against time and its spectrum) to this PNG");
    cmd->add_option("--threads", a->threads, "Query threads (0 = all)");
    add_data_options(cmd, *a);
    cmd->add_option("--preset", a->preset,
                    "With --data: the preset whose prediction is overlaid on the record (--plot)");
    cmd->add_flag("--quiet", a->quiet, "No progress lines");
    cmd->add_option(
        "--play", a->play,
        "With --view: play this many time steps offscreen (resample and draw each), print steps/s and exit");
    cmd->add_flag("--view", a->view,
                  "Open the interactive viewer over --times (time slider, play/pause, fields, glyphs, probe)");
#if defined(TIDEWATER_HAVE_INSPECT)
    return {cmd, [a] {
                a->chunks.dir = a->export_dir;
                return run_inspect(*a);
            }};
#else
    return {cmd, [] {
                return fail(
                    "inspect",
                    "this build has no inspector: install VTK (apt-get install libvtk9-dev) and configure again "
                    "with -DTIDEWATER_BUILD_INSPECTOR=ON");
            }};
#endif
}

}  // namespace tidewater::cli
