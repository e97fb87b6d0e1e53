// CGAL-backed shoreline geometry (private; CGAL stays inside shore_cgal.cpp).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <memory>
#include <vector>

#include "simplify_line.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/result.hpp"

namespace tidewater::detail {

struct ClassifiedShore {
    std::vector<ShoreLine> lines;  // simplified, land on the left, world units
    std::size_t polygons = 0;      // land polygons with holes
    std::size_t holes = 0;         // enclosed water bodies
};

/// Simplifies each line within `tolerance` (m, Douglas-Peucker) piece by piece between the
/// crossings of `lattice` (simplify_line.hpp) on `threads` threads and builds the land as
/// CGAL polygons with holes to count islands and enclosed waters.
ClassifiedShore simplify_and_classify(std::vector<ShoreLine> lines, double tolerance, const SimplifyLattice& lattice,
                                      unsigned threads);

/// Exact distance to a set of segments (a CGAL AABB tree), thread-safe for queries.
class ShoreDistance {
  public:
    struct Hit {
        double signed_distance = 0.0;  // m, + over water (right of the land-on-left segments)
        glm::dvec2 gradient{0.0};      // unit
        glm::dvec2 closest{0.0};       // nearest shore point
        std::size_t segment = 0;       // its segment; with `closest`, the next query's hint
    };
    /// A segment from `a` to `b`, land on its left.
    struct Segment {
        glm::dvec2 a, b;
    };
    static std::unique_ptr<ShoreDistance> build(const std::vector<ShoreLine>& lines);
    ~ShoreDistance();
    /// The nearest segment to `p` (CGAL AABB tree). `hint` is a previous answer near
    /// this one (e.g. the neighbouring texel's), or null.
    Hit query(glm::dvec2 p, const Hit* hint) const;
    /// Appends to `out` the index of every segment within `radius` of `p` (CGAL AABB tree).
    void segments_within(glm::dvec2 p, double radius, std::vector<std::uint32_t>& out) const;
    /// The signed distance from `p` to segment `s`, which the caller knows is the nearest;
    /// the sign is the side of the segment (the mean normal at a shared vertex).
    Hit hit_on(glm::dvec2 p, std::size_t s) const;
    /// The same, with the sign given: `water` says which side of the water level p is on.
    /// Where that disagrees with the side of the simplified line (within the simplification
    /// tolerance, or beyond an open line's end along the domain edge), the gradient is the
    /// segment's water-side normal.
    Hit hit_on(glm::dvec2 p, std::size_t s, bool water) const;
    const Segment& segment(std::size_t s) const;
    std::size_t segment_count() const;

  private:
    struct Impl;
    explicit ShoreDistance(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace tidewater::detail
