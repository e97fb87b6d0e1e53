// The inspector: exported files read back with VTK's own reader hold the documented
// arrays with values equal to the core queries; pictures have the asked size, are not
// blank, carry a colour legend, and differ between fields. Runs under xvfb-run.
#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkStructuredGrid.h>
#include <vtkXMLStructuredGridReader.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../baked_scene.hpp"
#include "colour_maps.hpp"
#include "tidewater/detail/image_io.hpp"
#include "tidewater/query.hpp"
#include "tidewater/world_query.hpp"
#include "vtk_output.hpp"
#include "vtk_viewer.hpp"

namespace tidewater::inspect {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {
    return fs::temp_directory_path() / ("tidewater_inspect_" + std::to_string(::getpid()) + "_" + name);
}

// CIE L* (0 black to 100 white) of an sRGB colour.
double luminance(glm::dvec3 c) {
    auto linear = [](double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    const double y = 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
    return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : y * 24389.0 / 27.0;
}

TEST(InspectColours, OneSignedFieldsRiseInLightnessWithoutHueBands) {
    // Viridis: lightness rises strictly from end to end, so equal steps of the field read
    // as steps of one kind (the rainbow's lightness goes up and down with its hue).
    double last = -1.0;
    for (int i = 0; i <= 255; ++i) {
        const double l = luminance(map_colour(ColourMap::sequential, i / 255.0));
        EXPECT_GT(l, last) << "at entry " << i;
        last = l;
    }
    EXPECT_NEAR(map_colour(ColourMap::sequential, 0.0).b, 0.329, 0.002) << "viridis starts dark violet";
    EXPECT_NEAR(map_colour(ColourMap::sequential, 1.0).r, 0.993, 0.002) << "and ends yellow";
    for (const char* name : {"foam", "depth", "jacobian", "velocity", "flow", "displacement"})
        EXPECT_EQ(colouring_for(*find_field(name), 0.0).map, ColourMap::sequential) << name;
}

TEST(InspectColours, SignedFieldsDivergeFromANeutralZero) {
    for (const char* name : {"height", "shore_distance", "wake"})
        EXPECT_EQ(colouring_for(*find_field(name), 0.0).map, ColourMap::diverging) << name;
    EXPECT_EQ(colouring_for(*find_field("height"), 2.5).centre, 2.5) << "heights about the water level";
    // The centre is grey and the lightest; the two arms are blue and red and darken
    // toward their ends at the same rate.
    const glm::dvec3 mid = map_colour(ColourMap::diverging, 0.5);
    EXPECT_NEAR(mid.r, mid.g, 1e-6);
    EXPECT_NEAR(mid.g, mid.b, 1e-6);
    const glm::dvec3 cold = map_colour(ColourMap::diverging, 0.0), warm = map_colour(ColourMap::diverging, 1.0);
    EXPECT_GT(cold.b, cold.r);
    EXPECT_GT(warm.r, warm.b);
    for (int i = 1; i <= 127; ++i) {
        const double d = i / 255.0;
        EXPECT_LT(luminance(map_colour(ColourMap::diverging, 0.5 - d)), luminance(mid)) << i;
        EXPECT_LT(luminance(map_colour(ColourMap::diverging, 0.5 + d)), luminance(mid)) << i;
    }
    EXPECT_NEAR(luminance(cold), luminance(warm), 1.0) << "both ends equally dark";
    // A lopsided sample keeps zero in the neutral middle.
    const auto [lo, hi] = colour_range({ColourMap::diverging, 0.0}, -0.4, 1.6);
    EXPECT_DOUBLE_EQ(lo, -1.6);
    EXPECT_DOUBLE_EQ(hi, 1.6);
    const auto [slo, shi] = colour_range({ColourMap::sequential, 0.0}, 0.2, 0.9);
    EXPECT_DOUBLE_EQ(slo, 0.2);
    EXPECT_DOUBLE_EQ(shi, 0.9);
}

TEST(Inspect, ExportReadsBackWithTheQueriesValues) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    SampleGrid grid;
    grid.min = {-900.0, -700.0};
    grid.max = {900.0, 800.0};  // open water, beaches and the island
    grid.nx = 41, grid.nz = 37;
    const fs::path dir = temp_dir("export");
    const std::vector<double> times{0.0, 7.25};
    ASSERT_TRUE(export_series(dir, *scene, grid, times, 0).ok());
    EXPECT_TRUE(fs::exists(dir / "surface.pvd"));
    EXPECT_TRUE(fs::exists(dir / "terrain.vts"));
    for (std::size_t step = 0; step < times.size(); ++step) {
        vtkNew<vtkXMLStructuredGridReader> reader;
        const fs::path file = dir / ("surface_000" + std::to_string(step) + ".vts");
        reader->SetFileName(file.c_str());
        reader->Update();
        vtkStructuredGrid* sg = reader->GetOutput();
        ASSERT_EQ(sg->GetNumberOfPoints(), static_cast<vtkIdType>(grid.points())) << file;
        for (const FieldInfo& f : field_infos()) {
            auto* a = vtkDoubleArray::SafeDownCast(sg->GetPointData()->GetArray(f.name));
            ASSERT_NE(a, nullptr) << f.name;
            EXPECT_EQ(a->GetNumberOfComponents(), f.components) << f.name;
            EXPECT_EQ(a->GetNumberOfTuples(), static_cast<vtkIdType>(grid.points())) << f.name;
        }
        auto* units = vtkStringArray::SafeDownCast(sg->GetFieldData()->GetAbstractArray("units"));
        ASSERT_NE(units, nullptr);
        EXPECT_EQ(units->GetNumberOfValues(), static_cast<vtkIdType>(field_infos().size()));
        EXPECT_EQ(units->GetValue(0).find("height: m"), 0u);
        // Every 7th point against an Eulerian query at the same place and time.
        double worst = 0.0;
        for (vtkIdType k = 0; k < sg->GetNumberOfPoints(); k += 7) {
            double p[3];
            sg->GetPoint(k, p);
            const glm::dvec2 where{p[0], p[2]};
            const WorldPoint out = query_world_point(*scene, times[step], where);
            auto* height = vtkDoubleArray::SafeDownCast(sg->GetPointData()->GetArray("height"));
            auto* velocity = vtkDoubleArray::SafeDownCast(sg->GetPointData()->GetArray("velocity"));
            worst = std::max({worst, std::abs(height->GetValue(k) - out.surface.height),
                              std::abs(p[1] - out.surface.height),
                              std::abs(velocity->GetComponent(k, 1) - out.surface.velocity.y)});
        }
        EXPECT_LT(worst, 1e-5) << "step " << step;
    }
    fs::remove_all(dir);
}

TEST(Inspect, ExportRefusesBadInputAndLeavesNothing) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    SampleGrid grid;
    grid.nx = 40000, grid.nz = 25000;  // 10^9 points
    const fs::path dir = temp_dir("refused");
    EXPECT_NE(export_series(dir, *scene, grid, {0.0}, 0).error().message.find("more than"), std::string::npos);
    grid.nx = grid.nz = 8;
    EXPECT_FALSE(export_series(dir, *scene, grid, {}, 0).ok());  // empty time range
    { std::ofstream(temp_dir("plain")) << "x"; }
    EXPECT_FALSE(export_series(temp_dir("plain") / "sub", *scene, grid, {0.0}, 0).ok());
    EXPECT_FALSE(fs::exists(dir));
    fs::remove(temp_dir("plain"));
}

