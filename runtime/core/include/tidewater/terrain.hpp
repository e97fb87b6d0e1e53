// Terrains: a flat floor, an inclined plane, a 16-bit heightmap, or a
// procedural island. Units: metres; y is up.
// Threading: immutable, safe to share (a heightmap's pixels are shared, not copied).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>

namespace tidewater {

/// A single-channel 16-bit image, row-major from the top row (a heightmap's pixels).
struct Gray16Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint16_t> pixels;
};

struct FlatTerrain {
    double height = -100.0;  ///< m
    bool operator==(const FlatTerrain&) const = default;
};

/// h(x, z) = height + slope.x * x + slope.y * z.
struct PlaneTerrain {
    double height = -100.0;   ///< m at the origin
    glm::dvec2 slope{0.0};    ///< dh/dx, dh/dz (dimensionless)
    bool operator==(const PlaneTerrain&) const = default;
};

/// A 16-bit greyscale heightmap: pixel value 0 is min_height, 65535 is max_height.
/// Image column i maps to x, row j to z, spanning `size` centred on `center`;
/// outside it the edge pixels extend. Sampled bilinearly between pixel centres.
struct HeightmapTerrain {
    std::string file;                     ///< Where it came from (for messages).
    glm::dvec2 size{1000.0, 1000.0};      ///< m along x and z, > 0.
    glm::dvec2 center{0.0};               ///< m
    double min_height = -50.0;            ///< m
    double max_height = 50.0;             ///< m
    std::shared_ptr<const Gray16Image> image;
    bool operator==(const HeightmapTerrain&) const = default;  ///< The same pixels object, not equal pixels.
};

/// A procedural island: beaches of a gentle slope, cliffs along part of the
/// coast, inland hills and an enclosed lagoon, all from `seed`.
struct IslandTerrain {
    std::uint32_t seed = 7;
    double radius = 600.0;    ///< m, mean distance from the centre to the coast (water level 0)
    double height = 80.0;     ///< m, typical inland height
    double seabed = -40.0;    ///< m, depth far offshore (< 0)
    glm::dvec2 center{0.0};   ///< m
    bool operator==(const IslandTerrain&) const = default;
};

class Terrain {
public:
    using Shape = std::variant<FlatTerrain, PlaneTerrain, HeightmapTerrain, IslandTerrain>;

    Terrain() = default;
    explicit Terrain(Shape shape) : shape_(std::move(shape)) {}

    double height_at(glm::dvec2 p) const;
    const Shape& shape() const { return shape_; }
    /// The same shape with the same parameters (a heightmap: the same pixels object).
    bool operator==(const Terrain&) const = default;
    const char* kind_name() const;
    /// Centre and half-size (m) of the square region worth drawing; unbounded
    /// shapes (flat, plane) report a 3 km half-size around the origin.
    glm::dvec2 extent_center() const;
    double extent_half_size() const;

private:
    Shape shape_{FlatTerrain{}};
};

}  // namespace tidewater
