// Lakes first (their extents are what rivers run into), then the rivers from the
// last receiver up: a tributary meets the surface of the river it joins.
#include "tidewater/detail/water_bodies_bake.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "bodies/lake_extent.hpp"
#include "bodies/river_channel.hpp"

namespace tidewater::detail {

namespace {

/// A plume reaches this many mouth widths into still water.
constexpr double kPlumeWidths = 4.0;
/// The most centreline samples a river may need.
constexpr double kMaxCentrelineSamples = 1e5;

Error named(const std::string& where, Error e) {
    e.message = fmt::format("{}: {}", where, e.message);
    return e;
}

std::string river_path(const Scene& scene, std::size_t r) {
    return fmt::format("{}: /rivers/{}", scene_label(scene), r);
}

/// Distance from p to the polyline and the distance along it of the nearest point.
double distance_to_line(const std::vector<glm::dvec2>& line, const std::vector<double>& along, glm::dvec2 p,
                        double* along_at = nullptr, double* across = nullptr) {
    double best = 1e300;
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
        const glm::dvec2 a = line[k], d = line[k + 1] - a, ap = p - a;
        const double len2 = d.x * d.x + d.y * d.y;
        const double u = std::clamp((ap.x * d.x + ap.y * d.y) / len2, 0.0, 1.0);
        const glm::dvec2 q = a + u * d;
        const double dist = std::hypot(p.x - q.x, p.y - q.y);
        if (dist < best) {
            best = dist;
            const double len = std::sqrt(len2);
            if (along_at) *along_at = along[k] + u * len;
            if (across) *across = (d.x * ap.y - d.y * ap.x) / len;
        }
    }
    return best;
}

struct RiverPlan {
    CentrelineSamples samples;  // truncated at the mouth
    RiverEnd end = RiverEnd::domain_edge;
    int receiver = -1;
    double joins_at = 0.0;  // along the receiving river
    int side = 0;           // the receiving river's bank it enters from
    double total = 0.0;     // discharge below all tributaries
};

Result<std::vector<LakeBake>> find_lakes(const Scene& scene, const Terrain& ground, const BodiesBakeOptions& options) {
    std::vector<LakeBake> lakes;
    if (scene.lakes.empty()) return lakes;
    FieldGrid grid;
    const double half = ground.extent_half_size();
    grid.nx = grid.nz = options.lake_resolution;
    grid.texel = 2.0 * half / options.lake_resolution;
    grid.corner = ground.extent_center() - glm::dvec2(half);
    const std::vector<float> heights = sample_terrain(ground, grid);
    for (std::size_t i = 0; i < scene.lakes.size(); ++i) {
        auto lake =
            find_lake_extent(scene.lakes[i], grid, heights, fmt::format("{}: /lakes/{}", scene_label(scene), i));
        if (!lake) return lake.error();
        lakes.push_back(std::move(lake).value());
    }
    for (std::size_t a = 0; a < lakes.size(); ++a)
        for (std::size_t b = a + 1; b < lakes.size(); ++b) {
            const LakeBake &la = lakes[a], &lb = lakes[b];
            for (int j = 0; j < la.grid.nz; ++j)
                for (int i = 0; i < la.grid.nx; ++i) {
                    const glm::dvec2 p = la.grid.center(i, j);
                    if (!la.inside[la.grid.index(i, j)] || !lb.grid.contains(p)) continue;
                    int bi = 0, bj = 0;
                    lb.grid.texel_of(p, bi, bj);
                    if (lb.inside[lb.grid.index(bi, bj)])
                        return Error{ErrorCode::invalid_argument,
                                     fmt::format("{}: /lakes/{}: lake \"{}\" overlaps lake \"{}\" at [{:.1f}, {:.1f}]",
                                                 scene_label(scene), b, lb.name, la.name, p.x, p.y)};
                }
        }
    return lakes;
}

/// Walks each river to where it first meets a lake, the ocean or another river.
Status plan_mouth(const Scene& scene, const Terrain& terrain, const std::vector<LakeBake>& lakes,
                  const std::vector<CentrelineSamples>& raw, std::size_t r, RiverPlan& plan) {
    const SceneRiver& river = scene.rivers[r];
    const CentrelineSamples& s = raw[r];
    // Whether river a's mouth lies within river b's channel.
    auto ends_in = [&](std::size_t a, std::size_t b) {
        double at = 0.0;
        const double d = distance_to_line(raw[b].points, raw[b].along, raw[a].points.back(), &at);
        return d <= 0.5 * at_along(raw[b].along, raw[b].width, at);
    };
    auto water_at = [&](glm::dvec2 p, RiverPlan& hit) {
        const double ground = terrain.height_at(p);
        for (std::size_t l = 0; l < lakes.size(); ++l)
            if (lakes[l].holds(p, ground)) {
                hit.end = RiverEnd::lake;
                hit.receiver = static_cast<int>(l);
                return true;
            }
        for (std::size_t o = 0; o < raw.size(); ++o) {
            if (o == r || ends_in(o, r)) continue;  // a tributary of this river is not its receiver
            double at = 0.0, across = 0.0;
            const double d = distance_to_line(raw[o].points, raw[o].along, p, &at, &across);
            if (d <= 0.5 * at_along(raw[o].along, raw[o].width, at)) {
                hit.end = RiverEnd::river;
                hit.receiver = static_cast<int>(o);
                hit.joins_at = at;
                hit.side = across >= 0.0 ? 1 : -1;
                return true;
            }
        }
        if (scene.has_ocean && ground < scene.water_level()) {
            hit.end = RiverEnd::ocean;
            return true;
        }
        return false;
    };
    RiverPlan probe;
    if (water_at(s.points[0], probe))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}/path/0: the river \"{}\" starts in water (its source must be on land)",
                                 river_path(scene, r), river.name)};
    for (std::size_t k = 1; k < s.points.size(); ++k) {
        if (!water_at(s.points[k], plan)) continue;
        plan.samples.points.assign(s.points.begin(), s.points.begin() + static_cast<long>(k) + 1);
        plan.samples.along.assign(s.along.begin(), s.along.begin() + static_cast<long>(k) + 1);
        plan.samples.width.assign(s.width.begin(), s.width.begin() + static_cast<long>(k) + 1);
        return {};
    }
    // No body: it must leave the terrain's extent.
    const glm::dvec2 c = terrain.extent_center(), e = s.points.back();
    const double half = terrain.extent_half_size();
    const double slack = std::max(s.width.back(), 0.01 * half);
    if (std::max(std::abs(e.x - c.x), std::abs(e.y - c.y)) < half - slack)
        return Error{
            ErrorCode::invalid_argument,
            fmt::format("{}/path: the river \"{}\" ends on land at [{:.1f}, {:.1f}]; a river ends in a lake, the "
                        "ocean, another river or at the domain edge",
                        river_path(scene, r), river.name, e.x, e.y)};
    plan.samples = s;
    plan.end = RiverEnd::domain_edge;
    return {};
}

