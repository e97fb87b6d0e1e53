#include "pipeline_statistics.hpp"

#include <fmt/format.h>

#include <string>

#include "tidewater/render/pipeline_statistics.hpp"
#include "vk_util.hpp"

namespace tidewater::render {

double PipelineStageStatistics::value(const std::string& name, double fallback) const {
    for (const ShaderStatistic& s : statistics)
        if (s.name == name) return s.value;
    return fallback;
}

namespace detail {

namespace {

double statistic_value(const VkPipelineExecutableStatisticKHR& s) {
    switch (s.format) {
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR:
            return s.value.b32 ? 1.0 : 0.0;
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR:
            return static_cast<double>(s.value.i64);
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR:
            return static_cast<double>(s.value.u64);
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR:
            return s.value.f64;
        default:
            return 0.0;
    }
}

}  // namespace

Status read_pipeline_statistics(const Device& ctx, VkPipeline pipeline, std::string_view name,
                                std::vector<PipelineStageStatistics>& out) {
    if (!ctx.pipeline_executable_info)
        return Error{ErrorCode::unsupported,
                     "pipeline statistics: the device was not given VK_KHR_pipeline_executable_properties "
                     "(DeviceContext::pipeline_executable_info)"};
    VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR};
    info.pipeline = pipeline;
    std::uint32_t count = 0;
    TW_VK_TRY(ctx.vk().GetPipelineExecutablePropertiesKHR(ctx.device, &info, &count, nullptr));
    std::vector<VkPipelineExecutablePropertiesKHR> executables(count,
                                                               {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
    TW_VK_TRY(ctx.vk().GetPipelineExecutablePropertiesKHR(ctx.device, &info, &count, executables.data()));
    for (std::uint32_t e = 0; e < count; ++e) {
        VkPipelineExecutableInfoKHR which{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR};
        which.pipeline = pipeline;
        which.executableIndex = e;
        std::uint32_t n = 0;
        TW_VK_TRY(ctx.vk().GetPipelineExecutableStatisticsKHR(ctx.device, &which, &n, nullptr));
        std::vector<VkPipelineExecutableStatisticKHR> stats(n, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
        TW_VK_TRY(ctx.vk().GetPipelineExecutableStatisticsKHR(ctx.device, &which, &n, stats.data()));
        PipelineStageStatistics stage;
        stage.pipeline = std::string(name);
        stage.stage = executables[e].name;
        for (std::uint32_t k = 0; k < n; ++k)
            stage.statistics.push_back({stats[k].name, stats[k].description, statistic_value(stats[k])});
        out.push_back(std::move(stage));
    }
    return {};
}

Result<std::vector<PipelineStageStatistics>> draw_pipeline_statistics(const Device& ctx, const DrawPipelines& draws) {
    std::vector<PipelineStageStatistics> out;
    const std::pair<const char*, VkPipeline> named[] = {{"sky", draws.sky.get()},
                                                        {"terrain", draws.terrain.get()},
                                                        {"terrain_wire", draws.terrain_wire.get()},
                                                        {"floats", draws.floats.get()},
                                                        {"water", draws.water.get()},
                                                        {"water_wire", draws.water_wire.get()},
                                                        {"host_light", draws.host_light.get()}};
    for (const auto& [name, pipeline] : named)
        if (pipeline)
            if (auto st = read_pipeline_statistics(ctx, pipeline, name, out); !st) return st.error();
    return out;
}

}  // namespace detail

Result<std::vector<PipelineStageStatistics>> compile_pipeline_statistics(const RendererInitInfo& init) {
    auto device = detail::load_device(init.device);
    if (!device) return device.error();
    if (!device->pipeline_executable_info)
        return Error{ErrorCode::unsupported,
                     "pipeline statistics: the device does not expose VK_KHR_pipeline_executable_properties "
                     "(or the host did not enable it: DeviceContext::pipeline_executable_info)"};
    auto quality = detail::drawn_quality(init, *device);
    if (!quality) return quality.error();
    auto pipelines = detail::FramePipelines::create(*device, detail::draw_options_for(init, *quality));
    if (!pipelines) return pipelines.error();
    return detail::draw_pipeline_statistics(*device, pipelines->draws);
}

}  // namespace tidewater::render
