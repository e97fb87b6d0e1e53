#include "bodies/river_channel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "bodies/monotone_cubic.hpp"
#include "bodies/river_blend.hpp"
#include "bodies/river_discharge.hpp"
#include "bodies/stream_function.hpp"
#include "host_device.h"
#include "tidewater/detail/bake_files_write.hpp"

namespace tidewater::detail {

namespace {

/// The largest river grid, texels per side.
constexpr int kMaxRiverGrid = 4096;
/// Texels the channel runs on above its source: more than a bilinear tap's reach (a
/// texel's diagonal), so every tap of the source's section is water.
constexpr double kSourceHeadTexels = 2.0;

/// Where each texel lies relative to the centreline: its nearest point on it.
struct ChannelFrame {
    std::vector<float> along, across, tx, tz;
    std::vector<std::int8_t> beyond;  // -1 before the source, +1 past the end, 0 alongside
    std::vector<float> distance;
};

double smoothstep(double a, double b, double x) {
    const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/// For every texel within `reach` of a segment of `line`, the nearest point of the line.
ChannelFrame nearest_on_line(const FieldGrid& g, const std::vector<glm::dvec2>& line, const std::vector<double>& along,
                             const std::vector<double>& reach) {
    ChannelFrame f;
    f.along.assign(g.size(), 0.0f);
    f.across.assign(g.size(), 0.0f);
    f.tx.assign(g.size(), 1.0f);
    f.tz.assign(g.size(), 0.0f);
    f.beyond.assign(g.size(), 1);
    f.distance.assign(g.size(), std::numeric_limits<float>::infinity());
    const std::size_t last = line.size() - 2;
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
        const glm::dvec2 a = line[k], b = line[k + 1], d = b - a;
        const double len2 = d.x * d.x + d.y * d.y, len = std::sqrt(len2);
        const glm::dvec2 t = d / len;
        const double r = std::max(reach[k], reach[k + 1]);
        const int i0 = std::max(0, static_cast<int>(std::floor((std::min(a.x, b.x) - r - g.corner.x) / g.texel)));
        const int i1 = std::min(g.nx - 1, static_cast<int>(std::ceil((std::max(a.x, b.x) + r - g.corner.x) / g.texel)));
        const int j0 = std::max(0, static_cast<int>(std::floor((std::min(a.y, b.y) - r - g.corner.y) / g.texel)));
        const int j1 = std::min(g.nz - 1, static_cast<int>(std::ceil((std::max(a.y, b.y) + r - g.corner.y) / g.texel)));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const glm::dvec2 p = g.center(i, j), ap = p - a;
                const double raw = (ap.x * d.x + ap.y * d.y) / len2, u = std::clamp(raw, 0.0, 1.0);
                const glm::dvec2 q = a + u * d, pq = p - q;
                const double dist = std::sqrt(pq.x * pq.x + pq.y * pq.y);
                const std::size_t at = g.index(i, j);
                if (dist >= static_cast<double>(f.distance[at])) continue;
                f.distance[at] = static_cast<float>(dist);
                f.along[at] = static_cast<float>(along[k] + u * len);
                f.across[at] = static_cast<float>(t.x * ap.y - t.y * ap.x);
                f.tx[at] = static_cast<float>(t.x);
                f.tz[at] = static_cast<float>(t.y);
                f.beyond[at] = (k == 0 && raw < 0.0) ? -1 : (k == last && raw > 1.0) ? 1 : 0;
            }
    }
    return f;
}

/// Calls visit(members, enclosed) for each 4-connected group of texels where in(t)
/// holds; `enclosed` says whether every texel next to the group is `ring(t)` and none
/// lies on the grid's edge.
template <typename In, typename Ring, typename Visit>
void for_each_group(const FieldGrid& g, In in, Ring ring, Visit visit) {
    std::vector<std::uint8_t> visited(g.size(), 0);
    std::vector<std::pair<int, int>> stack, members;
    for (int j0 = 0; j0 < g.nz; ++j0)
        for (int i0 = 0; i0 < g.nx; ++i0) {
            if (!in(g.index(i0, j0)) || visited[g.index(i0, j0)]) continue;
            bool enclosed = true;
            members.clear();
            stack.assign(1, {i0, j0});
            visited[g.index(i0, j0)] = 1;
            while (!stack.empty()) {
                const auto [i, j] = stack.back();
                stack.pop_back();
                members.push_back({i, j});
                for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
                    const int a = i + di, b = j + dj;
                    if (a < 0 || b < 0 || a >= g.nx || b >= g.nz) {
                        enclosed = false;
                        continue;
                    }
                    const std::size_t n = g.index(a, b);
                    if (in(n)) {
                        if (!visited[n]) {
                            visited[n] = 1;
                            stack.push_back({a, b});
                        }
                    } else if (!ring(n)) {
                        enclosed = false;
                    }
                }
            }
            visit(members, enclosed);
        }
}

