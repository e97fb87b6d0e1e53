// tidewater gpu-cost: each pass's time on reference AMD GPUs, estimated without them. The
// stages' invocations come from drawing standard views on this machine's device
// (pipeline statistics queries; lavapipe has them); the cost of one wave of each stage
// from the driver's compiler on RADV's null device, one process per GPU family (this
// program's shader-stats, run with RADV_FORCE_FAMILY). The model: gpu_cost_model.hpp.
#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "atomic_file.hpp"
#include "extent_option.hpp"
#include "gpu_cost_model.hpp"
#include "render_job.hpp"
#include "scene_option.hpp"
#include "verbs.hpp"

extern char** environ;

namespace tidewater::cli {

namespace {

struct GpuCostArgs {
    std::string scene;
    std::vector<std::string> sizes{"1920x1080", "3840x2160"};
    std::vector<std::string> tiers{"low", "medium", "high", "ultra"};
    std::string json, markdown;
    std::string radv_icd = "/usr/share/vulkan/icd.d/radeon_icd.x86_64.json";
};

using StageCosts = std::map<std::tuple<std::string, std::string, std::string>, StageCost>;  // (tier, pipeline, stage)

/// Runs this program's shader-stats on RADV's null device for `family` and every tier of
/// `tiers` (their shaders differ: specialization constants), into `json`.
Status compile_on_null_device(const std::string& family, const std::string& icd, const std::vector<std::string>& tiers,
                              const std::filesystem::path& json) {
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e) {
        const std::string_view v(*e);
        if (v.starts_with("RADV_FORCE_FAMILY=") || v.starts_with("VK_ICD_FILENAMES=") ||
            v.starts_with("VK_DRIVER_FILES=") || v.starts_with("NODEVICE_SELECT="))
            continue;
        env.emplace_back(v);
    }
    env.push_back("RADV_FORCE_FAMILY=" + family);
    env.push_back("VK_ICD_FILENAMES=" + icd);
    env.push_back("VK_DRIVER_FILES=" + icd);
    env.push_back("NODEVICE_SELECT=1");
    if (!std::getenv("XDG_RUNTIME_DIR")) env.push_back("XDG_RUNTIME_DIR=" + json.parent_path().string());
    std::vector<char*> envp;
    for (std::string& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    std::vector<std::string> args{"/proc/self/exe", "shader-stats", "--json", json.string(), "--tiers"};
    args.insert(args.end(), tiers.begin(), tiers.end());
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    // Its table goes nowhere; its errors reach our stderr.
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        return Error{ErrorCode::internal, fmt::format("could not start shader-stats for {}: {}", family, spawned)};
    int status = 0;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return Error{ErrorCode::unsupported,
                     fmt::format("building the pipelines on RADV's null device for {} failed (see above)", family)};
    return {};
}

Result<StageCosts> read_stage_costs(const std::filesystem::path& json) {
    std::ifstream in(json);
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("stages"))
        return Error{ErrorCode::internal, fmt::format("{}: not shader-stats output", json.string())};
    StageCosts costs;
    for (const auto& st : j["stages"]) {
        std::map<std::string, double> v;
        for (const auto& s : st["statistics"]) v[s["name"].get<std::string>()] = s["value"].get<double>();
        if (!v.count("Inverse Throughput") || !v.count("Latency") || !v.count("Subgroups per SIMD"))
            return Error{ErrorCode::unsupported,
                         fmt::format("{}: the driver gives no throughput, latency or "
                                     "occupancy for {} / {}",
                                     json.string(), st["pipeline"].get<std::string>(), st["stage"].get<std::string>())};
        costs[{st.value("tier", std::string("high")), st["pipeline"], st["stage"]}] = {
            v["Inverse Throughput"], v["Latency"], v["Subgroups per SIMD"]};
    }
    return costs;
}

/// The fragments a GPU shades in a pass, at least: the samples the pass writes, where the
/// device counted them (NVIDIA's driver shaded 2.1 times the water's samples at 1080p in the
/// default view: 2x2 quads at triangle edges, water drawn over water; lavapipe, which shades
/// before it tests depth, 32 times); else the fragment invocations counted.
std::uint64_t shaded_fragments(const nlohmann::json& pass) {
    return pass.contains("samples_passed") ? pass["samples_passed"].get<std::uint64_t>()
                                           : pass["fragment"].get<std::uint64_t>();
}

/// The standard views: the scene's camera, and the horizon seen from 3 m above the water
/// along the same heading.
std::vector<std::pair<std::string, render::Camera>> standard_views(const Scene& scene) {
    const render::Camera cam = default_camera(scene);
    render::Camera horizon = cam;
    glm::dvec3 ahead = cam.target - cam.position;
    ahead.y = 0.0;
    ahead = glm::length(ahead) > 1e-9 ? glm::normalize(ahead) : glm::dvec3(0.0, 0.0, 1.0);
    horizon.position.y = scene.water_level() + 3.0;
    horizon.target = horizon.position + 1000.0 * ahead;
    return {{"scene", cam}, {"horizon", horizon}};
}

int run_gpu_cost(const GpuCostArgs& a) {
    const char* verb = "gpu-cost";
    std::vector<VkExtent2D> sizes;
    for (const std::string& s : a.sizes) {
        auto e = parse_extent(s, "--sizes");
        if (!e) return fail(verb, e.error().message);
        sizes.push_back(*e);
    }
    std::vector<render::Quality> tiers;
    for (const std::string& t : a.tiers) {
        const auto q = render::quality_from_name(t);
        if (!q) return fail(verb, fmt::format("--tiers: \"{}\" is not a tier (low, medium, high, ultra)", t));
        tiers.push_back(*q);
    }
    if (!std::filesystem::exists(a.radv_icd))
        return fail(verb, fmt::format("RADV is missing: no \"{}\" (Debian: mesa-vulkan-drivers); the cost model "
                                      "compiles the shaders with RADV's null device",
                                      a.radv_icd));
    std::unique_ptr<AtomicFile> json_file, markdown_file;
    if (!a.json.empty()) {
        json_file = std::make_unique<AtomicFile>(a.json);
        if (!json_file->status()) return fail(verb, json_file->status().error().message);
    }
    if (!a.markdown.empty()) {
        markdown_file = std::make_unique<AtomicFile>(a.markdown);
        if (!markdown_file->status()) return fail(verb, markdown_file->status().error().message);
    }
    auto loaded = load_scene_option(a.scene);
    if (!loaded) return fail(verb, loaded.error().message);
    const std::shared_ptr<const Scene> scene = std::move(loaded).value();

    std::error_code ec;
    const std::filesystem::path work =
        std::filesystem::temp_directory_path() / fmt::format("tidewater-gpu-cost-{}", getpid());
    std::filesystem::create_directories(work, ec);
    if (ec) return fail(verb, fmt::format("cannot make {}: {}", work.string(), ec.message()));
    struct Cleanup {
        std::filesystem::path dir;
        ~Cleanup() {
            std::error_code e;
            std::filesystem::remove_all(dir, e);
        }
    } cleanup{work};

    std::map<std::string, StageCosts> costs;  // per family
    for (const ReferenceGpu& gpu : reference_gpus()) {
        const auto json = work / (gpu.family + ".json");
        if (auto st = compile_on_null_device(gpu.family, a.radv_icd, a.tiers, json); !st)
            return fail(verb, st.error().message);
        auto c = read_stage_costs(json);
        if (!c) return fail(verb, c.error().message);
        costs[gpu.family] = std::move(c).value();
    }

    nlohmann::json out{{"scene", scene->name}, {"wave_lanes", kWaveLanes}};
    std::string md = fmt::format(
        "Estimated GPU time per pass, ms (`tidewater gpu-cost`; scene \"{}\")\n\n"
        "| tier | view | size | GPU | water vertex + tess. control | water tess. evaluation | water fragment | "
        "scene copy | **water** | opaque (sky, terrain, floats) | frame |\n"
        "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n",
        scene->name);
    for (const render::Quality tier : tiers) {
        const std::string tier_name(render::quality_name(tier));
        for (const auto& [view_name, camera] : standard_views(*scene)) {
            for (const VkExtent2D size : sizes) {
                RenderJob job;
                job.extent = size;
                job.camera = camera;
                job.quality = tier;
                job.single_output = (work / "frame.png").string();
                auto result = run_render_job(*scene, job);
                if (!result) return fail(verb, result.error().message);
                const nlohmann::json& frame = result->stats["frames"][0];
                if (!frame.contains("invocations"))
                    return fail(verb, fmt::format("the device \"{}\" counts no invocations (pipelineStatisticsQuery): "
                                                  "run on one that does (lavapipe does)",
                                                  result->device));
                const nlohmann::json& water = frame["invocations"]["water"];
                const nlohmann::json& opaque = frame["invocations"]["opaque"];
                const std::uint64_t copy_bytes = std::uint64_t{size.width} * size.height * (4 + 4);  // RGBA8 + D32
                for (const ReferenceGpu& gpu : reference_gpus()) {
                    const StageCosts& c = costs[gpu.family];
                    auto cost = [&](const char* pipeline, const char* stage) {
                        const auto it = c.find({tier_name, pipeline, stage});
                        return it == c.end() ? StageCost{} : it->second;
                    };
                    const double vs = stage_ms(gpu, cost("water", "Vertex + Tessellation Control Shaders"),
                                               water["vertex"].get<std::uint64_t>());
                    const double tes = stage_ms(gpu, cost("water", "Tessellation Evaluation Shader"),
                                                water["tessellation_evaluation"].get<std::uint64_t>());
                    const double fs = stage_ms(gpu, cost("water", "Fragment Shader"), shaded_fragments(water));
                    const double copy = copy_ms(gpu, copy_bytes);
                    // The opaque pass at the terrain's cost per invocation (the sky's and floats' are cheaper).
                    const double opaque_ms =
                        stage_ms(gpu, cost("terrain", "Vertex Shader"), opaque["vertex"].get<std::uint64_t>()) +
                        stage_ms(gpu, cost("terrain", "Fragment Shader"), shaded_fragments(opaque));
                    const double water_ms = vs + tes + fs + copy;
                    out["estimates"].push_back({{"tier", tier_name},
                                                {"view", view_name},
                                                {"width", size.width},
                                                {"height", size.height},
                                                {"gpu", gpu.family},
                                                {"board", gpu.name},
                                                {"invocations", frame["invocations"]},
                                                {"water_vertex_tess_control_ms", vs},
                                                {"water_tess_evaluation_ms", tes},
                                                {"water_fragment_ms", fs},
                                                {"scene_copy_ms", copy},
                                                {"water_ms", water_ms},
                                                {"opaque_ms", opaque_ms},
                                                {"frame_ms", water_ms + opaque_ms}});
                    md += fmt::format(
                        "| {} | {} | {}x{} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | **{:.3f}** | {:.3f} | {:.3f} |\n",
                        tier_name, view_name, size.width, size.height, gpu.family, vs, tes, fs, copy, water_ms,
                        opaque_ms, water_ms + opaque_ms);
                }
            }
        }
    }
    std::fputs(md.c_str(), stdout);
    if (json_file)
        if (auto st = json_file->write_and_commit(out.dump(2) + "\n"); !st) return fail(verb, st.error().message);
    if (markdown_file)
        if (auto st = markdown_file->write_and_commit(md); !st) return fail(verb, st.error().message);
    return 0;
}

}  // namespace

Verb add_gpu_cost_verb(CLI::App& app) {
    auto args = std::make_shared<GpuCostArgs>();
    CLI::App* cmd = app.add_subcommand(
        "gpu-cost",
        "Estimate each pass's GPU time on reference AMD GPUs (RX 6800 XT, RX 7900 XTX) without them: invocations "
        "counted on this machine's device, each stage's cycles from RADV's null device");
    cmd->add_option("--scene", args->scene, "Scene JSON (default: the bundled default scene)");
    cmd->add_option("--sizes", args->sizes, "Frame sizes WxH")->capture_default_str();
    cmd->add_option("--tiers", args->tiers, "Quality tiers (low, medium, high, ultra)")->capture_default_str();
    cmd->add_option("--json", args->json, "Write the estimates and the invocation counts as JSON");
    cmd->add_option("--markdown", args->markdown, "Write the table as Markdown");
    cmd->add_option("--radv-icd", args->radv_icd, "RADV's Vulkan driver manifest")->capture_default_str();
    return {cmd, [args] { return run_gpu_cost(*args); }};
}

}  // namespace tidewater::cli
