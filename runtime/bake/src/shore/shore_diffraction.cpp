#include "shore/shore_diffraction.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <utility>

#include "shore/fast_marching.hpp"
#include "shore/parabolic_waves.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/detail/grid_taps.hpp"
#include "tidewater/dispersion.hpp"

namespace tidewater::detail {

namespace {

/// Points the march needs across a wave's crests (a wavelength across the march): all of
/// its share from the first, none under the second.
inline constexpr double kFullPoints = 3.0, kNoPoints = 2.0;
/// The march's spacing: at most the grid's texel and this part of the deep-water wavelength,
/// but no finer than this part of the texel: the amplitude is kept per texel, so a wave
/// shorter than the texel is left to the rays, and a march visits at most 8 times the
/// grid's texels (its frame is turned), not the area over the shortest wave's wavelength
/// squared.
inline constexpr double kPointsPerDeepWavelength = 8.0;
inline constexpr double kPointsPerTexel = 2.0;

/// The march's frame over the grid: x' along the wave, y' across; its first point and spacing.
struct MarchFrame {
    glm::dvec2 along, across;
    double x0 = 0.0, y0 = 0.0, spacing = 0.0;
    int steps = 0, points = 0;
    glm::dvec2 world(double x, double y) const { return x * along + y * across; }
};

MarchFrame march_frame(const Wave& wave, const ShoreField& field) {
    MarchFrame f;
    f.along = {wave.dir_x, wave.dir_z};
    f.across = {-wave.dir_z, wave.dir_x};
    const double side = field.texel * field.resolution;
    double x1 = -1e300, y1 = -1e300;
    f.x0 = f.y0 = 1e300;
    for (const glm::dvec2 c : {glm::dvec2(0.0), glm::dvec2(side, 0.0), glm::dvec2(0.0, side), glm::dvec2(side)}) {
        const glm::dvec2 p = field.corner + c;
        f.x0 = std::min(f.x0, glm::dot(p, f.along));
        x1 = std::max(x1, glm::dot(p, f.along));
        f.y0 = std::min(f.y0, glm::dot(p, f.across));
        y1 = std::max(y1, glm::dot(p, f.across));
    }
    f.spacing =
        std::max(field.texel / kPointsPerTexel, std::min(field.texel, kTwoPi / wave.k / kPointsPerDeepWavelength));
    const double area = (x1 - f.x0) * (y1 - f.y0);
    if (area / (f.spacing * f.spacing) > kMaxDiffractionPoints) f.spacing = std::sqrt(area / kMaxDiffractionPoints);
    f.steps = static_cast<int>(std::ceil((x1 - f.x0) / f.spacing)) + 2;
    f.points = static_cast<int>(std::ceil((y1 - f.y0) / f.spacing)) + 2;
    return f;
}

/// The texels to fill, grouped by the march row just before them. On the finest grids two
/// waves' buckets are held at once, so they are small: texel indices in 32 bits (a grid
/// is at most 8192 texels a side), and each texel's row found twice, in a counting pass
/// and a placing pass, with a byte a texel between them rather than its row.
struct RowBuckets {
    std::vector<std::size_t> offsets;  ///< per row, into texels (one past the last row too)
    std::vector<std::uint32_t> texels;
    int first_row = 0;  ///< the first row that holds a texel to fill or land
};

RowBuckets bucket_texels(const ShoreField& field, const MarchFrame& f, const std::function<bool(std::size_t)>& keep) {
    const int n = field.resolution;
    RowBuckets b;
    b.offsets.assign(static_cast<std::size_t>(f.steps) + 1, 0);
    b.first_row = f.steps;
    auto row_of = [&](int i, int j) {
        const double x = (glm::dot(field.texel_center(i, j), f.along) - f.x0) / f.spacing;
        return std::clamp(static_cast<int>(std::floor(x)), 0, f.steps - 2);
    };
    std::vector<std::uint8_t> fill(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t k = field.index(i, j);
            const bool land = field.depth[k] <= 0.0f;
            const bool kept = keep(k);
            if (land || !kept) b.first_row = std::min(b.first_row, row_of(i, j));
            if (land || kept) continue;
            fill[k] = 1;
            ++b.offsets[static_cast<std::size_t>(row_of(i, j)) + 1];
        }
    for (std::size_t r = 1; r < b.offsets.size(); ++r) b.offsets[r] += b.offsets[r - 1];
    b.texels.resize(b.offsets.back());
    std::vector<std::size_t> next(b.offsets.begin(), b.offsets.end() - 1);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t k = field.index(i, j);
            if (fill[k]) b.texels[next[static_cast<std::size_t>(row_of(i, j))]++] = static_cast<std::uint32_t>(k);
        }
    return b;
}

/// A row's magnitudes |A| and breaking, kept for the step after it.
struct KeptRow {
    std::vector<double> magnitude;
    std::vector<char> broken;
    void keep(const ParabolicRow& row) {
        magnitude.resize(row.amplitude.size());
        for (std::size_t j = 0; j < magnitude.size(); ++j) magnitude[j] = std::sqrt(std::norm(row.amplitude[j]));
        broken.assign(row.broken.begin(), row.broken.end());
    }
};

}  // namespace

