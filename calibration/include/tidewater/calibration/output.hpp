// What a fit writes: a preset the runtime loads unchanged, and a report.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tidewater/calibration/phase_fit.hpp"
#include "tidewater/calibration/record.hpp"
#include "tidewater/calibration/spectrum.hpp"
#include "tidewater/waves.hpp"

namespace tidewater::calibration {

/// The runtime's wave for a fitted one: deep-water wavelength 2 pi g / omega^2 (the
/// frequency is what the runtime conserves over depth), direction, amplitude, Q, phase.
WaveSpec to_wave_spec(const FittedWave& wave);

/// A preset JSON document (examples/presets format).
nlohmann::json preset_json(const std::string& name, const std::string& description, const std::vector<WaveSpec>& waves);

/// Hs, Tp and mean direction of a set of waves (Hs = 4 sqrt(sum A^2 / 2); Tp of the
/// largest; mean = amplitude^2-weighted circular mean of the travel directions).
SeaState sea_state_of(const std::vector<WaveSpec>& waves);

}  // namespace tidewater::calibration
