#include "bodies/stream_function.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>

namespace tidewater::detail {

namespace {

constexpr int kDi[4] = {1, -1, 0, 0};
constexpr int kDj[4] = {0, 0, 1, -1};

/// Marks the wet texels that some bank or island reaches through wet texels.
std::vector<std::uint8_t> anchored_wet(const StreamProblem& p) {
    const FieldGrid& g = p.grid;
    std::vector<std::uint8_t> seen(g.size(), 0);
    std::vector<std::pair<int, int>> stack;
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            if (p.cell[g.index(i, j)] != FlowCell::wet) continue;
            bool touches = false;
            for (int d = 0; d < 4; ++d) {
                const int a = i + kDi[d], b = j + kDj[d];
                if (a < 0 || b < 0 || a >= g.nx || b >= g.nz) continue;
                const FlowCell c = p.cell[g.index(a, b)];
                touches = touches || c == FlowCell::bank || c == FlowCell::island;
            }
            if (touches && !seen[g.index(i, j)]) {
                seen[g.index(i, j)] = 1;
                stack.push_back({i, j});
            }
        }
    while (!stack.empty()) {
        const auto [i, j] = stack.back();
        stack.pop_back();
        for (int d = 0; d < 4; ++d) {
            const int a = i + kDi[d], b = j + kDj[d];
            if (a < 0 || b < 0 || a >= g.nx || b >= g.nz) continue;
            const std::size_t n = g.index(a, b);
            if (p.cell[n] == FlowCell::wet && !seen[n]) {
                seen[n] = 1;
                stack.push_back({a, b});
            }
        }
    }
    return seen;
}

}  // namespace

Result<StreamSolution> solve_stream_function(const StreamProblem& p) {
    const FieldGrid& g = p.grid;
    const std::vector<std::uint8_t> anchored = anchored_wet(p);
    std::vector<int> unknown(g.size(), -1);
    int count = 0;
    for (std::size_t t = 0; t < g.size(); ++t)
        if (anchored[t]) unknown[t] = count++;
    const int total = count + p.islands;
    StreamSolution out;
    out.psi.assign(g.size(), std::nan(""));
    out.unknowns = static_cast<std::size_t>(total);
    if (total == 0) return out;

    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(count) * 5);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(total);
    auto face = [&](std::size_t a, std::size_t b, double ha, double hb) {
        const double floor = static_cast<double>(std::max(p.shallowest_face[a], p.shallowest_face[b]));
        return 1.0 / std::max(0.5 * (ha + hb), floor);
    };
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t t = g.index(i, j);
            const int row = unknown[t];
            if (row < 0) continue;
            const double ha = p.depth[t];
            for (int d = 0; d < 4; ++d) {
                const int a = i + kDi[d], b = j + kDj[d];
                if (a < 0 || b < 0 || a >= g.nx || b >= g.nz) continue;
                const std::size_t n = g.index(a, b);
                switch (p.cell[n]) {
                    case FlowCell::wet: {
                        if (unknown[n] < 0) break;
                        const double c = face(t, n, ha, p.depth[n]);
                        entries.emplace_back(row, row, c);
                        entries.emplace_back(row, unknown[n], -c);
                        break;
                    }
                    case FlowCell::bank: {
                        const double c = face(t, n, ha, 0.0);
                        entries.emplace_back(row, row, c);
                        rhs[row] += c * p.bank_value[n];
                        break;
                    }
                    case FlowCell::island: {
                        // The island's row gathers these same faces: its net flux is zero,
                        // which is no net circulation around it.
                        const double c = face(t, n, ha, 0.0);
                        const int isl = count + p.island_of[n];
                        entries.emplace_back(row, row, c);
                        entries.emplace_back(row, isl, -c);
                        entries.emplace_back(isl, isl, c);
                        entries.emplace_back(isl, row, -c);
                        break;
                    }
                    case FlowCell::open_end:
                        break;
                }
            }
        }
    // An island no flowing water reaches keeps psi = 0 rather than leave its row empty.
    std::vector<std::uint8_t> island_reached(static_cast<std::size_t>(p.islands), 0);
    for (const auto& e : entries)
        if (e.row() >= count && e.row() == e.col()) island_reached[static_cast<std::size_t>(e.row() - count)] = 1;
    for (int k = 0; k < p.islands; ++k)
        if (!island_reached[static_cast<std::size_t>(k)]) entries.emplace_back(count + k, count + k, 1.0);
    Eigen::SparseMatrix<double> matrix(total, total);
    matrix.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    solver.compute(matrix);
    if (solver.info() != Eigen::Success)
        return Error{ErrorCode::internal,
                     fmt::format("the stream function's system ({} unknowns) could not be factorised", total)};
    const Eigen::VectorXd x = solver.solve(rhs);
    if (solver.info() != Eigen::Success)
        return Error{ErrorCode::internal,
                     fmt::format("the stream function's system ({} unknowns) could not be solved", total)};
    for (std::size_t t = 0; t < g.size(); ++t) {
        if (unknown[t] >= 0)
            out.psi[t] = x[unknown[t]];
        else if (p.cell[t] == FlowCell::bank)
            out.psi[t] = p.bank_value[t];
        else if (p.cell[t] == FlowCell::island)
            out.psi[t] = x[count + p.island_of[t]];
    }
    return out;
}

}  // namespace tidewater::detail
