// Lakes and rivers as baked (internal): their extents, a river's falling surface,
// carved bed and current. Tidewater::bake makes them (water_bodies_bake.hpp), saved bakes
// load them; hosts reach them through bake_scene, load_scene_bake and query_world.
//
// Grids: values at texel centres, rows along +z, bilinear between centres.
// Units: metres, seconds; discharge m^3/s.
// Threading: immutable once baked, safe to share.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <memory>
#include <stop_token>
#include <string>
#include <vector>

#include "tidewater/detail/square_region.hpp"
#include "tidewater/result.hpp"
#include "tidewater/scene.hpp"

namespace tidewater::detail {

/// A regular grid of texels over a rectangle of the world.
struct FieldGrid {
    glm::dvec2 corner{0.0};  ///< World xz of the outer corner, m.
    double texel = 1.0;      ///< m
    int nx = 0, nz = 0;

    std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz); }
    std::size_t index(int i, int j) const {
        return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
    }
    glm::dvec2 center(int i, int j) const { return corner + texel * glm::dvec2(i + 0.5, j + 0.5); }
    bool contains(glm::dvec2 p) const {
        return p.x >= corner.x && p.y >= corner.y && p.x < corner.x + texel * nx && p.y < corner.y + texel * nz;
    }
    /// The texel holding p, clamped to the grid.
    void texel_of(glm::dvec2 p, int& i, int& j) const;
    /// Bilinear sample between texel centres, clamped at the edges.
    double sample(const std::vector<float>& field, glm::dvec2 p) const;
};

/// What a river runs into.
enum class RiverEnd { domain_edge, ocean, lake, river };
/// "domain_edge", "ocean", "lake" or "river" (summaries, saved bakes).
const char* river_end_name(RiverEnd end);

/// Which body a river texel's water belongs to.
enum class RiverTexel : std::uint8_t {
    none = 0,   ///< not this river's water
    river = 1,  ///< the river's own channel
    plume = 2,  ///< still water of the body it runs into, where its current fades out and its waves hand over
    mouth = 3,  ///< the river's own water next to that still water (its waves blend there too)
};

/// The river's own water (its channel, mouth included).
inline bool river_water(std::uint8_t texel) {
    return texel == static_cast<std::uint8_t>(RiverTexel::river) ||
           texel == static_cast<std::uint8_t>(RiverTexel::mouth);
}

struct LakeBake {
    std::string name;
    double level = 0.0;
    FieldGrid grid;                    ///< the lake's bounding box on the scene's body grid
    std::vector<std::uint8_t> inside;  ///< 1 where the lake is (at its level)
    std::size_t texels = 0;            ///< lake texels
    /// Whether p lies in the lake: below its level in or next to one of its texels.
    bool holds(glm::dvec2 p, double terrain_height) const;
};

/// The square a lake's shore model covers: its extent with a margin of beach.
SquareRegion lake_basin_region(const LakeBake& lake);

/// Everything a river's bake depends on besides the terrain under its grid: the same key
/// over the same terrain gives the same bake, so an edit re-bakes only the rivers it
/// changes (BodiesBakeOptions::previous).
struct RiverBakeKey {
    std::vector<glm::dvec2> path;
    std::vector<double> width;
    double discharge = 0.0, manning = 0.0, texel = 0.0;
    bool carve = true;
    std::size_t samples = 0;  ///< centreline samples to its mouth
    RiverEnd end = RiverEnd::domain_edge;
    int receiver = -1;
    double joins_at = 0.0, total = 0.0, mouth_level = 0.0, psi_left = 0.0, plume_length = 0.0;
    int side = 0;
    std::vector<std::array<double, 4>> inflows;  ///< along, width, discharge, side of each tributary
    bool operator==(const RiverBakeKey&) const = default;
};

struct RiverBake {
    std::string name;
    double discharge = 0.0;      ///< Q through every cross-section below all tributaries, m^3/s
    double own_discharge = 0.0;  ///< Q at the source
    double manning = 0.035;
    RiverEnd end = RiverEnd::domain_edge;
    int receiver = -1;         ///< index of the lake or river it runs into
    double mouth_level = 0.0;  ///< the surface where it ends (a lake's or the ocean's level, the river's at a
                               ///< confluence or the domain's edge), m
    double mean_speed = 0.0;   ///< Q / mean cross-section area, m/s: the waves ride it

    /// Centreline samples from source to mouth.
    std::vector<glm::dvec2> centreline;
    std::vector<double> along;    ///< distance from the source, m
    std::vector<double> width;    ///< wetted width, m
    std::vector<double> surface;  ///< water surface, never rising, m
    std::vector<double> bed;      ///< deepest bed in the section, m
    std::vector<double> slope;    ///< energy slope used for Manning

