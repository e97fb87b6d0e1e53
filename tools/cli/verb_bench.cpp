// tidewater bench: query throughput and accuracy against the reference loop, as JSON.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "atomic_file.hpp"
#include "bake_bench.hpp"
#include "bodies_bench.hpp"
#if defined(TIDEWATER_HAVE_CALIBRATION)
#include "fit_bench.hpp"
#endif
#include "query_bench.hpp"
#include "shore_query_bench.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

struct BenchArgs {
    BenchConfig config;
    bool bake = false;
    bool bodies = false;
    std::string fit_refdata;
    std::string out;
    std::string markdown;
    bool quiet = false;
};

int run_bench(const BenchArgs& a) {
    constexpr const char* verb = "bench";
    // Open outputs first so a bad path fails before minutes of timing.
    std::unique_ptr<AtomicFile> json_file, md_file;
    if (!a.out.empty()) {
        json_file = std::make_unique<AtomicFile>(a.out);
        if (!json_file->status()) return fail(verb, json_file->status().error().message);
    }
    if (!a.markdown.empty()) {
        md_file = std::make_unique<AtomicFile>(a.markdown);
        if (!md_file->status()) return fail(verb, md_file->status().error().message);
    }
    const auto progress = [&](const std::string& line) {
        if (!a.quiet) std::fprintf(stderr, "bench: %s\n", line.c_str());
    };
    std::string json, table;
    if (!a.fit_refdata.empty()) {
#if defined(TIDEWATER_HAVE_CALIBRATION)
        auto report = run_fit_bench(a.fit_refdata, a.config.threads, progress);
        if (!report) return fail(verb, report.error().message);
        json = report->dump(2) + "\n";
        table = fit_bench_markdown(*report);
#else
        return fail(verb,
                    "--fit needs the calibration library: install libceres-dev and libnetcdf-dev and configure again");
#endif
    } else if (a.bodies) {
        BodiesBenchConfig bodies_config;
        bodies_config.repeats = std::max(1, a.config.repeats);
        auto report = run_bodies_bench(bodies_config, progress);
        if (!report) return fail(verb, report.error().message);
        json = report->dump(2) + "\n";
        table = bodies_bench_markdown(*report);
    } else if (a.bake) {
        BakeBenchConfig bake_config;
        bake_config.threads = a.config.threads;
        auto report = run_bake_bench(bake_config, progress);
        if (!report) return fail(verb, report.error().message);
        json = report->dump(2) + "\n";
        table = bake_bench_markdown(*report);
    } else {
        auto report = run_query_bench(a.config, progress);
        if (!report) return fail(verb, report.error().message);
        ShoreBenchConfig shore_config;
        shore_config.points = a.config.points;
        shore_config.repeats = a.config.repeats;
        shore_config.threads = a.config.threads;
        shore_config.batch_calls = a.config.points >= 100000 ? 2000 : 200;
        auto shore = run_shore_query_bench(shore_config, progress);
        if (!shore) return fail(verb, shore.error().message);
        nlohmann::json combined = to_json(*report);
        combined["shore"] = *shore;
        json = combined.dump(2) + "\n";
        table = to_markdown(*report) + "\n" + shore_query_bench_markdown(*shore);
    }
    std::fputs(table.c_str(), stdout);
    if (!json_file) std::fputs(json.c_str(), stdout);
    for (auto& [file, text] : {std::pair{json_file.get(), &json}, std::pair{md_file.get(), &table}}) {
        if (!file) continue;
        if (auto st = file->write_and_commit(*text); !st) return fail(verb, st.error().message);
    }
    return 0;
}

}  // namespace

Verb add_bench_verb(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = app.add_subcommand("bench", "Benchmark Eulerian queries against the fixed-point reference loop");
    cmd->add_option("--out", args->out, "Write the JSON report here (default: standard output)");
    cmd->add_option("--markdown", args->markdown, "Also write the Markdown table here");
    cmd->add_option("--points", args->config.points, "Query points per timed run")->capture_default_str();
    cmd->add_option("--repeats", args->config.repeats, "Runs per measurement; the best is kept")->capture_default_str();
    cmd->add_option("--waves", args->config.wave_counts, "Wave counts to measure")->capture_default_str();
    cmd->add_option("--steepness", args->config.steepness, "Target sum(Q*k*A) of the generated sets")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    cmd->add_option("--seed", args->config.seed, "Seed for waves and points")->capture_default_str();
    cmd->add_option("--threads", args->config.threads, "Thread count of the 'all threads' runs (0 = all)");
    cmd->add_flag("--quiet", args->quiet, "No progress lines on standard error");
    cmd->add_flag("--bake", args->bake, "Benchmark the shore bake instead of the queries");
    cmd->add_flag("--bodies", args->bodies,
                  "Benchmark the lakes-and-rivers bake (4 km terrain at 1024^2 and 2048^2, re-bake of one reach)");
    cmd->add_option("--fit", args->fit_refdata,
                    "Benchmark phase-resolved fits on the reference data in this folder (../shared/refdata)");
    return {cmd, [args] {
                for (int w : args->config.wave_counts) {
                    if (w < 1 || w > 64) return fail("bench", "--waves: each count must be in 1..64");
                }
                return run_bench(*args);
            }};
}

}  // namespace tidewater::cli
