// Baking a scene (bake_scene) and saving its bake (save_scene_bake); loading a saved
// bake is Tidewater::core's (baked_scene.cpp).
#include "tidewater/scene_bake.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <mutex>

#include "shore/shore_edit_region.hpp"
#include "tidewater/detail/atomic_folder.hpp"
#include "tidewater/detail/bodies_bake_write.hpp"
#include "tidewater/detail/scene_bake_parts.hpp"
#include "tidewater/detail/shore_bake.hpp"
#include "tidewater/detail/shore_bake_write.hpp"
#include "tidewater/detail/shore_land_edit.hpp"
#include "tidewater/detail/shore_water_edit.hpp"
#include "tidewater/detail/shore_waves_bake.hpp"
#include "tidewater/detail/tiled_shore.hpp"
#include "tidewater/detail/water_bodies_bake.hpp"

namespace tidewater {

namespace {

/// Forwards stage progress as a whole-bake fraction that never goes back.
class BakeProgress {
  public:
    explicit BakeProgress(const SceneBakeOptions& options) : options_(options) {}

    /// Reports `fraction` of a stage that spans [begin, end] of the whole bake.
    void report(std::string_view stage, double begin, double end, double fraction) {
        if (!options_.progress) return;
        const std::lock_guard<std::mutex> lock(lock_);
        last_ = std::max(last_, begin + (end - begin) * std::clamp(fraction, 0.0, 1.0));
        options_.progress(stage, last_);
    }

