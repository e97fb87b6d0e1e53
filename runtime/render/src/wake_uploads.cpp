#include "wake_uploads.hpp"

#include <algorithm>
#include <cstring>

#include "tidewater/detail/wake_water.hpp"

namespace tidewater::render::detail {

std::size_t wake_buffer_bytes(std::size_t points) {
    return sizeof(glm::vec4) * gpu::kMaxWakeBlocks + sizeof(gpu::GpuWakePoint) * points;
}

void write_wake_buffer(const WakeUpload& upload, void* mapped) {
    auto* bytes = static_cast<unsigned char*>(mapped);
    if (!upload.blocks.empty()) std::memcpy(bytes, upload.blocks.data(), sizeof(glm::vec4) * upload.blocks.size());
    if (!upload.points.empty())
        std::memcpy(bytes + sizeof(glm::vec4) * gpu::kMaxWakeBlocks, upload.points.data(),
                    sizeof(gpu::GpuWakePoint) * upload.points.size());
}

Result<WakeUpload> pack_wakes(const Scene& scene, const Wakes* host, double time, glm::dvec2 origin) {
    if (scene.boats.empty() && (host == nullptr || host->point_count() == 0)) return WakeUpload{};
    Wakes wakes;
    if (host != nullptr) {
        if (auto st = host->validate("renderer: FrameInfo::wakes"); !st) return st.error();
        wakes = *host;
    }
    scene_boat_wakes(scene.boats, time, wakes);
    return pack_wakes(wakes, time, origin);
}

Result<WakeUpload> pack_wakes(const Wakes& given, double time, glm::dvec2 origin) {
    WakeUpload out;
    if (auto st = given.validate("wakes"); !st) return st.error();
    // What churns foam first (chains and splashes): the fragment shader walks only those for it.
    Wakes churning, calm;
    churning.splash_max_age = calm.splash_max_age = given.splash_max_age;
    auto churns = [](const DisturbancePoint& p) { return p.turbulence > 0.0; };
    for (const WakeChain& c : given.chains)
        (std::any_of(c.points.begin(), c.points.end(), churns) ? churning : calm).chains.push_back(c);
    for (std::size_t i = 0; i < given.splashes.size(); ++i) {
        Wakes& to = churns(given.splashes[i]) ? churning : calm;
        to.splashes.push_back(given.splashes[i]);
        to.splash_emitters.push_back(given.splash_emitters.empty() ? 0 : given.splash_emitters[i]);
    }
    std::vector<double> reach_x, reach_z, reach2;  // every point's reach disc, relative to O
    std::vector<unsigned char> linked;
    for (const Wakes* part : {&churning, &calm}) {
        const auto prepared = tidewater::detail::prepare_wakes<double>(*part, time);
        const glm::dvec2 shift = prepared.origin - origin;
        for (std::size_t i = 0; i < prepared.x.size(); ++i) {
            gpu::GpuWakePoint p;
            p.position_age =
                glm::vec4(static_cast<float>(prepared.x[i] + shift.x), static_cast<float>(prepared.z[i] + shift.y),
                          static_cast<float>(prepared.age[i]), static_cast<float>(prepared.strength[i]));
            p.shape = glm::vec4(static_cast<float>(prepared.size[i]), static_cast<float>(prepared.steepness[i]),
                                static_cast<float>(prepared.turbulence[i]), prepared.linked[i] ? 1.0f : 0.0f);
            out.points.push_back(p);
            reach_x.push_back(prepared.reach_x[i] + shift.x);
            reach_z.push_back(prepared.reach_z[i] + shift.y);
            reach2.push_back(prepared.reach2[i]);
            linked.push_back(prepared.linked[i]);
        }
        if (part == &churning) out.turbulent = static_cast<std::uint32_t>(out.points.size());
        out.displacement_bound += prepared.displacement_bound;
        for (const glm::dvec4& b : prepared.boxes) {
            const glm::vec4 box(static_cast<float>(b.x + shift.x), static_cast<float>(b.y + shift.y),
                                static_cast<float>(b.z + shift.x), static_cast<float>(b.w + shift.y));
            if (out.boxes.size() < gpu::kMaxWakeBoxes) {
                out.boxes.push_back(box);
            } else {  // merged into the last: larger, never smaller
                glm::vec4& last = out.boxes.back();
                last = glm::vec4(std::min(last.x, box.x), std::min(last.y, box.y), std::max(last.z, box.z),
                                 std::max(last.w, box.w));
            }
        }
    }
    for (const glm::dvec3& b : tidewater::detail::wake_block_discs(reach_x, reach_z, reach2, linked))
        out.blocks.push_back(
            glm::vec4(static_cast<float>(b.x), static_cast<float>(b.y), static_cast<float>(b.z), 0.0f));
    return out;
}

}  // namespace tidewater::render::detail
