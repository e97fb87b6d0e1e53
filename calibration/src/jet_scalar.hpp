// The plain value of a double or a Ceres Jet (private to the Ceres translation units).
#pragma once

#include <ceres/jet.h>

namespace tidewater::calibration::detail {

inline double scalar(double v) {
    return v;
}
template <typename T, int N>
double scalar(const ceres::Jet<T, N>& v) {
    return v.a;
}

}  // namespace tidewater::calibration::detail