double ramp(double value, double none, double full) {
    return std::clamp((value - none) / (full - none), 0.0, 1.0);
}

double march_share(double angle, double wavelength, double spacing) {
    const double across = std::abs(std::sin(angle)) * spacing;  // the march's spacing along the crests' normal
    const double points = across > 0.0 ? wavelength / across : kFullPoints;
    return ramp(angle, kNoAngle, kFullAngle) * ramp(points, kNoPoints, kFullPoints);
}

SeaState sea_state(std::span<const Wave> waves) {
    SeaState s;
    double weighted = 0.0;
    for (const Wave& w : waves) {
        const double e = w.amplitude * w.amplitude;
        if (e > 0.0) ++s.components;
        s.energy += e;
        weighted += e * w.period();
    }
    s.mean_period = s.energy > 0.0 ? weighted / s.energy : 0.0;
    return s;
}

DiffractedWave diffract_wave(const Wave& wave, const SeaState& sea, const ShoreField& field,
                             const std::function<bool(std::size_t)>& keep, const SeaHeight* sea_height) {
    const std::size_t count = static_cast<std::size_t>(field.resolution) * static_cast<std::size_t>(field.resolution);
    DiffractedWave out;
    out.share.assign(count, 0);
    out.amplitude.assign(count, 0.0f);
    out.broken.assign(count, 0);
    if (!(wave.amplitude > 0.0)) return out;
    const MarchFrame frame = march_frame(wave, field);
    out.spacing = frame.spacing;
    // A wave shorter than the texel (under 2 points a deep-water wavelength at the finest
    // spacing) is left to the rays: one amplitude a texel cannot hold what it would do.
    if (kTwoPi / wave.k / frame.spacing < kNoPoints) return out;
    const RowBuckets buckets = bucket_texels(field, frame, keep);
    if (buckets.texels.empty()) return out;
    // Rows before the first texel to fill or land are open sea: the march starts just before.
    const int start = std::max(0, buckets.first_row - 2);
    const double x_start = frame.x0 + start * frame.spacing;

    ParabolicInput in;
    in.grid = {frame.steps - start, frame.points, frame.spacing, frame.spacing};
    in.omega = wave.omega;
    in.depth_row = [&](int step, std::span<float> depth) {
        const double x = x_start + step * frame.spacing;
        for (std::size_t j = 0; j < depth.size(); ++j)
            depth[j] = static_cast<float>(
                field.sample(field.depth, frame.world(x, frame.y0 + static_cast<double>(j) * frame.spacing)));
    };
    in.incident_amplitude = wave.amplitude;
    in.incident_in_deep_water = true;
    in.sea_over_component = std::sqrt(sea.energy) / wave.amplitude;
    in.sea_period = sea.mean_period;
    in.random_sea = sea.components > 1;
    if (in.random_sea && sea_height != nullptr)
        in.sea_height_row = [&](int step, std::span<float> height) {
            const double x = x_start + step * frame.spacing;
            for (std::size_t j = 0; j < height.size(); ++j)
                height[j] = static_cast<float>(
                    sea_height->at(frame.world(x, frame.y0 + static_cast<double>(j) * frame.spacing)));
        };

    KeptRow before, after;
    const double s = frame.spacing;
    march_parabolic(in, [&](const ParabolicRow& row) {
        after.keep(row);
        if (row.step > 0) {
            const int r = start + row.step - 1;  // the texels between the row before and this one
            for (std::size_t at = buckets.offsets[static_cast<std::size_t>(r)];
                 at < buckets.offsets[static_cast<std::size_t>(r) + 1]; ++at) {
                const std::size_t k = buckets.texels[at];
                const int i = static_cast<int>(k % static_cast<std::size_t>(field.resolution)),
                          jj = static_cast<int>(k / static_cast<std::size_t>(field.resolution));
                const glm::dvec2 p = field.texel_center(i, jj);
                const double u = std::clamp((glm::dot(p, frame.along) - frame.x0) / s - r, 0.0, 1.0);
                const double fy = (glm::dot(p, frame.across) - frame.y0) / s;
                const auto j0 =
                    static_cast<std::size_t>(std::clamp(static_cast<int>(std::floor(fy)), 0, frame.points - 2));
                const double v = std::clamp(fy - static_cast<double>(j0), 0.0, 1.0);
                const double m00 = before.magnitude[j0], m01 = before.magnitude[j0 + 1];
                const double m10 = after.magnitude[j0], m11 = after.magnitude[j0 + 1];
                auto lerp = [&](double q00, double q01, double q10, double q11) {
                    return (1 - u) * ((1 - v) * q00 + v * q01) + u * ((1 - v) * q10 + v * q11);
                };
                const double magnitude = lerp(m00, m01, m10, m11);
                const double brk = lerp(before.broken[j0], before.broken[j0 + 1], row.broken[j0], row.broken[j0 + 1]);
                out.share[k] = std::max({m00, m01, m10, m11}) > 1e-6 * wave.amplitude ? 255 : 0;
                out.amplitude[k] = static_cast<float>(magnitude / wave.amplitude);
                out.broken[k] = brk >= 0.5 ? 1 : 0;
            }
        }
        std::swap(before, after);
    });
    return out;
}

