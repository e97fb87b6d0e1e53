#include "descriptor_sets.hpp"

#include <algorithm>
#include <array>

namespace tidewater::render::detail {

VkResult make_set_layout(const Device& device, std::span<const BindingRow> rows, VkShaderStageFlags stages,
                         OwnedSetLayout& out) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const BindingRow& r : rows) bindings.push_back({r.binding, r.type, 1, stages, nullptr});
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = static_cast<std::uint32_t>(bindings.size());
    info.pBindings = bindings.data();
    return make_owned(device, out, [&](VkDescriptorSetLayout* layout) {
        return device.vk().CreateDescriptorSetLayout(device.device, &info, device.allocator, layout);
    });
}

VkResult make_descriptor_pool(const Device& device, std::span<const BindingRow> rows, std::uint32_t sets,
                              OwnedDescriptorPool& out) {
    std::vector<VkDescriptorPoolSize> sizes;
    for (const BindingRow& r : rows) {
        auto same =
            std::find_if(sizes.begin(), sizes.end(), [&](const VkDescriptorPoolSize& s) { return s.type == r.type; });
        if (same == sizes.end()) same = sizes.insert(sizes.end(), {r.type, 0});
        same->descriptorCount += sets;
    }
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.maxSets = sets;
    info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
    info.pPoolSizes = sizes.data();
    return make_owned(device, out, [&](VkDescriptorPool* pool) {
        return device.vk().CreateDescriptorPool(device.device, &info, device.allocator, pool);
    });
}

void write_set(const Device& device, VkDescriptorSet set, std::span<const BindingRow> rows,
               std::span<const BoundResource> resources) {
    // Every frame writes its set: no allocation here.
    std::array<VkWriteDescriptorSet, kMaxSetBindings> writes{};
    const std::size_t count = std::min(rows.size(), resources.size());
    for (std::size_t i = 0; i < count; ++i) {
        VkWriteDescriptorSet& w = writes[i];
        w = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstSet = set;
        w.dstBinding = rows[i].binding;
        w.descriptorCount = 1;
        w.descriptorType = rows[i].type;
        if (rows[i].type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER)
            w.pImageInfo = &resources[i].image;
        else
            w.pBufferInfo = &resources[i].buffer;
    }
    device.vk().UpdateDescriptorSets(device.device, static_cast<std::uint32_t>(count), writes.data(), 0, nullptr);
}

}  // namespace tidewater::render::detail
