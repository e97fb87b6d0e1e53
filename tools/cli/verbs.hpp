// The tidewater program's verbs. Each adds its subcommand to the app and
// returns the action to run when that subcommand is chosen.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace tidewater::cli {

struct Verb {
    CLI::App* command = nullptr;
    std::function<int()> run;
};

Verb add_query_verb(CLI::App& app);
Verb add_drift_verb(CLI::App& app);
Verb add_bench_verb(CLI::App& app);
Verb add_demo_verb(CLI::App& app);
Verb add_bake_verb(CLI::App& app);
Verb add_fit_verb(CLI::App& app);
Verb add_inspect_verb(CLI::App& app);
Verb add_clip_texture_verb(CLI::App& app);
#if defined(TIDEWATER_HAVE_RENDER)
Verb add_render_verb(CLI::App& app);
Verb add_shader_stats_verb(CLI::App& app);
Verb add_gpu_cost_verb(CLI::App& app);
#endif

/// Prints "tidewater <verb>: <message>" to stderr and returns the exit code for failures.
int fail(const char* verb, const std::string& message);

}  // namespace tidewater::cli
