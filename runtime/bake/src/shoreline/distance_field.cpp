// Exact distances by blocks. A texel p of a block with centre c and radius r (centre
// to farthest texel) has d(p) <= d(c) + r, and its nearest segment lies within
// d(p) + r <= d(c) + 2r of c. So one CGAL nearest query and one CGAL range query per
// root block give a candidate list that holds every texel's nearest segment. Each
// block then splits in four, and a quadrant keeps only the candidates within
// d'(c_q) + 2 r_q of its own centre, where d'(c_q) is the nearest candidate's distance:
// the same argument keeps every texel's nearest segment in the list. Small blocks take
// each texel's minimum over what is left. The answer is the same as one nearest query
// per texel, several times faster: the tree is walked from its root once per root block.
// The sign is the texel's side of the water level, so it always agrees with the depth.
#include "distance_field.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <xsimd/xsimd.hpp>

#include "tidewater/detail/parallel.hpp"

namespace tidewater::detail {

namespace {

constexpr int kRootBlock = kDistanceRootBlock;  // texels per root block side (one CGAL range query each)
constexpr int kLeafBlock = 4;                   // blocks this small go texel by texel

using Batch = xsimd::batch<double>;
constexpr std::size_t kLanes = Batch::size;

/// Candidate segments in structure-of-arrays form (origin, direction, 1/|direction|^2),
/// padded to whole SIMD batches with a segment too far away to win.
struct Candidates {
    std::vector<std::uint32_t> id;
    std::vector<double> ax, ay, ex, ey, inv_len2;

    std::size_t size() const { return id.size(); }

    void clear() { id.clear(), ax.clear(), ay.clear(), ex.clear(), ey.clear(), inv_len2.clear(); }
    void push(std::uint32_t s, double x, double y, double dx, double dy, double inv) {
        id.push_back(s), ax.push_back(x), ay.push_back(y), ex.push_back(dx), ey.push_back(dy), inv_len2.push_back(inv);
    }
    void push(const Candidates& from, std::size_t k) {
        push(from.id[k], from.ax[k], from.ay[k], from.ex[k], from.ey[k], from.inv_len2[k]);
    }
    void push(const ShoreDistance& distance, std::uint32_t s) {
        const ShoreDistance::Segment& seg = distance.segment(s);
        const double dx = seg.b.x - seg.a.x, dy = seg.b.y - seg.a.y;
        const double len2 = dx * dx + dy * dy;
        push(s, seg.a.x, seg.a.y, dx, dy, len2 > 0.0 ? 1.0 / len2 : 0.0);
    }
    /// Pads the arrays (not `id`) to whole batches.
    void pad() {
        const std::size_t padded = (id.size() + kLanes - 1) / kLanes * kLanes;
        ax.resize(padded, 1e300), ay.resize(padded, 1e300);
        ex.resize(padded, 0.0), ey.resize(padded, 0.0), inv_len2.resize(padded, 0.0);
    }

    /// Squared distance from p to every candidate, into `out` (padded length).
    void squared_distances(glm::dvec2 p, std::vector<double>& out) const {
        const std::size_t n = ax.size();
        out.resize(n);
        const Batch px(p.x), py(p.y), zero(0.0), one(1.0);
        for (std::size_t k = 0; k < n; k += kLanes) {
            const Batch dx0 = px - Batch::load_unaligned(&ax[k]), dy0 = py - Batch::load_unaligned(&ay[k]);
            const Batch vx = Batch::load_unaligned(&ex[k]), vy = Batch::load_unaligned(&ey[k]);
            const Batch t =
                xsimd::min(xsimd::max((dx0 * vx + dy0 * vy) * Batch::load_unaligned(&inv_len2[k]), zero), one);
            const Batch dx = dx0 - t * vx, dy = dy0 - t * vy;
            (dx * dx + dy * dy).store_unaligned(&out[k]);
        }
    }
};

/// Scratch for one thread: a candidate list per quadtree level and a distance buffer.
struct Workspace {
    std::vector<Candidates> levels;
    std::vector<double> d2;
    std::vector<std::uint32_t> found;
};

struct Block {
    int i0, j0, i1, j1;  // texels [i0, i1) x [j0, j1)
};

class BlockFiller {
  public:
    BlockFiller(const ShoreDistance& distance, ShoreField& field, const TexelWindow& window)
        : distance_(distance), field_(field), window_(window) {}

    void fill_root(const Block& b, Workspace& w, ShoreDistance::Hit& hint, bool& have_hint) const {
        const auto [centre, radius] = bounds(b);
        const ShoreDistance::Hit at_centre = distance_.query(centre, have_hint ? &hint : nullptr);
        hint = at_centre;
        have_hint = true;
        // Rounding slack: the range must not lose a segment that touches its edge.
        const double reach = (std::abs(at_centre.signed_distance) + 2.0 * radius) * (1.0 + 1e-9) + 1e-9;
        w.found.clear();
        distance_.segments_within(centre, reach, w.found);
        if (w.found.empty()) w.found.push_back(static_cast<std::uint32_t>(at_centre.segment));
        if (w.levels.empty()) w.levels.resize(1);
        Candidates& root = w.levels[0];
        root.clear();
        for (std::uint32_t s : w.found) root.push(distance_, s);
        root.pad();
        fill(b, 0, w);
    }

  private:
    std::pair<glm::dvec2, double> bounds(const Block& b) const {
        const glm::dvec2 lo = field_.texel_center(b.i0, b.j0), hi = field_.texel_center(b.i1 - 1, b.j1 - 1);
        return {0.5 * (lo + hi), 0.5 * std::hypot(hi.x - lo.x, hi.y - lo.y)};
    }

