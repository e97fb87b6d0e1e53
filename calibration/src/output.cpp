#include "tidewater/calibration/output.hpp"

#include <algorithm>
#include <cmath>

#include "tidewater/constants.hpp"

namespace tidewater::calibration {

WaveSpec to_wave_spec(const FittedWave& w) {
    WaveSpec s;
    s.direction_deg = w.direction_deg;
    s.wavelength = kTwoPi * kGravity / (w.omega * w.omega);
    s.amplitude = w.amplitude;
    s.steepness = w.steepness;
    s.phase = w.phase;
    return s;
}

nlohmann::json preset_json(const std::string& name, const std::string& description,
                           const std::vector<WaveSpec>& waves) {
    nlohmann::json list = nlohmann::json::array();
    for (const WaveSpec& w : waves)
        list.push_back({{"direction", w.direction_deg},
                        {"wavelength", w.wavelength},
                        {"amplitude", w.amplitude},
                        {"steepness", w.steepness},
                        {"phase", w.phase}});
    return {{"version", 1}, {"name", name}, {"description", description}, {"waves", list}};
}

SeaState sea_state_of(const std::vector<WaveSpec>& waves) {
    SeaState s;
    double energy = 0.0, e = 0.0, n = 0.0, biggest = -1.0;
    for (const WaveSpec& w : waves) {
        energy += 0.5 * w.amplitude * w.amplitude;
        const double rad = w.direction_deg * kPi / 180.0;
        e += w.amplitude * w.amplitude * std::cos(rad);
        n += w.amplitude * w.amplitude * std::sin(rad);
        if (w.amplitude > biggest) {
            biggest = w.amplitude;
            s.tp = std::sqrt(kTwoPi * w.wavelength / kGravity);
            s.peak_from_deg = std::fmod(270.0 - w.direction_deg + 720.0, 360.0);
        }
    }
    s.hs = 4.0 * std::sqrt(energy);
    const double mean = std::atan2(n, e) * 180.0 / kPi;
    s.mean_travel_deg = mean < 0.0 ? mean + 360.0 : mean;
    return s;
}

}  // namespace tidewater::calibration
