// The one translation unit that includes GDAL: band 1 of a raster as heights in metres.
#include <cpl_error.h>
#include <fmt/format.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <mutex>
#include <numbers>

#include "tidewater/detail/elevation_raster.hpp"

namespace tidewater::detail {

namespace {

constexpr double kEarthRadius = 6371008.8;         // m, the mean radius (IUGG)
constexpr double kMaxGeographicSpan = 5.0;         // degrees: beyond, a local plane distorts too much
constexpr double kFoot = 0.3048;                   // m
constexpr double kUsSurveyFoot = 1200.0 / 3937.0;  // m
constexpr double kMaxAbsHeight = 1e5;              // m, as the scene's heights

/// Silences GDAL's default printing to stderr on this thread; its last message goes into
/// our errors instead.
class QuietGdal {
  public:
    QuietGdal() {
        static std::once_flag registered;
        std::call_once(registered, [] { GDALAllRegister(); });
        CPLPushErrorHandler(CPLQuietErrorHandler);
        CPLErrorReset();
    }
    ~QuietGdal() { CPLPopErrorHandler(); }
    QuietGdal(const QuietGdal&) = delete;
    QuietGdal& operator=(const QuietGdal&) = delete;
    static std::string last_message() {
        const char* m = CPLGetLastErrorMsg();
        return (m && *m) ? std::string(m) : std::string("no reason given");
    }
};

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

/// Metres per unit of the band's values, or 0 for a unit we do not know.
double unit_scale(const std::string& unit) {
    const std::string u = lower(unit);
    if (u.empty() || u == "m" || u == "metre" || u == "meter" || u == "metres" || u == "meters") return 1.0;
    if (u == "ft" || u == "foot" || u == "feet" || u == "international foot") return kFoot;
    if (u == "us_survey_foot" || u == "us survey foot" || u == "ft_us" || u == "us-ft") return kUsSurveyFoot;
    return 0.0;
}

/// Pixel spacing in metres along x and z from the geotransform, or an error.
Result<glm::dvec2> pixel_metres(GDALDataset& ds, const std::string& name, std::string& coordinates) {
    std::array<double, 6> gt{};
    if (ds.GetGeoTransform(gt.data()) != CE_None) {
        coordinates = "no georeference: give \"size\" in the scene";
        return glm::dvec2(0.0);
    }
    if (gt[2] != 0.0 || gt[4] != 0.0)
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: a rotated or sheared raster is not supported: warp it north-up first", name)};
    if (!(gt[1] != 0.0 && gt[5] != 0.0 && std::isfinite(gt[1]) && std::isfinite(gt[5])))
        return Error{ErrorCode::schema_error, fmt::format("{}: the raster's pixel size is zero or not finite", name)};
    const OGRSpatialReference* srs = ds.GetSpatialRef();
    if (srs && srs->IsGeographic()) {
        const double span_x = std::abs(gt[1]) * ds.GetRasterXSize(), span_y = std::abs(gt[5]) * ds.GetRasterYSize();
        if (span_x > kMaxGeographicSpan || span_y > kMaxGeographicSpan)
            return Error{ErrorCode::schema_error,
                         fmt::format("{}: {:.2f} x {:.2f} degrees: a geographic raster may span at most {} degrees; "
                                     "project it to metres first",
                                     name, span_x, span_y, kMaxGeographicSpan)};
        const double lat0 = gt[3] + 0.5 * gt[5] * ds.GetRasterYSize();
        if (std::abs(lat0) > 85.0)
            return Error{ErrorCode::schema_error,
                         fmt::format("{}: centre latitude {:.2f}: too near a pole", name, lat0)};
        const double rad = std::numbers::pi / 180.0;
        coordinates = fmt::format("geographic, local metres about latitude {:.4f}", lat0);
        return glm::dvec2(std::abs(gt[1]) * rad * kEarthRadius * std::cos(lat0 * rad),
                          std::abs(gt[5]) * rad * kEarthRadius);
    }
    const double to_m = (srs && srs->IsProjected()) ? srs->GetLinearUnits() : 1.0;
    coordinates = srs && srs->IsProjected() ? fmt::format("projected, {} m per unit", to_m)
                                            : "no coordinate system: pixel sizes read as metres";
    return glm::dvec2(std::abs(gt[1]) * to_m, std::abs(gt[5]) * to_m);
}

}  // namespace

/// The raster formats elevation and bathymetry come in (docs/scene-format.md): GDAL opens
/// only these. Its other drivers include formats whose headers size buffers before any
/// check (a 135-byte CTable2 file asked for 1.4 GB), and none of them holds terrain.
constexpr const char* kElevationDrivers[] = {"GTiff", "AAIGrid", "GRASSASCIIGrid", "XYZ",  "EHdr", "ENVI",
                                             "HFA",   "SRTMHGT", "USGSDEM",        "DTED", "BT",   "GSAG",
                                             "GSBG",  "GS7BG",   "netCDF",         "BAG",  nullptr};

Result<ElevationGrid> read_gdal_elevation(const std::filesystem::path& path, bool depth, std::int64_t max_pixels) {
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return Error{ErrorCode::io_error, fmt::format("{}: cannot open file", name)};
    QuietGdal quiet;
    GDALDatasetUniquePtr ds(
        GDALDataset::Open(name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, kElevationDrivers, nullptr, nullptr));
    if (!ds)
        return Error{ErrorCode::parse_error, fmt::format("{}: not a raster GDAL can read in an elevation format ({})",
                                                         name, QuietGdal::last_message())};
    const int w = ds->GetRasterXSize(), h = ds->GetRasterYSize();
    if (ds->GetRasterCount() != 1)
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: {} bands: an elevation raster has one", name, ds->GetRasterCount())};
    if (w < 2 || h < 2 || static_cast<std::int64_t>(w) * h > max_pixels)
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: {}x{} pixels is out of range (2x2 to {} pixels)", name, w, h, max_pixels)};
    GDALRasterBand* band = ds->GetRasterBand(1);
    const GDALDataType type = band->GetRasterDataType();
    if (type == GDT_Unknown || GDALDataTypeIsComplex(type))
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: {} pixels: expected integer or floating-point heights", name,
                                 GDALGetDataTypeName(type) ? GDALGetDataTypeName(type) : "unknown")};
    const double to_m = unit_scale(band->GetUnitType() ? band->GetUnitType() : "");
    if (to_m == 0.0)
        return Error{ErrorCode::schema_error,
                     fmt::format("{}: heights in \"{}\": expected metres or feet", name, band->GetUnitType())};

    ElevationGrid grid;
    grid.width = w;
    grid.height = h;
    auto spacing = pixel_metres(*ds, name, grid.coordinates);
    if (!spacing) return spacing.error();
    grid.pixel_size = *spacing;

    grid.heights.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    if (band->RasterIO(GF_Read, 0, 0, w, h, grid.heights.data(), w, h, GDT_Float32, 0, 0, nullptr) != CE_None)
        return Error{ErrorCode::parse_error, fmt::format("{}: corrupt raster ({})", name, QuietGdal::last_message())};

    int has_nodata = 0;
    const double nodata = band->GetNoDataValue(&has_nodata);
    const float nodata_f = static_cast<float>(nodata);
    int has_scale = 0, has_offset = 0;
    const double scale = band->GetScale(&has_scale), offset = band->GetOffset(&has_offset);
    const double a = (has_scale ? scale : 1.0) * to_m * (depth ? -1.0 : 1.0);
    const double b = (has_offset ? offset : 0.0) * to_m * (depth ? -1.0 : 1.0);
    std::vector<std::uint8_t> invalid(grid.heights.size(), 0);
    for (std::size_t i = 0; i < grid.heights.size(); ++i) {
        const float v = grid.heights[i];
        if (!std::isfinite(v) || (has_nodata && (v == nodata_f || (std::isnan(nodata) && std::isnan(v))))) {
            invalid[i] = 1;
            continue;
        }
        const double m = a * static_cast<double>(v) + b;
        if (std::abs(m) > kMaxAbsHeight)
            return Error{
                ErrorCode::schema_error,
                fmt::format("{}: pixel ({}, {}) is {} m: heights must lie within +-{} m (is its nodata "
                            "value set?)",
                            name, i % static_cast<std::size_t>(w), i / static_cast<std::size_t>(w), m, kMaxAbsHeight)};
        grid.heights[i] = static_cast<float>(m);
    }
    bool any_valid = false;
    grid.filled = fill_invalid(w, h, grid.heights, invalid, any_valid);
    if (!any_valid) return Error{ErrorCode::schema_error, fmt::format("{}: every pixel is nodata", name)};

    // GDAL's row 0 is the top of the geotransform; a south-up raster (positive y step)
    // is flipped so that row 0 is north, the smallest z.
    std::array<double, 6> gt{};
    if (ds->GetGeoTransform(gt.data()) == CE_None && gt[5] > 0.0) {
        for (int j = 0; j < h / 2; ++j)
            std::swap_ranges(grid.heights.begin() + static_cast<std::ptrdiff_t>(j) * w,
                             grid.heights.begin() + static_cast<std::ptrdiff_t>(j + 1) * w,
                             grid.heights.begin() + static_cast<std::ptrdiff_t>(h - 1 - j) * w);
    }
    return grid;
}

}  // namespace tidewater::detail
