// Terrain from elevation rasters: GeoTIFF (written here with GDAL's own writer), ESRI ASCII
// grids and raw 16-bit files of the same terrain load to the same heights; depths,
// geographic coordinates, nodata and south-up rasters are read as documented; bad files
// are refused by name before anything large is allocated.
#include <cpl_string.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>

#include "test_helpers.hpp"

namespace tidewater {
namespace {

namespace fs = std::filesystem;

constexpr int kW = 33, kH = 17;  // pixels
constexpr double kCell = 10.0;   // m
constexpr double kLo = -30.0, kHi = 50.0;

/// The terrain every file below holds: heights at pixel (i, j), row 0 north.
double true_height(int i, int j) {
    return kLo + (kHi - kLo) * (0.5 + 0.5 * std::sin(0.37 * i) * std::cos(0.51 * j));
}

/// World point of pixel (i, j) for a terrain centred on the origin (row 0 at the smallest z).
glm::dvec2 pixel_point(int i, int j) {
    return {(i - 0.5 * (kW - 1)) * kCell, (j - 0.5 * (kH - 1)) * kCell};
}

/// Writes a GeoTIFF with GDAL: `values` row-major from the top row, the given EPSG code
/// (0: none), pixel size and sign of the y step.
void write_geotiff(const fs::path& path, GDALDataType type, const std::vector<double>& values, int w, int h, int epsg,
                   double dx, double dy, int bands = 1, const char* nodata = nullptr, char** options = nullptr) {
    GDALAllRegister();
    GDALDriverH driver = GDALGetDriverByName("GTiff");
    ASSERT_NE(driver, nullptr);
    GDALDatasetH ds = GDALCreate(driver, path.c_str(), w, h, bands, type, options);
    ASSERT_NE(ds, nullptr);
    double gt[6] = {500000.0, dx, 0.0, dy < 0 ? 2200000.0 : 2100000.0, 0.0, dy};
    GDALSetGeoTransform(ds, gt);
    if (epsg != 0) {
        OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
        OSRImportFromEPSG(srs, epsg);
        GDALSetSpatialRef(ds, srs);
        OSRDestroySpatialReference(srs);
    }
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    if (nodata) GDALSetRasterNoDataValue(band, std::atof(nodata));
    if (!values.empty()) {
        std::vector<double> copy = values;
        EXPECT_EQ(GDALRasterIO(band, GF_Write, 0, 0, w, h, copy.data(), w, h, GDT_Float64, 0, 0), CE_None);
    }
    GDALClose(ds);
}

std::vector<double> terrain_values(bool depth = false) {
    std::vector<double> v;
    for (int j = 0; j < kH; ++j)
        for (int i = 0; i < kW; ++i) v.push_back(depth ? -true_height(i, j) : true_height(i, j));
    return v;
}

void write_ascii_grid(const fs::path& path, const std::vector<double>& v, const char* nodata = nullptr) {
    std::ofstream out(path);
    out << "ncols " << kW << "\nnrows " << kH << "\nxllcorner 1000\nyllcorner 2000\ncellsize " << kCell << "\n";
    if (nodata) out << "NODATA_value " << nodata << "\n";
    out.precision(10);
    for (int j = 0; j < kH; ++j) {
        for (int i = 0; i < kW; ++i) out << v[static_cast<std::size_t>(j * kW + i)] << ' ';
        out << '\n';
    }
}

Result<Scene> scene_with_heightmap(const fs::path& dir, const std::string& heightmap) {
    const std::string text =
        R"({"version": 1, "water_level": 0, "ocean": "pool_calm", "terrain": {"heightmap": )" + heightmap + "}}";
    return parse_scene(text, (dir / "scene.json").string(), dir);
}

const HeightmapTerrain& heightmap_of(const Scene& s) {
    return std::get<HeightmapTerrain>(s.terrain.shape());
}

// The same terrain as a Float32 GeoTIFF (UTM, metres), an ESRI ASCII grid and a raw
// little-endian 16-bit file loads to the same heights: within the 16-bit quantisation
// (80 m / 65535 = 1.2 mm) of the true heights at every pixel centre, the same size.
TEST(ElevationRasters, GeoTiffAsciiGridAndRawFileLoadToTheSameHeights) {
    test::TempDir dir;
    write_geotiff(dir.path / "t.tif", GDT_Float32, terrain_values(), kW, kH, 32605, kCell, -kCell);
    write_ascii_grid(dir.path / "t.asc", terrain_values());
    {
        std::ofstream raw(dir.path / "t.raw", std::ios::binary);
        for (int j = 0; j < kH; ++j)
            for (int i = 0; i < kW; ++i) {
                const auto code =
                    static_cast<std::uint16_t>(std::lround((true_height(i, j) - kLo) / (kHi - kLo) * 65535.0));
                const unsigned char b[2] = {static_cast<unsigned char>(code & 0xff),
                                            static_cast<unsigned char>(code >> 8)};
                raw.write(reinterpret_cast<const char*>(b), 2);
            }
    }
    std::ostringstream size;
    size << '[' << (kW - 1) * kCell << ", " << (kH - 1) * kCell << ']';
    const std::vector<std::string> heightmaps = {R"({"file": "t.tif"})", R"({"file": "t.asc"})",
                                                 R"({"file": "t.raw", "raw": {"width": 33, "height": 17}, "size": )" +
                                                     size.str() + R"(, "height_range": [-30, 50]})"};
    const double tolerance = 1.5 * (kHi - kLo) / 65535.0;
    for (const std::string& h : heightmaps) {
        SCOPED_TRACE(h);
        auto scene = scene_with_heightmap(dir.path, h);
        ASSERT_TRUE(scene.ok()) << scene.error().message;
        const HeightmapTerrain& map = heightmap_of(*scene);
        EXPECT_EQ(map.image->width, kW);
        EXPECT_EQ(map.image->height, kH);
        EXPECT_NEAR(map.size.x, (kW - 1) * kCell, 1e-9);
        EXPECT_NEAR(map.size.y, (kH - 1) * kCell, 1e-9);
        double worst = 0.0;
        for (int j = 0; j < kH; ++j)
            for (int i = 0; i < kW; ++i)
                worst = std::max(worst, std::abs(scene->terrain.height_at(pixel_point(i, j)) - true_height(i, j)));
        EXPECT_LT(worst, tolerance);
    }
}

// A grid of depths (positive down) is read as such: heights are their negatives.
TEST(ElevationRasters, DepthGridsBecomeHeights) {
    test::TempDir dir;
    write_ascii_grid(dir.path / "d.asc", terrain_values(true));
    auto scene = scene_with_heightmap(dir.path, R"({"file": "d.asc", "values": "depth"})");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    for (int j = 0; j < kH; j += 3)
        for (int i = 0; i < kW; i += 4)
            EXPECT_NEAR(scene->terrain.height_at(pixel_point(i, j)), true_height(i, j), 0.002);

    // A raw file of depths: code 0 is the shallowest depth given, 65535 the deepest.
    {
        std::ofstream raw(dir.path / "d.raw", std::ios::binary);
        const unsigned char px[8] = {0, 0, 0xff, 0xff, 0, 0, 0xff, 0xff};  // 2x2: 0, 65535 / 0, 65535
        raw.write(reinterpret_cast<const char*>(px), 8);
    }
    auto raw = scene_with_heightmap(
        dir.path,
        R"({"file": "d.raw", "raw": {"width": 2, "height": 2}, "size": [10, 10], "height_range": [5, 40], "values": "depth"})");
    ASSERT_TRUE(raw.ok()) << raw.error().message;
    EXPECT_NEAR(raw->terrain.height_at({-5.0, -5.0}), -5.0, 1e-3);
    EXPECT_NEAR(raw->terrain.height_at({5.0, -5.0}), -40.0, 1e-3);
}

// A geographic raster (WGS 84 degrees) becomes local metres: a degree of longitude is
// R cos(latitude) * pi / 180 metres about the raster's centre latitude.
TEST(ElevationRasters, GeographicRastersBecomeLocalMetres) {
    test::TempDir dir;
    GDALAllRegister();
    GDALDatasetH ds =
        GDALCreate(GDALGetDriverByName("GTiff"), (dir.path / "geo.tif").c_str(), 11, 9, 1, GDT_Int16, nullptr);
    ASSERT_NE(ds, nullptr);
    const double lat_top = 19.75, step = 0.0005;  // about 52 m x 55 m pixels at Hilo
    double gt[6] = {-155.09, step, 0.0, lat_top, 0.0, -step};
    GDALSetGeoTransform(ds, gt);
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(srs, 4326);
    GDALSetSpatialRef(ds, srs);
    OSRDestroySpatialReference(srs);
    std::vector<std::int16_t> v(99, 7);
    v[0] = -3;
    ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 11, 9, v.data(), 11, 9, GDT_Int16, 0, 0), CE_None);
    GDALClose(ds);
    auto scene = scene_with_heightmap(dir.path, R"({"file": "geo.tif"})");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const double rad = std::numbers::pi / 180.0, earth = 6371008.8;
    const double lat0 = lat_top - 4.5 * step;
    EXPECT_NEAR(heightmap_of(*scene).size.x, 10 * step * rad * earth * std::cos(lat0 * rad), 1e-6);
    EXPECT_NEAR(heightmap_of(*scene).size.y, 8 * step * rad * earth, 1e-6);
    EXPECT_NEAR(scene->terrain.height_at(-0.5 * heightmap_of(*scene).size), -3.0, 1e-3);  // the north-west pixel
}