  private:
    const SceneBakeOptions& options_;
    std::mutex lock_;
    double last_ = 0.0;
};

/// Each lake's own shore model over its basin (the square round its extent, with a
/// margin of beach), at the scene's shore resolution.
bool same_waves(const WaveSet& a, const WaveSet& b) {
    return std::ranges::equal(a.waves(), b.waves());
}

/// The previous bake's model of lake l when nothing it depends on changed: the lake's
/// extent and level, its waves, the shore settings and the cuts under its basin.
std::shared_ptr<const ShoreWaves> unchanged_lake_shore(const Scene& scene, const detail::WaterBodiesBake& bodies,
                                                       std::size_t l, const Scene* previous) {
    if (!previous || !previous->bake || !previous->bake->bodies || l >= previous->bake->lake_shores.size() ||
        l >= previous->lakes.size())
        return nullptr;
    const SceneBake& old = *previous->bake;
    const detail::LakeBake &now = bodies.lakes[l], &then = old.bodies->lakes[l];
    if (!old.lake_shores[l] || old.shore.resolution != scene.shore.resolution ||
        old.shore.breaking_index != scene.shore.breaking_index ||
        old.shore.texels_per_wavelength != scene.shore.texels_per_wavelength ||
        old.shore.diffraction != scene.shore.diffraction || now.level != then.level || now.inside != then.inside ||
        !(now.grid.corner == then.grid.corner) || now.grid.nx != then.grid.nx ||
        !same_waves(scene.lakes[l].body.waves(), previous->lakes[l].body.waves()))
        return nullptr;
    const SquareRegion region = detail::lake_basin_region(now);
    detail::FieldGrid basin;
    basin.corner = region.center - glm::dvec2(region.half_size);
    basin.texel = 2.0 * region.half_size;
    basin.nx = basin.nz = 1;
    if (detail::cuts_under(bodies.terrain.cuts(), basin) != detail::cuts_under(old.bodies->terrain.cuts(), basin))
        return nullptr;
    return old.lake_shores[l];
}

Result<std::vector<std::shared_ptr<const ShoreWaves>>> bake_lake_shores(const Scene& scene,
                                                                        const detail::WaterBodiesBake& bodies,
                                                                        const SceneBakeOptions& options,
                                                                        const std::function<void(double)>& progress,
                                                                        std::size_t& reused) {
    std::vector<std::shared_ptr<const ShoreWaves>> models;
    const std::size_t count = bodies.lakes.size();
    for (std::size_t l = 0; l < count; ++l) {
        if (auto same = unchanged_lake_shore(scene, bodies, l, options.previous.get())) {
            models.push_back(std::move(same));
            ++reused;
            progress(static_cast<double>(l + 1) / static_cast<double>(count));
            continue;
        }
        ShoreWaveOptions model_options;
        model_options.resolution = scene.shore.resolution;
        model_options.region = detail::lake_basin_region(bodies.lakes[l]);
        model_options.breaking_index = scene.shore.breaking_index;
        model_options.diffraction = scene.shore.diffraction;
        model_options.texels_per_wavelength = scene.shore.texels_per_wavelength;
        model_options.threads = options.threads;
        model_options.cancel = options.cancel;
        model_options.progress = [&](double f) { progress((static_cast<double>(l) + f) / static_cast<double>(count)); };
        auto model =
            bake_shore_waves(scene.lakes[l].body.waves(), bodies.terrain, bodies.lakes[l].level, model_options);
        if (!model) {
            Error e = model.error();
            e.message = fmt::format("{}: /lakes/{}: its shore: {}", scene_label(scene), l, e.message);
            return e;
        }
        models.push_back(std::move(model).value());
    }
    return models;
}

/// Whether the previous bake's ocean shore model was baked with this scene's waves, level,
/// shore settings and distance field (over whatever terrain).
bool same_ocean_shore_inputs(const Scene& scene, int distance_resolution, const Scene* previous) {
    if (!previous || !previous->bake || !previous->bake->ocean_shore || !previous->bake->shoreline ||
        previous->bake->loaded)
        return false;
    const SceneBake& old = *previous->bake;
    return old.water_level == scene.water_level() && old.shore.resolution == scene.shore.resolution &&
           old.shore.breaking_index == scene.shore.breaking_index &&
           old.shore.texels_per_wavelength == scene.shore.texels_per_wavelength &&
           old.shore.diffraction == scene.shore.diffraction && old.distance_resolution == distance_resolution &&
           same_waves(previous->ocean.waves(), scene.ocean.waves());
}

/// The ocean's distance field, baked over `terrain` at `resolution`.
Result<std::shared_ptr<const ShoreField>> bake_shoreline(const Scene& scene, const Terrain& terrain,
                                                         const SceneBakeOptions& options, int resolution,
                                                         const std::function<void(double)>& progress) {
    BakeOptions shoreline_options;
    shoreline_options.resolution = resolution;
    shoreline_options.threads = options.threads;
    shoreline_options.cancel = options.cancel;
    shoreline_options.progress = progress;
    progress(0.0);
    auto shoreline = bake_shore(terrain, scene.water_level(), shoreline_options);
    if (!shoreline) return detail::in_shore(scene, shoreline.error());
    return std::make_shared<const ShoreField>(std::move(shoreline).value());
}

/// The lakes' and rivers' bake options for `scene` (no progress, no previous bake).
detail::BodiesBakeOptions bodies_options_for(const Scene& scene, const SceneBakeOptions& options) {
    detail::BodiesBakeOptions bodies;
    bodies.lake_resolution = scene.shore.resolution;
    bodies.cancel = options.cancel;
    return bodies;
}

/// The ocean's shore model and the distance field it samples: the previous bake's when
/// nothing it depends on changed (the edit was inland), else baked over `terrain` (on the
/// distance field `given`, where not null), with progress from `begin` to the end of the whole bake.
Status bake_ocean_shore(const Scene& scene, const Terrain& terrain, const SceneBakeOptions& options,
                        BakeProgress& progress, double begin, std::shared_ptr<const ShoreField> given,
                        SceneBake& bake) {
    if (!(scene.shore.enabled && scene.has_ocean)) return {};
    const int distance_resolution = options.distance_resolution != 0       ? options.distance_resolution
                                    : scene.shore.distance_resolution != 0 ? scene.shore.distance_resolution
                                                                           : scene.shore.resolution;
    if (given) {
        const double half = terrain.extent_half_size();
        if (given->resolution != distance_resolution || given->texel != 2.0 * half / distance_resolution ||
            given->corner != terrain.extent_center() - glm::dvec2(half))
            return detail::in_shore(scene, Error{ErrorCode::invalid_argument,
                                                 fmt::format("the distance field given ({0}x{0}) is not the one the "
                                                             "scene's terrain and distance resolution ({1}x{1}) make",
                                                             given->resolution, distance_resolution)});
    }
    // A distance field baked here for an edit that then bakes in full.
    std::shared_ptr<const ShoreField> baked_line;
    if (!given && same_ocean_shore_inputs(scene, distance_resolution, options.previous.get())) {
        const SceneBake& old = *options.previous->bake;
        if (old.terrain == terrain) {
            bake.ocean_shore = old.ocean_shore;
            bake.shoreline = old.shoreline;
            if (options.keep_marches) bake.ocean_marches = old.ocean_marches;
            bake.distance_resolution = distance_resolution;
            bake.reused.ocean_shore = true;
            progress.report("shore waves", begin, 1.0, 1.0);
            return {};
        }
        // A local re-bake taken: its model and distance field, and which kind it was.
        auto take = [&](auto& edit, bool SceneBake::Reused::*kind) {
            bake.ocean_shore = std::move(edit->model);
            bake.shoreline = std::move(edit->shoreline);
            bake.distance_resolution = distance_resolution;
            bake.reused.*kind = true;
            progress.report("shore waves", begin, 1.0, 1.0);
        };
        // An edit of dry land, away from the water: only the ground's height under it.
        const detail::HeightmapChange change = detail::heightmap_change(old.terrain, terrain);
        if (auto edit = detail::rebake_land_edit(change, old.terrain, terrain, scene.water_level(), old.shoreline,
                                                 old.ocean_shore)) {
            take(edit, &SceneBake::Reused::ocean_shore_land_edit);
            // Dry land only: the marches read the same depths.
            if (options.keep_marches) bake.ocean_marches = old.ocean_marches;
            return {};
        }
        // An edit of the seabed, under the water: the waves re-marched where it reaches; with
        // diffraction, each wave's parabolic march taken up again from what it kept.
        if (!scene.shore.diffraction || old.ocean_marches) {
            auto water_edit = [&](const std::shared_ptr<const ShoreField>& line) {
                return detail::rebake_water_edit(change, old.terrain, terrain, scene.water_level(),
                                                 scene.ocean.waves().waves(), scene.shore.breaking_index, old.shoreline,
                                                 old.ocean_shore, options.threads,
                                                 scene.shore.diffraction ? old.ocean_marches : nullptr, line);
            };
            auto edit = water_edit(nullptr);
            if (!edit && change && *change && distance_resolution == scene.shore.resolution &&
                old.shoreline->resolution == distance_resolution) {
                // The shoreline moved (or the edit reaches further): the distance field
                // updated where the edit reaches (or baked again in full), which a full
                // bake needs too, and the waves re-baked where the edit and the distances
                // it moved reach.
                auto updated = update_shore(*old.shoreline, terrain, scene.water_level(), **change, options.threads);
                if (!updated) return detail::in_shore(scene, updated.error());
                if (*updated) {
                    baked_line = std::make_shared<const ShoreField>(std::move(**updated));
                } else {
                    auto line = bake_shoreline(scene, terrain, options, distance_resolution, [&](double f) {
                        progress.report("shoreline", begin, begin + 0.3 * (1.0 - begin), f);
                    });
                    if (!line) return line.error();
                    baked_line = std::move(line).value();
                }
                edit = water_edit(baked_line);
            }
            if (edit) {
                take(edit, &SceneBake::Reused::ocean_shore_water_edit);
                if (options.keep_marches) bake.ocean_marches = std::move(edit->marches);
                return {};
            }
        }
    }
    // One shoreline bake serves the distance field and the shore model, which samples
    // it: it may be finer than the model's grid, never coarser.
    if (distance_resolution < scene.shore.resolution)
        return detail::in_shore(
            scene, Error{ErrorCode::invalid_argument,
                         fmt::format("the distance field ({0}x{0}) is coarser than the shore model's grid ({1}x{1}), "
                                     "which samples it: give a distance resolution of at least {1}",
                                     distance_resolution, scene.shore.resolution)});
    const double shoreline_share = begin + 0.3 * (1.0 - begin);
    std::shared_ptr<const ShoreField> shoreline = given ? std::move(given) : std::move(baked_line);
    if (!shoreline) {
        auto baked = bake_shoreline(scene, terrain, options, distance_resolution,
                                    [&](double f) { progress.report("shoreline", begin, shoreline_share, f); });
        if (!baked) return baked.error();
        shoreline = std::move(baked).value();
    }
    progress.report("shore waves", shoreline_share, 1.0, 0.0);

    ShoreWaveOptions model_options;
    model_options.resolution = scene.shore.resolution;
    model_options.breaking_index = scene.shore.breaking_index;
    model_options.diffraction = scene.shore.diffraction;
    model_options.texels_per_wavelength = scene.shore.texels_per_wavelength;
    model_options.threads = options.threads;
    model_options.cancel = options.cancel;
    model_options.progress = [&](double f) { progress.report("shore waves", shoreline_share, 1.0, f); };
    if (options.keep_marches) model_options.keep_marches = &bake.ocean_marches;
    auto model = bake_shore_waves(scene.ocean.waves(), terrain, scene.water_level(), model_options, shoreline.get());
    if (!model) return detail::in_shore(scene, model.error());
    bake.ocean_shore = std::move(model).value();
    bake.shoreline = std::move(shoreline);
    bake.distance_resolution = distance_resolution;
    return {};
}

/// bake_scene, on the ocean's distance field `given` where not null.
Result<std::shared_ptr<const Scene>> bake_scene_given(const Scene& scene, const SceneBakeOptions& options,
                                                      std::shared_ptr<const ShoreField> given) {
    const auto start = std::chrono::steady_clock::now();
    if (options.distance_resolution != 0 && (options.distance_resolution < 8 || options.distance_resolution > 8192))
        return Error{
            ErrorCode::invalid_argument,
            fmt::format("bake: distance_resolution {} is out of range (8 to 8192, or 0)", options.distance_resolution)};
    // A scene that names its saved bake is loaded, not baked.
    if (!scene.shore.bake_folder.empty()) return load_scene_bake(scene, options.progress);
    try {
        auto bake = std::make_shared<SceneBake>();
        BakeProgress progress(options);
        // Lakes and rivers first: a river carves the terrain the shore is baked over.
        Terrain terrain = scene.terrain.with_cuts({});
        const bool has_bodies = !scene.lakes.empty() || !scene.rivers.empty();
        const bool shore = scene.shore.enabled && scene.has_ocean;
        const bool lake_shores = scene.shore.enabled && !scene.lakes.empty();
        // Shares of the progress: the bodies 1, the lakes' shores 1, the ocean's shore 3.
        const double total = (has_bodies ? 1.0 : 0.0) + (lake_shores ? 1.0 : 0.0) + (shore ? 3.0 : 0.0);
        const double bodies_end = total > 0.0 && has_bodies ? 1.0 / total : 0.0;
        const double bodies_share = total > 0.0 && lake_shores ? bodies_end + 1.0 / total : bodies_end;
        if (has_bodies) {
            progress.report("water bodies", 0.0, bodies_end, 0.0);
            detail::BodiesBakeOptions bodies_options = bodies_options_for(scene, options);
            bodies_options.progress = [&](double f) { progress.report("water bodies", 0.0, bodies_end, f); };
            const Scene* previous = options.previous.get();
            if (previous && previous->bake && previous->bake->bodies)
                bodies_options.previous = previous->bake->bodies.get();
            auto bodies = detail::bake_water_bodies(scene, bodies_options);
            if (!bodies) return bodies.error();
            bake->reused.rivers = bodies->reused_rivers;
            terrain = bodies->terrain;
            bake->bodies = std::make_shared<const detail::WaterBodiesBake>(std::move(bodies).value());
        }
        if (lake_shores) {
            progress.report("lake shores", bodies_end, bodies_share, 0.0);
            auto models = bake_lake_shores(
                scene, *bake->bodies, options,
                [&](double f) { progress.report("lake shores", bodies_end, bodies_share, f); },
                bake->reused.lake_shores);
            if (!models) return models.error();
            bake->lake_shores = std::move(models).value();
        }
        if (auto st = bake_ocean_shore(scene, terrain, options, progress, bodies_share, std::move(given), *bake); !st)
            return st.error();
        if (options.cancel.stop_requested())
            return Error{ErrorCode::cancelled, fmt::format("{}: the bake was cancelled", scene_label(scene))};
        bake->terrain = terrain;
        return detail::finish_scene_bake(scene, std::move(bake), start);
    } catch (const std::exception& e) {
        return Error{ErrorCode::internal, fmt::format("{}: the bake failed: {}", scene_label(scene), e.what())};
    }
}

}  // namespace

Result<std::shared_ptr<const Scene>> bake_scene(const Scene& scene, const SceneBakeOptions& options) {
    return bake_scene_given(scene, options, nullptr);
}

namespace tiled {

Result<Terrain> shore_terrain(const Scene& scene) {
    // As bake_scene: a river carves the terrain the shore is baked over.
    if (scene.lakes.empty() && scene.rivers.empty()) return scene.terrain.with_cuts({});
    auto bodies = detail::bake_water_bodies(scene, bodies_options_for(scene, {}));
    if (!bodies) return bodies.error();
    return bodies->terrain;
}

Result<std::shared_ptr<const Scene>> bake_scene_on_shoreline(const Scene& scene, const SceneBakeOptions& options,
                                                             std::shared_ptr<const ShoreField> shoreline) {
    if (!shoreline) return Error{ErrorCode::invalid_argument, "bake_scene_on_shoreline: no distance field given"};
    if (!scene.shore.bake_folder.empty() || !scene.shore.enabled || !scene.has_ocean)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: a distance field is given for an ocean shore the scene does not bake",
                                 scene_label(scene))};
    return bake_scene_given(scene, options, std::move(shoreline));
}

}  // namespace tiled

