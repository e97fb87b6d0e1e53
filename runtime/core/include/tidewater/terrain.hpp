// Terrains: a flat floor, an inclined plane, a 16-bit heightmap, or a
// procedural island. Units: metres; y is up.
// Threading: immutable, safe to share (a heightmap's pixels are shared, not copied).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace tidewater {

/// A single-channel 16-bit image, row-major from the top row (a heightmap's pixels).
struct Gray16Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint16_t> pixels;
};

/// What a bake of an unbounded terrain (flat, plane) spans about the origin by default:
/// the half-size of the square, m. A scene at another scale gives its own ("half_size").
inline constexpr double kDefaultUnboundedHalfSize = 3000.0;

struct FlatTerrain {
    double height = -100.0;                        ///< m
    double half_size = kDefaultUnboundedHalfSize;  ///< m: the square the bakes span about the origin
    bool operator==(const FlatTerrain&) const = default;
};

/// h(x, z) = height + slope.x * x + slope.y * z.
struct PlaneTerrain {
    double height = -100.0;                        ///< m at the origin
    glm::dvec2 slope{0.0};                         ///< dh/dx, dh/dz (dimensionless)
    double half_size = kDefaultUnboundedHalfSize;  ///< m: the square the bakes span about the origin
    bool operator==(const PlaneTerrain&) const = default;
};

/// A 16-bit greyscale heightmap: pixel value 0 is min_height, 65535 is max_height.
/// Image column i maps to x, row j to z, its pixel centres spanning `size` centred on
/// `center`. Sampled bilinearly between pixel centres; beyond them the edge value
/// fades to min_height (heightmap_edge_fade), so that a world goes on to the horizon.
struct HeightmapTerrain {
    std::string file;                 ///< Where it came from (for messages).
    glm::dvec2 size{1000.0, 1000.0};  ///< m along x and z, > 0.
    glm::dvec2 center{0.0};           ///< m
    double min_height = -50.0;        ///< m
    double max_height = 50.0;         ///< m
    std::shared_ptr<const Gray16Image> image;
    bool operator==(const HeightmapTerrain&) const = default;  ///< The same pixels object, not equal pixels.
};

/// How a heightmap goes on beyond its outermost pixel centres: its edge value eased
/// (smoothstep of the distance from them) to `seabed` over `distance`. One rule for the
/// CPU (Terrain::height_at) and the renderer (frame.glsl's terrain_height_at).
struct HeightmapEdgeFade {
    double distance = 0.0;  ///< m: a sixteenth of the heightmap's larger side
    double seabed = 0.0;    ///< m: its min_height
};
HeightmapEdgeFade heightmap_edge_fade(const HeightmapTerrain& t);

/// A rounded mound added to a procedural island where a designer wants one: a rock in a
/// river, a skerry, a hillock. Its profile is height * (1 - (r/radius)^2)^2.
struct Knoll {
    glm::dvec2 at{0.0};    ///< m
    double radius = 10.0;  ///< m, where it meets the ground
    double height = 3.0;   ///< m above the ground at its centre
    bool operator==(const Knoll&) const = default;
};

/// A procedural island: beaches of a gentle slope, cliffs along part of the
/// coast, inland hills and an enclosed lagoon, all from `seed`, and any knolls added.
struct IslandTerrain {
    std::uint32_t seed = 7;
    double radius = 600.0;   ///< m, mean distance from the centre to the coast (water level 0)
    double height = 80.0;    ///< m, typical inland height
    double seabed = -40.0;   ///< m, depth far offshore (< 0)
    glm::dvec2 center{0.0};  ///< m
    std::vector<Knoll> knolls;
    bool operator==(const IslandTerrain&) const = default;
};

/// A channel cut into a terrain (a river bake's "carve"): the depth removed below the
/// shape at texel centres, m (>= 0, 0 where nothing is cut), sampled bilinearly.
struct TerrainCut {
    glm::dvec2 corner{0.0};  ///< World xz of the grid's outer corner, m.
    double texel = 1.0;      ///< m
    int nx = 0, nz = 0;      ///< texels along x and z; rows along +z
    std::vector<float> depth;
    /// The cut depth at a world point (0 outside the grid).
    double depth_at(glm::dvec2 p) const;
};

class Terrain {
  public:
    using Shape = std::variant<FlatTerrain, PlaneTerrain, HeightmapTerrain, IslandTerrain>;

    Terrain() = default;
    explicit Terrain(Shape shape) : shape_(std::move(shape)) {}

    /// The shape's height minus the deepest cut at p, m.
    double height_at(glm::dvec2 p) const;
    /// The shape alone, without cuts.
    double shape_height_at(glm::dvec2 p) const;
    const Shape& shape() const { return shape_; }
    /// Channels cut into the shape (empty as parsed; bake_scene's rivers add them).
    const std::vector<std::shared_ptr<const TerrainCut>>& cuts() const { return cuts_; }
    /// This terrain with `cuts` in place of any it had.
    Terrain with_cuts(std::vector<std::shared_ptr<const TerrainCut>> cuts) const;
    /// The same shape with the same parameters (a heightmap: the same pixels object) and
    /// the same cut objects.
    bool operator==(const Terrain&) const = default;
    const char* kind_name() const;
    /// Centre and half-size (m) of the square region worth drawing and baking: a
    /// heightmap's with its fade to the seabed (heightmap_edge_fade); unbounded
    /// shapes (flat, plane) report a 3 km half-size around the origin.
    glm::dvec2 extent_center() const;
    double extent_half_size() const;

  private:
    Shape shape_{FlatTerrain{}};
    std::vector<std::shared_ptr<const TerrainCut>> cuts_;
};

}  // namespace tidewater
