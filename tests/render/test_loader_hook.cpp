// A host's loader hook (DeviceContext::get_instance_proc_addr / get_device_proc_addr)
// serves every Vulkan call Tidewater makes, on whatever thread makes it, and a lost
// device reaches the host as an Error from every public call that meets it.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "../baked_scene.hpp"
#include "render_helpers.hpp"
#include "tidewater/render/gpu_query.hpp"
#include "tidewater/render/offscreen.hpp"
#include "tidewater/render/renderer.hpp"
#include "tidewater/scene.hpp"
#include "vulkan_fixture.hpp"

namespace tidewater {
namespace {

// What the hook saw: each handle made through it and not yet destroyed, by type, and
// how many were destroyed through it.
struct HookLedger {
    std::mutex mutex;
    std::map<std::string, std::set<std::uint64_t>> live;
    std::map<std::string, int> made, destroyed;
    bool lose_device = false;  // vkQueueSubmit and vkDeviceWaitIdle report VK_ERROR_DEVICE_LOST
    int lost_reports = 0;
    int submits = 0, waits = 0;  // queue submissions; device, queue and fence waits

    void add(const char* type, std::uint64_t handle) {
        const std::lock_guard lock(mutex);
        live[type].insert(handle);
        ++made[type];
    }
    void remove(const char* type, std::uint64_t handle) {
        if (handle == 0) return;
        const std::lock_guard lock(mutex);
        live[type].erase(handle);
        ++destroyed[type];
    }
    std::size_t live_count() {
        const std::lock_guard lock(mutex);
        std::size_t n = 0;
        for (const auto& [type, handles] : live) n += handles.size();
        return n;
    }
};
HookLedger g_ledger;

template <typename H>
std::uint64_t id(H handle) {
    return reinterpret_cast<std::uint64_t>(handle);
}

std::map<std::string, PFN_vkVoidFunction> g_real;  // the system loader's, by name
template <typename Pfn>
Pfn real(const char* name) {
    return reinterpret_cast<Pfn>(g_real.at(name));
}

// One wrapped create/destroy pair per handle type Tidewater makes.
#define TW_HOOK_PAIR(Type, Create, CreateArgs, CreateCall, Destroy)                       \
    VKAPI_ATTR VkResult VKAPI_CALL hooked_##Create CreateArgs {                           \
        const VkResult r = real<PFN_vk##Create>("vk" #Create) CreateCall;                 \
        if (r == VK_SUCCESS) g_ledger.add(#Type, id(*out));                               \
        return r;                                                                         \
    }                                                                                     \
    VKAPI_ATTR void VKAPI_CALL hooked_##Destroy(VkDevice device, Vk##Type handle,         \
                                                const VkAllocationCallbacks* allocator) { \
        g_ledger.remove(#Type, id(handle));                                               \
        real<PFN_vk##Destroy>("vk" #Destroy)(device, handle, allocator);                  \
    }
#define TW_SIMPLE_PAIR(Type, InfoType)                                                                           \
    TW_HOOK_PAIR(Type, Create##Type,                                                                             \
                 (VkDevice device, const InfoType* info, const VkAllocationCallbacks* allocator, Vk##Type* out), \
                 (device, info, allocator, out), Destroy##Type)
TW_SIMPLE_PAIR(Buffer, VkBufferCreateInfo)
TW_SIMPLE_PAIR(Image, VkImageCreateInfo)
TW_SIMPLE_PAIR(ImageView, VkImageViewCreateInfo)
TW_SIMPLE_PAIR(Sampler, VkSamplerCreateInfo)
TW_SIMPLE_PAIR(ShaderModule, VkShaderModuleCreateInfo)
TW_SIMPLE_PAIR(PipelineLayout, VkPipelineLayoutCreateInfo)
TW_SIMPLE_PAIR(DescriptorSetLayout, VkDescriptorSetLayoutCreateInfo)
TW_SIMPLE_PAIR(DescriptorPool, VkDescriptorPoolCreateInfo)
TW_SIMPLE_PAIR(CommandPool, VkCommandPoolCreateInfo)
TW_SIMPLE_PAIR(QueryPool, VkQueryPoolCreateInfo)
TW_SIMPLE_PAIR(Fence, VkFenceCreateInfo)
TW_HOOK_PAIR(DeviceMemory, AllocateMemory,
             (VkDevice device, const VkMemoryAllocateInfo* info, const VkAllocationCallbacks* allocator,
              VkDeviceMemory* out),
             (device, info, allocator, out), FreeMemory)
#undef TW_SIMPLE_PAIR
#undef TW_HOOK_PAIR

// Pipelines: one create call may make several.
VKAPI_ATTR VkResult VKAPI_CALL hooked_CreateGraphicsPipelines(VkDevice device, VkPipelineCache cache,
                                                              std::uint32_t count,
                                                              const VkGraphicsPipelineCreateInfo* infos,
                                                              const VkAllocationCallbacks* allocator, VkPipeline* out) {
    const VkResult r =
        real<PFN_vkCreateGraphicsPipelines>("vkCreateGraphicsPipelines")(device, cache, count, infos, allocator, out);
    if (r == VK_SUCCESS)
        for (std::uint32_t i = 0; i < count; ++i) g_ledger.add("Pipeline", id(out[i]));
    return r;
}
VKAPI_ATTR VkResult VKAPI_CALL hooked_CreateComputePipelines(VkDevice device, VkPipelineCache cache,
                                                             std::uint32_t count,
                                                             const VkComputePipelineCreateInfo* infos,
                                                             const VkAllocationCallbacks* allocator, VkPipeline* out) {
    const VkResult r =
        real<PFN_vkCreateComputePipelines>("vkCreateComputePipelines")(device, cache, count, infos, allocator, out);
    if (r == VK_SUCCESS)
        for (std::uint32_t i = 0; i < count; ++i) g_ledger.add("Pipeline", id(out[i]));
    return r;
}
VKAPI_ATTR void VKAPI_CALL hooked_DestroyPipeline(VkDevice device, VkPipeline pipeline,
                                                  const VkAllocationCallbacks* allocator) {
    g_ledger.remove("Pipeline", id(pipeline));
    real<PFN_vkDestroyPipeline>("vkDestroyPipeline")(device, pipeline, allocator);
}

// A device lost on the host's side: the calls still reach the driver where skipping them
// would leave work in flight (the wait), and report the loss.
VKAPI_ATTR VkResult VKAPI_CALL hooked_QueueSubmit(VkQueue queue, std::uint32_t count, const VkSubmitInfo* submits,
                                                  VkFence fence) {
    if (g_ledger.lose_device) {
        ++g_ledger.lost_reports;
        return VK_ERROR_DEVICE_LOST;  // nothing was submitted
    }
    ++g_ledger.submits;
    return real<PFN_vkQueueSubmit>("vkQueueSubmit")(queue, count, submits, fence);
}
VKAPI_ATTR VkResult VKAPI_CALL hooked_QueueWaitIdle(VkQueue queue) {
    ++g_ledger.waits;
    return real<PFN_vkQueueWaitIdle>("vkQueueWaitIdle")(queue);
}
VKAPI_ATTR VkResult VKAPI_CALL hooked_WaitForFences(VkDevice device, std::uint32_t count, const VkFence* fences,
                                                    VkBool32 all, std::uint64_t timeout) {
    ++g_ledger.waits;
    return real<PFN_vkWaitForFences>("vkWaitForFences")(device, count, fences, all, timeout);
}
VKAPI_ATTR VkResult VKAPI_CALL hooked_DeviceWaitIdle(VkDevice device) {
    ++g_ledger.waits;
    const VkResult r = real<PFN_vkDeviceWaitIdle>("vkDeviceWaitIdle")(device);
    if (g_ledger.lose_device) {
        ++g_ledger.lost_reports;
        return VK_ERROR_DEVICE_LOST;
    }
    return r;
}

const std::map<std::string, PFN_vkVoidFunction>& hooks() {
    static const std::map<std::string, PFN_vkVoidFunction> table = {
#define TW_HOOK(name) {"vk" #name, reinterpret_cast<PFN_vkVoidFunction>(&hooked_##name)}
        TW_HOOK(CreateBuffer),
        TW_HOOK(DestroyBuffer),
        TW_HOOK(CreateImage),
        TW_HOOK(DestroyImage),
        TW_HOOK(CreateImageView),
        TW_HOOK(DestroyImageView),
        TW_HOOK(CreateSampler),
        TW_HOOK(DestroySampler),
        TW_HOOK(CreateShaderModule),
        TW_HOOK(DestroyShaderModule),
        TW_HOOK(CreatePipelineLayout),
        TW_HOOK(DestroyPipelineLayout),
        TW_HOOK(CreateDescriptorSetLayout),
        TW_HOOK(DestroyDescriptorSetLayout),
        TW_HOOK(CreateDescriptorPool),
        TW_HOOK(DestroyDescriptorPool),
        TW_HOOK(CreateCommandPool),
        TW_HOOK(DestroyCommandPool),
        TW_HOOK(CreateQueryPool),
        TW_HOOK(DestroyQueryPool),
        TW_HOOK(CreateFence),
        TW_HOOK(DestroyFence),
        TW_HOOK(AllocateMemory),
        TW_HOOK(FreeMemory),
        TW_HOOK(CreateGraphicsPipelines),
        TW_HOOK(CreateComputePipelines),
        TW_HOOK(DestroyPipeline),
        TW_HOOK(QueueSubmit),
        TW_HOOK(QueueWaitIdle),
        TW_HOOK(WaitForFences),
        TW_HOOK(DeviceWaitIdle),
#undef TW_HOOK
    };
    return table;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL hook_device_proc(VkDevice device, const char* name) {
    PFN_vkVoidFunction real_function = vkGetDeviceProcAddr(device, name);
    g_real[name] = real_function;
    const auto hooked = hooks().find(name);
    return hooked != hooks().end() && real_function ? hooked->second : real_function;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL hook_instance_proc(VkInstance instance, const char* name) {
    return vkGetInstanceProcAddr(instance, name);
}

class LoaderHookTest : public test::VulkanTest {
  protected:
    render::DeviceContext hooked_context() const {
        render::DeviceContext ctx = context();
        ctx.get_instance_proc_addr = &hook_instance_proc;
        ctx.get_device_proc_addr = &hook_device_proc;
        return ctx;
    }
    render::RendererInitInfo renderer_info(std::vector<std::string>* log) const {
        render::RendererInitInfo init;
        init.device = hooked_context();
        init.color_format = render::OffscreenTarget::kColorFormat;
        init.depth_format = render::OffscreenTarget::kDepthFormat;
        if (log) init.log = [log](const std::string& m) { log->push_back(m); };
        return init;
    }
    void TearDown() override {
        g_ledger.lose_device = false;
        test::VulkanTest::TearDown();
    }
};

TEST_F(LoaderHookTest, EveryHandleIsDestroyedThroughTheHostsLoaderFromAnotherThread) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    g_ledger.live.clear();
    g_ledger.made.clear();
    g_ledger.destroyed.clear();
    auto renderer = render::Renderer::create(renderer_info(nullptr));
    ASSERT_TRUE(renderer.ok()) << renderer.error().message;
    ASSERT_TRUE((*renderer)->set_scene(*scene).ok());
    auto target = render::OffscreenTarget::create(hooked_context(), 96, 64);
    ASSERT_TRUE(target.ok()) << target.error().message;
    auto image = (*target)->render(**renderer, test::island_frame());
    ASSERT_TRUE(image.ok()) << image.error().message;
    auto query = render::GpuQuery::create(hooked_context());
    ASSERT_TRUE(query.ok()) << query.error().message;
    const std::vector<glm::dvec2> points = {{10.0, 20.0}, {-30.0, 5.0}};
    std::vector<SurfacePoint> out(points.size());
    ASSERT_TRUE((*query)->query_surface(scene->ocean, 2.0, points, out).ok());
    EXPECT_GT(g_ledger.live_count(), 20u) << "the hook saw the handles made";
    for (const char* type :
         {"Buffer", "Image", "ImageView", "DeviceMemory", "Pipeline", "PipelineLayout", "DescriptorSetLayout",
          "DescriptorPool", "CommandPool", "Sampler", "ShaderModule", "Fence"})
        EXPECT_GT(g_ledger.made[type], 0) << type << " made through the host's loader";

    // Destroyed on a thread that never called Tidewater before.
    std::thread destroyer([&] {
        query->reset();
        target->reset();
        renderer->reset();
    });
    destroyer.join();
    EXPECT_EQ(g_ledger.live_count(), 0u) << "every handle went back through the host's loader";
    for (const auto& [type, handles] : g_ledger.live)
        EXPECT_TRUE(handles.empty()) << handles.size() << " " << type << " left";
    for (const auto& [type, n] : g_ledger.made) EXPECT_EQ(g_ledger.destroyed[type], n) << type;
}

// Views come, change size and go without the renderer submitting or waiting: a host adds
// a viewport, resizes a window or closes a split screen while its frames are in flight.
TEST_F(LoaderHookTest, AddingResizingAndRemovingViewsNeitherSubmitsNorWaits) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    auto renderer = render::Renderer::create(renderer_info(nullptr));
    ASSERT_TRUE(renderer.ok()) << renderer.error().message;
    render::Renderer& r = **renderer;
    ASSERT_TRUE(r.set_scene(*scene).ok());
    g_ledger.submits = g_ledger.waits = 0;
    ASSERT_TRUE(r.resize({96, 64}).ok());
    auto second = r.add_view({64, 48});
    ASSERT_TRUE(second.ok()) << second.error().message;
    ASSERT_TRUE(r.resize({80, 48}, *second).ok());
    ASSERT_TRUE(r.resize({120, 64}).ok());
    ASSERT_TRUE(r.remove_view(*second).ok());
    EXPECT_EQ(g_ledger.submits, 0) << "views are added, sized and removed without a submission";
    EXPECT_EQ(g_ledger.waits, 0) << "views are added, sized and removed without a wait";
    // Frames still draw after it (through a target of their own, which submits and waits).
    auto target = render::OffscreenTarget::create(hooked_context(), 120, 64);
    ASSERT_TRUE(target.ok()) << target.error().message;
    auto image = (*target)->render(r, test::island_frame());
    ASSERT_TRUE(image.ok()) << image.error().message;
    EXPECT_GT(g_ledger.submits, 0) << "the hook counts submissions";
}

TEST_F(LoaderHookTest, ALostDeviceComesBackAsAnErrorFromEveryCallThatMeetsIt) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    std::vector<std::string> log;
    auto renderer = render::Renderer::create(renderer_info(&log));
    ASSERT_TRUE(renderer.ok()) << renderer.error().message;
    auto target = render::OffscreenTarget::create(hooked_context(), 96, 64);
    ASSERT_TRUE(target.ok()) << target.error().message;
    auto query = render::GpuQuery::create(hooked_context());
    ASSERT_TRUE(query.ok()) << query.error().message;
    ASSERT_TRUE((*renderer)->set_scene(*scene).ok());

    g_ledger.lose_device = true;
    auto expect_lost = [](const Status& st, const char* call) {
        ASSERT_FALSE(st.ok()) << call << " ignored the lost device";
        EXPECT_EQ(st.error().code, ErrorCode::device_error) << call;
        EXPECT_EQ(st.error().vk_result, VK_ERROR_DEVICE_LOST) << call << ": " << st.error().message;
        EXPECT_NE(st.error().message.find("VK_ERROR_DEVICE_LOST"), std::string::npos) << st.error().message;
    };
    expect_lost((*renderer)->set_scene(*scene), "set_scene (an upload)");
    auto image = (*target)->render(**renderer, test::island_frame());
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().vk_result, VK_ERROR_DEVICE_LOST) << image.error().message;
    const std::vector<glm::dvec2> points = {{10.0, 20.0}};
    std::vector<SurfacePoint> out(points.size());
    expect_lost((*query)->query_surface(scene->ocean, 2.0, points, out), "GpuQuery::query_surface");

    // Destruction after the loss is clean (the validation layer and ASan watch it) and
    // the renderer tells the host what its last wait met.
    query->reset();
    target->reset();
    renderer->reset();
    bool told = false;
    for (const std::string& m : log) told = told || m.find("VK_ERROR_DEVICE_LOST") != std::string::npos;
    EXPECT_TRUE(told) << "the renderer's destruction reports the failed wait to the host's log";
    EXPECT_GT(g_ledger.lost_reports, 3);
}

}  // namespace
}  // namespace tidewater
