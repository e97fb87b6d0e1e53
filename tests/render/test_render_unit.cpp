// Render code that needs no device: errors keep their VkResult, the debug views' names,
// the descriptor tables' order. No Vulkan device is created here.
#include <gtest/gtest.h>

#include "descriptor_sets.hpp"
#include "tidewater/render/renderer.hpp"
#include "vk_util.hpp"

namespace tidewater {
namespace {

// A failed Vulkan call reaches the host as device_error with its VkResult as a field,
// not only inside the message.
TEST(VulkanErrors, KeepTheVkResult) {
    const Error e = render::detail::vk_error(VK_ERROR_DEVICE_LOST, "vkQueueSubmit");
    EXPECT_EQ(e.code, ErrorCode::device_error);
    EXPECT_EQ(e.vk_result, static_cast<std::int32_t>(VK_ERROR_DEVICE_LOST));
    EXPECT_NE(e.message.find("vkQueueSubmit"), std::string::npos);
    EXPECT_NE(e.message.find("VK_ERROR_DEVICE_LOST"), std::string::npos);
    EXPECT_EQ(Error{}.vk_result, 0);
}

// Every debug view's name reads back as that view, and an unknown name as none.
TEST(DebugViews, NamesReadBack) {
    for (const render::DebugView view : render::all_debug_views()) {
        const auto parsed = render::parse_debug_view(render::to_string(view));
        ASSERT_TRUE(parsed.has_value()) << render::to_string(view);
        EXPECT_EQ(*parsed, view);
    }
    EXPECT_EQ(render::all_debug_views().size(), std::size_t{gpu::kViewCount});
    EXPECT_FALSE(render::parse_debug_view("rainbow").has_value());
}

// The descriptor tables hold each binding once, in the shaders' numbering, with the
// pool counting each descriptor type as often as the set uses it.
TEST(DescriptorTables, OneRowPerBindingOfTheShaders) {
    EXPECT_EQ(render::detail::kFrameSetRows.size(), std::size_t{gpu::eFrameBindingCount});
    EXPECT_EQ(render::detail::kQuerySetRows.size(), std::size_t{gpu::eQueryBindingCount});
    EXPECT_EQ(render::detail::kFrameSetRows[gpu::eFrameConstants].type, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    EXPECT_EQ(render::detail::kFrameSetRows[gpu::eFrameSceneDepth].type, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    for (const auto& row : render::detail::kQuerySetRows) EXPECT_EQ(row.type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
}

}  // namespace
}  // namespace tidewater
