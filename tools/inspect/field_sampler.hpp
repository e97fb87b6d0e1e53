// Samples a scene's water over a grid through the core queries: exactly the field
// the runtime draws, as arrays for the inspector's VTK export and views (no VTK here).
// Units: metres, seconds, m/s. Threading: reentrant; `threads` query threads.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"

namespace tidewater::inspect {

/// A regular grid of surface positions (x, z) over [min, max], nx by nz points; or a
/// piece of one (a parallel export's band): nx by nz of the whole grid's points from
/// (first_i, first_j), each at exactly the whole grid's position.
struct SampleGrid {
    glm::dvec2 min{-50.0}, max{50.0};
    int nx = 64, nz = 64;
    int first_i = 0, first_j = 0;    ///< a piece's first point in the whole grid
    int whole_nx = 0, whole_nz = 0;  ///< a piece's whole grid (0: this grid is whole)
    std::size_t points() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz); }
    std::size_t index(int i, int j) const {
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
    }
    bool is_piece() const { return whole_nx > 0; }
    /// The world (x, z) of point (i, j), m.
    glm::dvec2 point(int i, int j) const {
        const int wx = is_piece() ? whole_nx : nx, wz = is_piece() ? whole_nz : nz;
        return min + (max - min) * glm::dvec2((first_i + i) / double(wx - 1), (first_j + j) / double(wz - 1));
    }
    /// The piece of this whole grid from point (i0, j0) to (i1, j1), both included.
    SampleGrid piece(int i0, int i1, int j0, int j1) const {
        SampleGrid p = *this;
        p.first_i = i0, p.first_j = j0, p.whole_nx = nx, p.whole_nz = nz;
        p.nx = i1 - i0 + 1, p.nz = j1 - j0 + 1;
        return p;
    }
};

/// The largest grid sampled in one go (about 1.6 GB of arrays).
inline constexpr std::size_t kMaxGridPoints = 16'000'000;

/// Checks a grid: at least 2 x 2 (a piece: 1 x 1 within its whole grid), at most
/// kMaxGridPoints, finite extent with max > min.
Status validate_grid(const SampleGrid& grid);

/// One array the inspector knows: name, components and unit.
struct FieldInfo {
    const char* name;
    int components;
    const char* unit;
    const char* meaning;
};
/// Every array a sample holds, in export order.
const std::vector<FieldInfo>& field_infos();
const FieldInfo* find_field(const std::string& name);

/// The water over the grid at one time. Point k = i + nx * j is grid point (i, j).
struct FieldSample {
    SampleGrid grid;
    double time = 0.0;
    std::vector<glm::dvec3> surface;  ///< Displaced surface positions (x, y, z), m, one per grid point.
    std::vector<double> height, jacobian, foam, depth, shore_distance, wet;
    std::vector<glm::dvec3> displacement, normal, velocity;
    std::vector<glm::dvec3> flow;  ///< The current alone (x, 0, z), m/s.
    std::vector<double> body;      ///< Body id (see body_names), one per grid point.
    std::vector<double> wake;      ///< The wakes' share of the height, m.
    /// Names of the body ids: 0 "" (land), 1 "ocean", then the lakes and the rivers in the scene's order.
    std::vector<std::string> body_names;
    bool has_shore = false;  ///< depth, shore_distance and wet are meaningful (the scene has terrain).

    /// The values of a scalar field (components 1) or a component of a vector field.
    double value(const std::string& field, std::size_t point, int component = 0) const;
};

/// Samples `scene` at `time`: the surface point above each grid position (Eulerian
/// queries of the whole world, as `tidewater query`: the ocean, lakes and rivers) plus
/// its particle data, its body and its current.
Result<FieldSample> sample_field(const Scene& scene, const SampleGrid& grid, double time, unsigned threads = 0);

/// The body ids of `scene` (FieldSample::body_names).
std::vector<std::string> body_names(const Scene& scene);

/// Terrain heights over the grid (the second surface), m.
std::vector<double> sample_terrain(const Scene& scene, const SampleGrid& grid);

}  // namespace tidewater::inspect
