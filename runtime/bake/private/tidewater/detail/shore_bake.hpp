// The shore bake: the shoreline (the terrain's contour at the water level)
// and the signed distance to it, computed exactly from that contour with CGAL.
// Internal to Tidewater::bake: hosts bake through bake_scene (scene_bake.hpp).
//
// Grid: `resolution` x `resolution` texels over the terrain's square extent;
// values are at texel centres, rows along +z. Units: metres.
// Threading: bake_shore is reentrant and uses `threads` worker threads;
// a ShoreField is immutable and safe to share.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <stop_token>
#include <vector>

#include "tidewater/detail/square_region.hpp"
#include "tidewater/result.hpp"
#include "tidewater/terrain.hpp"

namespace tidewater {

struct BakeOptions {
    int resolution = 1024;  ///< Texels per side, 8 to 8192.
    /// The square the grid covers; none: the terrain's extent (a lake's shore: its basin).
    std::optional<SquareRegion> region;
    double simplify_tolerance = 0.0;       ///< m; the contour moves at most this far (0 = half a texel).
    unsigned threads = 0;                  ///< 0 = every hardware thread.
    std::function<void(double)> progress;  ///< Called with 0..1 during long bakes (optional).
    std::stop_token cancel;                ///< Requested: the bake stops and returns ErrorCode::cancelled.
};

/// One closed or open (domain-edge) shoreline, land on its left.
struct ShoreLine {
    std::vector<glm::dvec2> points;  ///< World xz, m.
    bool closed = true;              ///< false where the shore leaves the domain.
};

/// Wall-clock seconds per bake stage (for benchmarks and progress reports).
struct ShoreBakeTimings {
    double heights = 0.0;   ///< Terrain sampled at every texel centre.
    double contour = 0.0;   ///< Marching squares and chaining.
    double simplify = 0.0;  ///< Simplification and CGAL polygons with holes.
    double tree = 0.0;      ///< CGAL AABB tree over the simplified segments.
    double distance = 0.0;  ///< Exact signed distance and gradient at every texel.
};

/// A grid's floats, shared between copies of the field that holds them until one of the
/// copies writes (write()): a field copied to change its depth copies the depth alone.
class SharedFloats {
  public:
    std::size_t size() const { return values_->size(); }
    bool empty() const { return values_->empty(); }
    const float* data() const { return values_->data(); }
    const float& operator[](std::size_t k) const { return (*values_)[k]; }
    auto begin() const { return values_->cbegin(); }
    auto end() const { return values_->cend(); }
    const std::vector<float>& values() const { return *values_; }
    /// The floats to write, copied first when another field shares them. Not to be called
    /// from two threads at once; the vector returned may be written from many.
    std::vector<float>& write() {
        if (values_.use_count() > 1) values_ = std::make_shared<std::vector<float>>(*values_);
        return *values_;
    }
    bool operator==(const SharedFloats& o) const { return values_ == o.values_ || *values_ == *o.values_; }

  private:
    std::shared_ptr<std::vector<float>> values_ = std::make_shared<std::vector<float>>();
};

struct ShoreField {
    glm::dvec2 corner{0.0};  ///< World xz of the grid's outer corner, m.
    double texel = 1.0;      ///< Texel size, m.
    int resolution = 0;
    /// Signed distance to the shoreline, m: positive over water, negative on land.
    /// The magnitude is the exact distance to the simplified shoreline; the sign is the
    /// texel's side of the water level, so it always agrees with `depth`.
    /// With no shoreline at all it is +-(domain diagonal): all water or all land.
    SharedFloats signed_distance;
    /// Unit gradient of the signed distance (points offshore over water), x and z.
    SharedFloats gradient_x, gradient_z;
    /// Water depth = level - terrain height, m (negative on land).
    SharedFloats depth;
    std::vector<ShoreLine> shorelines;  ///< The simplified contour the distances are exact to.
    std::size_t segment_count = 0;
    double simplify_tolerance = 0.0;  ///< m, as used.
    std::size_t polygons = 0;         ///< Land polygons (CGAL polygons with holes).
    std::size_t holes = 0;            ///< Water bodies enclosed by land (lakes, lagoons).
    ShoreBakeTimings timings;

    std::size_t index(int i, int j) const {
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(resolution) + static_cast<std::size_t>(i);
    }
    glm::dvec2 texel_center(int i, int j) const { return corner + texel * glm::dvec2(i + 0.5, j + 0.5); }
    /// Bilinear sample of one of this field's grids at a world point (clamped at the edges).
    double sample(const SharedFloats& grid, glm::dvec2 p) const;
    /// Bilinear sample of the signed distance at a world point (clamped at the edges).
    double distance_at(glm::dvec2 p) const { return sample(signed_distance, p); }
};

/// Bakes the shore of `terrain` at `water_level`. Fails on non-finite terrain heights
/// (naming where) or out-of-range options, and with ErrorCode::cancelled when cancelled.
Result<ShoreField> bake_shore(const Terrain& terrain, double water_level, const BakeOptions& options = {});

namespace reference {
/// Brute-force distance from `p` to the nearest shoreline segment (for benchmarks and
/// tests; slow by design).
double brute_force_shore_distance(const ShoreField& field, glm::dvec2 p);
}  // namespace reference

}  // namespace tidewater
