// A ring (a torus lying flat): a concave clip volume no box, sphere, capsule or convex mesh
// makes, as a distance texture sampled from its exact signed distance.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <memory>
#include <vector>

#include "tidewater/clip_volume.hpp"

namespace tidewater::test {

struct ClipTorus {
    double major = 3.5;  ///< m, the ring's centre line from its axis (y)
    double minor = 1.5;  ///< m, the tube's radius
    /// The exact signed distance at `local` (the ring's frame).
    double distance(glm::dvec3 local) const {
        const glm::dvec2 q(glm::length(glm::dvec2(local.x, local.z)) - major, local.y);
        return glm::length(q) - minor;
    }
    /// The box the texture spans: the ring and a margin of one tube's radius / 4.
    glm::dvec3 half_extents() const { return {major + 1.25 * minor, 1.25 * minor, major + 1.25 * minor}; }
    std::shared_ptr<const DistanceTexture> texture(glm::uvec3 size) const {
        const glm::dvec3 h = half_extents();
        std::vector<float> d;
        for (unsigned k = 0; k < size.z; ++k)
            for (unsigned j = 0; j < size.y; ++j)
                for (unsigned i = 0; i < size.x; ++i) {
                    const glm::dvec3 u(i / (size.x - 1.0), j / (size.y - 1.0), k / (size.z - 1.0));
                    d.push_back(static_cast<float>(distance(-h + 2.0 * h * u)));
                }
        auto made = DistanceTexture::create(size, std::move(d));
        return made ? std::move(made).value() : nullptr;
    }
    /// The ring as a closed mesh: `around` quads along its centre line, `across` round the
    /// tube, wound outward.
    void mesh(unsigned around, unsigned across, std::vector<glm::dvec3>& vertices,
              std::vector<std::array<std::uint32_t, 3>>& triangles) const {
        const double tau = 6.283185307179586;
        for (unsigned i = 0; i < around; ++i)
            for (unsigned j = 0; j < across; ++j) {
                const double a = tau * i / around, b = tau * j / across;
                const double r = major + minor * std::cos(b);
                vertices.emplace_back(r * std::cos(a), minor * std::sin(b), r * std::sin(a));
            }
        auto at = [&](unsigned i, unsigned j) { return (i % around) * across + (j % across); };
        for (unsigned i = 0; i < around; ++i)
            for (unsigned j = 0; j < across; ++j) {
                triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
                triangles.push_back({at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
            }
    }
};

}  // namespace tidewater::test
