// A baked scene as Tidewater::core knows it: whether a scene is ready (Scene::baked),
// loading the saved bake a scene names, and the step that puts a bake into a new scene.
#include "tidewater/baked_scene.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>

#include "tidewater/detail/bodies_bake_folder.hpp"
#include "tidewater/detail/scene_bake_parts.hpp"
#include "tidewater/detail/shore_bake_folder.hpp"
#include "tidewater/detail/shore_waves.hpp"
#include "tidewater/detail/water_bodies.hpp"

namespace tidewater {

namespace {

/// The lakes and rivers as baked, where what shapes their water is concerned.
bool same_bodies(const Scene& scene, const SceneBake& bake) {
    if (scene.lakes.size() != bake.lakes.size() || scene.rivers.size() != bake.rivers.size()) return false;
    for (std::size_t l = 0; l < scene.lakes.size(); ++l) {
        const SceneLake &a = scene.lakes[l], &b = bake.lakes[l];
        if (a.name != b.name || a.at != b.at || a.body.level() != b.body.level() ||
            a.body.waves().waves().size() != b.body.waves().waves().size())
            return false;
    }
    for (std::size_t r = 0; r < scene.rivers.size(); ++r) {
        const SceneRiver &a = scene.rivers[r], &b = bake.rivers[r];
        if (a.name != b.name || a.path != b.path || a.width != b.width || a.discharge != b.discharge ||
            a.manning != b.manning || a.carve != b.carve)
            return false;
    }
    return true;
}

}  // namespace

Error detail::in_shore(const Scene& scene, Error e) {
    e.message = fmt::format("{}: /shore: {}", scene_label(scene), e.message);
    return e;
}

Result<std::shared_ptr<const Scene>> detail::finish_scene_bake(const Scene& scene, std::shared_ptr<SceneBake> bake,
                                                               std::chrono::steady_clock::time_point start) {
    auto baked = std::make_shared<Scene>(scene);
    for (std::size_t l = 0; l < bake->lake_shores.size(); ++l) {
        const auto& model = bake->lake_shores[l];
        auto lake = scene.lakes[l].body.with_shore(model && !model->trivial() ? model : nullptr);
        if (!lake) return lake.error();
        baked->lakes[l].body = std::move(lake).value();
    }
    bake->lakes = scene.lakes;
    bake->rivers = scene.rivers;
    // An all-deep model changes nothing: the ocean carries none and queries skip the shore.
    std::shared_ptr<const ShoreWaves> felt =
        bake->ocean_shore && !bake->ocean_shore->trivial() ? bake->ocean_shore : nullptr;
    auto ocean = scene.ocean.with_shore(std::move(felt));
    if (!ocean) return in_shore(scene, ocean.error());
    baked->ocean = std::move(ocean).value();
    baked->terrain = bake->terrain;
    bake->water_level = scene.water_level();
    bake->shore = scene.shore;
    bake->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    baked->bake = std::move(bake);
    return std::shared_ptr<const Scene>(std::move(baked));
}

Result<std::shared_ptr<const Scene>> load_scene_bake(const Scene& scene, const BakeProgressCallback& progress) {
    const auto start = std::chrono::steady_clock::now();
    const bool has_bodies = !scene.lakes.empty() || !scene.rivers.empty();
    const bool shore = scene.shore.enabled && scene.has_ocean;
    const bool lake_shores = scene.shore.enabled && !scene.lakes.empty();
    const std::filesystem::path& folder = scene.shore.bake_folder;
    if (folder.empty()) {
        if (!has_bodies && !shore) return std::make_shared<const Scene>(scene);
        return detail::in_shore(scene,
                                Error{ErrorCode::invalid_argument,
                                      "names no saved bake (\"shore\": {\"bake\": folder}) to load: bake the scene "
                                      "with bake_scene (Tidewater::bake) or `tidewater bake`"});
    }
    try {
        // The scene as the bake was made: its shore settings the bake's (a scene naming a
        // saved bake gives none), so that an edit of it is baked at the same resolutions.
        Scene as_baked = scene;
        auto bake = std::make_shared<SceneBake>();
        bake->terrain = scene.terrain.with_cuts({});
        bake->loaded = has_bodies || shore;
        // The shares of the whole as bake_scene reports them: the bodies 1, the lakes'
        // shores 1, the ocean's shore 3.
        const double total = (has_bodies ? 1.0 : 0.0) + (lake_shores ? 1.0 : 0.0) + (shore ? 3.0 : 0.0);
        const double bodies_share = total > 0.0 ? ((has_bodies ? 1.0 : 0.0) + (lake_shores ? 1.0 : 0.0)) / total : 0.0;
        auto report = [&](double fraction) {
            if (progress) progress("loading", fraction);
        };
        report(0.0);
        if (has_bodies) {
            // The saved bake holds the lakes and rivers and their lakes' shores.
            detail::BodiesBakeOptions bodies_options;
            bodies_options.lake_resolution = scene.shore.resolution;
            auto loaded = load_bodies_bake(folder, scene, bodies_options, lake_shores);
            if (!loaded) return detail::in_shore(scene, loaded.error());
            bake->terrain = loaded->bodies.terrain;
            bake->bodies = std::make_shared<const detail::WaterBodiesBake>(std::move(loaded->bodies));
            if (lake_shores) bake->lake_shores = std::move(loaded->lake_shores);
            if (loaded->shore_settings) as_baked.shore = *loaded->shore_settings;
            report(bodies_share);
        } else if (std::filesystem::exists(folder / kBodiesSidecar)) {
            return detail::in_shore(
                scene,
                Error{ErrorCode::invalid_argument,
                      fmt::format("{}: the bake holds lakes or rivers the scene does not have; re-run tidewater bake",
                                  (folder / kBodiesSidecar).string())});
        }
        if (shore) {
            auto loaded = load_shore_bake(folder, scene.ocean.waves(), scene.water_level(), bake->terrain, nullptr,
                                          &as_baked.shore);
            if (!loaded) return detail::in_shore(scene, loaded.error());
            bake->ocean_shore = std::move(loaded).value();
        }
        report(1.0);
        return detail::finish_scene_bake(as_baked, std::move(bake), start);
    } catch (const std::exception& e) {
        return Error{ErrorCode::internal, fmt::format("{}: loading its bake failed: {}", scene_label(scene), e.what())};
    }
}

Status read_scene_bake_tiles(const Scene& scene) {
    if (!scene.bake) return {};
    if (const auto& ocean = scene.bake->ocean_shore)
        if (auto st = ocean->read_all(); !st) return st;
    for (const auto& lake : scene.bake->lake_shores)
        if (lake)
            if (auto st = lake->read_all(); !st) return st;
    return {};
}

bool Scene::baked() const {
    const bool has_bodies = !lakes.empty() || !rivers.empty();
    if (!has_bodies && !(shore.enabled && has_ocean)) return true;
    if (!bake || !(bake->terrain == terrain)) return false;
    if (has_bodies && (!bake->bodies || !same_bodies(*this, *bake))) return false;
    if (shore.enabled && !lakes.empty()) {
        if (bake->lake_shores.size() != lakes.size()) return false;
        for (std::size_t l = 0; l < lakes.size(); ++l) {
            const auto& model = bake->lake_shores[l];
            if (lakes[l].body.shore() != (model && !model->trivial() ? model : nullptr)) return false;
        }
    }
    if (!(shore.enabled && has_ocean)) return true;
    if (bake->water_level != water_level() || bake->shore.enabled != shore.enabled ||
        bake->shore.resolution != shore.resolution || bake->shore.breaking_index != shore.breaking_index ||
        bake->shore.diffraction != shore.diffraction || bake->shore.bake_folder != shore.bake_folder)
        return false;
    const auto& model = bake->ocean_shore;
    const bool felt = model && !model->trivial();
    return ocean.shore() == (felt ? model : nullptr);
}

}  // namespace tidewater
