// The probe chart (VTK's 2D charts): height against time and its spectrum.
#include "vtk_chart.hpp"

#include <fmt/format.h>
#include <vtkAxis.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPlot.h>
#include <vtkRenderWindow.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include "vtk_output.hpp"
#include "vtk_png.hpp"

namespace tidewater::inspect {

namespace {

vtkNew<vtkTable> table_of(const char* x_name, const std::vector<double>& x, const char* y_name,
                          const std::vector<double>& y, std::size_t count) {
    vtkNew<vtkTable> table;
    vtkNew<vtkDoubleArray> xs, ys;
    xs->SetName(x_name);
    ys->SetName(y_name);
    for (std::size_t k = 0; k < count; ++k) xs->InsertNextValue(x[k]), ys->InsertNextValue(y[k]);
    table->AddColumn(xs);
    table->AddColumn(ys);
    return table;
}

void style(vtkChartXY* chart, const std::string& title, const char* x_title, const char* y_title) {
    chart->SetTitle(title.c_str());
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(x_title);
    chart->GetAxis(vtkAxis::LEFT)->SetTitle(y_title);
}

}  // namespace

vtkSmartPointer<vtkContextView> probe_view(const ProbeSeries& p, int width, int height, bool offscreen) {
    auto series = table_of("t (s)", p.time, "height (m)", p.height, p.time.size());
    // The spectrum up to 4 times the dominant frequency.
    std::size_t shown = p.frequency.size();
    if (p.dominant_period > 0.0)
        while (shown > 2 && p.frequency[shown - 1] > 4.0 / p.dominant_period) --shown;
    auto spectrum = table_of("f (Hz)", p.frequency, "power (m^2/Hz)", p.power, shown);

    auto view = vtkSmartPointer<vtkContextView>::New();
    view->GetRenderWindow()->SetOffScreenRendering(offscreen ? 1 : 0);
    view->GetRenderWindow()->SetSize(width, height);
    view->GetRenderWindow()->SetWindowName("tidewater probe");
    vtkNew<vtkChartMatrix> matrix;
    matrix->SetSize(vtkVector2i(2, 1));
    view->GetScene()->AddItem(matrix);
    auto* left = vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(0, 0)));
    auto* right = vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(1, 0)));
    vtkPlot* line = left->AddPlot(vtkChart::LINE);
    line->SetInputData(series, 0, 1);
    line->SetColor(31, 119, 180, 255);
    style(left, fmt::format("height at x = {:g}, z = {:g} m", p.at.x, p.at.y), "t, s", "height, m");
    vtkPlot* power = right->AddPlot(vtkChart::LINE);
    power->SetInputData(spectrum, 0, 1);
    power->SetColor(214, 39, 40, 255);
    style(right,
          p.dominant_period > 0.0 ? fmt::format("spectrum: dominant period {:.3f} s", p.dominant_period)
                                  : std::string("spectrum: the height does not change here (dry land or still water)"),
          "frequency, Hz", "power, m^2/Hz");
    return view;
}

Status probe_chart(const ProbeSeries& p, const std::filesystem::path& png, int width, int height) {
    if (width < 200 || height < 120 || width > 8192 || height > 8192)
        return Error{ErrorCode::invalid_argument, fmt::format("chart size {}x{}: 200x120 to 8192x8192", width, height)};
    auto view = probe_view(p, width, height, true);
    return save_window_png(view->GetRenderWindow(), png);
}

Status overlay_chart(const std::vector<double>& axis, const std::vector<double>& measured,
                     const std::vector<double>& model, const std::string& title, const std::string& x_title,
                     const std::filesystem::path& png, int width, int height) {
    if (axis.empty() || measured.size() != axis.size() || model.size() != axis.size())
        return Error{ErrorCode::invalid_argument, "overlay chart: the series have different lengths"};
    vtkNew<vtkTable> table;
    vtkNew<vtkDoubleArray> x, m, p;
    x->SetName(x_title.c_str());
    m->SetName("measured");
    p->SetName("preset");
    for (std::size_t k = 0; k < axis.size(); ++k)
        x->InsertNextValue(axis[k]), m->InsertNextValue(measured[k]), p->InsertNextValue(model[k]);
    table->AddColumn(x);
    table->AddColumn(m);
    table->AddColumn(p);
    vtkNew<vtkContextView> view;
    view->GetRenderWindow()->SetOffScreenRendering(1);
    view->GetRenderWindow()->SetSize(width, height);
    vtkNew<vtkChartXY> chart;
    view->GetScene()->AddItem(chart);
    vtkPlot* measured_line = chart->AddPlot(vtkChart::LINE);
    measured_line->SetInputData(table, 0, 1);
    measured_line->SetColor(31, 119, 180, 255);
    vtkPlot* model_line = chart->AddPlot(vtkChart::LINE);
    model_line->SetInputData(table, 0, 2);
    model_line->SetColor(214, 39, 40, 255);
    chart->SetShowLegend(true);
    style(chart, title, x_title.c_str(), "elevation, m");
    return save_window_png(view->GetRenderWindow(), png);
}

}  // namespace tidewater::inspect
