#include "tidewater/calibration/plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tidewater::calibration {

namespace {

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

/// About five round tick values covering [lo, hi].
std::vector<double> ticks(double lo, double hi) {
    const double span = hi - lo;
    if (!(span > 0.0)) return {lo};
    const double raw = span / 5.0, mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2.0 * mag : raw / mag < 7.5 ? 5.0 * mag : 10.0 * mag;
    std::vector<double> t;
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step)
        t.push_back(std::abs(v) < 1e-12 * span ? 0.0 : v);
    return t;
}

}  // namespace

std::string line_chart_svg(const std::vector<ChartSeries>& series, const std::string& title, const std::string& x_label,
                           const std::string& y_label, int width, int height) {
    const double left = 70, right = 20, top = 34, bottom = 46;
    const double pw = width - left - right, ph = height - top - bottom;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    auto value = [](const ChartSeries& s, std::size_t k) {
        return s.log_y ? (s.y[k] > 0.0 ? std::log10(s.y[k]) : std::numeric_limits<double>::quiet_NaN()) : s.y[k];
    };
    for (const auto& s : series)
        for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
            const double v = value(s, k);
            if (!std::isfinite(v) || !std::isfinite(s.x[k])) continue;
            x0 = std::min(x0, s.x[k]), x1 = std::max(x1, s.x[k]), y0 = std::min(y0, v), y1 = std::max(y1, v);
        }
    if (!(x1 > x0)) x0 -= 1.0, x1 += 1.0;
    if (!(y1 > y0)) y0 -= 1.0, y1 += 1.0;
    const double pad = 0.05 * (y1 - y0);
    y0 -= pad, y1 += pad;
    auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * pw; };
    auto py = [&](double y) { return top + (1.0 - (y - y0) / (y1 - y0)) * ph; };
    std::string svg = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\" "
        "font-size=\"12\">\n"
        "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        "<text x=\"{}\" y=\"20\" font-size=\"14\" text-anchor=\"middle\">{}</text>\n",
        width, height, width / 2, escape(title));
    const bool log_y = !series.empty() && series.front().log_y;
    for (double t : ticks(x0, x1))
        svg += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\" stroke=\"#ddd\"/><text x=\"{0:.1f}\" "
            "y=\"{3:.1f}\" "
            "text-anchor=\"middle\">{4:g}</text>\n",
            px(t), top, top + ph, top + ph + 16, t);
    for (double t : ticks(y0, y1))
        svg += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"#ddd\"/><text x=\"{3:.1f}\" "
            "y=\"{4:.1f}\" "
            "text-anchor=\"end\">{5}</text>\n",
            left, py(t), left + pw, left - 6, py(t) + 4, log_y ? fmt::format("1e{:g}", t) : fmt::format("{:g}", t));
    svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>\n", left,
                       top, pw, ph);
    svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", left + pw / 2, height - 8,
                       escape(x_label));
    svg += fmt::format("<text transform=\"translate(16,{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
                       top + ph / 2, escape(y_label));
    for (std::size_t i = 0; i < series.size(); ++i) {
        const ChartSeries& s = series[i];
        std::string points;
        for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
            const double v = value(s, k);
            if (std::isfinite(v)) points += fmt::format("{:.1f},{:.1f} ", px(s.x[k]), py(v));
        }
        svg += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.3\" points=\"{}\"/>\n", s.colour,
                           points);
        const double ly = top + 14 + 16 * static_cast<double>(i);
        svg += fmt::format(
            "<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" stroke-width=\"2\"/>"
            "<text x=\"{4:.1f}\" y=\"{5:.1f}\">{6}</text>\n",
            left + pw - 170, ly, left + pw - 150, s.colour, left + pw - 144, ly + 4, escape(s.label));
    }
    return svg + "</svg>\n";
}

}  // namespace tidewater::calibration
