// Measured-versus-model charts as SVG (plain text: any browser or README shows them).
#pragma once

#include <string>
#include <vector>

namespace tidewater::calibration {

struct ChartSeries {
    std::string label;
    std::vector<double> x, y;
    std::string colour = "#1f77b4";
    bool log_y = false;  ///< Plot log10(y) (spectra); non-positive values are dropped.
};

/// A line chart with axes, ticks, a title and a legend, `width` x `height` pixels.
std::string line_chart_svg(const std::vector<ChartSeries>& series, const std::string& title, const std::string& x_label,
                           const std::string& y_label, int width = 900, int height = 360);

}  // namespace tidewater::calibration
