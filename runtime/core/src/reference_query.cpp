// Reference solvers: the seed project's fixed-point loop (the benchmark
// baseline) and a tight double-precision Newton (the accuracy yardstick).
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "tidewater/gerstner.hpp"
#include "tidewater/query.hpp"

namespace tidewater::reference {

namespace {

double fixed_point_one(std::span<const Wave> waves, const double* offsets, glm::dvec2 point) {
    glm::dvec2 sample = point;
    constexpr int kIterations = 4;
    for (int it = 0; it < kIterations; ++it) {
        glm::dvec2 horizontal{0.0};
        for (std::size_t i = 0; i < waves.size(); ++i) {
            const Wave& w = waves[i];
            const double theta = w.k * (w.dir_x * sample.x + w.dir_z * sample.y) + offsets[i];
            const double qa_c = w.steepness * w.amplitude * std::cos(theta);
            // The original divided this sum by the wave count, which is wrong.
            horizontal += glm::dvec2(qa_c * w.dir_x, qa_c * w.dir_z);
        }
        sample = point - horizontal;
    }
    double height = 0.0;
    for (std::size_t i = 0; i < waves.size(); ++i) {
        const Wave& w = waves[i];
        height += w.amplitude * std::sin(w.k * (w.dir_x * sample.x + w.dir_z * sample.y) + offsets[i]);
    }
    return height;
}

}  // namespace

double fixed_point_height(const WaveSet& set, double local_time, glm::dvec2 point) {
    double height = 0.0;
    fixed_point_heights(set, local_time, std::span<const glm::dvec2>(&point, 1), std::span<double>(&height, 1));
    return height;
}

void fixed_point_heights(const WaveSet& set, double local_time, std::span<const glm::dvec2> points,
                         std::span<double> heights) {
    std::vector<double> offsets(set.size());
    phase_offsets_at(set, local_time, offsets);
    for (std::size_t p = 0; p < points.size() && p < heights.size(); ++p) {
        heights[p] = fixed_point_one(set.waves(), offsets.data(), points[p]);
    }
}

glm::dvec2 solve_rest_position(const WaveSet& set, double local_time, glm::dvec2 point) {
    auto residual = [&](glm::dvec2 x0, LagrangianSample& s) {
        s = evaluate_lagrangian(set, x0, local_time);
        return x0 + glm::dvec2(s.displacement.x, s.displacement.z) - point;
    };
    glm::dvec2 x0 = point;
    LagrangianSample s;
    glm::dvec2 f = residual(x0, s);
    for (int it = 0; it < 200 && glm::length(f) > 1e-12; ++it) {
        const double det = s.jxx * s.jzz - s.jxz * s.jxz;
        const glm::dvec2 step{-(s.jzz * f.x - s.jxz * f.y) / det, -(s.jxx * f.y - s.jxz * f.x) / det};
        // Backtracking keeps every step a decrease of |F|.
        double scale = 1.0;
        for (int b = 0; b < 30; ++b, scale *= 0.5) {
            LagrangianSample trial;
            const glm::dvec2 candidate = x0 + scale * step;
            const glm::dvec2 fc = residual(candidate, trial);
            if (glm::length(fc) < glm::length(f) || b == 29) {
                x0 = candidate;
                f = fc;
                s = trial;
                break;
            }
        }
    }
    return x0;
}

}  // namespace tidewater::reference
