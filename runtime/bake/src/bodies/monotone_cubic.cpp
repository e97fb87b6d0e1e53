#include "bodies/monotone_cubic.hpp"

#include <algorithm>
#include <cmath>

namespace tidewater::detail {

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
    const std::size_t n = x_.size();
    slope_.assign(n, 0.0);
    if (n < 2) return;
    std::vector<double> secant(n - 1);
    for (std::size_t k = 0; k + 1 < n; ++k) secant[k] = (y_[k + 1] - y_[k]) / (x_[k + 1] - x_[k]);
    slope_[0] = secant[0];
    slope_[n - 1] = secant[n - 2];
    for (std::size_t k = 1; k + 1 < n; ++k)
        slope_[k] = secant[k - 1] * secant[k] <= 0.0 ? 0.0 : 0.5 * (secant[k - 1] + secant[k]);
    // Limit the tangents so that each interval stays monotone (alpha^2 + beta^2 <= 9).
    for (std::size_t k = 0; k + 1 < n; ++k) {
        if (secant[k] == 0.0) {
            slope_[k] = slope_[k + 1] = 0.0;
            continue;
        }
        const double a = slope_[k] / secant[k], b = slope_[k + 1] / secant[k];
        if (a < 0.0) slope_[k] = 0.0;
        if (b < 0.0) slope_[k + 1] = 0.0;
        const double r = a * a + b * b;
        if (r > 9.0) {
            const double t = 3.0 / std::sqrt(r);
            slope_[k] = t * a * secant[k];
            slope_[k + 1] = t * b * secant[k];
        }
    }
}

double MonotoneCubic::operator()(double x) const {
    if (x_.empty()) return 0.0;
    if (x <= x_.front()) return y_.front();
    if (x >= x_.back()) return y_.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
    const double h = x_[k + 1] - x_[k], t = (x - x_[k]) / h;
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y_[k] + (t3 - 2 * t2 + t) * h * slope_[k] + (-2 * t3 + 3 * t2) * y_[k + 1] +
           (t3 - t2) * h * slope_[k + 1];
}

}  // namespace tidewater::detail