// nodata pixels take their nearest valid neighbour's height; a south-up raster (positive
// y step) is turned so that its north row is still the smallest z.
TEST(ElevationRasters, NodataIsFilledAndSouthUpRastersAreTurned) {
    test::TempDir dir;
    std::vector<double> v = terrain_values();
    v[static_cast<std::size_t>(5 * kW + 7)] = -9999.0;
    v[static_cast<std::size_t>(5 * kW + 8)] = -9999.0;
    write_ascii_grid(dir.path / "holes.asc", v, "-9999");
    auto scene = scene_with_heightmap(dir.path, R"({"file": "holes.asc"})");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const double filled = scene->terrain.height_at(pixel_point(7, 5));
    const double neighbours[] = {true_height(6, 5), true_height(7, 4), true_height(7, 6)};
    EXPECT_TRUE(std::any_of(std::begin(neighbours), std::end(neighbours),
                            [&](double n) { return std::abs(filled - n) < 0.002; }))
        << "filled with " << filled;

    std::vector<double> flipped;
    for (int j = kH - 1; j >= 0; --j)
        for (int i = 0; i < kW; ++i) flipped.push_back(true_height(i, j));
    write_geotiff(dir.path / "south_up.tif", GDT_Float32, flipped, kW, kH, 32605, kCell, +kCell);
    auto turned = scene_with_heightmap(dir.path, R"({"file": "south_up.tif"})");
    ASSERT_TRUE(turned.ok()) << turned.error().message;
    for (int j = 0; j < kH; j += 4)
        for (int i = 0; i < kW; i += 5)
            EXPECT_NEAR(turned->terrain.height_at(pixel_point(i, j)), true_height(i, j), 0.002);
}

