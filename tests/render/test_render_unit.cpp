// Render code that needs no device: errors keep their VkResult, the debug views' names,
// the descriptor tables' order, the quality tiers. No Vulkan device is created here.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "descriptor_sets.hpp"
#include "frame_constants.hpp"
#include "tidewater/render/renderer.hpp"
#include "tidewater/water_body.hpp"
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

// The tiers space the water's vertices wider from ultra down to low and shade no more from
// one to the next (foam lags, reflection facets and march steps), each tier's name reads
// back as it, an override replaces the tier's value, and one out of range is refused by name.
TEST(QualityTiers, OrderedNamedAndOverridden) {
    const render::Quality tiers[] = {render::Quality::low, render::Quality::medium, render::Quality::high,
                                     render::Quality::ultra};
    double previous_spacing = 1e9;
    render::QualitySettings previous{.foam_lags = 0,
                                     .reflection_facets = 1,
                                     .reflection_march_steps = 4,
                                     .far_field_ring_patches = 8,
                                     .waves_drawn = 1,
                                     .scene_reflection = false,
                                     .caustics = false};
    for (const render::Quality tier : tiers) {
        const auto s = render::quality_settings(tier);
        ASSERT_TRUE(s.ok()) << s.error().message;
        EXPECT_LT(s->water_pixels_per_vertex, previous_spacing) << render::quality_name(tier);
        previous_spacing = s->water_pixels_per_vertex;
        EXPECT_GE(s->foam_lags, previous.foam_lags) << render::quality_name(tier);
        EXPECT_GE(s->reflection_facets, previous.reflection_facets) << render::quality_name(tier);
        EXPECT_GE(s->reflection_march_steps, previous.reflection_march_steps) << render::quality_name(tier);
        EXPECT_GE(s->far_field_ring_patches, previous.far_field_ring_patches) << render::quality_name(tier);
        EXPECT_GE(s->scene_reflection, previous.scene_reflection) << render::quality_name(tier);
        EXPECT_GE(s->caustics, previous.caustics) << render::quality_name(tier);
        // More waves drawn from one tier to the next; 0 (every wave) is the most.
        if (previous.waves_drawn == 0) {
            EXPECT_EQ(s->waves_drawn, 0) << render::quality_name(tier);
        } else if (s->waves_drawn != 0) {
            EXPECT_GT(s->waves_drawn, previous.waves_drawn) << render::quality_name(tier);
        }
        previous = *s;
        EXPECT_EQ(render::quality_from_name(render::quality_name(tier)), tier);
    }
    EXPECT_LT(render::quality_settings(render::Quality::ultra)->water_max_foreshortening,
              render::quality_settings(render::Quality::high)->water_max_foreshortening);
    EXPECT_GT(render::quality_settings(render::Quality::low)->water_max_foreshortening, 1.0);
    const auto high = render::quality_settings(render::Quality::high);
    EXPECT_EQ(high->foam_lags, 4);
    EXPECT_EQ(high->reflection_facets, 4);
    EXPECT_EQ(high->reflection_march_steps, 12);
    EXPECT_EQ(render::quality_settings(render::Quality::ultra)->reflection_march_steps, 24);
    EXPECT_FALSE(render::quality_from_name("extreme").has_value());
    EXPECT_EQ(render::RendererInitInfo{}.quality, render::Quality::high);

    render::QualityOverrides o;
    o.water_pixels_per_vertex = 12.5;
    EXPECT_EQ(render::quality_settings(render::Quality::ultra, o)->water_pixels_per_vertex, 12.5);
    for (const double bad : {0.5, 33.0, std::nan("")}) {
        o.water_pixels_per_vertex = bad;
        const auto refused = render::quality_settings(render::Quality::high, o);
        ASSERT_FALSE(refused.ok()) << bad;
        EXPECT_EQ(refused.error().code, ErrorCode::invalid_argument);
        EXPECT_NE(refused.error().message.find("water_pixels_per_vertex"), std::string::npos);
    }
    render::QualityOverrides f;
    f.water_max_foreshortening = 0.9;
    EXPECT_FALSE(render::quality_settings(render::Quality::low, f).ok());
    f.water_max_foreshortening = 20.0;
    EXPECT_EQ(render::quality_settings(render::Quality::high, f)->water_max_foreshortening, 20.0);

    const auto refused_by_name = [](const render::QualityOverrides& bad, const char* name) {
        const auto r = render::quality_settings(render::Quality::medium, bad);
        ASSERT_FALSE(r.ok()) << name;
        EXPECT_EQ(r.error().code, ErrorCode::invalid_argument);
        EXPECT_NE(r.error().message.find(name), std::string::npos) << r.error().message;
    };
    refused_by_name({.foam_lags = 5}, "foam_lags");
    refused_by_name({.foam_lags = -1}, "foam_lags");
    refused_by_name({.reflection_facets = 2}, "reflection_facets");
    refused_by_name({.reflection_march_steps = 3}, "reflection_march_steps");
    refused_by_name({.reflection_march_steps = 65}, "reflection_march_steps");
    refused_by_name({.far_field_ring_patches = 6}, "far_field_ring_patches");
    refused_by_name({.far_field_ring_patches = 17}, "far_field_ring_patches");
    refused_by_name({.far_field_ring_patches = 66}, "far_field_ring_patches");
    refused_by_name({.waves_drawn = -1}, "waves_drawn");
    refused_by_name({.waves_drawn = 1025}, "waves_drawn");
    EXPECT_EQ(render::quality_settings(render::Quality::high)->waves_drawn, 0) << "high draws every wave";
    const auto shading = render::quality_settings(render::Quality::low, {.foam_lags = 3, .reflection_facets = 4});
    ASSERT_TRUE(shading.ok()) << shading.error().message;
    EXPECT_EQ(shading->foam_lags, 3);
    EXPECT_EQ(shading->reflection_facets, 4);
}