/// Receivers before their tributaries; rivers running into each other in a loop are an error.
Result<std::vector<std::size_t>> bake_order(const Scene& scene, const std::vector<RiverPlan>& plans) {
    std::vector<std::size_t> order;
    std::vector<bool> placed(plans.size(), false);
    while (order.size() < plans.size()) {
        const std::size_t before = order.size();
        for (std::size_t r = 0; r < plans.size(); ++r) {
            if (placed[r]) continue;
            if (plans[r].end == RiverEnd::river && !placed[static_cast<std::size_t>(plans[r].receiver)]) continue;
            placed[r] = true;
            order.push_back(r);
        }
        if (order.size() == before) {
            const std::size_t r =
                static_cast<std::size_t>(std::find(placed.begin(), placed.end(), false) - placed.begin());
            return Error{ErrorCode::invalid_argument, fmt::format("{}: the river \"{}\" runs into a loop of rivers",
                                                                  river_path(scene, r), scene.rivers[r].name)};
        }
    }
    return order;
}

/// Each river's centreline sampled, its mouth found (ocean, lake, river or the domain's
/// edge), the order to bake them in (a river before its tributaries) and the discharge
/// each carries below its tributaries.
struct RiverPlans {
    std::vector<RiverPlan> plans;
    std::vector<std::size_t> order;
};
Result<RiverPlans> plan_rivers(const Scene& scene, const Terrain& uncut, const std::vector<LakeBake>& lakes) {
    const std::size_t count = scene.rivers.size();
    std::vector<CentrelineSamples> raw(count);
    for (std::size_t r = 0; r < count; ++r) {
        const auto& path = scene.rivers[r].path;
        const auto& w = scene.rivers[r].width;
        const double spacing = 0.25 * *std::min_element(w.begin(), w.end());
        double length = 0.0;
        for (std::size_t k = 0; k + 1 < path.size(); ++k)
            length += std::hypot(path[k + 1].x - path[k].x, path[k + 1].y - path[k].y);
        // Samples every quarter of the narrowest width: a very long, very narrow river would
        // need more than memory allows, and its grid could not hold it anyway.
        if (length / spacing > kMaxCentrelineSamples)
            return Error{
                ErrorCode::invalid_argument,
                fmt::format("{}/path: the river \"{}\" is {:.0f} m long and {} m wide at its narrowest: at most "
                            "{:.0f} widths long allowed",
                            river_path(scene, r), scene.rivers[r].name, length, 4.0 * spacing,
                            kMaxCentrelineSamples / 4.0)};
        raw[r] = resample_centreline(path, w, spacing);
    }
    RiverPlans out;
    out.plans.resize(count);
    for (std::size_t r = 0; r < count; ++r)
        if (auto st = plan_mouth(scene, uncut, lakes, raw, r, out.plans[r]); !st) return st.error();
    auto order = bake_order(scene, out.plans);
    if (!order) return order.error();
    out.order = std::move(order).value();
    // Discharges add downstream: tributaries (later in the order) first.
    for (std::size_t r = 0; r < count; ++r) out.plans[r].total = scene.rivers[r].discharge;
    for (auto it = out.order.rbegin(); it != out.order.rend(); ++it)
        if (out.plans[*it].end == RiverEnd::river)
            out.plans[static_cast<std::size_t>(out.plans[*it].receiver)].total += out.plans[*it].total;
    return out;
}

