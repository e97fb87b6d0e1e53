// Rendering to an image of the renderer's own and reading it back: the path
// the CLI, tools and tests use (no window, no swapchain).
// Lifetime: borrows the DeviceContext and Renderer, which must outlive it.
// Threading: one thread at a time; render() submits and waits.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "tidewater/render/renderer.hpp"

namespace tidewater::render {

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  ///< RGBA8, rows from the top.
};

class OffscreenTarget {
  public:
    /// Width and height in [16, 8192]; `samples` as the renderer's RendererInitInfo::samples
    /// (multisampled targets are resolved into the picture).
    static Result<std::unique_ptr<OffscreenTarget>> create(const DeviceContext& context, std::uint32_t width,
                                                           std::uint32_t height,
                                                           VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
    ~OffscreenTarget();
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;

    /// Renders one frame of the renderer's main view over the whole image and returns its pixels.
    Result<RgbaImage> render(Renderer& renderer, const FrameInfo& frame);
    /// Renders one frame of several views (split screen) and returns the picture: each
    /// view draws its rectangle, targets.offset to offset + extent, which must lie in the
    /// image (the target fills in its images; each view is sized to its extent first).
    Result<RgbaImage> render_views(Renderer& renderer, std::span<const ViewFrame> views);
    /// Formats to give RendererInitInfo for this target.
    static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  private:
    struct Impl;
    explicit OffscreenTarget(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace tidewater::render
