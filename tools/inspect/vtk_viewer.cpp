#include "vtk_viewer.hpp"

#include <fmt/format.h>
#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkContourFilter.h>
#include <vtkDoubleArray.h>
#include <vtkGlyph3D.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyLine.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSliderRepresentation2D.h>
#include <vtkSliderWidget.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "colour_maps.hpp"
#include "probe.hpp"
#include "tidewater/world_query.hpp"
#include "vtk_chart.hpp"
#include "vtk_output.hpp"
#include "vtk_png.hpp"

namespace tidewater::inspect {

namespace {

/// The grid's cells as triangle strips along rows, over `points` (grid.points() of them):
/// what the renderer draws fastest, built once while only the points change. Only cells
/// where `drawn(i, j)` holds are kept.
template <typename Drawn>
vtkSmartPointer<vtkPolyData> grid_strips(const SampleGrid& grid, vtkPoints* points, Drawn drawn) {
    vtkNew<vtkCellArray> strips;
    std::vector<vtkIdType> ids;
    auto flush = [&] {
        if (ids.size() >= 4) strips->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
        ids.clear();
    };
    for (int j = 0; j + 1 < grid.nz; ++j) {
        for (int i = 0; i < grid.nx; ++i) {
            // Column i closes cell i - 1 and opens cell i.
            const bool closes = i > 0 && drawn(i - 1, j), opens = i + 1 < grid.nx && drawn(i, j);
            if (closes || opens) {
                ids.push_back(static_cast<vtkIdType>(grid.index(i, j + 1)));
                ids.push_back(static_cast<vtkIdType>(grid.index(i, j)));
            }
            if (!opens) flush();
        }
        flush();
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetStrips(strips);
    return poly;
}

/// The table's 256 entries from `map` (colour_maps.hpp).
void fill_lookup_table(vtkLookupTable& lut, ColourMap map) {
    constexpr int kEntries = 256;
    lut.SetNumberOfTableValues(kEntries);
    for (int i = 0; i < kEntries; ++i) {
        const glm::dvec3 c = map_colour(map, i / double(kEntries - 1));
        lut.SetTableValue(i, c.r, c.g, c.b, 1.0);
    }
    lut.Modified();
}

/// Terrain this far under the level is always behind the (opaque) water surface.
constexpr double kHiddenSeabed = 10.0;  // m

}  // namespace

struct Viewer::Impl {
    const Scene* scene = nullptr;
    SampleGrid grid;
    std::vector<double> times;
    std::size_t time_index = 0;
    std::size_t field_index = 0;
    FieldSample sample;
    std::vector<double> terrain;
    bool playing = false;
    bool interactive = false;               // key hints in the caption
    vtkSmartPointer<vtkContextView> chart;  // the last probe's chart window

    vtkSmartPointer<vtkPolyData> surface, land;
    vtkNew<vtkDoubleArray> scalars, vectors;
    vtkNew<vtkLookupTable> lut;
    vtkNew<vtkPolyDataMapper> surface_mapper;
    vtkNew<vtkActor> surface_actor, land_actor, shore_actor, glyph_actor, track_actor;
    vtkSmartPointer<vtkGlyph3D> glyphs;
    vtkSmartPointer<vtkPolyData> glyph_points;

    /// Up to kGlyphs arrows on the points that move, evenly through them, the 95th
    /// percentile speed 3% of the view across (a few fast texels do not shrink
    /// every other arrow to nothing).
    void place_glyphs() {
        constexpr std::size_t kGlyphs = 400;
        std::vector<std::size_t> moving;
        std::vector<double> speeds;
        for (std::size_t k = 0; k < grid.points(); ++k) {
            double v[3];
            vectors->GetTuple(static_cast<vtkIdType>(k), v);
            const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            if (speed > 1e-6) moving.push_back(k), speeds.push_back(speed);
        }
        vtkNew<vtkPoints> at;
        vtkNew<vtkDoubleArray> arrows;
        arrows->SetNumberOfComponents(3);
        const std::size_t stride = std::max<std::size_t>(1, (moving.size() + kGlyphs - 1) / kGlyphs);
        for (std::size_t m = 0; m < moving.size(); m += stride) {
            const auto id = static_cast<vtkIdType>(moving[m]);
            at->InsertNextPoint(surface->GetPoints()->GetPoint(id));
            arrows->InsertNextTuple(vectors->GetTuple(id));
        }
        glyph_points->SetPoints(at);
        glyph_points->GetPointData()->SetVectors(arrows);
        glyph_points->Modified();
        double typical = 1.0;
        if (!speeds.empty()) {
            const auto p95 =
                speeds.begin() + static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(speeds.size() - 1));
            std::nth_element(speeds.begin(), p95, speeds.end());
            typical = *p95;
        }
        const double span = std::max(grid.max.x - grid.min.x, grid.max.y - grid.min.y);
        glyphs->SetScaleFactor(0.03 * span / typical);
    }
    vtkNew<vtkScalarBarActor> legend;
    vtkNew<vtkTextActor> caption;
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkRenderWindow> window;
    vtkNew<vtkSliderRepresentation2D> slider_rep;
    vtkNew<vtkSliderWidget> slider;

