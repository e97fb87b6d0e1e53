// Offscreen pictures of a sampled field: the warped surface coloured by a field with
// a colour legend, above the terrain.
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkStructuredGrid.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "vtk_output.hpp"
#include "vtk_png.hpp"

namespace tidewater::inspect {

namespace {

vtkNew<vtkStructuredGrid> grid_of(const SampleGrid& grid, const std::vector<glm::dvec3>& positions) {
    vtkNew<vtkStructuredGrid> sg;
    sg->SetDimensions(grid.nx, grid.nz, 1);
    vtkNew<vtkPoints> points;
    points->SetNumberOfPoints(static_cast<vtkIdType>(positions.size()));
    for (std::size_t k = 0; k < positions.size(); ++k)
        points->SetPoint(static_cast<vtkIdType>(k), positions[k].x, positions[k].y, positions[k].z);
    sg->SetPoints(points);
    return sg;
}

}  // namespace

Status screenshot(const FieldSample& sample, const std::vector<double>& terrain, const ScreenshotOptions& o, const std::filesystem::path& png) {
    const FieldInfo* info = find_field(o.field);
    if (!info) {
        std::string names;
        for (const FieldInfo& f : field_infos()) names += (names.empty() ? "" : ", ") + std::string(f.name);
        return Error{ErrorCode::invalid_argument, fmt::format("unknown field \"{}\" (fields: {})", o.field, names)};
    }
    if (o.width < 64 || o.height < 64 || o.width > 8192 || o.height > 8192)
        return Error{ErrorCode::invalid_argument, fmt::format("size {}x{}: 64 to 8192 pixels a side", o.width, o.height)};
    const SampleGrid& g = sample.grid;
    // Vector fields are coloured by their magnitude.
    vtkNew<vtkDoubleArray> values;
    values->SetName(o.field.c_str());
    values->SetNumberOfTuples(static_cast<vtkIdType>(g.points()));
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t k = 0; k < g.points(); ++k) {
        double v = 0.0;
        if (info->components == 1) {
            v = sample.value(o.field, k);
        } else {
            for (int c = 0; c < info->components; ++c) v += sample.value(o.field, k, c) * sample.value(o.field, k, c);
            v = std::sqrt(v);
        }
        values->SetValue(static_cast<vtkIdType>(k), v);
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (!(hi > lo)) lo = std::isfinite(lo) ? lo - 0.5 : 0.0, hi = lo + 1.0;
    // Dry points sink under the terrain, so land shows where there is no water.
    std::vector<glm::dvec3> water = sample.surface, ground(g.points());
    for (std::size_t k = 0; k < g.points(); ++k) {
        ground[k] = {sample.surface[k].x, terrain[k], sample.surface[k].z};
        if (sample.wet[k] == 0.0) water[k].y = terrain[k] - 1.0;
    }
    auto surface = grid_of(g, water);
    surface->GetPointData()->SetScalars(values);
    auto land = grid_of(g, ground);

    vtkNew<vtkLookupTable> lut;
    lut->SetHueRange(0.667, 0.0);  // blue to red
    lut->SetTableRange(lo, hi);
    lut->Build();
    vtkNew<vtkDataSetMapper> surface_mapper;
    surface_mapper->SetInputData(surface);
    surface_mapper->SetLookupTable(lut);
    surface_mapper->SetScalarRange(lo, hi);
    surface_mapper->ScalarVisibilityOn();
    vtkNew<vtkActor> surface_actor;
    surface_actor->SetMapper(surface_mapper);
    vtkNew<vtkDataSetMapper> land_mapper;
    land_mapper->SetInputData(land);
    land_mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> land_actor;
    land_actor->SetMapper(land_mapper);
    land_actor->GetProperty()->SetColor(0.55, 0.5, 0.4);

    vtkNew<vtkScalarBarActor> legend;
    legend->SetLookupTable(lut);
    legend->SetTitle(fmt::format("{} ({})", info->name, info->components > 1 ? fmt::format("|{}|, {}", info->name, info->unit) : info->unit).c_str());
    legend->SetNumberOfLabels(5);
    legend->SetPosition(0.88, 0.1);
    legend->SetWidth(0.1);
    legend->SetHeight(0.8);
    legend->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
    legend->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);

    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0.92, 0.94, 0.97);
    renderer->AddActor(land_actor);
    renderer->AddActor(surface_actor);
    renderer->AddActor2D(legend);
    vtkCamera* camera = renderer->GetActiveCamera();
    const glm::dvec2 centre = 0.5 * (g.min + g.max);
    const double span = std::max(g.max.x - g.min.x, g.max.y - g.min.y);
    camera->SetFocalPoint(centre.x, 0.0, centre.y);
    camera->SetPosition(centre.x - 0.9 * span, 0.9 * span, centre.y - 1.1 * span);
    camera->SetViewUp(0.0, 1.0, 0.0);
    renderer->ResetCameraClippingRange();

    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(o.width, o.height);
    window->AddRenderer(renderer);
    return save_window_png(window, png);
}

}  // namespace tidewater::inspect
