// tidewater: the command-line front end of the Tidewater runtime.
#include <cstdio>
#include <exception>
#include <vector>

#include "tidewater/version.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

int fail(const char* verb, const std::string& message) {
    std::fprintf(stderr, "tidewater %s: %s\n", verb, message.c_str());
    return 1;
}

}  // namespace tidewater::cli

int main(int argc, char** argv) {
    using namespace tidewater::cli;
    try {
        CLI::App app{
            "Tidewater: Gerstner water that feels the shore, with CPU queries that match what is drawn.\n"
            "Run 'tidewater <verb> --help' for a verb's options.",
            "tidewater"};
        app.set_version_flag("--version", TIDEWATER_VERSION_STRING);
        app.require_subcommand(1);
        std::vector<Verb> verbs = {add_query_verb(app),   add_drift_verb(app),       add_bench_verb(app),
                                   add_demo_verb(app),    add_bake_verb(app),        add_fit_verb(app),
                                   add_inspect_verb(app), add_clip_texture_verb(app)};
#if defined(TIDEWATER_HAVE_RENDER)
        verbs.push_back(add_render_verb(app));
        verbs.push_back(add_shader_stats_verb(app));
        verbs.push_back(add_gpu_cost_verb(app));
#endif
        CLI11_PARSE(app, argc, argv);
        for (const Verb& v : verbs) {
            if (v.command->parsed()) return v.run();
        }
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tidewater: unexpected error: %s\n", e.what());
        return 2;
    }
}