/// Pixels that differ from the background colour (the renderer's clear colour).
double coverage(const detail::Rgba8Image& img, int x0, int x1) {
    const std::uint8_t* bg = &img.pixels[0];
    std::size_t differ = 0, total = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t* p = &img.pixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) +
                                                     static_cast<std::size_t>(x))];
            differ += std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) > 30;
            ++total;
        }
    return static_cast<double>(differ) / static_cast<double>(total);
}

// A boat's wake: the sampled wake field is the world query's wake column, and it is there
// behind the tug of examples/scenes/tug.json.
TEST(Inspect, ExportsTheBoatsWakes) {
    auto parsed = load_scene(std::filesystem::path(TIDEWATER_EXAMPLES_DIR) / "scenes" / "tug.json");
    ASSERT_TRUE(parsed.ok()) << parsed.error().message;
    auto scene = test::baked(std::move(parsed));
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    SampleGrid grid;
    grid.min = {-500.0, -950.0};
    grid.max = {-120.0, -700.0};
    grid.nx = 39, grid.nz = 26;
    auto sample = sample_field(*scene, grid, 0.0);
    ASSERT_TRUE(sample.ok()) << sample.error().message;
    double worst = 0.0, biggest = 0.0;
    for (std::size_t k = 0; k < grid.points(); ++k) {
        const glm::dvec2 where{sample->surface[k].x, sample->surface[k].z};
        worst =
            std::max(worst, std::abs(sample->value("wake", k) - query_world_point(*scene, 0.0, where).surface.wake));
        biggest = std::max(biggest, std::abs(sample->wake[k]));
    }
    std::printf("sampled wake up to %.3f m; against the world query %.2g m\n", biggest, worst);
    EXPECT_GT(biggest, 0.1);
    EXPECT_LT(worst, 1e-6);  // the same evaluation (float lanes batched differently)
}