/// Everything a river's bake depends on, for reuse after an edit.
RiverBakeKey river_key(const SceneRiver& river, const RiverPlan& plan, const ChannelInputs& in, double mouth_level,
                       bool still_mouth) {
    RiverBakeKey key;
    key.path = river.path;
    key.width = river.width;
    key.discharge = river.discharge;
    key.manning = river.manning;
    key.texel = in.texel;
    key.carve = river.carve;
    key.samples = plan.samples.points.size();
    key.end = plan.end;
    key.receiver = plan.receiver;
    key.joins_at = plan.joins_at;
    key.total = plan.total;
    key.mouth_level = mouth_level;
    key.psi_left = in.psi_left;
    key.plume_length = still_mouth ? kPlumeWidths * plan.samples.width.back() : 0.0;
    key.side = plan.side;
    for (const Inflow& f : in.inflows)
        key.inflows.push_back({f.along, f.width, f.discharge, static_cast<double>(f.side)});
    return key;
}

/// Whether the previous bake's river `old` is this one: the same key, the same lake
/// extent where it runs into a lake (its plume), and the same cuts and ground under its
/// grid (`same_ground`).
template <typename SameGround>
bool unchanged_river(const RiverBake& old, const SceneRiver& river, const RiverBakeKey& key, const RiverPlan& plan,
                     const WaterBodiesBake& previous, const std::vector<LakeBake>& lakes,
                     const std::vector<std::shared_ptr<const TerrainCut>>& cuts, const SameGround& same_ground) {
    // NaN mouth levels (domain edge) compare unequal: compare the rest then.
    RiverBakeKey a = old.key, b = key;
    if (std::isnan(a.mouth_level) && std::isnan(b.mouth_level)) a.mouth_level = b.mouth_level = 0.0;
    const auto receiver = static_cast<std::size_t>(plan.receiver);
    const bool same_receiver =
        plan.end != RiverEnd::lake ||
        (receiver < previous.lakes.size() && previous.lakes[receiver].inside == lakes[receiver].inside &&
         previous.lakes[receiver].grid.corner == lakes[receiver].grid.corner);
    return old.name == river.name && a == b && same_receiver && old.baked_over == cuts_under(cuts, old.grid) &&
           same_ground(old.grid);
}

}  // namespace

