// Physical constants and limits shared by the CPU model and the shaders.
#pragma once

#include <cstddef>

namespace tidewater {

inline constexpr double kGravity = 9.81;  ///< m/s^2
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;

/// Most Gerstner waves one water body may hold (GPU uniform arrays are sized by it).
inline constexpr std::size_t kMaxWaves = 64;

/// The fold-free rule: the horizontal map is one-to-one while sum(Q*k*A) <= this.
inline constexpr double kFoldLimit = 1.0;

}  // namespace tidewater