    FieldGrid grid;
    std::vector<std::uint8_t> texel;              ///< RiverTexel
    std::vector<float> surface_height;            ///< water surface, m (where texel != none)
    std::vector<float> depth;                     ///< water column: surface - carved terrain, m (<= 0 dry)
    std::vector<float> psi;                       ///< stream function, m^3/s
    std::vector<float> discharge_x, discharge_z;  ///< h u, m^2/s (half the flux on bank texels)
    std::vector<float> flow_x, flow_z;            ///< depth-averaged current u, m/s (0 where dry)
    std::vector<float> channel_s, channel_n;      ///< along and across the centreline, m (n > 0 left)
    std::vector<float> tangent_x, tangent_z;      ///< downstream unit direction of the nearest centreline
    /// What the water evaluation samples, gpu::kRiverQueryStride floats per texel
    /// (host_device.h): surface above mouth_level, depth, tangent x and z, the weights of
    /// the river's waves and of the still water's.
    std::vector<float> query_texels;
    std::shared_ptr<const TerrainCut> cut;  ///< the carved channel (null: not carved)
    std::size_t islands = 0;                ///< dry islands inside the channel
    RiverBakeKey key;                       ///< what it was baked from
    /// The other rivers' cuts under its grid when it was baked (the terrain it saw).
    std::vector<std::shared_ptr<const TerrainCut>> baked_over;
};

/// A river's fields at a world point (bilinear, clamped to its grid).
struct RiverSample {
    double s = 0.0, n = 0.0;            ///< channel coordinates: along and across (left > 0), m
    double flow_x = 0.0, flow_z = 0.0;  ///< current, m/s
    double depth = 0.0;                 ///< still water column, m
    double surface = 0.0;               ///< still surface, world y, m
};
RiverSample sample_river(const RiverBake& river, glm::dvec2 p);

/// The texels whose currents sample_river reads at a world point and their weights:
/// bilinear times each texel's water column, over their sum (so that the depth times the
/// current is the bilinear field of h u wherever the four are wet); all weights 0 where
/// none of the four holds water. river_water.glsl is the GPU twin.
struct RiverCurrentTaps {
    std::array<std::size_t, 4> texel{};
    std::array<double, 4> weight{};
};
RiverCurrentTaps river_current_taps(const RiverBake& river, glm::dvec2 p);

/// A river's wave at one instant in its channel frame, as the shaders take it: its phase
/// at channel coordinates (s, n) is k_s s + k_n n + offset, the offset riding the river's
/// mean speed (the Doppler shift of prepare_river_waves), reduced to [-pi, pi).
struct RiverWaveAt {
    double k_s = 0.0, k_n = 0.0;  ///< rad/m, downstream and to the left
    double amplitude = 0.0, steepness = 0.0, omega = 0.0;
    double offset = 0.0;  ///< rad
};
/// `waves` of a river's preset at the body's local time.
std::vector<RiverWaveAt> river_waves_at(const WaveSet& waves, double local_time, double mean_speed);

/// The depth over which a river's `waves` die out toward its banks, m: the depth their
/// highest crest-to-trough height (2 sum(a)) breaks in, 2 sum(a) / kRiverBankBreakerIndex
/// (host_device.h); 0 for no waves.
double river_bank_ramp_depth(const WaveSet& waves);

/// Packs what the water evaluation samples (RiverBake::query_texels) from the river's
/// surface, depth and tangent fields and the weights of its waves and the still water's.
void pack_query_texels(RiverBake& river, const std::vector<float>& river_weight,
                       const std::vector<float>& still_weight);

/// Everything lakes and rivers bake to.
struct WaterBodiesBake {
    std::vector<LakeBake> lakes;    ///< in the scene's order
    std::vector<RiverBake> rivers;  ///< in the scene's order
    Terrain terrain;                ///< the scene's terrain with every river's cut
    int lake_resolution = 0;        ///< as baked
    double texels_across = 0.0;     ///< as baked
    std::size_t reused_rivers = 0;  ///< rivers taken from BodiesBakeOptions::previous unchanged
};

struct BodiesBakeOptions {
    int lake_resolution = 256;             ///< texels per side of the grid lakes are found on
    double texels_across = 8.0;            ///< a river grid's texels across its narrowest width
    std::function<void(double)> progress;  ///< 0..1
    std::stop_token cancel;
    /// The bake of the scene this one was edited from (null: none). Rivers whose key, the
    /// cuts under their grid and the terrain's shape there are unchanged are taken from
    /// it; the result is the same as baking everything.
    const WaterBodiesBake* previous = nullptr;
};

/// Whether a cut reaches into a grid (its zero ring of half a texel included).
bool cut_touches(const TerrainCut& cut, const FieldGrid& grid);
/// The cuts among `cuts` that reach into `grid`.
std::vector<std::shared_ptr<const TerrainCut>> cuts_under(const std::vector<std::shared_ptr<const TerrainCut>>& cuts,
                                                          const FieldGrid& grid);

}  // namespace tidewater::detail
