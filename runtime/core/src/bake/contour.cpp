#include "contour.hpp"

#include <algorithm>
#include <unordered_map>

namespace tidewater::detail {

namespace {

struct Segment {
    std::uint64_t from_key, to_key;
    glm::dvec2 from, to;
};

}  // namespace

std::vector<ContourChain> extract_contours(const std::vector<double>& raw, int n) {
    // Exact zeros become tiny positive (land) so that no crossing sits on a grid point.
    std::vector<double> v(raw.size());
    for (std::size_t k = 0; k < raw.size(); ++k) v[k] = raw[k] >= 0.0 ? std::max(raw[k], 1e-9) : raw[k];
    auto at = [&](int i, int j) { return v[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)]; };
    // Crossing keys name grid edges, so neighbouring cells produce the same point for the same edge.
    auto h_key = [&](int i, int j) { return 2u * (static_cast<std::uint64_t>(j) * static_cast<std::uint64_t>(n) + static_cast<std::uint64_t>(i)); };
    auto v_key = [&](int i, int j) { return h_key(i, j) + 1u; };
    auto cross = [](glm::dvec2 a, glm::dvec2 b, double va, double vb) { return a + (b - a) * (va / (va - vb)); };

    std::vector<Segment> segments;
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            const double c00 = at(i, j), c10 = at(i + 1, j), c11 = at(i + 1, j + 1), c01 = at(i, j + 1);
            const bool l00 = c00 >= 0, l10 = c10 >= 0, l11 = c11 >= 0, l01 = c01 >= 0;
            if (l00 == l10 && l10 == l11 && l11 == l01) continue;
            const glm::dvec2 p00(i, j), p10(i + 1, j), p11(i + 1, j + 1), p01(i, j + 1);
            // Crossing points on the cell's edges: 0 bottom, 1 right, 2 top, 3 left.
            struct Crossing {
                std::uint64_t key;
                glm::dvec2 p;
                bool present;
            } e[4] = {{h_key(i, j), l00 != l10 ? cross(p00, p10, c00, c10) : p00, l00 != l10},
                      {v_key(i + 1, j), l10 != l11 ? cross(p10, p11, c10, c11) : p10, l10 != l11},
                      {h_key(i, j + 1), l01 != l11 ? cross(p01, p11, c01, c11) : p01, l01 != l11},
                      {v_key(i, j), l00 != l01 ? cross(p00, p01, c00, c01) : p00, l00 != l01}};
            std::vector<std::pair<int, int>> pairs;
            const int count = int(e[0].present) + int(e[1].present) + int(e[2].present) + int(e[3].present);
            if (count == 2) {
                int a = -1, b = -1;
                for (int k = 0; k < 4; ++k)
                    if (e[k].present) (a < 0 ? a : b) = k;
                pairs.push_back({a, b});
            } else {
                // Saddle: the cell centre decides which diagonal corners connect.
                const bool centre_land = (c00 + c10 + c11 + c01) >= 0.0;
                if (centre_land == l00) {
                    pairs.push_back({0, 1});  // cuts off corner (i+1, j)
                    pairs.push_back({2, 3});  // cuts off corner (i, j+1)
                } else {
                    pairs.push_back({3, 0});  // cuts off corner (i, j)
                    pairs.push_back({1, 2});  // cuts off corner (i+1, j+1)
                }
            }
            for (auto [a, b] : pairs) {
                Segment s{e[a].key, e[b].key, e[a].p, e[b].p};
                // Land on the left: the left normal points up the bilinear gradient.
                const glm::dvec2 mid = 0.5 * (s.from + s.to) - p00;
                const double gx = (c10 - c00) * (1 - mid.y) + (c11 - c01) * mid.y;
                const double gy = (c01 - c00) * (1 - mid.x) + (c11 - c10) * mid.x;
                const glm::dvec2 d = s.to - s.from;
                if (-d.y * gx + d.x * gy < 0.0) {
                    std::swap(s.from_key, s.to_key);
                    std::swap(s.from, s.to);
                }
                segments.push_back(s);
            }
        }
    }

    // Link segments head to tail.
    std::unordered_map<std::uint64_t, std::size_t> starting_at;
    std::unordered_map<std::uint64_t, int> ending_at;
    starting_at.reserve(segments.size() * 2);
    for (std::size_t k = 0; k < segments.size(); ++k) {
        starting_at[segments[k].from_key] = k;
        ++ending_at[segments[k].to_key];
    }
    std::vector<bool> used(segments.size(), false);
    std::vector<ContourChain> chains;
    auto follow = [&](std::size_t first, bool open) {
        ContourChain chain;
        chain.closed = !open;
        chain.points.push_back(segments[first].from);
        std::size_t k = first;
        while (!used[k]) {
            used[k] = true;
            chain.points.push_back(segments[k].to);
            const auto next = starting_at.find(segments[k].to_key);
            if (next == starting_at.end()) break;
            k = next->second;
        }
        if (chain.closed && chain.points.size() > 1) chain.points.pop_back();  // last repeats the first
        if (chain.points.size() >= 2) chains.push_back(std::move(chain));
    };
    // Open chains start where no segment ends (the shore enters from the domain edge).
    for (std::size_t k = 0; k < segments.size(); ++k)
        if (!used[k] && ending_at.find(segments[k].from_key) == ending_at.end()) follow(k, true);
    for (std::size_t k = 0; k < segments.size(); ++k)
        if (!used[k]) follow(k, false);
    return chains;
}

}  // namespace tidewater::detail