/// Texels of land inside the channel: islands where water rings them (no bank or end
/// touches them).
int mark_islands(const FieldGrid& g, std::vector<FlowCell>& cell, const std::vector<std::uint8_t>& dry_inside,
                 std::vector<int>& island_of) {
    island_of.assign(g.size(), -1);
    int islands = 0;
    for_each_group(
        g, [&](std::size_t t) { return dry_inside[t] != 0; }, [&](std::size_t t) { return cell[t] == FlowCell::wet; },
        [&](const std::vector<std::pair<int, int>>& members, bool enclosed) {
            if (!enclosed) return;  // part of a bank: it keeps its bank value
            for (const auto& [i, j] : members) {
                cell[g.index(i, j)] = FlowCell::island;
                island_of[g.index(i, j)] = islands;
            }
            ++islands;
        });
    return islands;
}

/// Knolls a carve leaves standing: groups of at least kIslandMinimumTexels `standing`
/// texels ringed by `clear` ones (clear of the banks) and off the grid's edge.
std::vector<std::uint8_t> knolls(const FieldGrid& g, const std::vector<std::uint8_t>& standing,
                                 const std::vector<std::uint8_t>& clear) {
    std::vector<std::uint8_t> keep(g.size(), 0);
    for_each_group(
        g, [&](std::size_t t) { return standing[t] != 0; }, [&](std::size_t t) { return clear[t] != 0; },
        [&](const std::vector<std::pair<int, int>>& members, bool enclosed) {
            if (!enclosed || static_cast<int>(members.size()) < kIslandMinimumTexels) return;
            for (const auto& [i, j] : members) keep[g.index(i, j)] = 1;
        });
    return keep;
}

}  // namespace

double bank_psi(const ChannelInputs& in, double own_discharge, double along, int side) {
    double psi = side > 0 ? in.psi_left : in.psi_left + own_discharge;
    for (const Inflow& f : in.inflows) {
        if (f.side != side) continue;
        psi += side > 0 ? -f.entered(along) : f.entered(along);
    }
    return psi;
}