Result<WaterBodiesBake> bake_water_bodies(const Scene& scene, const BodiesBakeOptions& options) {
    WaterBodiesBake out;
    out.lake_resolution = options.lake_resolution;
    out.texels_across = options.texels_across;
    // Always from the shape alone: a baked scene's terrain already carries its cuts.
    const Terrain uncut = scene.terrain.with_cuts({});
    // Lakes are found again (a pass over the lake grid); the previous bake's rivers are
    // reused only over the same grids, where the ground under them is unchanged.
    const WaterBodiesBake* previous = options.previous;
    if (previous &&
        (previous->lake_resolution != options.lake_resolution || previous->texels_across != options.texels_across))
        previous = nullptr;
    const Terrain previous_shape = previous ? previous->terrain.with_cuts({}) : Terrain();
    auto same_ground = [&](const FieldGrid& g) {
        for (int j = 0; j < g.nz; ++j)
            for (int i = 0; i < g.nx; ++i)
                if (uncut.shape_height_at(g.center(i, j)) != previous_shape.shape_height_at(g.center(i, j)))
                    return false;
        return true;
    };
    auto lakes = find_lakes(scene, uncut, options);
    if (!lakes) return lakes.error();
    out.lakes = std::move(lakes).value();
    auto planned = plan_rivers(scene, uncut, out.lakes);
    if (!planned) return planned.error();
    const std::vector<RiverPlan>& plans = planned->plans;
    const std::vector<std::size_t>* order = &planned->order;
    const std::size_t count = scene.rivers.size();

    out.rivers.resize(count);
    std::vector<std::shared_ptr<const TerrainCut>> cuts;
    std::vector<ChannelInputs> inputs(count);
    for (std::size_t done = 0; done < order->size(); ++done) {
        if (options.cancel.stop_requested()) return Error{ErrorCode::cancelled, "bake: cancelled"};
        const std::size_t r = (*order)[done];
        const SceneRiver& river = scene.rivers[r];
        const RiverPlan& plan = plans[r];
        const Terrain terrain = uncut.with_cuts(cuts);
        RiverBake& bake = out.rivers[r];
        bake.name = river.name;
        bake.own_discharge = river.discharge;
        bake.discharge = plan.total;
        bake.manning = river.manning;
        bake.end = plan.end;
        bake.receiver = plan.receiver;
        ChannelInputs& in = inputs[r];
        in.terrain = &terrain;
        in.carve = river.carve;
        in.texel = *std::min_element(river.width.begin(), river.width.end()) / options.texels_across;
        for (std::size_t t = 0; t < count; ++t)
            if (plans[t].end == RiverEnd::river && static_cast<std::size_t>(plans[t].receiver) == r)
                in.inflows.push_back({plans[t].joins_at, plans[t].samples.width.back(), plans[t].total, plans[t].side});
        ProfileInputs profile;
        profile.terrain = &terrain;
        profile.carve = river.carve;
        profile.texel = in.texel;
        profile.manning = river.manning;
        profile.mouth_level = std::nan("");
        switch (plan.end) {
            case RiverEnd::ocean:
                profile.mouth_level = scene.water_level();
                break;
            case RiverEnd::lake:
                profile.mouth_level = out.lakes[static_cast<std::size_t>(plan.receiver)].level;
                break;
            case RiverEnd::river: {
                const RiverBake& main = out.rivers[static_cast<std::size_t>(plan.receiver)];
                const double at = plan.joins_at;
                profile.mouth_level = at_along(main.along, main.surface, at);
                // Its banks continue the ones of the river it joins, upstream of the junction.
                const ChannelInputs& main_in = inputs[static_cast<std::size_t>(plan.receiver)];
                const double upstream = at - 0.5 * plan.samples.width.back();
                in.psi_left = plan.side < 0 ? bank_psi(main_in, main.own_discharge, upstream, -1)
                                            : bank_psi(main_in, main.own_discharge, upstream, 1) - plan.total;
                in.receiver_river = &main;
                break;
            }
            case RiverEnd::domain_edge:
                break;
        }
        bake.mouth_level = profile.mouth_level;
        const bool still_mouth = plan.end == RiverEnd::lake || plan.end == RiverEnd::ocean;
        RiverBakeKey key = river_key(river, plan, in, profile.mouth_level, still_mouth);
        // Unchanged, over the same terrain under its grid: the previous bake is this one.
        if (previous && r < previous->rivers.size() &&
            unchanged_river(previous->rivers[r], river, key, plan, *previous, out.lakes, cuts, same_ground)) {
            bake = previous->rivers[r];
            ++out.reused_rivers;
            in.terrain = nullptr;
            if (bake.cut) cuts.push_back(bake.cut);
            if (options.progress) options.progress(static_cast<double>(done + 1) / static_cast<double>(order->size()));
            continue;
        }
        profile.discharge.resize(plan.samples.along.size());
        for (std::size_t k = 0; k < profile.discharge.size(); ++k) {
            double q = river.discharge;
            for (const Inflow& f : in.inflows) q += f.entered(plan.samples.along[k]);
            profile.discharge[k] = q;
        }
        in.centre_depth = bake_profile(plan.samples, profile, bake);
        // A river off the domain's edge meets no level: its surface there is its reference.
        if (std::isnan(bake.mouth_level)) bake.mouth_level = bake.surface.back();
        if (still_mouth) {
            in.plume_length = key.plume_length;
            if (plan.end == RiverEnd::lake) {
                const LakeBake* lake = &out.lakes[static_cast<std::size_t>(plan.receiver)];
                in.in_receiver = [lake](glm::dvec2 p, double ground) { return lake->holds(p, ground); };
            } else {
                const double level = scene.water_level();
                in.in_receiver = [level](glm::dvec2, double ground) { return ground < level; };
            }
        }
        if (auto st = bake_channel(in, bake); !st) return named(river_path(scene, r), st.error());
        bake.key = std::move(key);
        bake.baked_over = cuts_under(cuts, bake.grid);
        in.terrain = nullptr;  // `terrain` ends with this iteration
        if (bake.cut) cuts.push_back(bake.cut);
        if (options.progress) options.progress(static_cast<double>(done + 1) / static_cast<double>(order->size()));
    }
    out.terrain = uncut.with_cuts(cuts);
    if (options.progress) options.progress(1.0);
    return out;
}

}  // namespace tidewater::detail
