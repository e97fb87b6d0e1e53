#include "tidewater/clock.hpp"

#include <cmath>

namespace tidewater {

void Clock::advance(double real_seconds) {
    if (paused_ || !std::isfinite(real_seconds) || real_seconds <= 0.0) return;
    time_ += real_seconds * scale_;
}

bool Clock::set_scale(double scale) {
    if (!std::isfinite(scale) || scale < 0.0) return false;
    scale_ = scale;
    return true;
}

}  // namespace tidewater
