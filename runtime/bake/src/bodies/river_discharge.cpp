#include "bodies/river_discharge.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tidewater::detail {

namespace {

/// Points a texel across a section: fine against the bilinear fields' texel.
inline constexpr double kSamplesPerTexel = 8.0;
/// How far past the half width a section reaches (the wet edge wanders a texel or so).
inline constexpr double kReachTexels = 3.0;
/// Sections a texel along the channel: a texel's current weighs in the sections within
/// a texel of it, so the sections are taken finer than that.
inline constexpr double kSectionsPerTexel = 4.0;
/// A section whose query misses its discharge by more than this is not a clean crossing
/// (a tributary's last texel, 25 % and more, where the river it joins takes the channel
/// over): it is not matched. A tight bend on a steep reach misses 15 %.
inline constexpr double kMostMismatch = 0.2;
/// A section across an island crosses four waterlines, not two, each next to ground as
/// steep as the island's sides: it is matched from further off.
inline constexpr double kMostMismatchAcrossIsland = 0.5;
/// Past a lake or ocean mouth the sections run on this many texels into the plume, where
/// the query reads the river's current in the still water: matched to the h u field's
/// flux there, which fades out along the plume.
inline constexpr double kPlumeTexels = 3.0;
/// The most a texel's current is scaled up, and down. Down further: next to an island's
/// steep sides the sections are matched only when some texels' currents are cut to a
/// third or a quarter (0.28 at least at the default island's knoll), and slower water
/// beside an obstacle is plausible; a current raised further would race through the
/// shallow water there.
inline constexpr double kMostScaleUp = 1.5, kMostScaleDown = 0.25;
/// Solves with the factors past their bounds held there: each pass holds those the last
/// one took past them (the default island's brook takes two).
inline constexpr int kBoundPasses = 4;
/// The ridge that keeps the scales near 1 where the sections leave them free, against
/// the sections' own weight per texel (their mean over the texels): small enough that
/// the sections are matched within 0.3 % (1 % across an island), large enough that the
/// factors do not swing from texel to texel to match sections a quarter texel apart
/// (1e-3 matched those and missed the ones between by 4 %).
inline constexpr double kRidge = 1e-2;
/// Sections left off by more than this are solved again, each weighed by 1 + its misfit
/// over this: the brook's and the rill's worst fall from 1.09 and 0.97 % to 0.77 and
/// 0.50 % (and stay under 1 % from half this to twice it).
inline constexpr double kReweighMisfit = 0.005;

/// A section as the query reads it, with each texel's current scaled by its own factor:
/// what it carries is the sum of (coefficient * factor) over the texels it reads.
struct SectionTerms {
    double field = 0.0;  ///< m^3/s by the h u field
    bool crosses_island = false;
    std::vector<std::pair<std::size_t, double>> terms;  ///< (texel, m^3/s at factor 1), texels in order

    double queried() const {
        double q = 0.0;
        for (const auto& term : terms) q += term.second;
        return q;
    }
};

/// The section through the centreline `along` m from the source (past the mouth:
/// carried on along the last stretch, into the plume) as the query reads it.
SectionTerms section_terms(const RiverBake& river, const std::vector<FlowCell>& cells, double along) {
    const FieldGrid& g = river.grid;
    const std::vector<double>& a = river.along;
    const auto above = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(
        std::lower_bound(a.begin(), a.end(), along) - a.begin(), 1, static_cast<std::ptrdiff_t>(a.size()) - 1));
    const double beyond = std::max(along - a.back(), 0.0);
    const double w = std::clamp((along - a[above - 1]) / std::max(a[above] - a[above - 1], 1e-12), 0.0, 1.0);
    const glm::dvec2 d = river.centreline[above] - river.centreline[above - 1];
    const double length = std::hypot(d.x, d.y);
    SectionTerms out;
    if (!(length > 0.0)) return out;
    const glm::dvec2 t = d / length, n{-t.y, t.x};
    const glm::dvec2 p0 =
        river.centreline[above - 1] + w * (river.centreline[above] - river.centreline[above - 1]) + beyond * t;
    // The plume widens from the mouth: past it the section spans twice the mouth's width.
    const double width = (river.width[above - 1] + w * (river.width[above] - river.width[above - 1])) +
                         (beyond > 0.0 ? river.width.back() : 0.0);
    const double reach = 0.5 * width + kReachTexels * g.texel, step = g.texel / kSamplesPerTexel;
    const auto count = static_cast<int>(std::ceil(2.0 * reach / step));
    const auto current = [&](std::size_t k) {
        return static_cast<double>(river.flow_x[k]) * t.x + static_cast<double>(river.flow_z[k]) * t.y;
    };
    std::unordered_map<std::size_t, double> by_texel;
    for (int m = 0; m <= count; ++m) {
        const glm::dvec2 p = p0 + (-reach + m * step) * n;
        if (!g.contains(p)) continue;
        out.field += (g.sample(river.discharge_x, p) * t.x + g.sample(river.discharge_z, p) * t.y) * step;
        int i = 0, j = 0;
        g.texel_of(p, i, j);
        if (cells[g.index(i, j)] == FlowCell::island) out.crosses_island = true;
        const std::uint8_t kind = river.texel[g.index(i, j)];
        if (!river_water(kind) && kind != static_cast<std::uint8_t>(RiverTexel::plume)) continue;
        // What the query reads (sample_river), in the river and in its plume alike: the
        // bilinear depth times the texels' currents weighted by their water columns.
        const double depth = g.sample(river.depth, p);
        if (!(depth > 0.0)) continue;
        const RiverCurrentTaps taps = river_current_taps(river, p);
        for (std::size_t q = 0; q < 4; ++q)
            if (taps.weight[q] > 0.0 && current(taps.texel[q]) != 0.0)
                by_texel[taps.texel[q]] += depth * taps.weight[q] * current(taps.texel[q]) * step;
    }
    out.terms.assign(by_texel.begin(), by_texel.end());
    std::sort(out.terms.begin(), out.terms.end());
    return out;
}

