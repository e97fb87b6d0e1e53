#include "editor_options.hpp"

#include <cstdio>
#include <cstdlib>

namespace tidewater::editor {

std::optional<Options> parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        const char* v = nullptr;
        if (a == "--scene" && (v = next()))
            o.scene = v;
        else if (a == "--screenshot" && (v = next()))
            o.screenshot = v;
        else if (a == "--frames" && (v = next()))
            o.frames = std::atol(v);
        else if (a == "--resize-at" && (v = next()))
            o.resize_at = std::atol(v);
        else if (a == "--script" && (v = next()))
            o.script = v;
        else if (a == "--shader-dir" && (v = next()))
            o.shader_dir = v;
        else if (a == "--size" && (v = next())) {
            if (std::sscanf(v, "%dx%d", &o.width, &o.height) != 2 || o.width < 320 || o.height < 240)
                return std::nullopt;
        } else if (a == "--probe" && (v = next())) {
            double x = 0, y = 0;
            if (std::sscanf(v, "%lf,%lf", &x, &y) != 2) return std::nullopt;
            o.probe = glm::dvec2(x, y);
        } else if (a == "--no-validation")
            o.validation = false;
        else if (a == "--memory-log")
            o.memory_log = true;
        else if (a == "--keep-saved-bake")
            o.ready_edits = false;
        else
            return std::nullopt;
    }
    return o;
}

}  // namespace tidewater::editor
