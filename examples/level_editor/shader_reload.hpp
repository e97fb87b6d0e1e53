// Shader hot reload for the editor: watches a folder holding Tidewater's GLSL sources
// (a copy of shaders/), compiles the renderer's graphics shaders with the glslang
// library when a file there changes, and hands the SPIR-V to Renderer::reload_shaders.
// A failed compile reports its first error as FILE:LINE: message and leaves the
// current pipelines drawing.
// Threading: the main thread (compiles take tens of milliseconds).
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <tidewater/render/renderer.hpp>

namespace tidewater::editor {

class ShaderReload {
  public:
    explicit ShaderReload(std::filesystem::path dir);
    ~ShaderReload();

    /// Whether a source changed since the last look (the first look only records).
    bool changed();
    /// Compiles every graphics shader; on success swaps them into `renderer`. Returns
    /// the line to print: "shader reload: ok (N ms)" or "shader reload: FILE:LINE: message".
    std::string reload(render::Renderer& renderer);
    /// The last error, "" after a success.
    const std::string& error() const { return error_; }

  private:
    std::filesystem::path dir_;
    std::map<std::filesystem::path, std::filesystem::file_time_type> stamps_;
    std::optional<std::chrono::steady_clock::time_point> seen_change_;
    std::string error_;
};

}  // namespace tidewater::editor
