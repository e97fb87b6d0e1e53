#include "drawn_table.hpp"

#include <cstring>
#include <glm/geometric.hpp>

#include "render_pipelines.hpp"
#include "sky_model.hpp"
#include "vk_util.hpp"

namespace tidewater::render::detail {

namespace {
constexpr VkFormat kTableFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // every device draws and filters it
constexpr VkPipelineStageFlags kReaders = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
}  // namespace

Result<DrawnTable> DrawnTable::create(const Device& ctx, VkCommandPool pool, std::uint32_t side,
                                      std::string_view fragment, std::uint32_t push_bytes) {
    DrawnTable t;
    auto table =
        GpuImage::create(ctx, {side, side}, kTableFormat,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    if (!table) return table.error();
    t.table_ = std::move(table).value();
    const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, push_bytes};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.pushConstantRangeCount = push_bytes > 0 ? 1 : 0;
    layout_info.pPushConstantRanges = &push;
    TW_VK_TRY(make_owned(ctx, t.layout_, [&](VkPipelineLayout* out) {
        return ctx.vk().CreatePipelineLayout(ctx.device, &layout_info, ctx.allocator, out);
    }));
    PipelineDesc desc;
    desc.layout = t.layout_.get();
    desc.color_format = kTableFormat;
    desc.vertex = "sky.vert";
    desc.fragment = fragment;
    desc.depth_write = false;
    auto pipeline = create_pipeline(ctx, desc);
    if (!pipeline) return pipeline.error();
    t.pipeline_ = OwnedPipeline(ctx, *pipeline);
    if (auto st = submit_and_wait(ctx, pool,
                                  [&](VkCommandBuffer cmd) {
                                      transition(ctx.vk(), cmd, t.table_.handle(), VK_IMAGE_ASPECT_COLOR_BIT,
                                                 VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                 VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, kReaders,
                                                 VK_ACCESS_SHADER_READ_BIT);
                                  });
        !st)
        return st.error();
    return t;
}

void DrawnTable::record(const VulkanFunctions& vk, VkCommandBuffer cmd, std::span<const std::byte> push) const {
    // Every texel is drawn again: the old contents go.
    transition(vk, cmd, table_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, kReaders, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = table_.view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    const VkExtent2D extent = table_.extent();
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    vk.CmdBeginRendering(cmd, &rendering);
    set_viewport(vk, cmd, extent);
    vk.CmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    if (!push.empty())
        vk.CmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                            static_cast<std::uint32_t>(push.size()), push.data());
    vk.CmdDraw(cmd, 3, 1, 0, 0);
    vk.CmdEndRendering(cmd);
    transition(vk, cmd, table_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, kReaders, VK_ACCESS_SHADER_READ_BIT);
}

gpu::GpuSky gpu_sky(glm::dvec3 sun_direction, double turbidity) {
    const glm::dvec3 sun = glm::normalize(sun_direction);
    const PreethamSky sky = preetham_sky(sun, turbidity);
    gpu::GpuSky g{};
    g.Y = glm::vec4(sky.abcd[0]);
    g.x = glm::vec4(sky.abcd[1]);
    g.y = glm::vec4(sky.abcd[2]);
    g.e = glm::vec4(glm::vec3(sky.e), static_cast<float>(kSkyExposure));
    g.zenith =
        glm::vec4(static_cast<float>(sky.zenith_over_f0.x / sky.zenith.x), static_cast<float>(sky.zenith_over_f0.y),
                  static_cast<float>(sky.zenith_over_f0.z), static_cast<float>(kSkySaturation));
    g.balance = glm::vec4(glm::vec3(sky_white_balance(sky, sun)), 0.0f);
    g.sun = glm::vec4(glm::vec3(sun), 1.0f);
    return g;
}

Result<SkyTable> SkyTable::create(const Device& ctx, VkCommandPool pool) {
    auto table = DrawnTable::create(ctx, pool, gpu::kSkyTableSide, "sky_table.frag", sizeof(gpu::GpuSky));
    if (!table) return table.error();
    SkyTable t;
    t.table_ = std::move(table).value();
    return t;
}

void SkyTable::record(const VulkanFunctions& vk, VkCommandBuffer cmd, const gpu::GpuSky& sky) {
    table_.record(vk, cmd, std::as_bytes(std::span(&sky, 1)));
    recorded_ = sky;
}

bool SkyTable::holds(const gpu::GpuSky& sky) const {
    return recorded_ && std::memcmp(&*recorded_, &sky, sizeof(sky)) == 0;
}

Result<DrawnTable> make_foam_noise_table(const Device& ctx, VkCommandPool pool) {
    auto table = DrawnTable::create(ctx, pool, gpu::kFoamNoiseSide, "foam_noise.frag", 0);
    if (!table) return table.error();
    if (auto st = submit_and_wait(ctx, pool, [&](VkCommandBuffer cmd) { table->record(ctx.vk(), cmd, {}); }); !st)
        return st.error();
    return table;
}

}  // namespace tidewater::render::detail