// The default scene's brook and rill: the export's body ids name them through body_names,
// its flow is the world query's current, and a flow picture with glyphs and a drift
// track differs from the same picture without them.
TEST(Inspect, ExportsTheCurrentAndTheBodyAndShowsFlowGlyphs) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    SampleGrid grid;
    grid.min = {-60.0, -620.0};
    grid.max = {180.0, -300.0};
    grid.nx = 49, grid.nz = 65;
    auto sample = sample_field(*scene, grid, 2.0);
    ASSERT_TRUE(sample.ok()) << sample.error().message;
    ASSERT_EQ(sample->body_names.size(), 2u + scene->lakes.size() + scene->rivers.size());
    std::size_t in_rivers = 0;
    double worst = 0.0;
    for (std::size_t k = 0; k < grid.points(); ++k) {
        const auto id = static_cast<std::size_t>(sample->body[k]);
        ASSERT_LT(id, sample->body_names.size());
        const glm::dvec2 where{sample->surface[k].x, sample->surface[k].z};
        const WorldPoint w = query_world_point(*scene, 2.0, where);
        EXPECT_EQ(sample->body_names[id], body_name(*scene, w.body)) << "at " << where.x << ", " << where.y;
        worst = std::max({worst, std::abs(sample->flow[k].x - w.flow.x), std::abs(sample->flow[k].z - w.flow.y)});
        if (w.body.kind == BodyKind::river) {
            ++in_rivers;
            EXPECT_GT(std::hypot(sample->flow[k].x, sample->flow[k].z), 0.0) << "a river point without a current";
        }
    }
    EXPECT_GT(in_rivers, 50u) << "the extent holds the brook and the rill";
    EXPECT_LT(worst, 1e-12);

    const fs::path dir = temp_dir("bodies");
    ASSERT_TRUE(export_series(dir, *scene, grid, {2.0}, 0).ok());
    vtkNew<vtkXMLStructuredGridReader> reader;
    reader->SetFileName((dir / "surface_0000.vts").c_str());
    reader->Update();
    auto* names = vtkStringArray::SafeDownCast(reader->GetOutput()->GetFieldData()->GetAbstractArray("body_names"));
    ASSERT_NE(names, nullptr);
    ASSERT_EQ(names->GetNumberOfValues(), static_cast<vtkIdType>(sample->body_names.size()));
    EXPECT_EQ(names->GetValue(1), "ocean");
    EXPECT_EQ(names->GetValue(static_cast<vtkIdType>(2 + scene->lakes.size())), scene->rivers[0].name);
    fs::remove_all(dir);

    std::vector<detail::Rgba8Image> pictures;
    for (const bool decorated : {false, true}) {
        const fs::path png = temp_dir(decorated ? "flow_glyphs.png" : "flow.png");
        ScreenshotOptions o;
        o.field = "flow";
        o.width = 480, o.height = 320;
        o.glyphs = decorated;
        if (decorated) o.track = {{20.0, -340.0}, {25.0, -420.0}, {45.0, -500.0}};
        ASSERT_TRUE(screenshot(*scene, grid, 2.0, o, png).ok());
        auto img = detail::read_png_rgba8(png);
        ASSERT_TRUE(img.ok()) << img.error().message;
        pictures.push_back(std::move(img).value());
        fs::remove(png);
    }
    std::size_t differ = 0;
    for (std::size_t k = 0; k < pictures[0].pixels.size(); ++k)
        differ += pictures[0].pixels[k] != pictures[1].pixels[k];
    EXPECT_GT(differ, 500u) << "glyphs and the track are drawn";
}

TEST(Inspect, ScreenshotsHaveSizeLegendAndDifferByField) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    SampleGrid grid;
    grid.min = {-1200.0, -1200.0};
    grid.max = {1200.0, 1200.0};
    grid.nx = grid.nz = 96;
    std::vector<detail::Rgba8Image> pictures;
    for (const char* field : {"height", "foam"}) {
        const fs::path png = temp_dir(std::string(field) + ".png");
        ScreenshotOptions o;
        o.field = field;
        o.width = 640, o.height = 360;
        ASSERT_TRUE(screenshot(*scene, grid, 3.0, o, png).ok()) << field;
        auto img = detail::read_png_rgba8(png);
        ASSERT_TRUE(img.ok()) << img.error().message;
        EXPECT_EQ(img->width, 640);
        EXPECT_EQ(img->height, 360);
        EXPECT_GT(coverage(*img, 0, img->width), 0.2) << field << ": the picture is blank";
        // The legend sits in the right tenth of the picture.
        EXPECT_GT(coverage(*img, static_cast<int>(0.89 * img->width), static_cast<int>(0.95 * img->width)), 0.3)
            << field << ": no legend";
        pictures.push_back(std::move(img).value());
        fs::remove(png);
    }
    std::size_t differ = 0;
    for (std::size_t k = 0; k < pictures[0].pixels.size(); ++k)
        differ += pictures[0].pixels[k] != pictures[1].pixels[k];
    EXPECT_GT(static_cast<double>(differ) / static_cast<double>(pictures[0].pixels.size()), 0.05);
    ScreenshotOptions bad;
    bad.field = "vorticity";
    EXPECT_NE(screenshot(*scene, grid, 3.0, bad, temp_dir("bad.png")).error().message.find("unknown field"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(temp_dir("bad.png")));
}

