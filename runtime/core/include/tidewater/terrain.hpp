// Analytic terrains for scenes: a flat floor or an inclined plane.
// Heightmaps and procedural islands join with the renderer.
// Units: metres; y is up. Threading: immutable, safe to share.
#pragma once

#include <glm/vec2.hpp>
#include <variant>

namespace tidewater {

struct FlatTerrain {
    double height = -100.0;  ///< m
};

/// h(x, z) = height + slope.x * x + slope.y * z.
struct PlaneTerrain {
    double height = -100.0;   ///< m at the origin
    glm::dvec2 slope{0.0};    ///< dh/dx, dh/dz (dimensionless)
};

class Terrain {
public:
    Terrain() = default;
    explicit Terrain(FlatTerrain flat) : shape_(flat) {}
    explicit Terrain(PlaneTerrain plane) : shape_(plane) {}

    double height_at(glm::dvec2 p) const;
    const std::variant<FlatTerrain, PlaneTerrain>& shape() const { return shape_; }
    const char* kind_name() const;

private:
    std::variant<FlatTerrain, PlaneTerrain> shape_{FlatTerrain{}};
};

}  // namespace tidewater