/// The river's discharge at `along` m from the source as the scene gives it: its own,
/// and each tributary's once it has joined; NaN within a tributary's mouth, where its
/// water is still entering.
double given_discharge(const RiverBake& river, std::span<const Inflow> inflows, double along) {
    double q = river.own_discharge;
    for (const Inflow& f : inflows) {
        const double entered = f.entered(along);
        if (entered > 0.0 && entered < f.discharge) return std::nan("");
        q += entered;
    }
    return q;
}

/// The factors' changes g (one per texel column of `entries`) that match the sections'
/// rows, each weighed by `row_weight`: row . (1 + g) = 1, right-hand sides `mismatch`.
Eigen::VectorXd solve_factors(const std::vector<Eigen::Triplet<double>>& entries, const std::vector<double>& mismatch,
                              const std::vector<double>& row_weight, int texels) {
    // The factors' change g that matches the rows in the least squares, and among the ways
    // to do so the smallest: the rows stacked over sqrt(ridge) I.
    const auto rows = static_cast<int>(mismatch.size());
    double weight = 0.0;
    for (const auto& e : entries) weight += e.value() * e.value();
    const double ridge = std::sqrt(kRidge * weight / texels);
    // A factor the solve takes past its bounds is held at the bound and the others solved
    // again (an active set): clamped after the solve alone, it would leave the sections it
    // serves unmatched, where its neighbours could make up the rest.
    std::vector<double> held(static_cast<std::size_t>(texels), std::nan(""));
    Eigen::VectorXd change = Eigen::VectorXd::Zero(texels);
    for (int pass = 0; pass < kBoundPasses; ++pass) {
        std::vector<int> column(static_cast<std::size_t>(texels), -1);
        int free = 0;
        for (int u = 0; u < texels; ++u)
            if (std::isnan(held[static_cast<std::size_t>(u)])) column[static_cast<std::size_t>(u)] = free++;
        if (free == 0) break;
        std::vector<Eigen::Triplet<double>> active;
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows + free);
        for (int r = 0; r < rows; ++r)
            rhs[r] = row_weight[static_cast<std::size_t>(r)] * mismatch[static_cast<std::size_t>(r)];
        for (const auto& e : entries) {
            const int c = column[static_cast<std::size_t>(e.col())];
            const double value = row_weight[static_cast<std::size_t>(e.row())] * e.value();
            if (c >= 0)
                active.emplace_back(e.row(), c, value);
            else
                rhs[e.row()] -= value * held[static_cast<std::size_t>(e.col())];
        }
        for (int u = 0; u < texels; ++u)
            if (const int c = column[static_cast<std::size_t>(u)]; c >= 0) active.emplace_back(rows + c, c, ridge);
        Eigen::SparseMatrix<double> system(rows + free, free);
        system.setFromTriplets(active.begin(), active.end());
        Eigen::LeastSquaresConjugateGradient<Eigen::SparseMatrix<double>> solver;
        solver.setTolerance(1e-8);
        solver.setMaxIterations(1000);
        solver.compute(system);
        const Eigen::VectorXd solved = solver.solve(rhs);
        bool bound = false;
        for (int u = 0; u < texels; ++u) {
            const auto k = static_cast<std::size_t>(u);
            if (column[k] < 0) continue;
            const double g = solved[column[k]];
            change[u] = g;
            if (1.0 + g > kMostScaleUp || 1.0 + g < kMostScaleDown) {
                held[k] = std::clamp(1.0 + g, kMostScaleDown, kMostScaleUp) - 1.0;
                change[u] = held[k];
                bound = true;
            }
        }
        if (!bound) break;
    }
    return change;
}

