#include "shader_reload.hpp"

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace tidewater::editor {

namespace {

namespace fs = std::filesystem;

/// The renderer's graphics shaders and their stages.
constexpr std::pair<const char*, EShLanguage> kShaders[] = {
    {"sky.vert", EShLangVertex},        {"sky.frag", EShLangFragment},         {"terrain.vert", EShLangVertex},
    {"mesh.vert", EShLangVertex},       {"terrain.frag", EShLangFragment},     {"water.vert", EShLangVertex},
    {"water.tesc", EShLangTessControl}, {"water.tese", EShLangTessEvaluation}, {"water.frag", EShLangFragment}};

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// #include "x" resolved in the watched folder (GL_GOOGLE_include_directive).
class FolderIncluder : public glslang::TShader::Includer {
  public:
    explicit FolderIncluder(fs::path dir) : dir_(std::move(dir)) {}
    IncludeResult* includeLocal(const char* name, const char*, size_t) override { return include(name); }
    IncludeResult* includeSystem(const char* name, const char*, size_t) override { return include(name); }
    void releaseInclude(IncludeResult* result) override {
        if (!result) return;
        delete static_cast<std::string*>(result->userData);
        delete result;
    }

  private:
    IncludeResult* include(const char* name) {
        const fs::path path = dir_ / name;
        if (!fs::exists(path)) return nullptr;
        auto* text = new std::string(read_file(path));
        return new IncludeResult(name, text->data(), text->size(), text);
    }
    fs::path dir_;
};

/// "ERROR: water.frag:149: 'x' : message" -> "water.frag:149: 'x' : message".
std::string first_error(const std::string& log, const std::string& fallback) {
    static const std::regex error(R"(ERROR: ([^:\n]+):(\d+): ([^\n]*))");
    std::smatch m;
    if (std::regex_search(log, m, error)) return fmt::format("{}:{}: {}", m[1].str(), m[2].str(), m[3].str());
    const auto end = log.find('\n');
    return fmt::format("{}: {}", fallback, end == std::string::npos ? log : log.substr(0, end));
}

}  // namespace

ShaderReload::ShaderReload(fs::path dir) : dir_(std::move(dir)) {
    glslang::InitializeProcess();
}
ShaderReload::~ShaderReload() {
    glslang::FinalizeProcess();
}

bool ShaderReload::changed() {
    bool any = false, first = stamps_.empty();
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir_, ec)) {
        if (!entry.is_regular_file()) continue;
        const auto stamp = entry.last_write_time(ec);
        auto& known = stamps_[entry.path()];
        if (known != stamp) any = true;
        known = stamp;
    }
    return any && !first;
}

std::string ShaderReload::reload(render::Renderer& renderer) {
    const auto start = std::chrono::steady_clock::now();
    render::Renderer::ShaderSpirv spirv;
    for (const auto& [name, stage] : kShaders) {
        const fs::path path = dir_ / name;
        const std::string text = read_file(path);
        const char* source = text.c_str();
        const char* label = name;
        glslang::TShader shader(stage);
        shader.setStringsWithLengthsAndNames(&source, nullptr, &label, 1);
        shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
        shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
        shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
        FolderIncluder includer(dir_);
        const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
        if (!shader.parse(GetDefaultResources(), 450, false, messages, includer)) {
            error_ = first_error(shader.getInfoLog(), name);
            return "shader reload: " + error_;
        }
        glslang::TProgram program;
        program.addShader(&shader);
        if (!program.link(messages)) {
            error_ = first_error(program.getInfoLog(), name);
            return "shader reload: " + error_;
        }
        std::vector<std::uint32_t> words;
        glslang::GlslangToSpv(*program.getIntermediate(stage), words);
        spirv.emplace(name, std::move(words));
    }
    if (auto st = renderer.reload_shaders(spirv); !st) {
        error_ = st.error().message;
        return "shader reload: " + error_;
    }
    error_.clear();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return fmt::format("shader reload: ok ({:.0f} ms)", ms);
}

}  // namespace tidewater::editor
