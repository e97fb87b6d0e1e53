// First-arrival eikonal solve |grad T| = s(x) on a grid of square texels by fast marching
// (Sethian 1996) with second-order upwind differences where two known values line up,
// first order elsewhere; and its re-solve round a local change of s. Private.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "tidewater/constants.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater::detail {

inline constexpr double kUnreached = std::numeric_limits<double>::infinity();

/// A wave's phase is marched from deep water (k h >= kDeepKh, where tanh(k h) > 0.996),
/// where the open-ocean phase holds.
inline constexpr double kDeepKh = 3.14159265358979323846;

/// A wave's local wavenumber k(h) (rad/m; 0 on land, h <= 0) at still-water depth h, as
/// the marches and every field baked from them read it: in float, the precision of the
/// depths it comes from, so that a march's slowness grid takes half a double grid's memory.
inline float marched_wavenumber(double omega, double h) {
    return h > 0.0 ? static_cast<float>(wavenumber_at_depth(omega, h)) : 0.0f;
}
/// Whether the water is deep for the wave there (k h >= kDeepKh), `k` its marched wavenumber.
inline bool marched_deep(float k, double h) {
    return h > 0.0 && static_cast<double>(k) * h >= kDeepKh;
}

/// Whether depth h (m) is deep water for a wave of angular frequency `omega` (rad/s):
/// marched_deep of its marched_wavenumber, the same answer, without solving the
/// dispersion but within a ten-thousandth of the depth where k h = kDeepKh (k h grows with
/// h, a ten-thousandth of it there: a thousand times the float's rounding). An edit asks
/// it of every texel its re-marches cross.
inline bool marched_deep_water(double omega, double h) {
    static const double kTanhDeepKh = std::tanh(kDeepKh);
    const double threshold = kDeepKh * kTanhDeepKh * kGravity / (omega * omega);  // omega^2 = g k tanh(k h)
    if (h < threshold * (1.0 - 1e-4)) return false;
    if (h > threshold * (1.0 + 1e-4)) return true;
    return marched_deep(marched_wavenumber(omega, h), h);
}

/// Whether texel (i, j) of an n x n grid is a source of a wave's marched phase (its
/// open-ocean phase there): deep water (`deep`) where the grid has any (`any_deep`), else
/// an edge the wave enters through (direction x, z): shallow edges would otherwise pin
/// the unrefracted phase along them.
inline bool phase_source(bool any_deep, bool deep, int i, int j, int n, double dir_x, double dir_z) {
    if (any_deep) return deep;
    return (i == 0 && dir_x > 0.05) || (i == n - 1 && dir_x < -0.05) || (j == 0 && dir_z > 0.05) ||
           (j == n - 1 && dir_z < -0.05);
}

/// `slowness` per texel (<= 0 marks a blocked texel); `value` holds the known sources
/// (finite) and kUnreached elsewhere, and receives the arrival values; `h` is the texel size.
void fast_march(const std::vector<float>& slowness, std::vector<double>& value, int n, double h);

/// Texels [i0, i1) x [j0, j1) of a grid.
struct TexelWindow {
    int i0 = 0, j0 = 0, i1 = 0, j1 = 0;
    bool contains(int i, int j) const { return i >= i0 && i < i1 && j >= j0 && j < j1; }
};

/// A first-arrival solution over an n x n grid, before and after its slowness changed.
struct MarchChange {
    int n = 0;
    double h = 0.0;                           ///< texel size
    std::function<float(int, int)> slowness;  ///< after the change (<= 0: blocked)
    std::function<double(int, int)> source;   ///< after: a source's value, else kUnreached
    std::function<double(int, int)> before;   ///< the solution before (kUnreached: unreached)
    TexelWindow changed;                      ///< where slowness or sources changed
    double tolerance = 1e-3;                  ///< on the values, in their units
};

/// The solution after the change, re-solved in a window round it.
struct MarchWindow {
    TexelWindow window;
    std::vector<double> value;  ///< row-major over the window
    int solves = 0;             ///< windows marched until the one returned
    double at(int i, int j) const {
        return value[static_cast<std::size_t>(j - window.j0) * static_cast<std::size_t>(window.i1 - window.i0) +
                     static_cast<std::size_t>(i - window.i0)];
    }
};

/// Marches the window `change.changed` grown by `margin` texels from the values round it
/// (two rings of the solution before, frozen), then compares the two texels along each
/// side of the window with the solution before: where one differs by more than the
/// tolerance, the change reaches past that side, which grows by the margin (doubled at
/// each growth), and the window is marched again, until none differs or the window is the
/// whole grid. Outside the window the solution before stands, within about the tolerance
/// of a full solve's.
MarchWindow remarch(const MarchChange& change, int margin);

}  // namespace tidewater::detail