namespace {

/// The channel's centreline, extended past a lake or ocean mouth along the plume's axis
/// (widening to three times the mouth), each sample's reach (half width, banks and their
/// slope), and the grid over them; an error when the grid would be too large.
struct ChannelLine {
    std::vector<glm::dvec2> line;
    std::vector<double> along, width, reach;
};
Result<ChannelLine> channel_line_and_grid(const ChannelInputs& in, RiverBake& river) {
    const double mouth = river.along.back();
    const double mouth_width = river.width.back();
    ChannelLine c;
    std::vector<glm::dvec2>& line = c.line;
    line = river.centreline;
    c.along = river.along;
    c.width = river.width;
    std::vector<double>& along = c.along;
    std::vector<double>& width = c.width;
    std::vector<double>& reach = c.reach;
    // The channel begins a head of kSourceHeadTexels before its source: the texels up to
    // two texels above the source are then water carrying the whole discharge, so
    // the source's section, sampled bilinearly, carries it too.
    {
        const glm::dvec2 d = line[1] - line[0];
        const glm::dvec2 t = d / std::sqrt(d.x * d.x + d.y * d.y);
        const double head = kSourceHeadTexels * in.texel;
        line.insert(line.begin(), line.front() - head * t);
        along.insert(along.begin(), along.front() - head);
        width.insert(width.begin(), width.front());
    }
    if (in.plume_length > 0.0) {
        const glm::dvec2 d = line.back() - line[line.size() - 2];
        const glm::dvec2 t = d / std::sqrt(d.x * d.x + d.y * d.y);
        const int steps = 8;
        for (int k = 1; k <= steps; ++k) {
            const double s = in.plume_length * k / steps;
            line.push_back(river.centreline.back() + s * t);
            along.push_back(mouth + s);
            width.push_back(mouth_width * (1.0 + 2.0 * s / in.plume_length));
        }
    }
    const double widest = *std::max_element(width.begin(), width.end());
    reach.resize(width.size());
    for (std::size_t k = 0; k < width.size(); ++k)
        reach[k] = width[k] + 2.0 * in.texel;  // half width, banks and their slope
    glm::dvec2 lo = line[0], hi = line[0];
    for (const auto& p : line) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    const double margin = widest + 3.0 * in.texel;
    FieldGrid& g = river.grid;
    g.texel = in.texel;
    g.corner = lo - glm::dvec2(margin);
    const double nx = std::ceil((hi.x - lo.x + 2 * margin) / in.texel),
                 nz = std::ceil((hi.y - lo.y + 2 * margin) / in.texel);
    if (nx > kMaxRiverGrid || nz > kMaxRiverGrid)
        return Error{
            ErrorCode::invalid_argument,
            fmt::format("its grid at {:.2f} m texels would be {} x {} (at most {} per side): widen the river or "
                        "split it",
                        in.texel, nx, nz, kMaxRiverGrid)};
    g.nx = static_cast<int>(nx);
    g.nz = static_cast<int>(nz);
    return c;
}

/// Whether p lies in the water of the river this one joins: a texel of its water, not
/// of the dry banks beside it that are its own only where its water reaches them.
bool in_receiver_water(const ChannelInputs& in, glm::dvec2 p) {
    const RiverBake* receiver = in.receiver_river;
    if (receiver == nullptr || !receiver->grid.contains(p)) return false;
    int a = 0, b = 0;
    receiver->grid.texel_of(p, a, b);
    const std::size_t r = receiver->grid.index(a, b);
    return river_water(receiver->texel[r]) && receiver->depth[r] > 0.0f;
}

/// Each centreline sample's section depth, its surface over its bed, m: the river's own
/// depth, which the shallowest depths the stream solve and the current take are shares of.
std::vector<double> section_depths(const RiverBake& river) {
    std::vector<double> depth(river.along.size());
    for (std::size_t k = 0; k < depth.size(); ++k) depth[k] = river.surface[k] - river.bed[k];
    return depth;
}

/// The depth-integrated current h u = (-d psi/dz, d psi/dx) and the current u on the wet
/// texels from the solved stream function; returns the summed depth of the river's own
/// texels (its wet area over texel^2).
double current_from_psi(const ChannelInputs& in, const StreamProblem& problem, const std::vector<double>& psi,
                        const ChannelFrame& frame, double mouth, RiverBake& river) {
    const FieldGrid& g = river.grid;
    // h u = (-d psi/dz, d psi/dx) by central differences. A bank texel next to the water
    // carries half the flux of its faces, so the flux summed across a section is exactly
    // the psi difference between the banks: the discharge.
    river.psi.assign(g.size(), 0.0f);
    river.discharge_x.assign(g.size(), 0.0f);
    river.discharge_z.assign(g.size(), 0.0f);
    river.flow_x.assign(g.size(), 0.0f);
    river.flow_z.assign(g.size(), 0.0f);
    auto has = [&](int i, int j) {
        return i >= 0 && j >= 0 && i < g.nx && j < g.nz && !std::isnan(psi[g.index(i, j)]);
    };
    auto flowing = [&](int i, int j) { return has(i, j) && problem.cell[g.index(i, j)] == FlowCell::wet; };
    // The current is h u over a depth no shallower than a share of the section's deepest
    // (its surface over its bed): the waterline's texels hold almost no water, and the
    // floor is the river's own depth, not a length of its own.
    const std::vector<double> section_depth = section_depths(river);
    auto next_to_land = [&](int i, int j) {
        for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
            const int a = i + di, b = j + dj;
            if (a < 0 || b < 0 || a >= g.nx || b >= g.nz) continue;
            const FlowCell c = problem.cell[g.index(a, b)];
            if (c == FlowCell::bank || c == FlowCell::island) return true;
        }
        return false;
    };
    auto depth_gradient = [&](int i, int j) {
        auto d = [&](int a, int b) {
            a = std::clamp(a, 0, g.nx - 1);
            b = std::clamp(b, 0, g.nz - 1);
            return static_cast<double>(river.depth[g.index(a, b)]);
        };
        return glm::dvec2(d(i + 1, j) - d(i - 1, j), d(i, j + 1) - d(i, j - 1));
    };
    double area_sum = 0.0;
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t t = g.index(i, j);
            if (!has(i, j)) continue;
            river.psi[t] = static_cast<float>(psi[t]);
            const bool wet = problem.cell[t] == FlowCell::wet;
            // d psi along one axis: across faces to water (and, from water, to banks and islands).
            auto derivative = [&](int di, int dj) {
                double sum = 0.0;
                int faces = 0;
                for (const int sgn : {1, -1}) {
                    const int a = i + sgn * di, b = j + sgn * dj;
                    if (!has(a, b) || !(wet || flowing(a, b))) continue;
                    sum += sgn * (psi[g.index(a, b)] - psi[t]);
                    ++faces;
                }
                // Water between two faces: a central difference; water at an open end: one-sided.
                return wet && faces == 1 ? sum / g.texel : sum / (2.0 * g.texel);
            };
            const double dpsi_dx = derivative(1, 0), dpsi_dz = derivative(0, 1);
            double fade = 1.0;
            if (river.texel[t] == static_cast<std::uint8_t>(RiverTexel::plume))
                fade = 1.0 - smoothstep(mouth, mouth + in.plume_length, frame.along[t]);
            const double qx = -dpsi_dz * fade, qz = dpsi_dx * fade;
            river.discharge_x[t] = static_cast<float>(qx);
            river.discharge_z[t] = static_cast<float>(qz);
            if (wet) {
                const double floor =
                    kShallowestCurrentDepth *
                    at_along(river.along, section_depth, std::min(static_cast<double>(frame.along[t]), mouth));
                const double h = std::max(static_cast<double>(problem.depth[t]), floor);  // wet: depth > 0
                double ux = qx / h, uz = qz / h;
                // At the waterline the staircase of texels bends the discrete contours of psi;
                // the current there keeps the no-flux condition: nothing across the bank,
                // whose normal is the depth's gradient.
                if (next_to_land(i, j)) {
                    const glm::dvec2 normal = depth_gradient(i, j);
                    const double len = std::hypot(normal.x, normal.y);
                    if (len > 0.0) {
                        const double across = (ux * normal.x + uz * normal.y) / (len * len);
                        ux -= across * normal.x;
                        uz -= across * normal.y;
                    }
                }
                river.flow_x[t] = static_cast<float>(ux);
                river.flow_z[t] = static_cast<float>(uz);
                if (river.texel[t] == static_cast<std::uint8_t>(RiverTexel::river))
                    area_sum += static_cast<double>(problem.depth[t]);
            }
        }
    return area_sum;
}

