// Loading saved shore bakes (the writer is Tidewater::bake's, shore_bake_write.cpp).
#include "tidewater/detail/shore_bake_folder.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "shore/shore_tile_files.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/bake_files.hpp"
#include "tidewater/detail/image_io.hpp"
#include "tidewater/detail/json_reader.hpp"
#include "tidewater/detail/parallel.hpp"
#include "tidewater/detail/shore_settings_limits.hpp"

namespace tidewater {

namespace {

namespace fs = std::filesystem;
using detail::ObjectReader;

/// The depth row's tolerance: half its 16-bit step, and float rounding.
double depth_tolerance(double step) {
    return 0.51 * step + 1e-3;
}

/// One layer's tiles (`at`: /model/tiles, or /model/runs/R/tiles): which are stored, each
/// row's encoding, and a reader of the stored tiles' PNGs in tiles/`layer`/ (slots in tile
/// order, after the open-sea and dry-land ones), read on demand; each file must be there.
/// `waves` and `first`: the layer's run of waves (0 waves: the shared layer, whose depths
/// are checked against `depth_check`, given then, as they are read; its tolerance is set here).
Result<ShoreTiles> read_tiles(const std::shared_ptr<const OpenBakeFolder>& folder, const ObjectReader& owner,
                              const std::string& at, int n, const std::string& layer, std::size_t first,
                              std::size_t waves, ShoreDepthCheck* depth_check) {
    if (!owner.has("tiles")) return owner.error("tiles", "is missing");
    auto tiles = ObjectReader::open(owner.at("tiles"), owner.source(), at);
    if (!tiles) return tiles.error();
    std::int64_t tile_texels = 0, per_side = 0;
    if (auto st = tiles->integer("tile_texels", tile_texels, 1, 4096, true); !st) return st.error();
    if (tile_texels != ShoreTiles::kTile)
        return tiles->error("tile_texels", fmt::format("is {}, this version reads tiles of {}: re-run tidewater bake",
                                                       tile_texels, ShoreTiles::kTile));
    const int m = (n + ShoreTiles::kTile - 1) / ShoreTiles::kTile;
    if (auto st = tiles->integer("tiles_per_side", per_side, m, m, true); !st) return st.error();
    std::string kinds;
    if (auto st = tiles->string("kinds", kinds, true); !st) return st.error();
    const std::size_t count = static_cast<std::size_t>(m) * static_cast<std::size_t>(m);
    if (kinds.size() != count)
        return tiles->error("kinds", fmt::format("has {} tiles, expected {}x{}", kinds.size(), m, m));
    const std::size_t row_count = waves > 0 ? 4 * waves : kShoreSharedRows;
    if (!tiles->has("rows") || !tiles->at("rows").is_array() || tiles->at("rows").size() != row_count)
        return tiles->error("rows", waves > 0 ? fmt::format("expected {} rows (4 per wave)", row_count)
                                              : fmt::format("expected {} shared rows", row_count));
    std::vector<detail::FieldEncoding> rows(row_count);
    for (std::size_t r = 0; r < rows.size(); ++r) {
        auto row = ObjectReader::open(tiles->at("rows")[r], tiles->source(), fmt::format("{}/rows/{}", at, r));
        if (!row) return row.error();
        const auto [field, local_wave, unit] = shore_row_name(r, waves);  // the unit is the writer's, not checked
        const std::int64_t wave = local_wave >= 0 ? static_cast<std::int64_t>(first) + local_wave : -1;
        std::string name;
        std::int64_t row_wave = -1;
        if (auto st = row->string("field", name, true); !st) return st.error();
        if (wave >= 0)
            if (auto st = row->integer("wave", row_wave, 0, 1 << 20, true); !st) return st.error();
        if (name != field || row_wave != wave)
            return row->error("field", fmt::format("expected {}{}", field,
                                                   wave >= 0 ? fmt::format(" of wave {}", wave) : std::string()));
        double step = 0.0, zero = 0.0;
        if (auto st = row->number("step", step, true); !st) return st.error();
        if (auto st = row->number("zero_pixel", zero, true); !st) return st.error();
        if (!(step > 0.0) || !std::isfinite(step)) return row->error("step", "must be a finite number > 0");
        if (zero != std::floor(zero) || std::abs(zero) > 1e15) return row->error("zero_pixel", "must be an integer");
        rows[r].step = step;
        rows[r].zero = static_cast<std::int64_t>(zero);
    }
    if (depth_check) depth_check->tolerance = depth_tolerance(rows[0].step);
    ShoreTiles t = ShoreTiles::open_grid(n, row_count);
    std::vector<std::size_t> stored;
    for (std::size_t k = 0; k < count; ++k) {
        if (kinds[k] == 'o') continue;
        if (kinds[k] == 'd') {
            t.pages[k] = gpu::kShoreDrySlot;
        } else if (kinds[k] == 's') {
            t.pages[k] = static_cast<std::uint32_t>(gpu::kShoreFirstStoredSlot + stored.size());
            stored.push_back(k);
        } else {
            return tiles->error(
                "kinds",
                fmt::format("tile {} is '{}': expected o (open sea), d (dry land) or s (stored)", k, kinds[k]));
        }
    }
    const std::size_t slot_count = gpu::kShoreFirstStoredSlot + stored.size();
    auto files =
        std::make_unique<ShoreTileFiles>(folder, layer, n, std::move(stored), std::move(rows),
                                         depth_check ? std::optional<ShoreDepthCheck>(*depth_check) : std::nullopt);
    if (auto st = files->check_files(); !st) return st.error();
    // The constant slots are written by ShoreWaves::from_tiles; the stored ones are read on demand.
    t.slots.assign(slot_count, nullptr);
    for (std::size_t s = 0; s < gpu::kShoreFirstStoredSlot; ++s)
        t.slots[s] = std::make_shared<float[]>(t.slot_floats());
    t.lazy = std::make_shared<const LazyShoreSlots>(std::move(files), slot_count, t.slot_floats());
    return t;
}

/// A layer's grid: resolution, texel_m and corner_m of `reader`.
Result<ShoreGrid> read_grid(const ObjectReader& reader) {
    ShoreGrid g;
    std::int64_t n = 0;
    if (auto st = reader.integer("resolution", n, 2, 65536, true); !st) return st.error();
    g.resolution = static_cast<int>(n);
    if (auto st = reader.number("texel_m", g.texel, true); !st) return st.error();
    if (!(g.texel > 0.0) || !std::isfinite(g.texel)) return reader.error("texel_m", "must be a finite number > 0");
    if (!reader.has("corner_m") || !reader.at("corner_m").is_array() || reader.at("corner_m").size() != 2 ||
        !reader.at("corner_m")[0].is_number() || !reader.at("corner_m")[1].is_number())
        return reader.error("corner_m", "expected [x, z] in metres");
    g.corner = {reader.at("corner_m")[0].get<double>(), reader.at("corner_m")[1].get<double>()};
    if (!std::isfinite(g.corner.x) || !std::isfinite(g.corner.y)) return reader.error("corner_m", "must be finite");
    return g;
}

/// The runs of waves of /model/runs: each one's grid and tiles, covering `waves` in order.
Result<std::vector<ShoreWaveLayer>> read_runs(const std::shared_ptr<const OpenBakeFolder>& folder,
                                              const ObjectReader& model, std::size_t waves) {
    if (!model.has("runs") || !model.at("runs").is_array()) return model.error("runs", "expected an array");
    const auto& list = model.at("runs");
    if (list.size() > gpu::kShoreMaxLayers)
        return model.error("runs", fmt::format("has {} runs, at most {}", list.size(), gpu::kShoreMaxLayers));
    std::vector<ShoreWaveLayer> layers;
    std::size_t next = 0;
    for (std::size_t r = 0; r < list.size(); ++r) {
        const std::string at = fmt::format("/model/runs/{}", r);
        auto run = ObjectReader::open(list[r], model.source(), at);
        if (!run) return run.error();
        ShoreWaveLayer layer;
        std::int64_t first = 0, count = 0;
        if (auto st = run->integer("first_wave", first, static_cast<std::int64_t>(next),
                                   static_cast<std::int64_t>(next), true);
            !st)
            return st.error();
        if (auto st = run->integer("waves", count, 1, static_cast<std::int64_t>(waves - next), true); !st)
            return st.error();
        auto grid = read_grid(*run);
        if (!grid) return grid.error();
        layer.grid = *grid;
        layer.first = next;
        layer.count = static_cast<std::size_t>(count);
        auto tiles = read_tiles(folder, *run, at + "/tiles", layer.grid.resolution,
                                shore_layer_folder(static_cast<int>(r)), layer.first, layer.count, nullptr);
        if (!tiles) return tiles.error();
        layer.tiles = std::move(tiles).value();
        next += layer.count;
        layers.push_back(std::move(layer));
    }
    if (next != waves)
        return model.error("runs", fmt::format("hold {} waves, the bake {}: re-run tidewater bake", next, waves));
    return layers;
}

bool close(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

/// What the bake at `root` (its `model`) was made with, over `given` (see load_shore_bake).
Result<SceneShore> saved_settings(const ObjectReader& root, const ObjectReader& model, const ShoreGrid& grid,
                                  SceneShore given) {
    given.resolution = grid.resolution;
    given.distance_resolution = 0;
    if (root.has("distance_field")) {
        auto distance = ObjectReader::open(root.at("distance_field"), root.source(), "/distance_field");
        if (!distance) return distance.error();
        std::int64_t n = 0;
        if (auto st = distance->integer("resolution", n, 2, 65536, true); !st) return st.error();
        given.distance_resolution = static_cast<int>(n);
    }
    if (auto st = model.number("breaking_index", given.breaking_index); !st) return st.error();
    if (!(given.breaking_index >= detail::kLowestBreakingIndex &&
          given.breaking_index <= detail::kHighestBreakingIndex))
        return model.error("breaking_index", fmt::format("expected {} to {}", detail::kLowestBreakingIndex,
                                                         detail::kHighestBreakingIndex));
    if (auto st = model.number("texels_per_wavelength", given.texels_per_wavelength); !st) return st.error();
    if (!(given.texels_per_wavelength == 0.0 || (given.texels_per_wavelength >= detail::kFewestTexelsPerWavelength &&
                                                 given.texels_per_wavelength <= detail::kMostTexelsPerWavelength)))
        return model.error("texels_per_wavelength",
                           fmt::format("expected 0 or {} to {}", detail::kFewestTexelsPerWavelength,
                                       detail::kMostTexelsPerWavelength));
    if (model.has("diffraction")) {
        const nlohmann::json& d = model.at("diffraction");
        if (!d.is_boolean()) return model.error("diffraction", "expected true or false");
        given.diffraction = d.get<bool>();
    }
    return given;
}

}  // namespace

Result<std::shared_ptr<const ShoreWaves>> load_shore_bake(const fs::path& dir, const WaveSet& waves, double water_level,
                                                          const Terrain& terrain, const SquareRegion* region,
                                                          SceneShore* settings) {
    const fs::path sidecar_path = dir / kShoreSidecar;
    auto doc = detail::read_sidecar(sidecar_path, kShoreBakeFormatVersion);
    if (!doc) return doc.error();
    auto root = ObjectReader::open(*doc, sidecar_path.string(), "");
    if (!root) return root.error();
    double level = 0.0;
    if (auto st = root->number("water_level_m", level, true); !st) return st.error();
    if (!close(level, water_level))
        return root->error(
            "water_level_m",
            fmt::format("the bake was made at water level {} m, the scene's is {} m: re-run tidewater bake", level,
                        water_level));
    if (!root->has("model")) return root->error("model", "is missing");
    auto model = ObjectReader::open(root->at("model"), root->source(), "/model");
    if (!model) return model.error();

    auto grid = read_grid(*model);
    if (!grid) return grid.error();
    const ShoreGrid f = *grid;
    const std::int64_t n = f.resolution;
    // The grid covers the terrain's extent (or the region), as bake_scene's own bake would.
    const double half = region ? region->half_size : terrain.extent_half_size();
    const glm::dvec2 corner = (region ? region->center : terrain.extent_center()) - glm::dvec2(half);
    if (!close(f.texel * static_cast<double>(n), 2.0 * half) || !close(f.corner.x, corner.x) ||
        !close(f.corner.y, corner.y))
        return model->error(
            "corner_m",
            fmt::format("the bake covers {} m from ({}, {}), the terrain {} m from ({}, {}): "
                        "it was made for another terrain; re-run tidewater bake",
                        f.texel * static_cast<double>(n), f.corner.x, f.corner.y, 2.0 * half, corner.x, corner.y));

    // The waves must be the ones baked for: the fields depend on each one's frequency,
    // direction, amplitude (breaking) and steepness (the fold limit).
    if (!model->has("waves") || !model->at("waves").is_array()) return model->error("waves", "expected an array");
    const auto& list = model->at("waves");
    const auto set = waves.waves();
    if (list.size() != set.size())
        return model->error("waves", fmt::format("the bake has {} waves, the scene's ocean {}: re-run tidewater bake",
                                                 list.size(), set.size()));
    for (std::size_t i = 0; i < set.size(); ++i) {
        auto w = ObjectReader::open(list[i], model->source(), fmt::format("/model/waves/{}", i));
        if (!w) return w.error();
        double omega = 0.0, amplitude = 0.0, steepness = 0.0;
        if (auto st = w->number("omega_rad_s", omega, true); !st) return st.error();
        if (auto st = w->number("amplitude_m", amplitude, true); !st) return st.error();
        if (auto st = w->number("steepness", steepness, true); !st) return st.error();
        const auto& dir_json = w->has("direction") ? w->at("direction") : nlohmann::json();
        if (!dir_json.is_array() || dir_json.size() != 2 || !dir_json[0].is_number() || !dir_json[1].is_number())
            return w->error("direction", "expected [x, z]");
        const Wave& s = set[i];
        if (!close(omega, s.omega) || !close(amplitude, s.amplitude) || !close(steepness, s.steepness) ||
            !close(dir_json[0].get<double>(), s.dir_x) || !close(dir_json[1].get<double>(), s.dir_z))
            return w->error("", "differs from the scene's wave " + std::to_string(i) +
                                    ": the bake was made for other waves; re-run tidewater bake");
    }
    // The terrain must be the one baked over: its depth at every stored texel within the
    // encoding (checked as each stored tile is read), water under every open-sea tile and
    // land under every dry one (checked here).
    ShoreDepthCheck depth_check{terrain, f, water_level, 0.0};
    auto folder = OpenBakeFolder::open(dir);
    if (!folder) return folder.error();
    auto tiles = read_tiles(*folder, *model, "/model/tiles", f.resolution, shore_layer_folder(-1), 0, 0, &depth_check);
    if (!tiles) return tiles.error();
    auto runs = read_runs(*folder, *model, set.size());
    if (!runs) return runs.error();
    // Rows in parallel; the first row (in grid order) that does not fit is reported.
    std::vector<std::string> misfit(static_cast<std::size_t>(f.resolution));
    detail::parallel_for_each(misfit.size(), 0, [&](std::size_t row) {
        const int j = static_cast<int>(row);
        for (int i = 0; i < f.resolution; ++i) {
            const std::uint32_t page = tiles->page(i / ShoreTiles::kTile, j / ShoreTiles::kTile);
            if (page >= gpu::kShoreFirstStoredSlot) {
                i = (i / ShoreTiles::kTile + 1) * ShoreTiles::kTile - 1;  // the tile's reader checks it
                continue;
            }
            const glm::dvec2 p = f.corner + f.texel * glm::dvec2(i + 0.5, j + 0.5);
            misfit[row] = shore_depth_misfit(water_level - terrain.height_at(p), p, page, 0.0, depth_check.tolerance);
            if (!misfit[row].empty()) return;
        }
    });
    for (const std::string& m : misfit)
        if (!m.empty()) return model->error("tiles", m);
    auto made = ShoreWaves::from_tiles(f, std::move(tiles).value(), std::move(runs).value(), set);
    if (!made) {
        Error e = std::move(made).error();
        e.message = fmt::format("{}: {}", dir.string(), e.message);
        return e;
    }
    if (settings) {
        auto saved = saved_settings(*root, *model, f, *settings);
        if (!saved) return saved.error();
        *settings = std::move(saved).value();
    }
    return made;
}

std::string shore_tile_file(const std::string& layer, int ti, int tj) {
    return fmt::format("tiles/{}/x{:03}_z{:03}.png", layer, ti, tj);
}

std::string shore_layer_folder(int run) {
    return run < 0 ? std::string("shared") : fmt::format("run{}", run);
}

}  // namespace tidewater
