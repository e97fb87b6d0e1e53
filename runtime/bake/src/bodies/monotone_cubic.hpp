// Monotone piecewise-cubic interpolation (Fritsch and Carlson 1980): between samples
// it never overshoots them, so a non-increasing profile stays non-increasing (private).
#pragma once

#include <vector>

namespace tidewater::detail {

class MonotoneCubic {
  public:
    MonotoneCubic() = default;
    /// `x` strictly increasing, `y` the values there (at least two samples).
    MonotoneCubic(std::vector<double> x, std::vector<double> y);
    /// The interpolant at x, held constant beyond the ends.
    double operator()(double x) const;

  private:
    std::vector<double> x_, y_, slope_;
};

}  // namespace tidewater::detail