Status save_scene_bake(const std::filesystem::path& dir, const Scene& baked) {
    const bool ocean = baked.bake && baked.bake->ocean_shore;
    const bool bodies = baked.bake && baked.bake->bodies;
    if (!ocean && !bodies)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{} has no bake to save: {}", scene_label(baked),
                                 !baked.bake ? "pass it through bake_scene first"
                                             : "its shore is disabled and it has no lakes or rivers")};
    if (!baked.baked())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{} was edited after its bake: pass it through bake_scene again", scene_label(baked))};
    return detail::write_folder_atomically(dir, [&](const std::filesystem::path& temp) -> Status {
        if (ocean) {
            ShoreBakeContents contents;
            contents.model = baked.bake->ocean_shore.get();
            contents.waves = &baked.ocean.waves();
            contents.water_level = baked.water_level();
            contents.breaking_index = baked.shore.breaking_index;
            contents.texels_per_wavelength = baked.shore.texels_per_wavelength;
            contents.diffraction = baked.shore.diffraction;
            contents.scene_name = baked.name;
            contents.distance_field = baked.bake->shoreline.get();
            if (auto st = write_shore_bake_into(temp, contents); !st) return st;
        }
        if (bodies)
            if (auto st = write_bodies_bake_into(temp, baked); !st) return st;
        return {};
    });
}

}  // namespace tidewater