double SeaHeight::at(glm::dvec2 p) const {
    if (field == nullptr || height.empty()) return 0.0;
    const GridTaps taps = grid_taps(field->corner, field->texel, field->resolution, field->resolution, p);
    double sum = 0.0, weight = 0.0;
    for (const auto& [k, w] : {std::pair{taps.k00, taps.w00}, std::pair{taps.k10, taps.w10},
                               std::pair{taps.k01, taps.w01}, std::pair{taps.k11, taps.w11}}) {
        if (!(height[k] > 0.0f) || w <= 0.0) continue;
        sum += w * static_cast<double>(height[k]);
        weight += w;
    }
    return weight > 0.0 ? sum / weight : 0.0;
}

SeaHeight march_sea(std::span<const Wave> waves, const SeaState& sea, std::shared_ptr<const ShoreField> grid) {
    SeaHeight out;
    if (!grid) return out;
    const ShoreField& field = *grid;
    out.field = std::move(grid);
    glm::dvec2 heading(0.0);
    for (const Wave& w : waves) heading += w.amplitude * w.amplitude * glm::dvec2(w.dir_x, w.dir_z);
    const double length = glm::length(heading);
    if (sea.components < 2 || !(sea.mean_period > 0.0) || !(length > 0.0)) return out;
    Wave whole;
    whole.dir_x = heading.x / length;
    whole.dir_z = heading.y / length;
    whole.omega = kTwoPi / sea.mean_period;
    whole.k = whole.omega * whole.omega / kGravity;
    whole.amplitude = std::sqrt(sea.energy);
    // Deep water for the sea's mean wave is the open sea's: nothing breaks there.
    const DiffractedWave marched = diffract_wave(whole, sea, field, [&](std::size_t k) {
        return static_cast<double>(field.depth.values()[k]) * whole.k >= kDeepKh;
    });
    out.height.assign(marched.amplitude.size(), 0.0f);
    for (std::size_t k = 0; k < out.height.size(); ++k)
        if (marched.share[k] > 0)
            out.height[k] = static_cast<float>(2.0 * whole.amplitude * static_cast<double>(marched.amplitude[k]));
    return out;
}

}  // namespace tidewater::detail
