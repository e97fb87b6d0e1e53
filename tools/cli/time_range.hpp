// Time options of the CLI: a single time or a "t0:t1:dt" range.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater::cli {

inline constexpr double kMaxAbsTime = 1e9;  ///< s; beyond this nothing is meaningful.
inline constexpr std::size_t kMaxTimeSteps = 1'000'000;

/// Checks a single time value named `option` in messages.
Status check_time(double t, const char* option);
/// Parses "t0:t1:dt" into t0, t0+dt, ... <= t1 (inclusive within dt/1e6).
Result<std::vector<double>> parse_time_range(const std::string& text, const char* option);
/// The times of a verb's --time / --times pair: exactly one must be given.
Result<std::vector<double>> times_from_options(const std::optional<double>& time, const std::string& times);

}  // namespace tidewater::cli