/// The dry texels beside the river's own water (banks and islands alongside the channel)
/// are the river's too: a point belongs to the texel nearest it, and within half a texel
/// of a bank the water is still up to 0.4 of the channel's depth. The query and the draw
/// then find the river out to its bilinear waterline; the texels keep no current (their
/// water column is none), so the current there is the wet neighbours'.
void claim_bank_ring(const ChannelInputs& in, const FieldGrid& g, const StreamProblem& problem,
                     const ChannelFrame& frame, double mouth, RiverBake& river) {
    // Ground under the water of the river this one joins, or cut by a river baked before,
    // is that river's.
    auto joined = [&](glm::dvec2 p) {
        return in.terrain->height_at(p) < in.terrain->shape_height_at(p) || in_receiver_water(in, p);
    };
    // Where a tributary comes in, its water there is its own (it is baked after this one):
    // the bank is left along its width and a texel each side, on its side.
    auto tributary = [&](std::size_t t) {
        const double s = frame.along[t], n = frame.across[t];
        for (const Inflow& f : in.inflows)
            if (std::abs(s - f.along) < 0.5 * f.width + g.texel && n * f.side > 0.0) return true;
        return false;
    };
    const auto own = static_cast<std::uint8_t>(RiverTexel::river);
    std::vector<std::size_t> ring;
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t t = g.index(i, j);
            const FlowCell c = problem.cell[t];
            if (river.texel[t] != static_cast<std::uint8_t>(RiverTexel::none) || frame.beyond[t] != 0 ||
                static_cast<double>(frame.along[t]) > mouth || (c != FlowCell::bank && c != FlowCell::island) ||
                tributary(t) || joined(g.center(i, j)))
                continue;
            for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
                const int a = i + di, b = j + dj;
                if (a >= 0 && b >= 0 && a < g.nx && b < g.nz && river.texel[g.index(a, b)] == own) {
                    ring.push_back(t);
                    break;
                }
            }
        }
    for (const std::size_t t : ring) river.texel[t] = own;
}

}  // namespace

