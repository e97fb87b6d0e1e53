// Shared by the spectral-file readers (private).
#pragma once

#include "tidewater/calibration/spectrum.hpp"

namespace tidewater::calibration {

/// Sets bin k's energy-weighted travel vector and r1 from the direction waves come
/// from (degrees clockwise from true north) and r1.
void set_direction(MeasuredSpectrum& s, std::size_t k, double from_deg, double r1);

}  // namespace tidewater::calibration
