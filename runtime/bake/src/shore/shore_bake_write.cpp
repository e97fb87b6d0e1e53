// Writing saved shore bakes (the format is in docs/scene-format.md; shore_bake_folder.cpp
// loads them).
#include "tidewater/detail/shore_bake_write.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <tuple>

#include "tidewater/constants.hpp"
#include "tidewater/detail/atomic_folder.hpp"
#include "tidewater/detail/bake_files_write.hpp"
#include "tidewater/detail/image_write.hpp"
#include "tidewater/detail/parallel.hpp"

namespace tidewater {

namespace {

namespace fs = std::filesystem;

/// The distance field's PNGs as one GDAL raster (a VRT) for GIS tools: a band per field,
/// each with its PNG's scale and offset, so GDAL reads metres; georeferenced north-up with
/// x east and z south (Tidewater's axes), in local metres.
Status write_distance_vrt(const fs::path& temp, const ShoreField& d, const nlohmann::json& fields) {
    std::string vrt = fmt::format("<VRTDataset rasterXSize=\"{0}\" rasterYSize=\"{0}\">\n", d.resolution);
    // Image row j lies at z = corner + (j + 0.5) texel; GIS y (north) is -z.
    vrt += fmt::format("  <GeoTransform>{:.17g}, {:.17g}, 0, {:.17g}, 0, {:.17g}</GeoTransform>\n", d.corner.x, d.texel,
                       -d.corner.y, -d.texel);
    int band = 1;
    for (const char* name : {"signed_distance", "gradient_x", "gradient_z", "depth"}) {
        const nlohmann::json& f = fields.at(name);
        const double step = f.at("step").get<double>();
        const double zero = f.at("zero_pixel").get<double>();
        vrt += fmt::format(
            "  <VRTRasterBand dataType=\"UInt16\" band=\"{}\">\n    <Description>{}</Description>\n"
            "    <UnitType>{}</UnitType>\n    <Offset>{:.17g}</Offset>\n    <Scale>{:.17g}</Scale>\n"
            "    <SimpleSource>\n      <SourceFilename relativeToVRT=\"1\">{}</SourceFilename>\n"
            "      <SourceBand>1</SourceBand>\n    </SimpleSource>\n  </VRTRasterBand>\n",
            band++, name, f.at("unit").get<std::string>(), -zero * step, step, f.at("file").get<std::string>());
    }
    vrt += "</VRTDataset>\n";
    return detail::write_text_file(temp / kDistanceVrt, vrt);
}

/// One layer's tiles: which tiles are stored, and a 16-bit grey PNG per stored tile (in
/// tiles/`layer`/) whose row r holds field row r at the slot's texels, each row encoded over
/// its range across every stored tile. `first` and `waves`: the layer's run of waves (0
/// waves: the shared layer).
Result<nlohmann::json> write_tiles(const fs::path& temp, const ShoreTiles& t, const std::string& layer,
                                   std::size_t first, std::size_t waves) {
    const std::size_t rows = t.stride, slots = t.slot_count();
    std::vector<double> lo(rows, 0.0), hi(rows, 0.0);
    for (std::size_t slot = gpu::kShoreFirstStoredSlot; slot < slots; ++slot)
        for (std::size_t k = 0; k < ShoreTiles::kSlotTexels; ++k) {
            const float* v = t.slot(slot) + k * rows;
            const bool first_value = slot == gpu::kShoreFirstStoredSlot && k == 0;
            for (std::size_t r = 0; r < rows; ++r) {
                const double value = static_cast<double>(v[r]);
                lo[r] = first_value ? value : std::min(lo[r], value);
                hi[r] = first_value ? value : std::max(hi[r], value);
            }
        }
    std::vector<detail::FieldEncoding> encodings(rows);
    nlohmann::json row_list = nlohmann::json::array();
    for (std::size_t r = 0; r < rows; ++r) {
        encodings[r] = detail::FieldEncoding::covering(lo[r], hi[r]);
        const ShoreRowName name = shore_row_name(r, waves);
        nlohmann::json row = {
            {"field", name.field}, {"unit", name.unit}, {"zero_pixel", encodings[r].zero}, {"step", encodings[r].step}};
        if (name.wave >= 0) row["wave"] = first + static_cast<std::size_t>(name.wave);
        row_list.push_back(row);
    }
    std::string kinds;
    kinds.reserve(t.pages.size());
    for (std::uint32_t page : t.pages)
        kinds.push_back(page == gpu::kShoreOpenSlot ? 'o' : page == gpu::kShoreDrySlot ? 'd' : 's');
    std::error_code ec;
    const fs::path folder = temp / "tiles" / layer;
    fs::create_directories(folder, ec);
    if (ec)
        return Error{ErrorCode::io_error,
                     fmt::format("{}: cannot create the folder: {}", folder.string(), ec.message())};
    const int side = t.tiles_per_side;
    std::vector<std::size_t> stored;
    for (std::size_t k = 0; k < t.pages.size(); ++k)
        if (t.pages[k] >= gpu::kShoreFirstStoredSlot) stored.push_back(k);
    std::vector<Status> written(stored.size());
    detail::parallel_for_each(stored.size(), 0, [&](std::size_t s) {
        const std::size_t k = stored[s];
        Gray16Image img;
        img.width = static_cast<int>(ShoreTiles::kSlotTexels);
        img.height = static_cast<int>(rows);
        img.pixels.resize(ShoreTiles::kSlotTexels * rows);
        const float* slot = t.slot(t.pages[k]);
        for (std::size_t texel = 0; texel < ShoreTiles::kSlotTexels; ++texel)
            for (std::size_t r = 0; r < rows; ++r)
                img.pixels[r * ShoreTiles::kSlotTexels + texel] = encodings[r].encode(slot[texel * rows + r]);
        written[s] =
            detail::write_png_gray16(temp / shore_tile_file(layer, static_cast<int>(k % static_cast<std::size_t>(side)),
                                                            static_cast<int>(k / static_cast<std::size_t>(side))),
                                     img);
    });
    for (const Status& st : written)
        if (!st) return st.error();
    return nlohmann::json{{"tile_texels", ShoreTiles::kTile},
                          {"tiles_per_side", side},
                          {"kinds", kinds},
                          {"stored", stored.size()},
                          {"rows", row_list}};
}

nlohmann::json grid_json(const ShoreGrid& g) {
    return {{"resolution", g.resolution},
            {"texel_m", g.texel},
            {"corner_m", {g.corner.x, g.corner.y}},
            {"size_m", g.texel * g.resolution}};
}

/// Fills `temp` with the bake.
Status write_bake(const fs::path& temp, const ShoreBakeContents& c) {
    const ShoreWaves& m = *c.model;
    nlohmann::json model = grid_json(m.grid());
    model["breaking_index"] = c.breaking_index;
    model["texels_per_wavelength"] = c.texels_per_wavelength;
    model["diffraction"] = c.diffraction;
    auto tiles = write_tiles(temp, m.shared(), shore_layer_folder(-1), 0, 0);
    if (!tiles) return tiles.error();
    model["tiles"] = std::move(tiles).value();
    model["runs"] = nlohmann::json::array();
    for (std::size_t r = 0; r < m.layers().size(); ++r) {
        const ShoreWaveLayer& layer = m.layers()[r];
        nlohmann::json run = grid_json(layer.grid);
        run["first_wave"] = layer.first;
        run["waves"] = layer.count;
        auto run_tiles =
            write_tiles(temp, layer.tiles, shore_layer_folder(static_cast<int>(r)), layer.first, layer.count);
        if (!run_tiles) return run_tiles.error();
        run["tiles"] = std::move(run_tiles).value();
        model["runs"].push_back(std::move(run));
    }
    const auto waves = c.waves->waves();
    model["waves"] = nlohmann::json::array();
    for (std::size_t i = 0; i < waves.size(); ++i) {
        const Wave& w = waves[i];
        model["waves"].push_back({{"deep_water_wavelength_m", kTwoPi / w.k},
                                  {"omega_rad_s", w.omega},
                                  {"period_s", w.period()},
                                  {"direction", {w.dir_x, w.dir_z}},
                                  {"amplitude_m", w.amplitude},
                                  {"steepness", w.steepness}});
    }
    nlohmann::json sidecar = {{"version", kShoreBakeFormatVersion},
                              {"scene", c.scene_name},
                              {"water_level_m", c.water_level},
                              {"encoding", detail::kFieldEncoding},
                              {"model", model}};
    if (const ShoreField* d = c.distance_field) {
        nlohmann::json dist = {{"resolution", d->resolution},
                               {"texel_m", d->texel},
                               {"corner_m", {d->corner.x, d->corner.y}},
                               {"size_m", d->texel * d->resolution},
                               {"shoreline",
                                {{"file", "shorelines.json"},
                                 {"segments", d->segment_count},
                                 {"land_polygons", d->polygons},
                                 {"enclosed_waters", d->holes},
                                 {"simplify_tolerance_m", d->simplify_tolerance}}},
                               {"notes", "exact distance to the simplified shoreline (CGAL): positive over water"}};
        // Each field's rows as the save asks for them: the gradient's from its angles.
        const std::size_t n = static_cast<std::size_t>(d->resolution);
        auto floats = [n](const SharedFloats& grid) {
            return
                [&grid, n](int j, float* out) { std::copy_n(grid.data() + static_cast<std::size_t>(j) * n, n, out); };
        };
        auto gradient = [d, n](int axis) {
            return [d, n, axis](int j, float* out) {
                for (std::size_t i = 0; i < n; ++i) out[i] = d->gradient[static_cast<std::size_t>(j) * n + i][axis];
            };
        };
        const std::tuple<const char*, std::function<void(int, float*)>, const char*> fields[] = {
            {"signed_distance", floats(d->signed_distance), "m"},
            {"gradient_x", gradient(0), "1"},
            {"gradient_z", gradient(1), "1"},
            {"depth", floats(d->depth), "m"}};
        // The four images at once: at 4096² and more, encoding them is most of a bake's save.
        std::vector<Result<nlohmann::json>> written(std::size(fields), nlohmann::json{});
        detail::parallel_for_each(std::size(fields), 0, [&](std::size_t k) {
            const auto& [name, rows, unit] = fields[k];
            written[k] = detail::write_field_png_rows(temp, fmt::format("distance_{}", name), rows, d->resolution,
                                                      d->resolution, unit);
        });
        for (std::size_t k = 0; k < std::size(fields); ++k) {
            if (!written[k]) return written[k].error();
            dist["fields"][std::get<0>(fields[k])] = *written[k];
        }
        if (auto st = write_distance_vrt(temp, *d, dist["fields"]); !st) return st;
        dist["gis"] = kDistanceVrt;
        nlohmann::json lines = nlohmann::json::array();
        for (const ShoreLine& l : d->shorelines) {
            nlohmann::json pts = nlohmann::json::array();
            for (const auto& p : l.points) pts.push_back({p.x, p.y});
            lines.push_back({{"closed", l.closed}, {"points", pts}});
        }
        if (auto st = detail::write_text_file(temp / "shorelines.json", lines.dump()); !st) return st;
        sidecar["distance_field"] = dist;
    }
    return detail::write_text_file(temp / kShoreSidecar, sidecar.dump(2));
}

}  // namespace

Status write_shore_bake_into(const fs::path& dir, const ShoreBakeContents& contents) {
    if (!contents.model || !contents.waves)
        return Error{ErrorCode::invalid_argument, "save_shore_bake: the model and its waves are required"};
    if (contents.model->wave_count() != contents.waves->size())
        return Error{ErrorCode::invalid_argument,
                     fmt::format("save_shore_bake: the model has {} waves, the wave set {}",
                                 contents.model->wave_count(), contents.waves->size())};
    // A loaded model's tiles are read on demand: every one now, before a folder is
    // replaced (perhaps the one they come from); one that cannot be read fails the save.
    if (auto st = contents.model->read_all(); !st) return st;
    return write_bake(dir, contents);
}

Status save_shore_bake(const fs::path& dir, const ShoreBakeContents& contents) {
    return detail::write_folder_atomically(dir,
                                           [&](const fs::path& temp) { return write_shore_bake_into(temp, contents); });
}

}  // namespace tidewater
