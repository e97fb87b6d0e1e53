// tidewater shader-stats: the renderer's pipelines as the driver compiles them, per stage
// (instructions, registers, spills, latency, inverse throughput), without drawing. On a
// machine without a GPU, RADV's null device gives them for an AMD GPU that is not there.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "atomic_file.hpp"
#include "tidewater/render/offscreen.hpp"
#include "tidewater/render/pipeline_statistics.hpp"
#include "tidewater/render/quality.hpp"
#include "tidewater/render/standalone.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

struct ShaderStatsArgs {
    std::string json;
    std::string budget;
    std::vector<std::string> tiers{"high"};
    int samples = 1;
    bool water_per_sample = false;
};

/// The statistics the table shows, by RADV's names; a driver without one shows "-".
constexpr const char* kColumns[] = {"Instructions", "VGPRs", "SGPRs", "Spilled VGPRs", "Latency", "Inverse Throughput"};

/// A stage's statistics as built for one quality tier.
struct TierStage {
    std::string tier;
    render::PipelineStageStatistics stage;
};

std::string markdown_table(const std::string& device, const std::vector<TierStage>& stages) {
    std::string s = fmt::format("Pipelines on {}\n\n| tier | pipeline | stage |", device);
    for (const char* c : kColumns) s += fmt::format(" {} |", c);
    s += "\n|---|---|---|";
    for (std::size_t c = 0; c < std::size(kColumns); ++c) s += "---:|";
    s += "\n";
    for (const auto& [tier, st] : stages) {
        s += fmt::format("| {} | {} | {} |", tier, st.pipeline, st.stage);
        for (const char* c : kColumns) {
            const double v = st.value(c);
            s += v < 0.0 ? " - |" : fmt::format(" {:.0f} |", v);
        }
        s += "\n";
    }
    return s;
}

/// One row of a budget table: a stage's instructions and VGPRs at a tier as last accepted.
struct BudgetRow {
    std::string tier, pipeline, stage;
    double instructions = 0.0, vgprs = 0.0;
    bool seen = false;
};

/// Reads a budget table: a header line, then "tier,pipeline,stage,instructions,vgprs" rows.
Result<std::vector<BudgetRow>> read_budget(const std::string& path) {
    std::ifstream in(path);
    if (!in) return Error{ErrorCode::not_found, fmt::format("--budget: cannot read \"{}\"", path)};
    std::vector<BudgetRow> rows;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (number == 1 || line.empty()) continue;  // the header
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
        BudgetRow row;
        char* end = nullptr;
        if (cells.size() == 5 && render::quality_from_name(cells[0])) {
            row.tier = cells[0];
            row.pipeline = cells[1];
            row.stage = cells[2];
            row.instructions = std::strtod(cells[3].c_str(), &end);
            const bool ok = end != cells[3].c_str() && *end == '\0';
            row.vgprs = std::strtod(cells[4].c_str(), &end);
            if (ok && end != cells[4].c_str() && *end == '\0' && row.instructions > 0.0 && row.vgprs > 0.0) {
                rows.push_back(row);
                continue;
            }
        }
        return Error{ErrorCode::invalid_argument,
                     fmt::format("--budget: \"{}\" line {}: expected tier,pipeline,stage,instructions,vgprs (a tier "
                                 "low, medium, high or ultra, positive counts), got \"{}\"",
                                 path, number, line)};
    }
    return rows;
}

/// Every way `stages` break `budget`: a stage over its row by more than 10 % in
/// instructions or VGPRs, a stage that spills, a stage without a row, a row of a tier
/// built without a stage (rows of tiers not built are not checked).
std::vector<std::string> budget_breaches(const std::vector<TierStage>& stages, std::vector<BudgetRow> budget) {
    std::vector<std::string> out;
    for (const auto& [tier, st] : stages) {
        const std::string name = fmt::format("{} / {} / {}", tier, st.pipeline, st.stage);
        if (st.value("Spilled VGPRs", 0.0) > 0.0 || st.value("Spilled SGPRs", 0.0) > 0.0)
            out.push_back(fmt::format("{} spills registers", name));
        auto row = std::find_if(budget.begin(), budget.end(), [&, &t = tier, &s = st](const BudgetRow& r) {
            return r.tier == t && r.pipeline == s.pipeline && r.stage == s.stage;
        });
        if (row == budget.end()) {
            out.push_back(fmt::format("{} has no row in the budget: add one", name));
            continue;
        }
        row->seen = true;
        for (const auto& [what, limit] : {std::pair{"Instructions", row->instructions}, std::pair{"VGPRs", row->vgprs}})
            if (const double v = st.value(what, 0.0); v > 1.1 * limit)
                out.push_back(
                    fmt::format("{}: {} {:.0f}, more than 10 % over its budget of {:.0f}", name, what, v, limit));
    }
    for (const BudgetRow& r : budget) {
        const bool tier_built =
            std::any_of(stages.begin(), stages.end(), [&](const TierStage& s) { return s.tier == r.tier; });
        if (tier_built && !r.seen)
            out.push_back(fmt::format("{} / {} / {} is in the budget but was not built: remove its row", r.tier,
                                      r.pipeline, r.stage));
    }
    return out;
}