    const FieldInfo& info() const { return field_infos()[field_index]; }

    /// Points and colours for the current sample and field.
    void update() {
        const std::size_t n = grid.points();
        vtkPoints* points = surface->GetPoints();
        double lo = INFINITY, hi = -INFINITY;
        scalars->SetNumberOfTuples(static_cast<vtkIdType>(n));
        vectors->SetNumberOfComponents(3);
        vectors->SetNumberOfTuples(static_cast<vtkIdType>(n));
        for (std::size_t k = 0; k < n; ++k) {
            const glm::dvec3& p = sample.surface[k];
            // Dry points sink under the terrain, so land shows where there is no water.
            points->SetPoint(static_cast<vtkIdType>(k), p.x, sample.wet[k] == 0.0 ? terrain[k] - 1.0 : p.y, p.z);
            double v = 0.0;
            if (info().components == 1) {
                v = sample.value(info().name, k);
            } else {
                for (int c = 0; c < info().components; ++c)
                    v += sample.value(info().name, k, c) * sample.value(info().name, k, c);
                v = std::sqrt(v);
            }
            scalars->SetValue(static_cast<vtkIdType>(k), v);
            if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
            // Glyphs: the current under the flow field, else the particle velocity.
            const glm::dvec3& arrow = std::string(info().name) == "flow" ? sample.flow[k] : sample.velocity[k];
            vectors->SetTuple3(static_cast<vtkIdType>(k), arrow.x, arrow.y, arrow.z);
        }
        if (!(hi > lo)) lo = std::isfinite(lo) ? lo - 0.5 : 0.0, hi = lo + 1.0;
        points->Modified();
        scalars->Modified();
        vectors->Modified();
        if (glyphs) place_glyphs();
        const FieldColouring colouring = colouring_for(info(), scene->water_level());
        fill_lookup_table(*lut, colouring.map);
        const auto [from, to] = colour_range(colouring, lo, hi);
        lut->SetTableRange(from, to);
        surface_mapper->SetScalarRange(from, to);
        legend->SetTitle(
            fmt::format("{} ({})", info().name,
                        info().components > 1 ? fmt::format("|{}|, {}", info().name, info().unit) : info().unit)
                .c_str());
        caption->SetInput(fmt::format("t = {:.2f} s   field: {}{}", sample.time, info().name,
                                      interactive ? "   [space] play  [f] field  [g] glyphs  [p] probe" : "")
                              .c_str());
    }

