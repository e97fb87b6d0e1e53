// tidewater query: the water surface at points from a CSV, at one time or a range.
#include <fmt/format.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "atomic_file.hpp"
#include "points_csv.hpp"
#include "query_backend.hpp"
#include "scene_option.hpp"
#include "tidewater/query.hpp"
#include "tidewater/world_query.hpp"
#include "time_range.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

struct QueryArgs {
    std::string scene;
    std::optional<double> time;
    std::string times;
    std::string points;
    std::string out;
    unsigned threads = 0;
    std::string backend = "cpu";
};

/// Appends CSV rows to `buffer`, handing it to `sink` whenever it grows large. Every
/// column is the library's WorldPoint as returned: the SurfacePoint (depth at the query
/// point, from the shore model or else the terrain; shore_distance inf without a shore
/// model), then the body's name and the current.
template <typename Sink>
void write_rows(std::string& buffer, const Sink& sink, const Scene& scene, const std::optional<double>& t,
                const std::vector<glm::dvec2>& points, const std::vector<WorldPoint>& results) {
    for (std::size_t i = 0; i < points.size(); ++i) {
        const SurfacePoint& s = results[i].surface;
        if (t) fmt::format_to(std::back_inserter(buffer), "{},", *t);
        fmt::format_to(std::back_inserter(buffer),
                       "{},{},{:.9g},{:.7g},{:.7g},{:.7g},{:.7g},{:.7g},{:.7g},{:.7g},{:.6g},{:.6g},{},{:.4g},{},{:.6g}"
                       ",{:.6g},{:.6g}\n",
                       points[i].x, points[i].y, s.height, s.normal.x, s.normal.y, s.normal.z, s.velocity.x,
                       s.velocity.y, s.velocity.z, s.jacobian, s.depth, s.shore_distance, s.wet ? 1 : 0, s.foam,
                       body_name(scene, results[i].body), results[i].flow.x, results[i].flow.y, s.wake);
        if (buffer.size() > (1u << 20)) {
            sink(buffer);
            buffer.clear();
        }
    }
}

int run_query(const QueryArgs& a) {
    constexpr const char* verb = "query";
    auto parsed_times = times_from_options(a.time, a.times);
    if (!parsed_times) return fail(verb, parsed_times.error().message);
    const std::vector<double> times = std::move(parsed_times).value();
    // The points and the output first: a bad one is told before the scene's bake.
    auto points = read_points_csv(a.points);
    if (!points) return fail(verb, points.error().message);
    // A file output goes to a temporary that is renamed only after the last row:
    // any failure on the way leaves no partial file.
    std::unique_ptr<AtomicFile> file;
    if (!a.out.empty()) {
        file = std::make_unique<AtomicFile>(a.out);
        if (!file->status()) return fail(verb, file->status().error().message);
    }
    auto loaded = load_scene_option(a.scene, OceanNeed::optional);
    if (!loaded) return fail(verb, loaded.error().message);
    const std::shared_ptr<const Scene> scene = std::move(loaded).value();
    for (const std::string& w : scene->warnings) std::fprintf(stderr, "tidewater query: warning: %s\n", w.c_str());
    const auto sink = [&](const std::string& chunk) {
        if (file) {
            file->stream().write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        } else {
            std::fwrite(chunk.data(), 1, chunk.size(), stdout);
        }
    };
    std::string buffer;
    buffer.reserve(1u << 21);
    buffer += a.time ? "" : "t,";
    buffer += "x,z,height,nx,ny,nz,vx,vy,vz,jacobian,depth,shore_distance,wet,foam,body,flow_x,flow_z,wake\n";

    const bool has_bodies = !scene->lakes.empty() || !scene->rivers.empty();
    // Both backends answer the whole scene with query_world's contract.
    std::optional<QueryBackend> gpu;
    if (a.backend == "gpu") {
        auto backend = make_gpu_query_backend();
        if (!backend) return fail(verb, backend.error().message);
        gpu = std::move(backend).value();
    }
    std::vector<WorldPoint> results(points->size());
    const bool open_water = !scene->ocean.shore() && !has_bodies;
    std::size_t unconverged = 0;
    for (double t : times) {
        QueryOptions options;
        options.threads = a.threads;
        // The body, the current and the surface of every point, in one query.
        const Status st = gpu ? (*gpu)(*scene, t, *points, results) : query_world(*scene, t, *points, results, options);
        if (!st) return fail(verb, st.error().message);
        for (const WorldPoint& w : results) {
            if (w.surface.converged) continue;
            // Open water always converges; at the waterline a shore or a bank can fold the surface.
            if (open_water) return fail(verb, fmt::format("the surface solve did not converge at t = {}", t));
            ++unconverged;
        }
        write_rows(buffer, sink, *scene, a.time ? std::nullopt : std::optional<double>(t), *points, results);
    }
    sink(buffer);
    if (unconverged > 0) {
        std::fprintf(stderr,
                     "tidewater query: warning: %zu point(s) at the waterline where the shore folds the surface: "
                     "best estimates written\n",
                     unconverged);
    }
    if (file) {
        if (auto st = file->commit(); !st) return fail(verb, st.error().message);
        return 0;
    }
    return std::fflush(stdout) == 0 ? 0 : fail(verb, "writing to standard output failed");
}

}  // namespace

Verb add_query_verb(CLI::App& app) {
    auto args = std::make_shared<QueryArgs>();
    CLI::App* cmd =
        app.add_subcommand("query", "Water surface at fixed (x, z) points: height, normal, velocity, Jacobian");
    cmd->add_option("--scene", args->scene, "Scene JSON (default: the bundled default scene)");
    cmd->add_option("--time", args->time, "Clock time, s");
    cmd->add_option("--times", args->times, "Time range t0:t1:dt, s (writes a leading t column)");
    cmd->add_option("--points", args->points, "CSV with a header naming columns x and z, m")->required();
    cmd->add_option("--out", args->out, "Output CSV (default: standard output); written whole or not at all");
    cmd->add_option("--threads", args->threads, "Worker threads of the CPU backend (0 = all)");
    cmd->add_option("--backend", args->backend, "cpu, or gpu (a Vulkan compute shader; same columns)")
        ->check(CLI::IsMember({"cpu", "gpu"}))
        ->capture_default_str();
    cmd->footer(
        "Output columns: "
        "[t,]x,z,height,nx,ny,nz,vx,vy,vz,jacobian,depth,shore_distance,wet,foam,body,flow_x,flow_z,wake\n"
        "(SI units; height is world y; velocity is the current plus the waves' orbital velocity; depth is the still\n"
        "water column at the point (< 0 on land); shore_distance (> 0 over water) comes from the shore model, inf\n"
        "without one; wet = 1 where the surface is above the terrain; foam 0..1; body is the water body's name, empty\n"
        "on land; flow_x, flow_z are the current alone, m/s; wake is the boats' wakes' share of the height, m).");
    return {cmd, [args] { return run_query(*args); }};
}

}  // namespace tidewater::cli
