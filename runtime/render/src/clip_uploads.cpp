#include "clip_uploads.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace tidewater::render::detail {

namespace {

static_assert(ClipVolume::kMaxPlanes == gpu::kMaxClipPlanesPerVolume);

/// The frame's clip_planes a volume takes: a convex one's planes, a distance texture's head.
std::size_t plane_slots(const ClipVolume& v) {
    return v.shape == ClipVolume::Shape::distance_texture ? 2 : v.planes.size();
}

std::size_t planes_of(std::span<const ClipVolume> volumes) {
    std::size_t n = 0;
    for (const ClipVolume& v : volumes) n += plane_slots(v);
    return n;
}

/// The distance textures' room taken by `v` besides `held` (a texture shared by volumes is
/// uploaded once).
std::size_t new_samples(const ClipVolume& v, std::span<const std::shared_ptr<const DistanceTexture>> held) {
    if (!v.texture || std::find(held.begin(), held.end(), v.texture) != held.end()) return 0;
    return v.texture->distances().size();
}

void hold_texture(const ClipVolume& v, std::vector<std::shared_ptr<const DistanceTexture>>& held) {
    if (v.texture && std::find(held.begin(), held.end(), v.texture) == held.end()) held.push_back(v.texture);
}

/// The volume relative to O; a convex one's planes (a distance texture's head) from
/// `first_plane` on in the frame.
gpu::GpuClipVolume gpu_clip(const ClipVolume& v, glm::dvec2 origin, std::size_t first_plane) {
    const glm::dquat q = glm::normalize(v.orientation);
    const glm::dvec3 x = q * glm::dvec3(1.0, 0.0, 0.0), y = q * glm::dvec3(0.0, 1.0, 0.0),
                     z = q * glm::dvec3(0.0, 0.0, 1.0);
    gpu::GpuClipVolume g{};
    const glm::dvec3 c = v.center - glm::dvec3(origin.x, 0.0, origin.y);
    float shape = static_cast<float>(gpu::kClipBox);
    glm::dvec3 sizes = v.half_extents;
    if (v.shape == ClipVolume::Shape::sphere) {
        shape = static_cast<float>(gpu::kClipSphere);
        sizes = glm::dvec3(v.radius, 0.0, 0.0);
    } else if (v.shape == ClipVolume::Shape::capsule) {
        shape = static_cast<float>(gpu::kClipCapsule);
        sizes = glm::dvec3(v.radius, v.half_length, 0.0);
    } else if (v.shape == ClipVolume::Shape::convex) {
        shape = static_cast<float>(gpu::kClipConvex);
        sizes = glm::dvec3(static_cast<double>(first_plane), static_cast<double>(v.planes.size()), 0.0);
    } else if (v.shape == ClipVolume::Shape::distance_texture) {
        shape = static_cast<float>(gpu::kClipTexture);
        sizes = glm::dvec3(static_cast<double>(first_plane), 2.0, 0.0);
    }
    g.center = glm::vec4(glm::vec3(c), shape);
    g.axis_x = glm::vec4(glm::vec3(x), static_cast<float>(sizes.x));
    g.axis_y = glm::vec4(glm::vec3(y), static_cast<float>(sizes.y));
    g.axis_z = glm::vec4(glm::vec3(z), static_cast<float>(sizes.z));
    return g;
}

}  // namespace