    Status resample(std::size_t index) {
        auto s = sample_field(*scene, grid, times[index], 0);
        if (!s) return s.error();
        sample = std::move(s).value();
        time_index = index;
        update();
        return {};
    }
};

Viewer::Viewer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Viewer::~Viewer() = default;

Result<std::unique_ptr<Viewer>> Viewer::create(const Scene& scene, const SampleGrid& grid, std::vector<double> times,
                                               const std::string& field, int width, int height, bool offscreen) {
    if (auto st = validate_grid(grid); !st) return st.error();
    if (times.empty()) return Error{ErrorCode::invalid_argument, "viewer: the time range holds no time"};
    if (width < 64 || height < 64 || width > 8192 || height > 8192)
        return Error{ErrorCode::invalid_argument, fmt::format("size {}x{}: 64 to 8192 pixels a side", width, height)};
    const FieldInfo* chosen = find_field(field);
    if (!chosen) {
        std::string names;
        for (const FieldInfo& f : field_infos()) names += (names.empty() ? "" : ", ") + std::string(f.name);
        return Error{ErrorCode::invalid_argument, fmt::format("unknown field \"{}\" (fields: {})", field, names)};
    }
    auto m = std::make_unique<Impl>();
    m->scene = &scene;
    m->grid = grid;
    m->times = std::move(times);
    m->interactive = !offscreen;
    m->field_index = static_cast<std::size_t>(chosen - field_infos().data());
    m->terrain = sample_terrain(scene, grid);

    const std::size_t n = grid.points();
    vtkNew<vtkPoints> surface_points, land_points;
    surface_points->SetNumberOfPoints(static_cast<vtkIdType>(n));
    land_points->SetNumberOfPoints(static_cast<vtkIdType>(n));
    vtkNew<vtkDoubleArray> ground;
    ground->SetName("terrain");
    ground->SetNumberOfTuples(static_cast<vtkIdType>(n));
    for (int j = 0; j < grid.nz; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            const std::size_t k = grid.index(i, j);
            const glm::dvec2 p = grid.point(i, j);
            land_points->SetPoint(static_cast<vtkIdType>(k), p.x, m->terrain[k], p.y);
            ground->SetValue(static_cast<vtkIdType>(k), m->terrain[k] - scene.water_level());
        }
    m->surface = grid_strips(grid, surface_points, [](int, int) { return true; });
    m->scalars->SetName("field");
    m->vectors->SetName("velocity");
    m->vectors->SetNumberOfComponents(3);
    m->surface->GetPointData()->SetScalars(m->scalars);
    m->surface->GetPointData()->SetVectors(m->vectors);
    // Only the land that can show: where the water thins out or the terrain is dry.
    m->land = grid_strips(grid, land_points, [&](int i, int j) {
        double top = -INFINITY;
        for (int dj = 0; dj < 2; ++dj)
            for (int di = 0; di < 2; ++di) top = std::max(top, m->terrain[grid.index(i + di, j + dj)]);
        return top > scene.water_level() - kHiddenSeabed;
    });
    m->land->GetPointData()->SetScalars(ground);

    m->surface_mapper->SetInputData(m->surface);
    m->surface_mapper->SetLookupTable(m->lut);
    m->surface_actor->SetMapper(m->surface_mapper);
    vtkNew<vtkPolyDataMapper> land_mapper;
    land_mapper->SetInputData(m->land);
    land_mapper->ScalarVisibilityOff();
    m->land_actor->SetMapper(land_mapper);
    m->land_actor->GetProperty()->SetColor(0.55, 0.5, 0.4);
    // The shoreline: the terrain's contour at the water level.
    vtkNew<vtkContourFilter> shoreline;
    shoreline->SetInputData(m->land);
    shoreline->SetValue(0, 0.0);
    vtkNew<vtkPolyDataMapper> shore_mapper;
    shore_mapper->SetInputConnection(shoreline->GetOutputPort());
    shore_mapper->ScalarVisibilityOff();
    m->shore_actor->SetMapper(shore_mapper);
    m->shore_actor->GetProperty()->SetColor(0.1, 0.1, 0.1);
    m->shore_actor->GetProperty()->SetLineWidth(2.0);
    // Glyphs on up to 400 of the moving points (update() picks them and scales the arrows).
    m->glyph_points = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkArrowSource> arrow;
    vtkNew<vtkGlyph3D> glyphs;
    glyphs->SetInputData(m->glyph_points);
    glyphs->SetSourceConnection(arrow->GetOutputPort());
    glyphs->SetVectorModeToUseVector();
    glyphs->SetScaleModeToScaleByVector();
    m->glyphs = glyphs;
    vtkNew<vtkPolyDataMapper> glyph_mapper;
    glyph_mapper->SetInputConnection(glyphs->GetOutputPort());
    glyph_mapper->ScalarVisibilityOff();
    m->glyph_actor->SetMapper(glyph_mapper);
    m->glyph_actor->GetProperty()->SetColor(0.1, 0.1, 0.1);
    m->glyph_actor->SetVisibility(false);

    m->legend->SetLookupTable(m->lut);
    m->legend->SetNumberOfLabels(5);
    m->legend->SetPosition(0.88, 0.1);
    m->legend->SetWidth(0.1);
    m->legend->SetHeight(0.8);
    m->legend->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
    m->legend->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
    m->caption->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
    m->caption->GetTextProperty()->SetFontSize(14);
    m->caption->SetDisplayPosition(10, 10);

    m->renderer->SetBackground(0.92, 0.94, 0.97);
    m->track_actor->GetProperty()->SetColor(0.85, 0.1, 0.1);
    m->track_actor->GetProperty()->SetLineWidth(3.0);
    m->track_actor->SetVisibility(false);
    for (vtkActor* a : {m->land_actor.Get(), m->surface_actor.Get(), m->shore_actor.Get(), m->glyph_actor.Get(),
                        m->track_actor.Get()})
        m->renderer->AddActor(a);
    m->renderer->AddActor2D(m->legend);
    m->renderer->AddActor2D(m->caption);
    vtkCamera* camera = m->renderer->GetActiveCamera();
    const glm::dvec2 centre = 0.5 * (grid.min + grid.max);
    const double span = std::max(grid.max.x - grid.min.x, grid.max.y - grid.min.y);
    camera->SetFocalPoint(centre.x, 0.0, centre.y);
    camera->SetPosition(centre.x - 0.9 * span, 0.9 * span, centre.y - 1.1 * span);
    camera->SetViewUp(0.0, 1.0, 0.0);
    m->window->SetOffScreenRendering(offscreen ? 1 : 0);
    m->window->SetSize(width, height);
    // No multisampling: in software GL (llvmpipe) it costs more than sampling the water.
    m->window->SetMultiSamples(0);
    m->window->SetWindowName("tidewater inspect");
    m->window->AddRenderer(m->renderer);
    if (auto st = m->resample(0); !st) return st.error();
    m->renderer->ResetCameraClippingRange();
    return std::unique_ptr<Viewer>(new Viewer(std::move(m)));
}

Status Viewer::set_time_index(std::size_t index) {
    if (index >= impl_->times.size()) return Error{ErrorCode::invalid_argument, "viewer: time index out of range"};
    return impl_->resample(index);
}

void Viewer::next_field() {
    impl_->field_index = (impl_->field_index + 1) % field_infos().size();
    impl_->update();
}

void Viewer::set_glyphs(bool on) {
    impl_->glyph_actor->SetVisibility(on);
}

void Viewer::set_track(const std::vector<glm::dvec2>& path) {
    Impl& m = *impl_;
    // Drawn a little above the surface at the shown time, so the water does not hide it.
    constexpr double kLift = 0.5;  // m
    vtkNew<vtkPoints> points;
    vtkNew<vtkPolyLine> line;
    line->GetPointIds()->SetNumberOfIds(static_cast<vtkIdType>(path.size()));
    for (std::size_t k = 0; k < path.size(); ++k) {
        const WorldPoint w = query_world_point(*m.scene, m.sample.time, path[k]);
        points->InsertNextPoint(path[k].x, w.surface.height + kLift, path[k].y);
        line->GetPointIds()->SetId(static_cast<vtkIdType>(k), static_cast<vtkIdType>(k));
    }
    vtkNew<vtkCellArray> cells;
    cells->InsertNextCell(line);
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    poly->SetLines(cells);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(poly);
    m.track_actor->SetMapper(mapper);
    m.track_actor->SetVisibility(path.size() >= 2);
}

Result<double> Viewer::probe(glm::dvec2 at, const std::filesystem::path& png) {
    auto series = inspect::probe(*impl_->scene, at, impl_->times);
    if (!series) return series.error();
    if (auto st = probe_chart(*series, png); !st) return st.error();
    return series->dominant_period;
}

Status Viewer::save(const std::filesystem::path& png) {
    return save_window_png(impl_->window, png);
}
void Viewer::render() {
    impl_->window->Render();
}
std::string Viewer::field() const {
    return impl_->info().name;
}
double Viewer::time() const {
    return impl_->sample.time;
}

void Viewer::run() {
    Impl& m = *impl_;
    vtkNew<vtkRenderWindowInteractor> interactor;
    interactor->SetRenderWindow(m.window);
    interactor->Initialize();
    // The time slider.
    m.slider_rep->SetMinimumValue(0.0);
    m.slider_rep->SetMaximumValue(static_cast<double>(m.times.size() - 1));
    m.slider_rep->SetValue(0.0);
    m.slider_rep->SetTitleText("time step");
    m.slider_rep->GetPoint1Coordinate()->SetCoordinateSystemToNormalizedDisplay();
    m.slider_rep->GetPoint1Coordinate()->SetValue(0.1, 0.08);
    m.slider_rep->GetPoint2Coordinate()->SetCoordinateSystemToNormalizedDisplay();
    m.slider_rep->GetPoint2Coordinate()->SetValue(0.8, 0.08);
    m.slider->SetInteractor(interactor);
    m.slider->SetRepresentation(m.slider_rep);
    m.slider->SetAnimationModeToJump();
    m.slider->EnabledOn();
    vtkNew<vtkCallbackCommand> on_slide;
    on_slide->SetClientData(this);
    on_slide->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
        auto* v = static_cast<Viewer*>(self);
        const auto index = static_cast<std::size_t>(std::lround(v->impl_->slider_rep->GetValue()));
        if (index != v->impl_->time_index) (void)v->set_time_index(index);
        v->impl_->window->Render();
    });
    m.slider->AddObserver(vtkCommand::InteractionEvent, on_slide);
    // Keys: space, f, g, p.
    vtkNew<vtkCallbackCommand> on_key;
    on_key->SetClientData(this);
    on_key->SetCallback([](vtkObject* caller, unsigned long, void* self, void*) {
        auto* v = static_cast<Viewer*>(self);
        auto* iren = static_cast<vtkRenderWindowInteractor*>(caller);
        const std::string key = iren->GetKeySym() ? iren->GetKeySym() : "";
        if (key == "space") {
            v->impl_->playing = !v->impl_->playing;
        } else if (key == "f") {
            v->next_field();
        } else if (key == "g") {
            v->set_glyphs(!v->impl_->glyph_actor->GetVisibility());
        } else if (key == "p") {
            vtkNew<vtkCellPicker> picker;
            int* pos = iren->GetEventPosition();
            if (picker->Pick(pos[0], pos[1], 0, v->impl_->renderer)) {
                double* w = picker->GetPickPosition();
                const std::string png = fmt::format("probe_{:.0f}_{:.0f}.png", w[0], w[2]);
                auto series = inspect::probe(*v->impl_->scene, {w[0], w[2]}, v->impl_->times);
                if (!series) {
                    std::printf("probe: %s\n", series.error().message.c_str());
                } else {
                    const Status written = probe_chart(*series, png);
                    std::printf("probe at x = %.1f, z = %.1f m: dominant period %.3f s%s\n", w[0], w[2],
                                series->dominant_period, written ? (" -> " + png).c_str() : "");
                    // Show the chart in a window of its own beside the viewer.
                    v->impl_->chart = probe_view(*series, 900, 320, false);
                    v->impl_->chart->GetRenderWindow()->Render();
                }
            }
        }
        v->impl_->window->Render();
    });
    interactor->AddObserver(vtkCommand::KeyPressEvent, on_key);
    // Play: a repeating timer advances one step.
    vtkNew<vtkCallbackCommand> on_timer;
    on_timer->SetClientData(this);
    on_timer->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
        auto* v = static_cast<Viewer*>(self);
        if (!v->impl_->playing || v->impl_->times.size() < 2) return;
        const std::size_t next = (v->impl_->time_index + 1) % v->impl_->times.size();
        (void)v->set_time_index(next);
        v->impl_->slider_rep->SetValue(static_cast<double>(next));
        v->impl_->window->Render();
    });
    interactor->AddObserver(vtkCommand::TimerEvent, on_timer);
    interactor->CreateRepeatingTimer(100);
    m.window->Render();
    interactor->Start();
}

Status screenshot(const Scene& scene, const SampleGrid& grid, double time, const ScreenshotOptions& o,
                  const std::filesystem::path& png) {
    auto viewer = Viewer::create(scene, grid, {time}, o.field, o.width, o.height, true);
    if (!viewer) return viewer.error();
    (*viewer)->set_glyphs(o.glyphs);
    if (!o.track.empty()) (*viewer)->set_track(o.track);
    return (*viewer)->save(png);
}

}  // namespace tidewater::inspect
