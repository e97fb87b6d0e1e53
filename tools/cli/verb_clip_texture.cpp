// tidewater clip-texture: a closed mesh (OBJ) as a distance texture, the 16-bit PNG a
// scene's "distance_texture" clip volume reads, with the scene key that places it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "tidewater/clip_texture_bake.hpp"
#include "tidewater/detail/image_write.hpp"
#include "verbs.hpp"

namespace tidewater::cli {

namespace {

struct ClipTextureArgs {
    std::string obj;
    std::string out;
    unsigned samples = 48;
    double margin = -1.0;  // < 0: two samples' spacing
};

int run_clip_texture(const ClipTextureArgs& a) {
    constexpr const char* verb = "clip-texture";
    if (a.samples < DistanceTexture::kMinSide || a.samples > DistanceTexture::kMaxSide)
        return fail(verb, fmt::format("--samples {} is out of range ({} to {})", a.samples, DistanceTexture::kMinSide,
                                      DistanceTexture::kMaxSide));
    if (!(std::isfinite(a.margin) && a.margin <= 1e4))
        return fail(verb, fmt::format("--margin {} is out of range (up to 1e4 m)", a.margin));
    auto mesh = read_obj_mesh(a.obj);
    if (!mesh) return fail(verb, mesh.error().message);
    // The longest side takes --samples; the others as many at about the same spacing.
    const TextureBox bounds = texture_box(*mesh, 0.0);
    const double longest = 2.0 * std::max({bounds.half_extents.x, bounds.half_extents.y, bounds.half_extents.z});
    const double margin = a.margin >= 0.0 ? a.margin : 2.0 * longest / (a.samples - 3.0);
    const TextureBox box = texture_box(*mesh, margin);
    const double spacing =
        2.0 * std::max({box.half_extents.x, box.half_extents.y, box.half_extents.z}) / (a.samples - 1);
    glm::uvec3 size;
    for (int c = 0; c < 3; ++c)
        size[c] = static_cast<unsigned>(std::clamp(std::ceil(2.0 * box.half_extents[c] / spacing) + 1.0,
                                                   static_cast<double>(DistanceTexture::kMinSide),
                                                   static_cast<double>(a.samples)));
    auto texture = bake_distance_texture(*mesh, box, size);
    if (!texture) return fail(verb, fmt::format("{}: {}", a.obj, texture.error().message));
    // Every distance in the box fits the range: its diagonal.
    const double range = 2.0 * glm::length(box.half_extents);
    if (auto st = detail::write_distance_texture_png(a.out, **texture, range); !st)
        return fail(verb, st.error().message);
    std::printf(
        "{\"shape\": \"distance_texture\", \"center\": [%.6g, %.6g, %.6g], \"half_extents\": [%.6g, %.6g, %.6g], "
        "\"file\": \"%s\", \"slices\": %u, \"range\": %.6g}\n",
        box.center.x, box.center.y, box.center.z, box.half_extents.x, box.half_extents.y, box.half_extents.z,
        a.out.c_str(), size.z, range);
    std::fprintf(stderr, "tidewater clip-texture: %zu triangles, %u x %u x %u samples %.3g m apart, range %.3g m\n",
                 mesh->triangles.size(), size.x, size.y, size.z, spacing, range);
    return 0;
}

}  // namespace

Verb add_clip_texture_verb(CLI::App& app) {
    auto args = std::make_shared<ClipTextureArgs>();
    CLI::App* cmd = app.add_subcommand(
        "clip-texture",
        "A closed mesh (OBJ) as the distance texture of a clip volume (a 16-bit PNG of stacked slices)");
    cmd->add_option("--obj", args->obj, "The closed mesh, a Wavefront OBJ (the volume's own frame, m)")->required();
    cmd->add_option("--out", args->out, "Output PNG; written whole or not at all")->required();
    cmd->add_option("--samples", args->samples, "Samples along the longest side (2 to 128)")->capture_default_str();
    cmd->add_option("--margin", args->margin, "Room round the mesh, m (default: two samples' spacing)");
    cmd->footer(
        "Prints the scene's clip volume entry on stdout: add it to \"clip_volumes\" with the\n"
        "mesh's centre placed in the world (its \"center\" is the box's, in the mesh's frame).");
    return {cmd, [args] { return run_clip_texture(*args); }};
}

}  // namespace tidewater::cli
