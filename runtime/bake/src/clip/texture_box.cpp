#include <algorithm>
#include <limits>

#include "tidewater/clip_texture_bake.hpp"

namespace tidewater {

TextureBox texture_box(const TriangleMesh& mesh, double margin) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const auto& t : mesh.triangles)
        for (std::uint32_t i : t) {
            if (i >= mesh.vertices.size()) continue;  // bake_distance_texture refuses it by name
            lo = glm::min(lo, mesh.vertices[i]);
            hi = glm::max(hi, mesh.vertices[i]);
        }
    if (lo.x > hi.x) return {};  // no triangles: an empty box, refused by the bake
    return {0.5 * (lo + hi), 0.5 * (hi - lo) + glm::dvec3(margin)};
}

}  // namespace tidewater