// A tier that caps the waves in the mesh flags a body's largest in amplitude (the first
// among equals) and keeps every wave in its order, for the shore model's runs; 0, or a
// cap past the count, leaves every wave in the mesh.
TEST(QualityTiers, TheMeshDrawsABodysLargestWaves) {
    WaterProfile profile;
    for (const double amplitude : {0.1, 0.5, 0.3, 0.5, 0.2})
        profile.waves.push_back(
            {.direction_deg = 10.0 * amplitude, .wavelength = 40.0, .amplitude = amplitude, .steepness = 0.1});
    const auto body = WaterBody::create(profile, 0.0, "test");
    ASSERT_TRUE(body.ok()) << body.error().message;
    const auto drawn = [&](int cap) {
        std::vector<int> flags;
        for (const gpu::GpuWave& w : render::detail::waves_at_origin(*body, 1.0, {100.0, -50.0}, cap))
            flags.push_back(static_cast<int>(w.steep_omega.w));
        return flags;
    };
    EXPECT_EQ(drawn(0), (std::vector<int>{1, 1, 1, 1, 1}));
    EXPECT_EQ(drawn(9), (std::vector<int>{1, 1, 1, 1, 1}));
    EXPECT_EQ(drawn(3), (std::vector<int>{0, 1, 1, 1, 0}));
    EXPECT_EQ(drawn(1), (std::vector<int>{0, 1, 0, 0, 0}));
    const auto all = render::detail::waves_at_origin(*body, 1.0, {100.0, -50.0}, 0);
    const auto capped = render::detail::waves_at_origin(*body, 1.0, {100.0, -50.0}, 2);
    for (std::size_t i = 0; i < all.size(); ++i) {
        EXPECT_EQ(all[i].dir_k_amp, capped[i].dir_k_amp) << i;
        EXPECT_EQ(all[i].steep_omega.z, capped[i].steep_omega.z) << i;
    }
}

// Fewer steps of the reflection's march grow faster, to reach as far as high's 24 steps
// growing by 1.25: the first step times the sum of g^i, i < n.
TEST(QualityTiers, AShorterReflectionMarchReachesAsFar) {
    const auto reach = [](double g, int n) { return (std::pow(g, n) - 1.0) / (g - 1.0); };
    EXPECT_EQ(render::reflection_step_growth(24), 1.25);
    for (const int steps : {4, 8, 12, 32, 64}) {
        const double g = render::reflection_step_growth(steps);
        EXPECT_NEAR(reach(g, steps) / reach(1.25, 24), 1.0, 1e-6) << steps;
        EXPECT_EQ(g > 1.25, steps < 24) << steps;
    }
}

// Every debug view's name reads back as that view, and an unknown name as none.
// The near plane's corners lie a near-plane distance along the view, spanning the field
// of view: its height 2 n tan(fov / 2), its width that times the aspect.
TEST(Camera, NearPlaneCornersSpanTheFieldOfView) {
    render::Camera camera;
    camera.position = {10.0, -3.0, 5.0};
    camera.target = {10.0 + 30.0, -3.0 - 4.0, 5.0 + 40.0};
    camera.fov_y_deg = 60.0;
    camera.near_plane = 0.5;
    const auto c = render::near_plane_corners(camera, 2.0);
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 centre = 0.25 * (c[0] + c[1] + c[2] + c[3]);
    EXPECT_NEAR(glm::length(centre - (camera.position + 0.5 * forward)), 0.0, 1e-12);
    const double height = 2.0 * 0.5 * std::tan(30.0 * 3.14159265358979323846 / 180.0);
    EXPECT_NEAR(glm::length(c[3] - c[0]), height, 1e-12);
    EXPECT_NEAR(glm::length(c[1] - c[0]), 2.0 * height, 1e-12);
    for (const auto& corner : c) EXPECT_NEAR(glm::dot(corner - camera.position, forward), 0.5, 1e-12);
    EXPECT_GT(c[3].y, c[0].y) << "the top corners are the higher";
    EXPECT_GT(glm::dot(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)), c[1] - c[0]), 0.0) << "right is right";
}

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
