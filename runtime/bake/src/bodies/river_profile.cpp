#include "bodies/river_profile.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace tidewater::detail {

namespace {

/// Lateral samples of a section (odd: one on the centreline).
constexpr std::size_t kSectionSamples = 33;

glm::dvec2 left_normal(glm::dvec2 t) {
    return {-t.y, t.x};
}

glm::dvec2 tangent_at(const CentrelineSamples& s, std::size_t k) {
    const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(k + 1, s.points.size() - 1);
    const glm::dvec2 d = s.points[b] - s.points[a];
    return d / std::sqrt(d.x * d.x + d.y * d.y);
}

/// The root above `from` of a function increasing in x, negative at `from`: its bracket
/// grows from `scale` (a length of the problem's own: a section's width) by doubling,
/// then bisection. No length of its own: a flume's millimetres and a delta's metres alike.
template <typename F>
double increasing_root_above(F f, double from, double scale) {
    double lo = from, hi = from + scale;
    for (int grow = 0; grow < 64 && f(hi) < 0.0; ++grow) {
        lo = hi;
        hi = from + 2.0 * (hi - from);
    }
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

double at_along(const std::vector<double>& along, const std::vector<double>& values, double s) {
    if (s <= along.front()) return values.front();
    if (s >= along.back()) return values.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(along.begin(), along.end(), s) - along.begin()) - 1;
    const double t = (s - along[k]) / (along[k + 1] - along[k]);
    return values[k] + t * (values[k + 1] - values[k]);
}

CentrelineSamples resample_centreline(const std::vector<glm::dvec2>& path, const std::vector<double>& width,
                                      double spacing) {
    CentrelineSamples out;
    double along = 0.0;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        const glm::dvec2 d = path[i + 1] - path[i];
        const double len = std::sqrt(d.x * d.x + d.y * d.y);
        const int steps = std::max(1, static_cast<int>(std::ceil(len / spacing)));
        for (int k = 0; k < steps; ++k) {
            const double t = static_cast<double>(k) / steps;
            out.points.push_back(path[i] + t * d);
            out.along.push_back(along + t * len);
            out.width.push_back(width[i] + t * (width[i + 1] - width[i]));
        }
        along += len;
    }
    out.points.push_back(path.back());
    out.along.push_back(along);
    out.width.push_back(width.back());
    return out;
}

double manning_discharge(const double* bed, int count, double spacing, double eta, double slope, double manning,
                         double* area, double* perimeter) {
    double a = 0.0, p = 0.0;
    for (int j = 0; j + 1 < count; ++j) {
        const double d0 = eta - bed[j], d1 = eta - bed[j + 1];
        if (d0 <= 0.0 && d1 <= 0.0) continue;
        // The wet part of the interval (the waterline crosses it where one end is dry).
        double frac = 1.0, wet0 = std::max(d0, 0.0), wet1 = std::max(d1, 0.0);
        if (d0 <= 0.0 || d1 <= 0.0) frac = std::max(d0, d1) / std::abs(d1 - d0);
        const double run = frac * spacing;
        a += 0.5 * (wet0 + wet1) * run;
        const double rise = frac * (bed[j + 1] - bed[j]);
        p += std::sqrt(run * run + rise * rise);
    }
    if (area) *area = a;
    if (perimeter) *perimeter = p;
    if (a <= 0.0 || p <= 0.0) return 0.0;
    return a * std::pow(a / p, 2.0 / 3.0) * std::sqrt(slope) / manning;
}

std::vector<double> bake_profile(const CentrelineSamples& samples, const ProfileInputs& in, RiverBake& river) {
    const std::size_t n = samples.points.size();
    std::vector<std::array<double, kSectionSamples>> section(n);
    std::vector<double> lowest(n);
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec2 across = left_normal(tangent_at(samples, k));
        double low = 1e300;
        for (std::size_t j = 0; j < kSectionSamples; ++j) {
            const double offset = (static_cast<double>(j) / (kSectionSamples - 1.0) - 0.5) * samples.width[k];
            section[k][j] = in.terrain->height_at(samples.points[k] + offset * across);
            low = std::min(low, section[k][j]);
        }
        // The surface can stand no higher than the section's lowest ground: where the
        // ground falls across the channel (a path along a hillside) water above it would
        // spill over the low bank, and a carved channel would be a sheet over the high side.
        lowest[k] = low;
    }
    // The bed follows the terrain downhill and never rises: a running minimum.
    std::vector<double> bed(n);
    for (std::size_t k = 0; k < n; ++k) bed[k] = k == 0 ? lowest[0] : std::min(bed[k - 1], lowest[k]);
    // The end falls to the level it meets, no steeper than kMouthRampSlope.
    auto meet_mouth = [&](std::vector<double>& profile) {
        if (std::isnan(in.mouth_level)) return;
        const double end = samples.along.back();
        for (std::size_t k = 0; k < n; ++k)
            profile[k] = std::max(in.mouth_level,
                                  std::min(profile[k], in.mouth_level + kMouthRampSlope * (end - samples.along[k])));
    };
    auto slope_of = [&](const std::vector<double>& profile, std::size_t k) {
        // Over about two widths each way: a local dip in the terrain is not a weir.
        const double reach = 2.0 * samples.width[k];
        std::size_t a = k, b = k;
        while (a > 0 && samples.along[k] - samples.along[a] < reach) --a;
        while (b + 1 < n && samples.along[b] - samples.along[k] < reach) ++b;
        if (b == a) return kMinimumSlope;
        return std::max(kMinimumSlope, (profile[a] - profile[b]) / (samples.along[b] - samples.along[a]));
    };
    std::vector<double> surface(n), slope(n), centre_depth(n, 0.0);
    if (in.carve) {
        surface = bed;
        meet_mouth(surface);
        for (std::size_t k = 0; k < n; ++k) {
            slope[k] = slope_of(surface, k);
            const double w = samples.width[k], dn = w / (kSectionSamples - 1.0);
            std::array<double, kSectionSamples> carved{};
            auto shape = [&](double hc) {
                for (std::size_t j = 0; j < kSectionSamples; ++j) {
                    const double x = std::abs(2.0 * static_cast<double>(j) / (kSectionSamples - 1.0) - 1.0);
                    carved[j] = std::min(section[k][j], surface[k] - hc * carved_depth_fraction(x, 2.0 * in.texel / w));
                }
                return manning_discharge(carved.data(), static_cast<int>(kSectionSamples), dn, surface[k], slope[k],
                                         in.manning) -
                       in.discharge[k];
            };
            centre_depth[k] = increasing_root_above(shape, 0.0, w);
            shape(centre_depth[k]);
            bed[k] = *std::min_element(carved.begin(), carved.end());
        }
    } else {
        for (std::size_t k = 0; k < n; ++k) {
            slope[k] = slope_of(bed, k);
            const double dn = samples.width[k] / (kSectionSamples - 1.0);
            surface[k] = increasing_root_above(
                [&](double eta) {
                    return manning_discharge(section[k].data(), static_cast<int>(kSectionSamples), dn, eta, slope[k],
                                             in.manning) -
                           in.discharge[k];
                },
                bed[k], samples.width[k]);
        }
        for (std::size_t k = 1; k < n; ++k) surface[k] = std::min(surface[k], surface[k - 1]);
        meet_mouth(surface);
    }
    river.centreline = samples.points;
    river.along = samples.along;
    river.width = samples.width;
    river.surface = surface;
    river.bed = bed;
    river.slope = slope;
    return centre_depth;
}

}  // namespace tidewater::detail
