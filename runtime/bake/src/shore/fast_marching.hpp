// First-arrival eikonal solve |grad T| = s(x) on a square grid by fast marching
// (Sethian 1996) with second-order upwind differences where two known values line up,
// first order elsewhere. Private.
#pragma once

#include <limits>
#include <vector>

namespace tidewater::detail {

inline constexpr double kUnreached = std::numeric_limits<double>::infinity();

/// `slowness` per texel (<= 0 marks a blocked texel); `value` holds the known sources
/// (finite) and kUnreached elsewhere, and receives the arrival values; `h` is the texel size.
void fast_march(const std::vector<double>& slowness, std::vector<double>& value, int n, double h);

}  // namespace tidewater::detail
