#include "contour.hpp"

#include <algorithm>
#include <atomic>

#include "tidewater/detail/parallel.hpp"

namespace tidewater::detail {

namespace {

// Cell edges: 0 bottom (j), 1 right (i + 1), 2 top (j + 1), 3 left (i).
constexpr int kOpposite[4] = {2, 3, 0, 1};
constexpr int kStepI[4] = {0, 1, 0, -1};
constexpr int kStepJ[4] = {-1, 0, 1, 0};

using Segment = ContourCell;

/// Marching squares over row j of the window's cells; appends that row's segments in order of i.
void row_segments(const std::vector<double>& v, const CellWindow& w, int j, std::vector<Segment>& out) {
    // Exact zeros count as land and cross as a tiny positive value, so no crossing sits on a grid point.
    const std::size_t width = static_cast<std::size_t>(w.i1 - w.i0 + 1);
    auto at = [&](int i, int jj) {
        const double x = v[static_cast<std::size_t>(jj - w.j0) * width + static_cast<std::size_t>(i - w.i0)];
        return x >= 0.0 ? std::max(x, 1e-9) : x;
    };
    auto cross = [](glm::dvec2 a, glm::dvec2 b, double va, double vb) { return a + (b - a) * (va / (va - vb)); };
    for (int i = w.i0; i < w.i1; ++i) {
        const double c00 = at(i, j), c10 = at(i + 1, j), c11 = at(i + 1, j + 1), c01 = at(i, j + 1);
        const bool l00 = c00 >= 0, l10 = c10 >= 0, l11 = c11 >= 0, l01 = c01 >= 0;
        if (l00 == l10 && l10 == l11 && l11 == l01) continue;
        const glm::dvec2 p00(i, j), p10(i + 1, j), p11(i + 1, j + 1), p01(i, j + 1);
        const bool present[4] = {l00 != l10, l10 != l11, l01 != l11, l00 != l01};
        const glm::dvec2 point[4] = {
            present[0] ? cross(p00, p10, c00, c10) : p00, present[1] ? cross(p10, p11, c10, c11) : p10,
            present[2] ? cross(p01, p11, c01, c11) : p01, present[3] ? cross(p00, p01, c00, c01) : p00};
        int pairs[2][2];
        int count = 0;
        if (int(present[0]) + int(present[1]) + int(present[2]) + int(present[3]) == 2) {
            int a = -1, b = -1;
            for (int k = 0; k < 4; ++k)
                if (present[k]) (a < 0 ? a : b) = k;
            pairs[count][0] = a, pairs[count][1] = b, ++count;
        } else if ((c00 + c10 + c11 + c01 >= 0.0) == l00) {
            // Saddle: the cell centre decides which diagonal corners connect.
            pairs[0][0] = 0, pairs[0][1] = 1;  // cuts off corner (i+1, j)
            pairs[1][0] = 2, pairs[1][1] = 3;  // cuts off corner (i, j+1)
            count = 2;
        } else {
            pairs[0][0] = 3, pairs[0][1] = 0;  // cuts off corner (i, j)
            pairs[1][0] = 1, pairs[1][1] = 2;  // cuts off corner (i+1, j+1)
            count = 2;
        }
        for (int k = 0; k < count; ++k) {
            Segment s{i, j, pairs[k][0], pairs[k][1], point[pairs[k][0]], point[pairs[k][1]]};
            // Land on the left: the left normal points up the bilinear gradient.
            const glm::dvec2 mid = 0.5 * (s.from + s.to) - p00;
            const double gx = (c10 - c00) * (1 - mid.y) + (c11 - c01) * mid.y;
            const double gy = (c01 - c00) * (1 - mid.x) + (c11 - c10) * mid.x;
            const glm::dvec2 d = s.to - s.from;
            if (-d.y * gx + d.x * gy < 0.0) {
                std::swap(s.from_edge, s.to_edge);
                std::swap(s.from, s.to);
            }
            out.push_back(s);
        }
    }
}

}  // namespace

std::vector<ContourCell> contour_cells(const std::vector<double>& values, const CellWindow& window, unsigned threads) {
    // Rows of cells are independent: find their segments in parallel.
    std::vector<std::vector<Segment>> rows(static_cast<std::size_t>(std::max(window.j1 - window.j0, 0)));
    parallel_for_each(rows.size(), threads,
                      [&](std::size_t r) { row_segments(values, window, window.j0 + static_cast<int>(r), rows[r]); });
    std::vector<Segment> segments;
    std::size_t total = 0;
    for (const auto& r : rows) total += r.size();
    segments.reserve(total);
    for (auto& r : rows) segments.insert(segments.end(), r.begin(), r.end());
    return segments;
}

std::vector<ContourChain> chain_contour_cells(std::vector<ContourCell> segments, int n) {
    const int cell_rows = n - 1;
    std::vector<std::size_t> row_start(static_cast<std::size_t>(std::max(cell_rows, 0)) + 1, 0);
    for (const Segment& s : segments) ++row_start[static_cast<std::size_t>(s.j) + 1];
    for (std::size_t j = 1; j < row_start.size(); ++j) row_start[j] += row_start[j - 1];

    // The next segment lies in the cell across the exit edge and enters through the
    // same edge; segments are sorted by (j, i), so it is found by a search in its row.
    auto successor = [&](const Segment& s) -> std::ptrdiff_t {
        const int i = s.i + kStepI[s.to_edge], j = s.j + kStepJ[s.to_edge];
        if (i < 0 || j < 0 || i >= cell_rows || j >= cell_rows) return -1;
        const auto first = segments.begin() + static_cast<std::ptrdiff_t>(row_start[static_cast<std::size_t>(j)]);
        const auto last = segments.begin() + static_cast<std::ptrdiff_t>(row_start[static_cast<std::size_t>(j) + 1]);
        auto it = std::lower_bound(first, last, i, [](const Segment& a, int ci) { return a.i < ci; });
        for (; it != last && it->i == i; ++it)
            if (it->from_edge == kOpposite[s.to_edge]) return it - segments.begin();
        return -1;
    };
    // Only a segment entering through the domain's edge has no predecessor.
    auto starts_on_domain_edge = [&](const Segment& s) {
        const int i = s.i + kStepI[s.from_edge], j = s.j + kStepJ[s.from_edge];
        return i < 0 || j < 0 || i >= cell_rows || j >= cell_rows;
    };

    std::vector<char> used(segments.size(), 0);
    std::vector<ContourChain> chains;
    auto follow = [&](std::size_t first, bool open) {
        ContourChain chain;
        chain.closed = !open;
        chain.points.push_back(segments[first].from);
        std::ptrdiff_t k = static_cast<std::ptrdiff_t>(first);
        while (k >= 0 && !used[static_cast<std::size_t>(k)]) {
            const Segment& s = segments[static_cast<std::size_t>(k)];
            used[static_cast<std::size_t>(k)] = 1;
            chain.points.push_back(s.to);
            k = successor(s);
        }
        if (chain.closed && chain.points.size() > 1) chain.points.pop_back();  // last repeats the first
        if (chain.points.size() >= 2) chains.push_back(std::move(chain));
    };
    // Open chains first (the shore enters from the domain edge), then the closed loops.
    for (std::size_t k = 0; k < segments.size(); ++k)
        if (!used[k] && starts_on_domain_edge(segments[k])) follow(k, true);
    for (std::size_t k = 0; k < segments.size(); ++k)
        if (!used[k]) follow(k, false);
    return chains;
}

std::vector<ContourChain> extract_contours(const std::vector<double>& values, int n, unsigned threads) {
    return chain_contour_cells(contour_cells(values, {0, 0, n - 1, n - 1}, threads), n);
}

}  // namespace tidewater::detail