Result<FrameClips> gather_clip_volumes(const Scene& scene, std::span<const ClipVolume> host,
                                       std::span<const FloatDraw> floats, glm::dvec3 camera) {
    FrameClips out;
    const std::size_t fixed = scene.clip_volumes.size() + host.size();
    if (fixed > gpu::kMaxClipVolumes)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: FrameInfo::clip_volumes: {} volumes with the scene's {}; at most {} in all",
                                 host.size(), scene.clip_volumes.size(), gpu::kMaxClipVolumes)};
    for (std::size_t i = 0; i < host.size(); ++i) {
        if (auto st = validate(host[i], fmt::format("renderer: FrameInfo::clip_volumes/{}", i)); !st) return st.error();
        out.host_and_floats.push_back(host[i]);
    }
    const std::size_t fixed_planes = planes_of(scene.clip_volumes) + planes_of(host);
    if (fixed_planes > gpu::kMaxClipPlanes)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: FrameInfo::clip_volumes: the convex volumes have {} planes with the "
                                 "scene's; at most {} in all",
                                 fixed_planes, gpu::kMaxClipPlanes)};
    for (const ClipVolume& v : scene.clip_volumes) hold_texture(v, out.textures);
    for (const ClipVolume& v : host) hold_texture(v, out.textures);
    std::size_t samples = texture_samples(out.textures);
    if (samples > gpu::kMaxClipTextureSamples)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("renderer: FrameInfo::clip_volumes: the distance textures have {} samples with the "
                                 "scene's; at most {} in all",
                                 samples, gpu::kMaxClipTextureSamples)};
    std::vector<ClipVolume> of_floats;
    for (std::size_t i = 0; i < floats.size(); ++i) {
        const FloatDraw& f = floats[i];
        if (!f.clip) continue;
        if (auto st = validate(*f.clip, fmt::format("renderer: FrameInfo::floats/{}/clip", i)); !st) return st.error();
        ClipVolume world = *f.clip;
        const glm::dquat pose = glm::normalize(f.orientation);
        world.center = f.position + pose * f.clip->center;
        world.orientation = pose * f.clip->orientation;
        of_floats.push_back(world);
    }
    const std::size_t room = gpu::kMaxClipVolumes - fixed;
    if (of_floats.size() > room) {
        std::nth_element(of_floats.begin(), of_floats.begin() + static_cast<std::ptrdiff_t>(room), of_floats.end(),
                         [&](const ClipVolume& a, const ClipVolume& b) {
                             return clip_distance(a, camera) < clip_distance(b, camera);
                         });
        out.left_out = static_cast<std::uint32_t>(of_floats.size() - room);
        of_floats.resize(room);
    }
    // The floats' convex hulls and distance textures take the planes and samples left, the
    // nearest first.
    std::sort(of_floats.begin(), of_floats.end(), [&](const ClipVolume& a, const ClipVolume& b) {
        return clip_distance(a, camera) < clip_distance(b, camera);
    });
    std::size_t planes_left = gpu::kMaxClipPlanes - fixed_planes;
    const auto no_room = std::remove_if(of_floats.begin(), of_floats.end(), [&](const ClipVolume& v) {
        const std::size_t more = new_samples(v, out.textures);
        if (plane_slots(v) > planes_left || samples + more > gpu::kMaxClipTextureSamples) return true;
        planes_left -= plane_slots(v);
        samples += more;
        hold_texture(v, out.textures);
        return false;
    });
    out.left_out += static_cast<std::uint32_t>(of_floats.end() - no_room);
    of_floats.erase(no_room, of_floats.end());
    out.host_and_floats.insert(out.host_and_floats.end(), of_floats.begin(), of_floats.end());
    out.total = static_cast<std::uint32_t>(scene.clip_volumes.size() + out.host_and_floats.size());
    return out;
}

void pack_clip_volumes(const Scene& scene, const FrameClips& clips, glm::dvec2 origin, gpu::GpuFrame& frame) {
    std::size_t n = 0, planes = 0;  // gather_clip_volumes kept both within the frame's room
    auto pack = [&](const ClipVolume& v) {
        frame.clip_volumes[n++] = gpu_clip(v, origin, planes);
        for (const glm::dvec4& plane : v.planes) frame.clip_planes[planes++] = glm::vec4(plane);
        if (v.texture) {
            std::size_t first = 0;
            for (const auto& t : clips.textures) {
                if (t == v.texture) break;
                first += t->distances().size();
            }
            frame.clip_planes[planes++] = glm::vec4(glm::vec3(v.half_extents), static_cast<float>(first));
            frame.clip_planes[planes++] = glm::vec4(glm::vec3(v.texture->size()), 0.0f);
        }
    };
    for (const ClipVolume& v : scene.clip_volumes) pack(v);
    for (const ClipVolume& v : clips.host_and_floats) pack(v);
    frame.clips = glm::vec4(static_cast<float>(n), 0.0f, 0.0f, 0.0f);
}

std::size_t texture_samples(std::span<const std::shared_ptr<const DistanceTexture>> textures) {
    std::size_t n = 0;
    for (const auto& t : textures) n += t->distances().size();
    return n;
}

void write_texture_samples(std::span<const std::shared_ptr<const DistanceTexture>> textures, float* out) {
    for (const auto& t : textures) out = std::copy(t->distances().begin(), t->distances().end(), out);
}

}  // namespace tidewater::render::detail