// A single wave: the probe's dominant period is the wave's, sqrt(2 pi L / g), within 1%.
TEST(Inspect, ProbeFindsTheWavePeriod) {
    auto scene = parse_scene(
        R"({"version": 1, "water_level": 0, "terrain": {"flat": {"height": -300}}, "shore": {"enabled": false},
        "ocean": {"waves": [{"direction": 30, "wavelength": 48, "amplitude": 0.6, "steepness": 0.5, "phase": 0.3}]}})",
        "single wave");
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    const double period = std::sqrt(2.0 * 3.14159265358979 * 48.0 / 9.81);
    std::vector<double> times;
    for (int k = 0; k <= 40 * 32; ++k) times.push_back(k * period / 32.0 + 0.37);
    auto p = probe(*scene, {12.0, -7.0}, times);
    ASSERT_TRUE(p.ok()) << p.error().message;
    std::printf("probe: dominant period %.4f s, wave period %.4f s (%.3f%%)\n", p->dominant_period, period,
                100.0 * std::abs(p->dominant_period - period) / period);
    EXPECT_NEAR(p->dominant_period, period, 0.01 * period);
    const fs::path png = temp_dir("probe.png");
    ASSERT_TRUE(probe_chart(*p, png, 900, 300).ok());
    auto img = detail::read_png_rgba8(png);
    ASSERT_TRUE(img.ok()) << img.error().message;
    EXPECT_EQ(img->width, 900);
    EXPECT_EQ(img->height, 300);
    EXPECT_GT(coverage(*img, 0, img->width), 0.01);
    fs::remove(png);
    EXPECT_FALSE(probe(*scene, {0.0, 0.0}, {0.0, 1.0}).ok());  // too few steps
}

// The interactive viewer, driven without its event loop (offscreen): time, field and
// glyph changes change the picture; a probe from it finds the sea's period.
TEST(Inspect, ViewerStepsTimeSwitchesFieldsAndProbes) {
    auto scene = test::baked(default_scene());
    ASSERT_TRUE(scene.ok());
    SampleGrid grid;
    grid.min = {-1200.0, -1200.0};
    grid.max = {1200.0, 1200.0};
    grid.nx = grid.nz = 64;
    std::vector<double> times;
    for (int k = 0; k < 64; ++k) times.push_back(0.5 * k);
    auto viewer = Viewer::create(*scene, grid, times, "height", 480, 300, true);
    ASSERT_TRUE(viewer.ok()) << viewer.error().message;
    Viewer& v = **viewer;
    auto shot = [&](const char* name) {
        const fs::path png = temp_dir(name);
        EXPECT_TRUE(v.save(png).ok());
        auto img = detail::read_png_rgba8(png);
        fs::remove(png);
        return img.ok() ? std::move(img).value() : detail::Rgba8Image{};
    };
    auto differ = [](const detail::Rgba8Image& a, const detail::Rgba8Image& b) {
        std::size_t d = 0;
        for (std::size_t k = 0; k < std::min(a.pixels.size(), b.pixels.size()); ++k) d += a.pixels[k] != b.pixels[k];
        return static_cast<double>(d) / static_cast<double>(std::max<std::size_t>(1, a.pixels.size()));
    };
    const detail::Rgba8Image first = shot("v0.png");
    ASSERT_EQ(first.width, 480);
    ASSERT_TRUE(v.set_time_index(10).ok());
    EXPECT_DOUBLE_EQ(v.time(), 5.0);
    const detail::Rgba8Image later = shot("v1.png");
    EXPECT_GT(differ(first, later), 0.01) << "a later time looks the same";
    v.next_field();
    EXPECT_EQ(v.field(), "displacement");
    const detail::Rgba8Image other = shot("v2.png");
    EXPECT_GT(differ(later, other), 0.01) << "another field looks the same";
    v.set_glyphs(true);
    EXPECT_GT(differ(other, shot("v3.png")), 0.001) << "glyphs drew nothing";
    EXPECT_FALSE(v.set_time_index(64).ok());
    const fs::path png = temp_dir("viewer_probe.png");
    auto period = v.probe({1000.0, 50.0}, png);
    ASSERT_TRUE(period.ok()) << period.error().message;
    EXPECT_GT(*period, 3.0);
    EXPECT_LT(*period, 20.0);
    EXPECT_TRUE(fs::exists(png));
    fs::remove(png);
}

}  // namespace
}  // namespace tidewater::inspect