    /// Fills block `b`, whose every texel has its nearest segment in w.levels[level].
    void fill(const Block& b, std::size_t level, Workspace& w) const {
        const Candidates& cand = w.levels[level];
        if ((b.i1 - b.i0 <= kLeafBlock && b.j1 - b.j0 <= kLeafBlock) || cand.size() <= kLanes) {
            fill_texels(b, cand, w.d2);
            return;
        }
        const int im = (b.i0 + b.i1) / 2, jm = (b.j0 + b.j1) / 2;
        const Block quadrants[4] = {
            {b.i0, b.j0, im, jm}, {im, b.j0, b.i1, jm}, {b.i0, jm, im, b.j1}, {im, jm, b.i1, b.j1}};
        if (w.levels.size() <= level + 1) w.levels.resize(level + 2);
        for (const Block& q : quadrants) {
            if (q.i0 >= q.i1 || q.j0 >= q.j1) continue;
            const auto [centre, radius] = bounds(q);
            const Candidates& parent = w.levels[level];  // stable: levels grows before the loop
            parent.squared_distances(centre, w.d2);
            double nearest = INFINITY;
            for (std::size_t k = 0; k < parent.size(); ++k) nearest = std::min(nearest, w.d2[k]);
            const double reach = (std::sqrt(nearest) + 2.0 * radius) * (1.0 + 1e-9) + 1e-9;
            Candidates& child = w.levels[level + 1];
            child.clear();
            for (std::size_t k = 0; k < parent.size(); ++k)
                if (w.d2[k] <= reach * reach) child.push(parent, k);
            child.pad();
            fill(q, level + 1, w);
        }
    }

    void fill_texels(const Block& b, const Candidates& cand, std::vector<double>& d2) const {
        for (int j = b.j0; j < b.j1; ++j)
            for (int i = b.i0; i < b.i1; ++i) {
                const glm::dvec2 p = field_.texel_center(i, j);
                cand.squared_distances(p, d2);
                std::size_t arg = 0;
                for (std::size_t k = 1; k < cand.size(); ++k)
                    if (d2[k] < d2[arg]) arg = k;
                const std::size_t t =
                    static_cast<std::size_t>(j - window_.j0) * static_cast<std::size_t>(window_.size) +
                    static_cast<std::size_t>(i - window_.i0);
                const auto hit = distance_.hit_on(p, cand.id[arg], field_.depth[t] > 0.0f);
                signed_distance_[t] = static_cast<float>(hit.signed_distance);
                gradient_[t] = SharedDirections::encode(hit.gradient);
            }
    }

    const ShoreDistance& distance_;
    ShoreField& field_;
    const TexelWindow window_;
    // The field's grids to write, taken once: the workers write distinct texels.
    float* signed_distance_ = field_.signed_distance.write().data();
    std::uint16_t* gradient_ = field_.gradient.write().data();
};

}  // namespace

void fill_distance_field(const ShoreDistance& distance, ShoreField& field, unsigned threads,
                         const std::function<void(double)>& progress, const std::stop_token& cancel) {
    fill_distance_window(distance, field, {0, 0, field.resolution}, threads, progress, cancel);
}

void fill_distance_window(const ShoreDistance& distance, ShoreField& field, const TexelWindow& window, unsigned threads,
                          const std::function<void(double)>& progress, const std::stop_token& cancel) {
    // Root blocks are laid from the whole grid's corner, so a window that starts on a root
    // block's edge is filled exactly as the whole grid is there.
    const int n = window.size;
    const int block_rows = (n + kRootBlock - 1) / kRootBlock;
    const BlockFiller filler(distance, field, window);
    std::atomic<int> done{0};
    std::mutex progress_lock;  // the callback is the caller's: one call at a time
    parallel_for_each(static_cast<std::size_t>(block_rows), threads, [&](std::size_t row) {
        if (cancel.stop_requested()) return;  // the caller throws the field away
        Workspace w;
        ShoreDistance::Hit hint;
        bool have_hint = false;
        const int j0 = window.j0 + static_cast<int>(row) * kRootBlock;
        const int j1 = std::min(window.j0 + n, j0 + kRootBlock);
        for (int i0 = window.i0; i0 < window.i0 + n; i0 += kRootBlock)
            filler.fill_root({i0, j0, std::min(window.i0 + n, i0 + kRootBlock), j1}, w, hint, have_hint);
        const int rows = ++done;
        if (progress) {
            const std::lock_guard<std::mutex> lock(progress_lock);
            progress(static_cast<double>(rows) / block_rows);
        }
    });
}

void fill_distance_roots(const ShoreDistance& distance, ShoreField& field, std::span<const std::size_t> roots,
                         unsigned threads) {
    const int n = field.resolution;
    const std::size_t per_side = static_cast<std::size_t>((n + kRootBlock - 1) / kRootBlock);
    const BlockFiller filler(distance, field, {0, 0, n});
    parallel_for_each(roots.size(), threads, [&](std::size_t k) {
        Workspace w;
        ShoreDistance::Hit hint;
        bool have_hint = false;
        const int i0 = static_cast<int>(roots[k] % per_side) * kRootBlock;
        const int j0 = static_cast<int>(roots[k] / per_side) * kRootBlock;
        filler.fill_root({i0, j0, std::min(n, i0 + kRootBlock), std::min(n, j0 + kRootBlock)}, w, hint, have_hint);
    });
}

}  // namespace tidewater::detail