int run_shader_stats(const ShaderStatsArgs& a) {
    const char* verb = "shader-stats";
    std::unique_ptr<AtomicFile> json_file;
    if (!a.json.empty()) {
        json_file = std::make_unique<AtomicFile>(a.json);
        if (!json_file->status()) return fail(verb, json_file->status().error().message);
    }
    std::vector<BudgetRow> budget;
    if (!a.budget.empty()) {
        auto rows = read_budget(a.budget);
        if (!rows) return fail(verb, rows.error().message);
        budget = std::move(rows).value();
    }
    render::StandaloneOptions options;
    options.compile_only = true;  // nothing is drawn: a null device serves
    auto device = render::StandaloneDevice::create(options);
    if (!device) return fail(verb, device.error().message);
    if (!(*device)->context().pipeline_executable_info)
        return fail(verb, fmt::format("the device \"{}\" does not expose VK_KHR_pipeline_executable_properties; run "
                                      "on a driver that does (without a GPU: RADV's null device, "
                                      "RADV_FORCE_FAMILY=navi21 "
                                      "VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/radeon_icd.x86_64.json)",
                                      (*device)->device_name()));
    render::RendererInitInfo init;
    init.device = (*device)->context();
    init.color_format = render::OffscreenTarget::kColorFormat;
    init.depth_format = render::OffscreenTarget::kDepthFormat;
    init.samples = static_cast<VkSampleCountFlagBits>(a.samples);
    init.shade_water_per_sample = a.water_per_sample;
    init.wireframe = (*device)->context().enabled_features.fillModeNonSolid == VK_TRUE;
    std::vector<TierStage> stages;
    for (const std::string& tier : a.tiers) {
        const auto quality = render::quality_from_name(tier);
        if (!quality) return fail(verb, fmt::format("--tiers: \"{}\" is not a tier (low, medium, high, ultra)", tier));
        init.quality = *quality;
        auto built = render::compile_pipeline_statistics(init);
        if (!built) return fail(verb, built.error().message);
        for (auto& st : *built) stages.push_back({tier, std::move(st)});
    }
    std::fputs(markdown_table((*device)->device_name(), stages).c_str(), stdout);
    if (json_file) {
        nlohmann::json j;
        j["device"] = (*device)->device_name();
        j["samples"] = a.samples;
        j["water_per_sample"] = a.water_per_sample;
        for (const auto& [tier, st] : stages) {
            nlohmann::json stage{{"tier", tier}, {"pipeline", st.pipeline}, {"stage", st.stage}};
            for (const auto& s : st.statistics)
                stage["statistics"].push_back({{"name", s.name}, {"description", s.description}, {"value", s.value}});
            j["stages"].push_back(stage);
        }
        if (auto st = json_file->write_and_commit(j.dump(2) + "\n"); !st) return fail(verb, st.error().message);
    }
    if (!a.budget.empty()) {
        const std::vector<std::string> breaches = budget_breaches(stages, budget);
        for (const std::string& b : breaches)
            std::fprintf(stderr, "tidewater shader-stats: over budget: %s\n", b.c_str());
        if (!breaches.empty())
            return fail(verb, fmt::format("{} stage(s) break the budget \"{}\" (update it on purpose, with the reason)",
                                          breaches.size(), a.budget));
    }
    return 0;
}

}  // namespace

Verb add_shader_stats_verb(CLI::App& app) {
    auto args = std::make_shared<ShaderStatsArgs>();
    CLI::App* cmd = app.add_subcommand(
        "shader-stats",
        "The renderer's shaders as the driver compiles them, per pipeline and stage (instructions, registers, "
        "spills, latency), without drawing: works on a driver's null device (RADV_FORCE_FAMILY)");
    cmd->add_option("--json", args->json, "Write every statistic of every stage as JSON");
    cmd->add_option("--budget", args->budget,
                    "A table of each stage's instructions and VGPRs per tier (CSV: tier,pipeline,stage,instructions,"
                    "vgprs); fail when a stage built grows more than 10 % past its row, spills, or has no row");
    cmd->add_option("--tiers", args->tiers, "Quality tiers to build the pipelines for (low, medium, high, ultra)")
        ->capture_default_str();
    cmd->add_option("--samples", args->samples, "Samples per pixel of the targets (1, 2, 4 or 8)")
        ->check(CLI::IsMember({1, 2, 4, 8}));
    cmd->add_flag("--water-per-sample", args->water_per_sample, "The water shaded at every sample");
    return {cmd, [args] { return run_shader_stats(*args); }};
}

}  // namespace tidewater::cli