/// Each row's misfit left by the changes g: its mismatch less row . g.
std::vector<double> row_misfits(const std::vector<Eigen::Triplet<double>>& entries, const std::vector<double>& mismatch,
                                const Eigen::VectorXd& change) {
    std::vector<double> misfit = mismatch;
    for (const auto& e : entries) misfit[static_cast<std::size_t>(e.row())] -= e.value() * change[e.col()];
    return misfit;
}

}  // namespace

void match_queried_discharge(RiverBake& river, const std::vector<FlowCell>& cells, std::span<const Inflow> inflows) {
    const std::size_t samples = river.centreline.size();
    if (samples < 2 || river.along.size() != samples) return;
    const double first = river.along.front(), mouth = river.along.back();
    const bool plume = std::any_of(river.texel.begin(), river.texel.end(), [](std::uint8_t kind) {
        return kind == static_cast<std::uint8_t>(RiverTexel::plume);
    });
    const double last = mouth + (plume ? kPlumeTexels * river.grid.texel : 0.0);
    const double spacing = river.grid.texel / kSectionsPerTexel;
    const auto stations = static_cast<std::size_t>(std::ceil((last - first) / spacing)) + 1;
    // One row per section matched, over the texels it reads (numbered as met), divided by
    // its discharge: row . (1 + g) = 1 is matched; its right-hand side is 1 - queried / Q.
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> mismatch;
    std::vector<std::size_t> texel_of;
    std::unordered_map<std::size_t, int> unknown;
    for (std::size_t m = 0; m < stations; ++m) {
        const double along = std::min(first + static_cast<double>(m) * spacing, last);
        const SectionTerms s = section_terms(river, cells, along);
        const double given = given_discharge(river, inflows, along);
        const double q = std::isnan(given) || along > mouth ? s.field : given, queried = s.queried();
        if (!(q > 0.0 && queried > 0.0)) continue;
        const double off = 1.0 - queried / q;
        if (std::abs(off) > (s.crosses_island ? kMostMismatchAcrossIsland : kMostMismatch)) continue;
        const int row = static_cast<int>(mismatch.size());
        for (const auto& [texel, coefficient] : s.terms) {
            const auto [it, added] = unknown.try_emplace(texel, static_cast<int>(texel_of.size()));
            if (added) texel_of.push_back(texel);
            entries.emplace_back(row, it->second, coefficient / q);
        }
        mismatch.push_back(off);
    }
    const auto rows = static_cast<int>(mismatch.size()), texels = static_cast<int>(texel_of.size());
    if (rows == 0 || texels == 0) return;
    // Least squares spreads the misfit over every section. Where some are left off by more
    // than kReweighMisfit (beside the knoll's steep sides), every section is weighed again
    // by how far off it still is and the factors solved once more: a step toward the
    // smallest worst misfit (Lawson's reweighting).
    std::vector<double> row_weight(static_cast<std::size_t>(rows), 1.0);
    Eigen::VectorXd change = solve_factors(entries, mismatch, row_weight, texels);
    const std::vector<double> misfit = row_misfits(entries, mismatch, change);
    if (std::any_of(misfit.begin(), misfit.end(), [](double m) { return std::abs(m) > kReweighMisfit; })) {
        for (std::size_t r = 0; r < misfit.size(); ++r) row_weight[r] = 1.0 + std::abs(misfit[r]) / kReweighMisfit;
        change = solve_factors(entries, mismatch, row_weight, texels);
    }
    for (int u = 0; u < texels; ++u) {
        const double f = std::clamp(1.0 + change[u], kMostScaleDown, kMostScaleUp);
        if (!std::isfinite(f)) continue;
        const std::size_t t = texel_of[static_cast<std::size_t>(u)];
        river.flow_x[t] = static_cast<float>(static_cast<double>(river.flow_x[t]) * f);
        river.flow_z[t] = static_cast<float>(static_cast<double>(river.flow_z[t]) * f);
    }
}

}  // namespace tidewater::detail
