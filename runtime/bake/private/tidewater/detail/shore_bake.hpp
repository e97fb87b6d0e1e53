// The shore bake: the shoreline (the terrain's contour at the water level)
// and the signed distance to it, computed exactly from that contour with CGAL.
// Internal to Tidewater::bake: hosts bake through bake_scene (scene_bake.hpp).
//
// Grid: `resolution` x `resolution` texels over the terrain's square extent;
// values are at texel centres, rows along +z. Units: metres.
// Threading: bake_shore is reentrant and uses `threads` worker threads;
// a ShoreField is immutable and safe to share.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <optional>
#include <stop_token>
#include <vector>

#include "tidewater/detail/contour_cell.hpp"
#include "tidewater/detail/heightmap_change.hpp"
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

/// A grid's values, shared between copies of the field that holds them until one of the
/// copies writes (write()): a field copied to change its depth copies the depth alone.
template <typename T>
class SharedGrid {
  public:
    std::size_t size() const { return values_->size(); }
    bool empty() const { return values_->empty(); }
    const T* data() const { return values_->data(); }
    const T& operator[](std::size_t k) const { return (*values_)[k]; }
    auto begin() const { return values_->cbegin(); }
    auto end() const { return values_->cend(); }
    const std::vector<T>& values() const { return *values_; }
    /// The values to write, copied first when another field shares them. Not to be called
    /// from two threads at once; the vector returned may be written from many.
    std::vector<T>& write() {
        if (values_.use_count() > 1) values_ = std::make_shared<std::vector<T>>(*values_);
        return *values_;
    }
    bool operator==(const SharedGrid& o) const { return values_ == o.values_ || *values_ == *o.values_; }

  private:
    std::shared_ptr<std::vector<T>> values_ = std::make_shared<std::vector<T>>();
};
using SharedFloats = SharedGrid<float>;

/// A unit vector a texel held as its angle in 16 bits: a turn in 65 535 steps (within
/// 4.8e-5 rad), and kNone for no direction. Two floats would take 8 bytes a texel, 537 MB over
/// an 8192² field; this takes 2.
class SharedDirections {
  public:
    static constexpr std::uint16_t kNone = 0xFFFF;
    /// The code of `v`, a unit vector or zero (kNone: a length under a half).
    static std::uint16_t encode(glm::dvec2 v);
    /// The unit vector of `code` (zero for kNone); encode(decode(c)) == c.
    static glm::vec2 decode(std::uint16_t code);

    std::size_t size() const { return codes_.size(); }
    bool empty() const { return codes_.empty(); }
    glm::vec2 operator[](std::size_t k) const { return decode(codes_[k]); }
    const std::vector<std::uint16_t>& codes() const { return codes_.values(); }
    /// The codes to write (as SharedGrid::write).
    std::vector<std::uint16_t>& write() { return codes_.write(); }
    bool operator==(const SharedDirections& o) const { return codes_ == o.codes_; }

  private:
    SharedGrid<std::uint16_t> codes_;
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
    /// Unit gradient of the signed distance (points offshore over water), as its angle;
    /// none (zero) where the field has no shoreline.
    SharedDirections gradient;
    /// Water depth = level - terrain height, m (negative on land).
    SharedFloats depth;
    std::vector<ShoreLine> shorelines;  ///< The simplified contour the distances are exact to.
    /// The contour's cells before chaining (sorted by (j, i)), kept so that an edit can
    /// update the field where it reaches (update_shore). Null where not kept (a loaded or
    /// tiled bake, or a region's).
    std::shared_ptr<const std::vector<detail::ContourCell>> contour;
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
    /// The gradient's four taps around a world point blended bilinearly (clamped at the
    /// edges): not of unit length between texels whose directions differ.
    glm::dvec2 gradient_at(glm::dvec2 p) const;
};

/// The shore distance a grid other than the shoreline's holds at `p` (world xz) over water
/// `depth` deep (m; <= 0 on land): the shoreline's, signed by the texel's own depth so that
/// the two agree (m, in float as the grid holds it).
inline float resampled_distance(const ShoreField& from, glm::dvec2 p, double depth) {
    return static_cast<float>(std::copysign(std::abs(from.distance_at(p)), depth > 0.0 ? 1.0 : -1.0));
}

/// Bakes the shore of `terrain` at `water_level`. Fails on non-finite terrain heights
/// (naming where) or out-of-range options, and with ErrorCode::cancelled when cancelled.
Result<ShoreField> bake_shore(const Terrain& terrain, double water_level, const BakeOptions& options = {});

/// `before` (baked by bake_shore over a terrain whose heights differ from `terrain`'s only
/// within `changed`, at `water_level`) updated for `terrain`: the depths and the contour's
/// cells sampled again under the change, the shoreline chained and simplified again (only
/// the pieces the change touches differ: simplify_line.hpp), and the distances filled again
/// in the blocks where a changed segment may be nearest a texel or a depth changed. Every
/// other texel keeps its value, which is the full bake's there: the result is bake_shore's
/// over `terrain` with `before`'s options, to the bit but at a texel exactly as near two
/// shoreline points (its direction may be the other's). nullopt where it cannot be: `before`
/// kept no contour or has no shoreline (bake in full). Fails as bake_shore does.
Result<std::optional<ShoreField>> update_shore(const ShoreField& before, const Terrain& terrain, double water_level,
                                               const detail::WorldRect& changed, unsigned threads);

namespace reference {
/// Brute-force distance from `p` to the nearest shoreline segment (for benchmarks and
/// tests; slow by design).
double brute_force_shore_distance(const ShoreField& field, glm::dvec2 p);
}  // namespace reference

}  // namespace tidewater