Status bake_channel(const ChannelInputs& in, RiverBake& river) {
    const double mouth = river.along.back();
    const double mouth_width = river.width.back();
    auto channel = channel_line_and_grid(in, river);
    if (!channel) return channel.error();
    const std::vector<double>&along = channel->along, &width = channel->width;
    FieldGrid& g = river.grid;
    const ChannelFrame frame = nearest_on_line(g, channel->line, along, channel->reach);
    const MonotoneCubic surface_at(river.along, river.surface);
    const std::vector<double> section_depth = section_depths(river);

    StreamProblem problem;
    problem.grid = g;
    problem.cell.assign(g.size(), FlowCell::open_end);
    problem.depth.assign(g.size(), 0.0f);
    problem.bank_value.assign(g.size(), 0.0);
    problem.shallowest_face.assign(g.size(), 0.0f);
    std::vector<std::uint8_t> dry_inside(g.size(), 0), still(g.size(), 0);
    river.texel.assign(g.size(), static_cast<std::uint8_t>(RiverTexel::none));
    river.surface_height.assign(g.size(), 0.0f);
    river.depth.assign(g.size(), 0.0f);
    auto cut = std::make_shared<TerrainCut>();
    cut->corner = g.corner;
    cut->texel = g.texel;
    cut->nx = g.nx;
    cut->nz = g.nz;
    cut->depth.assign(g.size(), 0.0f);
    bool any_cut = false;
    // The still surface and the ground at every texel, and the knolls the carve keeps.
    std::vector<double> surface(g.size()), ground_at(g.size());
    std::vector<std::uint8_t> standing(g.size(), 0), clear(g.size(), 0);
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t t = g.index(i, j);
            const double s = frame.along[t], n = frame.across[t];
            const bool plume = s > mouth;
            surface[t] = plume ? river.surface.back() : surface_at(s);
            ground_at[t] = in.terrain->height_at(g.center(i, j));
            problem.shallowest_face[t] =
                static_cast<float>(kShallowestCurrentDepth * at_along(river.along, section_depth, std::min(s, mouth)));
            // Clear of the banks by a texel: a knoll must be ringed by these.
            const bool inside =
                frame.beyond[t] == 0 && !plume && std::abs(n) < 0.5 * at_along(along, width, s) - g.texel;
            clear[t] = inside ? 1 : 0;
            // Ground standing several channel depths above the surface is a knoll, not a bump to cut.
            const double freeboard = kIslandFreeboard * at_along(river.along, in.centre_depth, std::min(s, mouth));
            standing[t] = in.carve && inside && ground_at[t] > surface[t] + freeboard ? 1 : 0;
        }
    const std::vector<std::uint8_t> knoll = knolls(g, standing, clear);
    for (int j = 0; j < g.nz; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const std::size_t t = g.index(i, j);
            const glm::dvec2 p = g.center(i, j);
            const double s = frame.along[t], n = frame.across[t];
            const bool plume = s > mouth;
            const double eta = surface[t];
            const double ground = ground_at[t];
            if (in.in_receiver) still[t] = in.in_receiver(p, ground);
            river.surface_height[t] = static_cast<float>(eta);
            river.depth[t] = static_cast<float>(eta - ground);
            if (frame.beyond[t] != 0) continue;  // the cut at the ends: open
            const double half = 0.5 * at_along(along, width, s);
            double bed = ground;
            if (in.carve && !knoll[t]) {
                // The channel runs on into the still water and shoals out through the plume,
                // so the river does not pour off a step into shallows.
                const double fade = plume ? 1.0 - smoothstep(mouth, mouth + in.plume_length, s) : 1.0;
                const double hc = at_along(river.along, in.centre_depth, std::min(s, mouth)) * fade;
                const double x = std::abs(n) / half;
                const double profile =
                    x <= 1.0 ? eta - hc * carved_depth_fraction(x) : eta + (std::abs(n) - half) * kCarvedBankSlope;
                if (profile < ground) {
                    bed = profile;
                    cut->depth[t] = static_cast<float>(in.terrain->shape_height_at(p) - profile);
                    any_cut = true;
                }
            }
            const double depth = eta - bed;
            river.surface_height[t] = static_cast<float>(eta);
            river.depth[t] = static_cast<float>(depth);
            problem.bank_value[t] = bank_psi(in, river.own_discharge, std::min(s, mouth), n >= 0.0 ? 1 : -1);
            if (std::abs(n) > half) {
                problem.cell[t] = FlowCell::bank;
                continue;
            }
            bool wet = depth > 0.0;
            if (plume) wet = wet && in.in_receiver && in.in_receiver(p, ground);
            if (wet && in_receiver_water(in, p)) {
                problem.cell[t] = FlowCell::open_end;  // the river it joins owns this water
                continue;
            }
            if (wet) {
                problem.cell[t] = FlowCell::wet;
                problem.depth[t] = static_cast<float>(depth);
                river.texel[t] = static_cast<std::uint8_t>(plume ? RiverTexel::plume : RiverTexel::river);
            } else {
                problem.cell[t] = FlowCell::bank;
                dry_inside[t] = 1;
            }
        }
    problem.islands = mark_islands(g, problem.cell, dry_inside, problem.island_of);
    river.islands = static_cast<std::size_t>(problem.islands);
    auto solved = solve_stream_function(problem);
    if (!solved) return solved.error();
    const std::vector<double>& psi = solved->psi;

    const double area_sum = current_from_psi(in, problem, psi, frame, mouth, river);
    claim_bank_ring(in, g, problem, frame, mouth, river);
    std::vector<float> river_weight, still_weight;
    blend_with_still_water(g, still, std::max(mouth_width, 2.0 * g.texel), river.texel, river_weight, still_weight);
    river.channel_s = frame.along;
    river.channel_n = frame.across;
    river.tangent_x = frame.tx;
    river.tangent_z = frame.tz;
    // The query weighs the current by the texels' depths: the depth the discharge is matched
    // with is the one a saved bake reads back, so a saved river carries the same current.
    round_to_saved_encoding(river.depth);
    match_queried_discharge(river, problem.cell, in.inflows);
    pack_query_texels(river, river_weight, still_weight);
    // Mean speed: discharge over the mean section (wet area / length).
    const double mean_area = area_sum * g.texel * g.texel / std::max(mouth, g.texel);
    river.mean_speed = mean_area > 0.0 ? river.discharge / mean_area : 0.0;
    if (any_cut) river.cut = std::move(cut);
    return {};
}

}  // namespace tidewater::detail
