#include "time_range.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string_view>

namespace tidewater::cli {

Status check_time(double t, const char* option) {
    if (!std::isfinite(t) || std::abs(t) > kMaxAbsTime) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: {} is out of range (allowed: finite, |t| <= 1e9 s)", option, t)};
    }
    return {};
}

Result<std::vector<double>> parse_time_range(const std::string& text, const char* option) {
    double v[3] = {0, 0, 0};
    std::string_view rest = text;
    for (int i = 0; i < 3; ++i) {
        const std::size_t colon = rest.find(':');
        if ((i < 2) != (colon != std::string_view::npos)) {
            return Error{ErrorCode::invalid_argument, fmt::format("{}: \"{}\" is not t0:t1:dt", option, text)};
        }
        const std::string_view part = rest.substr(0, colon);
        const auto res = std::from_chars(part.data(), part.data() + part.size(), v[i]);
        if (res.ec != std::errc() || res.ptr != part.data() + part.size() || !std::isfinite(v[i])) {
            return Error{ErrorCode::invalid_argument,
                         fmt::format("{}: \"{}\" in \"{}\" is not a finite number", option, part, text)};
        }
        rest = colon == std::string_view::npos ? std::string_view{} : rest.substr(colon + 1);
    }
    const double t0 = v[0], t1 = v[1], dt = v[2];
    if (auto st = check_time(t0, option); !st) return st.error();
    if (auto st = check_time(t1, option); !st) return st.error();
    if (!(dt > 0.0)) return Error{ErrorCode::invalid_argument, fmt::format("{}: dt must be > 0 (got {})", option, dt)};
    if (t1 < t0)
        return Error{ErrorCode::invalid_argument, fmt::format("{}: t1 ({}) is before t0 ({})", option, t1, t0)};
    const double steps = std::floor((t1 - t0) / dt * (1.0 + 1e-9) + 1e-6) + 1.0;
    if (steps > static_cast<double>(kMaxTimeSteps)) {
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: {} steps requested, at most {} allowed", option, steps, kMaxTimeSteps)};
    }
    std::vector<double> times;
    times.reserve(static_cast<std::size_t>(steps));
    for (std::size_t i = 0; i < static_cast<std::size_t>(steps); ++i) times.push_back(t0 + static_cast<double>(i) * dt);
    return times;
}

Result<std::vector<double>> times_from_options(const std::optional<double>& time, const std::string& times) {
    if (time.has_value() == !times.empty())
        return Error{ErrorCode::invalid_argument, "give exactly one of --time and --times"};
    if (!time) return parse_time_range(times, "--times");
    if (auto st = check_time(*time, "--time"); !st) return st.error();
    return std::vector<double>{*time};
}

}  // namespace tidewater::cli