void expect_refused(const fs::path& dir, const std::string& heightmap, const std::string& file,
                    const std::string& why) {
    SCOPED_TRACE(heightmap);
    auto scene = scene_with_heightmap(dir, heightmap);
    ASSERT_FALSE(scene.ok());
    EXPECT_NE(scene.error().message.find("/terrain/heightmap/"), std::string::npos) << scene.error().message;
    EXPECT_NE(scene.error().message.find(file), std::string::npos) << scene.error().message;
    EXPECT_NE(scene.error().message.find(why), std::string::npos) << scene.error().message;
}

// Bad rasters are refused, naming the file and why; the one too large is refused from its
// header (a sparse 17000² GeoTIFF of a few kilobytes), before its pixels are read.
TEST(ElevationRasters, BadRastersAreRefusedByName) {
    test::TempDir dir;
    std::ofstream(dir.path / "notes.tif") << "not a raster at all\n";
    expect_refused(dir.path, R"({"file": "notes.tif"})", "notes.tif", "not a raster GDAL can read");
    expect_refused(dir.path, R"({"file": "missing.tif"})", "missing.tif", "cannot open file");

    write_geotiff(dir.path / "complex.tif", GDT_CInt16, {}, 4, 4, 32605, 1.0, -1.0);
    expect_refused(dir.path, R"({"file": "complex.tif"})", "complex.tif", "expected integer or floating-point");

    write_geotiff(dir.path / "rgb.tif", GDT_Byte, {}, 4, 4, 32605, 1.0, -1.0, 3);
    expect_refused(dir.path, R"({"file": "rgb.tif"})", "rgb.tif", "3 bands");

    char** sparse = CSLSetNameValue(nullptr, "SPARSE_OK", "TRUE");
    sparse = CSLSetNameValue(sparse, "TILED", "YES");
    write_geotiff(dir.path / "huge.tif", GDT_Float32, {}, 17000, 17000, 32605, 1.0, -1.0, 1, nullptr, sparse);
    CSLDestroy(sparse);
    ASSERT_LT(fs::file_size(dir.path / "huge.tif"), 10u << 20);
    expect_refused(dir.path, R"({"file": "huge.tif"})", "huge.tif", "17000x17000 pixels is out of range");

    std::vector<double> none(static_cast<std::size_t>(kW * kH), -9999.0);
    write_ascii_grid(dir.path / "empty.asc", none, "-9999");
    expect_refused(dir.path, R"({"file": "empty.asc"})", "empty.asc", "every pixel is nodata");

    std::vector<double> wild = terrain_values();
    wild[3] = -3.4e38;  // an unmarked nodata value
    write_ascii_grid(dir.path / "wild.asc", wild);
    expect_refused(dir.path, R"({"file": "wild.asc"})", "wild.asc", "is its nodata value set?");

    std::ofstream(dir.path / "short.raw", std::ios::binary) << "abc";
    expect_refused(
        dir.path,
        R"({"file": "short.raw", "raw": {"width": 4, "height": 4}, "size": [10, 10], "height_range": [0, 1]})",
        "short.raw", "3 bytes, but 4x4 16-bit pixels take 32");
    auto no_size = scene_with_heightmap(dir.path, R"({"file": "short.raw", "raw": {"width": 4, "height": 4}})");
    ASSERT_FALSE(no_size.ok());
    EXPECT_NE(no_size.error().message.find("/terrain/heightmap/size"), std::string::npos) << no_size.error().message;
    write_ascii_grid(dir.path / "t.asc", terrain_values());
    auto ranged = scene_with_heightmap(dir.path, R"({"file": "t.asc", "height_range": [0, 1]})");
    ASSERT_FALSE(ranged.ok());
    EXPECT_NE(ranged.error().message.find("/terrain/heightmap/height_range"), std::string::npos);
    auto bad_format = scene_with_heightmap(dir.path, R"({"file": "t.asc", "format": "dem"})");
    ASSERT_FALSE(bad_format.ok());
    EXPECT_NE(bad_format.error().message.find("/terrain/heightmap/format"), std::string::npos);
    // "format" overrides the name: an ASCII grid read as a PNG is refused as one.
    auto as_png = scene_with_heightmap(
        dir.path, R"({"file": "t.asc", "format": "png16", "size": [10, 10], "height_range": [0, 1]})");
    ASSERT_FALSE(as_png.ok());
    EXPECT_NE(as_png.error().message.find("t.asc: not a readable image"), std::string::npos) << as_png.error().message;
    auto bad_values = scene_with_heightmap(dir.path, R"({"file": "t.asc", "values": "altitude"})");
    ASSERT_FALSE(bad_values.ok());
    EXPECT_NE(bad_values.error().message.find("/terrain/heightmap/values"), std::string::npos);
}

}  // namespace
}  // namespace tidewater
