// GPU data layouts shared by C++ and GLSL: written once, read by both.
// In C++ the GLSL types map to glm; static_asserts pin every size so a
// change on one side that the other does not see fails to compile.
#ifndef TIDEWATER_HOST_DEVICE_H
#define TIDEWATER_HOST_DEVICE_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
namespace tidewater::gpu {
using vec2 = glm::vec2;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
using uint = std::uint32_t;
#define TW_CONST inline constexpr
#else
#define TW_CONST const
#endif

TW_CONST uint kGpuMaxWaves = 64u;
TW_CONST uint kQueryWorkgroupSize = 64u;

// The Eulerian solve (x0 + d(x0) = p by Newton's method), the same on CPU and GPU.
// A point stops at the first evaluation whose residual |x0 + d(x0) - p| is under
// max(floor, scale * sum(Q A)) m; after the cap it is reported unconverged.
TW_CONST int kMaxNewtonIterations = 32;
TW_CONST float kNewtonToleranceFloor = 3.0e-5f;   // m: above float rounding of the residual
TW_CONST float kNewtonToleranceScale = 1.2e-5f;   // per metre of sum(Q A)
// The rest position lies within sum(Q A) of the point; steps are kept within
// sum(Q A) * slack + floor (the slack keeps the clamp from cutting the true solution).
TW_CONST float kNewtonRadiusSlack = 1.001f;
TW_CONST float kNewtonRadiusFloor = 1.0e-6f;

// Waves die out at the waterline, so that the surface is continuous across it (the
// Eulerian solve has a root there) and rests on land. A shore model's waves scale by
// clamp(shore distance / its grid's texel, 0, 1) at the rest position: over the last texel
// of water, where its fields blend wet and dry texels (a length of the scene's, so the
// shore has none of its own). A river's by clamp(depth / ramp, 0, 1), ramp the depth
// its waves' highest crest-to-trough height 2 sum(a) breaks in, over this index: they
// never stand higher than a depth-limited breaker (a depth of the river's own waves, so
// its waves have no length of their own either). Per river: GpuBodyDraw.rivers.w and
// GpuQueryParams.river_bank_ramp (tidewater::detail::river_bank_ramp_depth).
TW_CONST float kRiverBankBreakerIndex = 0.78f;

// The shore model in tiles (tidewater::ShoreTiles): the grid is cut into tiles of
// kShoreTileTexels texels a side, and a page per tile names the slot that holds it.
// A slot stores kShoreSlotSide^2 texels: its tile's and one more row and column
// (the apron), so the four taps of a bilinear sample always lie in one slot. Tiles
// where the waves do not feel the bottom are not stored: their page names slot
// kShoreOpenSlot (the open sea's values) or kShoreDrySlot (dry land's), where depth
// and shore distance read +-kShoreFarValue (the queries report them as infinite).
TW_CONST uint kShoreTileTexels = 32u;
TW_CONST uint kShoreSlotSide = kShoreTileTexels + 1u;
TW_CONST uint kShoreSlotTexels = kShoreSlotSide * kShoreSlotSide;
TW_CONST uint kShoreOpenSlot = 0u;
TW_CONST uint kShoreDrySlot = 1u;
TW_CONST uint kShoreFirstStoredSlot = 2u;
TW_CONST float kShoreFarValue = 1.0e9f;  // m

// Light through water (shaders/water_medium.glsl): water's refractive index against air
// (each body's extinction and colour are its own: GpuBodyDraw.optics_*, GpuFrame.water_*).
TW_CONST float kWaterRefractiveIndex = 1.333f;
TW_CONST float kGravityAcceleration = 9.81f;  // m/s^2, tidewater::kGravity (static_assert in wake_water.cpp)
// The model keeps its fields in layers, each a grid of such tiles: the shared fields
// (depth, breaking, steepness scale, shore distance) at the model's texel, and the
// waves in runs of consecutive waves, each run at the texel its shortest wave needs
// (a power of two times the model's). At most kShoreMaxLayers runs. A model's records
// lie one after another in shore_layers[]: its shared fields', then its runs' in order.
// Over the renderer's memory budget a layer's tiles are streamed: a page naming
// kShoreNotResident sends the tap to the layer's coarse grid (every k-th texel, always
// resident); elsewhere the coarse grid is the layer's own and no page names it.
TW_CONST uint kShoreMaxLayers = 4u;
TW_CONST uint kShoreNotResident = 0xffffffffu;
struct GpuShoreLayer {
    vec4 grid;    // xy: its grid's outer corner from the model's shared grid's (m); z: texel (m); w: resolution (texels a side)
    uvec4 waves;  // x: first wave of the run; y: its wave count (0: the shared fields); z: its first page in
                  // shore_pages[]; w: its slot 0's first element in shore_waves[] (shore_shared[]: the shared fields)
    vec4 coarse_grid;  // the grid read where a page names kShoreNotResident, as `grid`
    uvec4 coarse;      // x: that grid's first page in shore_pages[]; y: its slot 0's first element; zw: 0
};

// A river's fields as the water evaluation samples them: kRiverQueryStride floats per
// texel of its grid, bilinear between texel centres. The surface is relative to the
// river's mouth level; the tangent points downstream (normalised after sampling); the
// river's wave weight is 1 in its water and falls to 0 over a blend width of the still
// water it runs into, whose own waves take the rest (still weight, 0 on land).
TW_CONST uint kRiverQueryStride = 6u;
TW_CONST uint kRiverQuerySurface = 0u;     // m above the mouth level
TW_CONST uint kRiverQueryDepth = 1u;       // still water column, m (<= 0 dry)
TW_CONST uint kRiverQueryTangentX = 2u;
TW_CONST uint kRiverQueryTangentZ = 3u;
TW_CONST uint kRiverQueryWaveWeight = 4u;
TW_CONST uint kRiverQueryStillWeight = 5u;

// Flow-mapped detail (tidewater::flow_detail, shaders/flow_detail.glsl): the noise
// lattice repeats every kFlowNoisePeriod cells; the per-texel time offset is a noise
// kFlowOffsetScale times as fine as the detail's, seeded kFlowStaggerSeed above it.
TW_CONST float kFlowNoisePeriod = 256.0f;
TW_CONST float kFlowOffsetScale = 0.25f;
TW_CONST uint kFlowStaggerSeed = 101u;

// Crest foam from the horizontal map compressing (tidewater::crest_foam): a smoothstep
// from 0 to 1 across the body's whitecap Jacobian J* (tidewater/whitecaps.hpp), over a
// width of kFoamRampFraction * (1 - J*), so foam >= 1/2 exactly where J < J*.
TW_CONST float kFoamRampFraction = 0.5f;
// Crest foam lingers and fades (tidewater::detail::remembered_foam): a particle adds the
// crest foam its compression made l * kFoamLagStep seconds ago (l = 1..kFoamLags), faded
// by exp(-l * kFoamLagStep / kFoamDecayTime). Lags of half a second keep the copies of a
// whitecap that runs at up to ~8 m/s overlapping (whitecaps are ~5 m across).
TW_CONST uint kFoamLags = 4u;          // the shaders carry them in a vec4
TW_CONST float kFoamLagStep = 0.5f;    // s
TW_CONST float kFoamDecayTime = 1.0f;  // s: e-folding time of whitecap foam

// Wakes (tidewater/wakes.hpp, shaders/wake_point.glsl). A wake wave's Q k A is held to
// at most kWakeFoldLimit so that a wake never folds the surface on its own; turbulence
// foam decays over kWakeFoamLifetime seconds and spreads as kWakeFoamSpread sqrt(age)
// metres beyond half the source's size. A frame holds at most kMaxWakePoints points.
TW_CONST float kWakeFoldLimit = 0.5f;
TW_CONST float kWakeFoamLifetime = 30.0f;  // s
TW_CONST float kWakeFoamSpread = 0.6f;     // m / sqrt(s)
TW_CONST uint kMaxWakePoints = 4096u;
TW_CONST uint kMaxWakeBoxes = 8u;  // where the wakes reach (tidewater::detail::wake_reach), per chain; more are merged
// How far a chain's waves are felt (tidewater::detail::wake_reach): kWakeReachSpeedShare
// of the emitter's speed times the age, plus kWakeReachSizes source sizes and
// kWakeReachMargin metres; a splash's at the group speed of its longest waves, those at
// kWakeSplashLongest of its peak wavenumber.
TW_CONST float kWakeReachSpeedShare = 1.25f;
TW_CONST float kWakeReachSizes = 2.0f;
TW_CONST float kWakeReachMargin = 60.0f;  // m
TW_CONST float kWakeSplashLongest = 0.05f;
TW_CONST float kWakeReachFullShare = 0.8f;  // within this share of the reach a segment counts fully, fading to none at it
// The walk skips kWakeBlockPoints consecutive points at once where a disc holding all
// their reach discs says none is felt. The wake buffer holds kMaxWakeBlocks such discs
// (vec4: centre xz relative to the render origin, squared radius, unused), then the points.
TW_CONST uint kWakeBlockPoints = 32u;
TW_CONST uint kMaxWakeBlocks = kMaxWakePoints / kWakeBlockPoints;

// One disturbance of a wake as the GPU reads it (8 floats). Chains are stored oldest
// first; `linked` says the next point continues the chain (a segment joins them).
struct GpuWakePoint {
    vec4 position_age;  // xy: world xz relative to the render origin (m), z: age (s), w: strength (m^4/s^2; a lone point's impulse, m^4/s)
    vec4 shape;         // x: source size (m), y: steepness Q, z: turbulence (0..1, when made), w: linked (1) or last of its chain (0)
};

// One Gerstner wave. Phases are not stored: the host reduces them in double
// and passes them per phase cell (see GpuQueryPoint.cell) or per frame.
struct GpuWave {
    vec4 dir_k_amp;      // x: D.x, y: D.z, z: k (rad/m), w: amplitude (m)
    vec4 steep_omega;    // x: steepness Q, y: omega (rad/s), z: phase at the render origin (rad, per frame);
                         // w: 1 where the water draws the wave, 0 where the tier leaves it to the
                         // shading's slope variance (QualitySettings::waves_drawn); 1 for queries
    vec4 lag_turn;       // x, y: sin and cos of omega kFoamLagStep (the lagged sums' turn per lag); zw: unused
};

// One river wave in the river's channel frame. Its phase at a point is
// k_s s + k_n n + omega_phase.y, with (s, n) the channel coordinates there and the
// offset (phase minus the Doppler-shifted omega t) reduced in double on the host.
struct GpuRiverWave {
    vec4 k_amp;        // x: k_s (rad/m, downstream), y: k_n (rad/m, left), z: amplitude (m), w: steepness Q
    vec4 omega_phase;  // x: omega (rad/s), y: phase offset at the time (rad, in [-pi, pi)), zw: unused
};

// A query point, relative to the origin of its phase cell.
struct GpuQueryPoint {
    vec2 local;          // m, point minus its cell origin
    uint cell;           // row in the base-phase table
    uint pad;
};

// Result of a GPU query, the CPU SurfacePoint's fields in float.
struct GpuQueryResult {
    vec4 height_normal;  // x: eta (m, without the water level), yzw: unit normal
    vec4 velocity_jac;   // xyz: particle velocity (m/s), w: Jacobian determinant
    vec4 disp_iter;      // xy: horizontal displacement (m), z: Newton evaluations, w: 1 if converged
    vec4 shore;          // x: depth (m), y: shore distance (m), both at the query point; z: breaking at the rest position;
                         // w: river mode: the still river surface at the point, m above the mouth level
    vec4 flow;           // xy: the river current at the query point (m/s, 0 outside rivers); zw: its flow-detail slope
    vec4 wake;           // x: the wakes' share of eta (m), y: their foam, at the rest position; zw: unused
    vec4 lagged_jac;     // the Jacobian determinant of the waves at the rest position, l * kFoamLagStep s ago (l = 1..4)
};

// Descriptor bindings and push constants, declared once: the shaders name them in
// their layout qualifiers, and the C++ builds layouts, pool sizes and descriptor writes
// from the same names (render_pipelines.cpp, gpu_query.cpp). A new binding is one name
// here, one row in its set's table there, and its use in a shader.
#ifdef __cplusplus
#define TW_BINDINGS(name) enum name : uint {
#define TW_BINDINGS_END() }
#else
#define TW_BINDINGS(name) const uint
#define TW_BINDINGS_END()
#endif

// Set 0 of the render pipelines (frame.glsl, water_draw.glsl).
TW_CONST uint kFrameSet = 0u;
TW_BINDINGS(FrameBinding)
    eFrameConstants = 0u,     // uniform GpuFrame
    eFrameWaves = 1u,         // GpuWave[] of every draw
    eFrameTerrainHeight = 2u, // sampler2D, R16 unorm heights (GpuFrame.terrain_heights decodes them)
    eFrameSceneColor = 3u,    // sampler2D, the opaque scene's colour copy
    eFrameSceneDepth = 4u,    // sampler2D, its depth copy
    eFrameShoreWaves = 5u,    // vec4[] shore fields of the wave runs, per slot, wave and texel
    eFrameShoreShared = 6u,   // vec4[] shore fields per slot and texel
    eFrameBodyDraws = 7u,     // GpuBodyDraw[]
    eFrameRiverTexels = 8u,   // float[] river query texels
    eFrameRiverChannel = 9u,  // vec4[] river channel coordinates and current
    eFrameBodyMasks = 10u,    // float[] river texel kinds, lake masks
    eFrameRiverWaves = 11u,   // GpuRiverWave[]
    eFramePatchList = 12u,    // uint[] water patches
    eFrameWakePoints = 13u,   // wake blocks, then GpuWakePoint[]
    eFrameShorePages = 14u,   // uint[] shore slot per tile, grid after grid
    eFrameShoreLayers = 15u,  // GpuShoreLayer[], model after model
    eFrameSkyTable = 16u,     // sampler2D, the sky table (kSkyTableSide, sky.glsl)
    eFrameFoamNoise = 17u,    // sampler2D (repeating), the foam's noise (kFoamNoiseSide, foam_noise.frag)
    eFrameClipTextures = 18u, // float[] the frame's distance textures' samples, texture after texture (clip_volumes.glsl)
    eFrameBindingCount = 19u
TW_BINDINGS_END();

// Specialization constants of the water's shaders: what the quality tier
// (QualitySettings) chooses at pipeline creation (water_quality.glsl).
TW_CONST uint kSpecFoamLags = 0u;             // uint: lags of the crests' compression the foam shows (0..kFoamLags)
TW_CONST uint kSpecReflectionFacets = 1u;     // uint: facets the reflection averages over (1 or 4)
TW_CONST uint kSpecReflectionSteps = 2u;      // int: steps of the reflection's march
TW_CONST uint kSpecReflectionStepGrowth = 3u; // float: each step that many times the last
TW_CONST uint kSpecCaustics = 4u;             // bool: caustics on the ground under water (terrain.frag)
TW_CONST uint kSpecSceneReflection = 5u;      // bool: the water reflects the opaque scene, not only the sky
TW_CONST uint kSpecWavesCapped = 6u;          // bool: the tier draws only some of a body's waves (GpuWave.steep_omega.w)

// The push constants of the graphics pipelines: one range over every stage. Bytes 0-15
// hold the terrain mesh's origin (vec4, relative to O); bytes 16-31 a float's paint
// (vec4, float.frag) or the water draw's index (uint, water_draw.glsl).
TW_CONST uint kPushMeshOrigin = 0u;
TW_CONST uint kPushFloatPaint = 16u;
TW_CONST uint kPushDrawIndex = 16u;
TW_CONST uint kPushConstantBytes = 32u;

// Set 0 of the GPU query pipeline (query.comp); its push constant is GpuQueryParams.
TW_CONST uint kQuerySet = 0u;
TW_BINDINGS(QueryBinding)
    eQueryWaves = 0u,         // GpuWave[]
    eQueryBasePhases = 1u,    // float[cell * wave_count + i]
    eQueryPoints = 2u,        // GpuQueryPoint[]
    eQueryResults = 3u,       // GpuQueryResult[]
    eQueryShoreWaves = 4u,    // a run's vec4[(slot * run waves + wave) * kShoreSlotTexels + texel]
    eQueryShoreShared = 5u,   // vec4[slot * kShoreSlotTexels + texel]
    eQueryCellOrigins = 6u,   // vec2[]
    eQueryRiverTexels = 7u,   // float[]
    eQueryRiverChannel = 8u,  // vec4[]
    eQueryRiverWaves = 9u,    // GpuRiverWave[]
    eQueryWakePoints = 10u,   // wake blocks, then GpuWakePoint[]
    eQueryShorePages = 11u,   // uint[tile]: its slot, grid after grid
    eQueryShoreLayers = 12u,  // GpuShoreLayer[]: the model's runs of waves
    eQueryBindingCount = 13u
TW_BINDINGS_END();
#undef TW_BINDINGS
#undef TW_BINDINGS_END

// Debug views (GpuFrame.params.w).
TW_CONST uint kViewShaded = 0u;
TW_CONST uint kViewHeight = 1u;
TW_CONST uint kViewNormals = 2u;
TW_CONST uint kViewJacobian = 3u;
TW_CONST uint kViewDepth = 4u;
TW_CONST uint kViewLod = 5u;
TW_CONST uint kViewWireframe = 6u;
TW_CONST uint kViewShore = 7u;
TW_CONST uint kViewBreaking = 8u;
TW_CONST uint kViewFlow = 9u;
TW_CONST uint kViewWake = 10u;
TW_CONST uint kViewFoam = 11u;
TW_CONST uint kViewCount = 12u;  // tidewater::render::DebugView holds the same order (static_assert in renderer.cpp)

// Clip volumes (tidewater/clip_volume.hpp, shaders/clip_volumes.glsl): where the water is
// removed, at most kMaxClipVolumes a frame, whose convex ones share kMaxClipPlanes planes.
TW_CONST uint kMaxClipVolumes = 32u;
TW_CONST uint kMaxClipPlanes = 96u;
TW_CONST uint kMaxClipPlanesPerVolume = 24u;  // tidewater::ClipVolume::kMaxPlanes
TW_CONST uint kClipBox = 0u;
TW_CONST uint kClipSphere = 1u;
TW_CONST uint kClipCapsule = 2u;
TW_CONST uint kClipConvex = 3u;
TW_CONST uint kClipTexture = 4u;  // a distance texture: two clip_planes (half extents and first sample; samples a side)
TW_CONST uint kMaxClipTextureSamples = 1u << 22;  // a frame's distance textures' samples (floats, eFrameClipTextures)
struct GpuClipVolume {
    vec4 center;  // xyz: centre relative to O (m); w: shape (kClip*)
    vec4 axis_x;  // xyz: the volume's x axis (world, unit); w: a box's half extent along it, the radius, or a
                  // convex volume's first plane in GpuFrame.clip_planes
    vec4 axis_y;  // xyz: its y axis; w: a box's half extent, a capsule's half length, or a convex volume's planes
    vec4 axis_z;  // xyz: its z axis; w: a box's half extent
};

// What a water draw covers (GpuBodyDraw.body.x).
TW_CONST uint kBodyOcean = 0u;
TW_CONST uint kBodyLake = 1u;
TW_CONST uint kBodyRiver = 2u;
// A river texel's kind in the body masks (tidewater::detail::RiverTexel).
TW_CONST float kRiverTexelNone = 0.0f;

// The sky (sky.glsl): the Preetham sky (runtime/render/src/sky_model.hpp) as the frame's
// constants hold it and as the sky table's pass takes it in push constants (kSkyTable*).
struct GpuSky {
    // A, B, C, D of the Perez function for luminance Y and chromaticity x, y; their E; the
    // zenith values over F(0, theta_s) with Y divided by the zenith luminance (the
    // exposure's reference).
    vec4 Y;
    vec4 x;
    vec4 y;
    vec4 e;        // xyz: E for Y, x, y; w: exposure (per zenith luminance)
    vec4 zenith;   // xyz: zenith Y (relative, 1) / F(0, theta_s), x / F, y / F; w: saturation of the display look
    vec4 balance;  // xyz: white-balance gains on linear sRGB; w: unused
    vec4 sun;      // xyz: unit direction toward the sun; w: intensity
};
// The sky table (sky.glsl sky_table_uv): the sky without the sun's disc over the upper
// hemisphere, projected stereographically onto a square of this many texels a side, in
// this format; refreshed by its own pass from GpuSky in push constants.
TW_CONST uint kSkyTableSide = 256u;
// The foam's noise table (foam_noise.frag, foam_cover.glsl): four channels of gradient
// noise that tile every kFoamNoiseCells lattice cells, kFoamNoiseSide texels a side.
TW_CONST uint kFoamNoiseCells = 32u;
TW_CONST uint kFoamNoiseSide = 256u;

// Per-frame constants. Positions are relative to the render origin O (the
// camera snapped to the phase-cell grid, in double on the host), so float
// keeps millimetres anywhere in the world; y is not shifted.
struct GpuFrame {
    mat4 view_proj;          // world (relative to O) to clip
    mat4 inv_view_proj;
    vec4 camera;             // xyz: camera position relative to O; w: ripple/caustic time, s (reduced)
    vec4 sun;                // xyz: unit direction toward the sun; w: intensity
    vec4 params;             // x: water level (m); y: wave count; z: projection scale, pixels per metre across the
                             // view at 1 m from the camera (height / (2 tan(fov_y / 2))); w: debug view
    vec4 terrain_rect;       // xy: corner of the terrain height texture relative to O (m); zw: its size (m)
    vec4 terrain_heights;    // x: the highest ground (m); y: the height of texel value 0 (m); z: metres per unit
                             // texel value; w: the seabed the terrain fades to beyond its edge (m)
    vec4 terrain_lod;        // x: how far beyond its outermost texel centres the terrain fades to the seabed
                             // (m; 0: the edge extends); y, z: texel size along x, z (m); w: the lowest ground (m)
    vec4 viewport;           // xy: the view's size (px); zw: 1 / size
    vec4 view_corner;        // xy: the view's top-left corner in the host's targets (px, FrameTargets::offset); zw: unused
    vec4 options;            // x: has scene copy (0/1); y: the target wants linear colour (sRGB or float formats, 0/1);
                             // z: the swash's run-up above the level (m); w: its angular frequency (rad/s)
    vec4 water_patch;        // x: patch size (m); y: patches per side; zw: grid corner relative to O (m)
    vec4 origin_mod;         // xy: O mod 2048 m (caustics, foam grain); zw: unused
    vec4 water_density;      // x: water shading footprints per pixel side: 1, or sqrt(samples) where the water
                             // shades every sample of a multisampled target; y: the water's vertex spacing on
                             // screen, in footprints (QualitySettings::water_pixels_per_vertex); z: 1 where the
                             // scene copy's depth is each pixel's (single-sample targets), else 0; w: how much
                             // further apart the vertices may be along the view than across it
                             // (QualitySettings::water_max_foreshortening)
    vec4 underwater;         // x: 1 where some of the near plane is under a body's surface (query_submersion),
                             // else 0; y: how far under it the camera is, m (0 above it); z: the surface's height
                             // over the camera (world y, m); w: unused
    vec4 near_plane_depths;  // how far under the surface each corner of the near plane lies (m, > 0 under): the
                             // image's top left, top right, bottom right, bottom left (water_medium.glsl)
    vec4 water_extinction;   // xyz: the extinction (1/m, red, green, blue) of the body over the camera, the ocean's
                             // when it is above every surface (tidewater::optics_of); w: unused
    vec4 water_color;        // xyz: that body's deep-water colour (tidewater::WaterOptics::color); w: unused
    GpuSky sky;
    vec4 wakes;              // x: wake points (GpuWakePoint); y: how many of the first carry turbulence; z: boxes; w: unused
    vec4 wake_boxes[kMaxWakeBoxes];  // xy: min, zw: max (relative to O) of where the wakes can be felt
    vec4 clips;                      // x: clip volumes in clip_volumes; yzw: unused
    GpuClipVolume clip_volumes[kMaxClipVolumes];
    vec4 clip_planes[kMaxClipPlanes];  // convex clip volumes' planes in their own frames: xyz outward normal, w offset;
                                       // a distance texture's head (kClipTexture)
};

// A body's flow-mapped detail settings for one frame (tidewater::FlowDetailSpec with
// its FlowDetailClock).
struct GpuFlowDetail {
    vec4 params;  // x: tiling (1/m), y: speed, z: strength (0 = off), w: offset
    vec4 clock;   // x: period (s), y: frac(t / period), zw: jump per cycle (noise cells)
    vec4 jump;    // xy: floor(t / period) * jump mod kFlowNoisePeriod (cells); z: seed; w: unused
    vec4 origin;  // xy: world xz of the positions' zero, reduced modulo kFlowNoisePeriod / (tiling * kFlowOffsetScale) m
};

// What one GPU query dispatch solves. Still water (a body's waves, with its shore
// fields when shore_resolution > 0) is evaluated at cell_origin + local; in river mode
// (river_nx > 0) cell origins are relative to the river
// grid's corner, the river's water is evaluated there, and the still water's waves
// join it with the river's still weight when `still` is 1 (a mouth or plume).
// One water draw of a frame: the ocean, a lake or a river. Counts and indices are
// stored as floats (exact below 2^24).
struct GpuBodyDraw {
    vec4 patch_grid;  // xy: patch grid corner relative to O (m); z: patch size (m); w: patches per row, 0: patches from the patch list
    vec4 body;        // x: kind (kBodyOcean, kBodyLake, kBodyRiver); y: rest level (m; a river's mouth level); z: first wave; w: wave count (a river's still water)
    vec4 grid;        // xy: the river's or lake's grid corner relative to O (m); z: texel (m); w: its first texel in the river fields or body masks.
                      // An ocean ring: xy the corner and z the side of the square it leaves to the draw inside (m)
    vec4 river;       // x, y: grid texels along x and z; z: first river wave; w: river wave count
    vec4 extra;       // x: whitecap Jacobian J* (crest_foam); y: first patch in the patch list;
                      // z: highest rest surface above the level (m); w: largest wave displacement (m)
    vec4 rivers;      // x: first river draw; y: river draw count (every draw skips the rivers' texels but a river's own);
                      // z: first lake draw (the lakes' draws run to x); w: a river's bank ramp depth (m; see kRiverBankBreakerIndex)
    GpuFlowDetail flow;  // a river's flow-mapped detail (strength 0: none)
    // The still water's shore model (the ocean's, a lake's, or the one a river runs into):
    vec4 shore;       // xy: its shared grid's corner relative to O (m); z: texel (m); w: resolution (0 = none)
    uvec4 shore_base; // x: its first record (the shared fields') in shore_layers[]; yzw: 0
    // The ocean's or a lake's ripples (tidewater::RippleField):
    vec4 ripple;        // x: amplitude (m, 0 = none); y: 1 / wavelength (1/m); z: octaves; w: seed (as float)
    vec4 ripple_offset; // xy: drift (lattice units, reduced mod 256); zw: O mod 256 ripple wavelengths (m)
    vec4 lod;           // x: the mean square slope of its waves (WaveSet::mean_square_slope; a river's: its own and its still water's)
    vec4 optics_extinction;  // xyz: its water's extinction (1/m, red, green, blue; tidewater::optics_of); w: unused
    vec4 optics_color;       // xyz: its deep-water colour (tidewater::WaterOptics::color); w: unused
};

struct GpuQueryParams {
    uint wave_count;        // the still water's waves
    uint point_count;
    float max_offset;       // sum(Q*A) of every wave that can move the point: how far a rest position can lie from it, m
    uint river_wave_count;
    uint shore_resolution;  // texels per side of the shared shore fields; 0 = open water
    float shore_texel;      // m
    vec2 shore_offset;      // the shared shore grid's corner seen from the cell origins' zero, m (subtracted)
    uint river_nx, river_nz;  // the river grid; 0 = no river (plain still water)
    float river_texel;      // m
    float still;            // 1: the still water's waves join the river's (mouth, plume); 0: not
    GpuFlowDetail flow;     // the river preset's flow detail (strength 0: none)
    uint wake_count;        // wake points (still water only; 0: none)
    uint wake_turbulent;    // how many of the first carry turbulence
    float wake_radius;      // how far the wakes can move a particle sideways, m (widens the solve's radius)
    float river_bank_ramp;  // m: where the river's waves die out (see kRiverBankBreakerIndex)
};

// The shore fields (tidewater::ShoreWaves), as storage buffers read with the
// same bilinear weights as the CPU, slot after slot (kShoreSlotTexels texels each):
//   a wave run's, per slot, wave and texel: (phase residual rad, amplitude factor, wavevector x, z rad/m)
//   the shared, per slot and texel:         (depth m, breaking 0..1, steepness scale, shore distance m)
// Terrain level of detail (CDLOD, Strugar 2009): each node the CPU selects draws one
// patch of kTerrainPatchQuads x kTerrainPatchQuads quads; as its distance (terrain_lod.glsl)
// nears the end of its level's range, its odd vertices slide onto the next level's grid.
TW_CONST uint kTerrainPatchQuads = 32u;
struct GpuTerrainNode {
    vec4 rect;   // xy: corner relative to O (m); z: side along x (m); w: level (0 the finest)
    vec4 morph;  // x: distance where the morph starts (m); y: 1 / the distance it takes (1/m);
                 // z: the camera's height above or below the ground's band, squared (m^2); w: side along z (m)
};

#ifdef __cplusplus
static_assert(sizeof(GpuWave) == 48);
static_assert(sizeof(GpuWakePoint) == 32);
static_assert(sizeof(GpuQueryPoint) == 16);
static_assert(sizeof(GpuRiverWave) == 32);
static_assert(sizeof(GpuQueryResult) == 112);
static_assert(kFoamLags == 4u);  // the shaders' vec4s
static_assert(sizeof(GpuQueryParams) == 128);
static_assert(sizeof(GpuFlowDetail) == 64);
static_assert(sizeof(GpuSky) == 112);  // within the 128 bytes of push constants every device has
static_assert(sizeof(GpuBodyDraw) == 13 * 16 + 64);
static_assert(sizeof(GpuClipVolume) == 64);
static_assert(sizeof(GpuFrame) ==
              2 * 64 + 18 * 16 + sizeof(GpuSky) + 16 * kMaxWakeBoxes + sizeof(GpuClipVolume) * kMaxClipVolumes +
                  16 * kMaxClipPlanes);
static_assert(sizeof(GpuTerrainNode) == 32);
}  // namespace tidewater::gpu
#undef TW_CONST
#endif

#endif  // TIDEWATER_HOST_DEVICE_H
