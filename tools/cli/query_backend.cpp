#include "query_backend.hpp"

#include <memory>

#if defined(TIDEWATER_HAVE_RENDER)
#include "tidewater/render/gpu_query.hpp"
#include "tidewater/render/standalone.hpp"
#endif

namespace tidewater::cli {

Result<QueryBackend> make_gpu_query_backend() {
#if defined(TIDEWATER_HAVE_RENDER)
    auto device = render::StandaloneDevice::create();
    if (!device) return device.error();
    std::shared_ptr<render::StandaloneDevice> shared_device = std::move(device).value();
    auto gpu = render::GpuQuery::create(shared_device->context());
    if (!gpu) return gpu.error();
    // Members die in reverse order: the query engine before the device it borrows.
    struct Engine {
        std::shared_ptr<render::StandaloneDevice> device;
        std::unique_ptr<render::GpuQuery> query;
    };
    auto engine = std::make_shared<Engine>(Engine{shared_device, std::move(gpu).value()});
    return QueryBackend([engine](const Scene& scene, double t, std::span<const glm::dvec2> pts,
                                 std::span<WorldPoint> out) { return engine->query->query_world(scene, t, pts, out); });
#else
    return Error{ErrorCode::unsupported,
                 "--backend gpu: this build has no renderer (configure with TIDEWATER_BUILD_RENDER=ON)"};
#endif
}

}  // namespace tidewater::cli
