#include "shore/shore_diffraction.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <optional>
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
    /// The last bucket that holds a texel (as offsets count them), -1 where none does: the
    /// march need not go past the row after it.
    int last_filled() const {
        for (std::size_t r = offsets.size() - 1; r > 0; --r)
            if (offsets[r] > offsets[r - 1]) return static_cast<int>(r) - 1;
        return -1;
    }
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

/// The values of the texel centred at `p` between the march's rows r and r + 1
/// (`before` and `after`, whose first point is the frame's point `first`): the magnitude
/// blended bilinearly, the breaking where the blend is at least a half, and whether the
/// march reached it (a magnitude over `least` at a corner).
struct TexelFromRows {
    double magnitude = 0.0;
    bool broken = false, reached = false;
};
TexelFromRows texel_from_rows(const MarchFrame& f, glm::dvec2 p, int r, const KeptRow& before, const KeptRow& after,
                              int first, double least) {
    const double s = f.spacing;
    const double u = std::clamp((glm::dot(p, f.along) - f.x0) / s - r, 0.0, 1.0);
    const double fy = (glm::dot(p, f.across) - f.y0) / s;
    const int j0 = std::clamp(static_cast<int>(std::floor(fy)), 0, f.points - 2);
    const double v = std::clamp(fy - static_cast<double>(j0), 0.0, 1.0);
    const auto j = static_cast<std::size_t>(j0 - first);
    const double m00 = before.magnitude[j], m01 = before.magnitude[j + 1];
    const double m10 = after.magnitude[j], m11 = after.magnitude[j + 1];
    auto lerp = [&](double q00, double q01, double q10, double q11) {
        return (1 - u) * ((1 - v) * q00 + v * q01) + u * ((1 - v) * q10 + v * q11);
    };
    TexelFromRows t;
    t.magnitude = lerp(m00, m01, m10, m11);
    t.broken = lerp(before.broken[j], before.broken[j + 1], after.broken[j], after.broken[j + 1]) >= 0.5;
    t.reached = std::max({m00, m01, m10, m11}) > least;
    return t;
}

/// The march of `wave` over `depths` (world xz to m; it must outlive the march; sea
/// heights `sea_height`, may be null) in `frame`, from its row `start` to its last, over
/// its points [first, first + points).
template <typename Depths>
ParabolicInput march_input(const Wave& wave, const SeaState& sea, const MarchFrame& frame, int start, int first,
                           int points, const Depths& depths, const SeaHeight* sea_height) {
    const double x_start = frame.x0 + start * frame.spacing;
    const double y_first = frame.y0 + first * frame.spacing;
    ParabolicInput in;
    in.grid = {frame.steps - start, points, frame.spacing, frame.spacing};
    in.omega = wave.omega;
    in.depth_row = [&depths, frame, x_start, y_first](int step, std::span<float> depth) {
        const double x = x_start + step * frame.spacing;
        for (std::size_t j = 0; j < depth.size(); ++j)
            depth[j] = static_cast<float>(depths(frame.world(x, y_first + static_cast<double>(j) * frame.spacing)));
    };
    in.incident_amplitude = wave.amplitude;
    in.incident_in_deep_water = true;
    in.sea_over_component = std::sqrt(sea.energy) / wave.amplitude;
    in.sea_period = sea.mean_period;
    in.random_sea = sea.components > 1;
    if (in.random_sea && sea_height != nullptr) {
        in.sea_height_row = [sea_height, frame, x_start, y_first](int step, std::span<float> height,
                                                                  std::span<const char> asked) {
            const double x = x_start + step * frame.spacing;
            for (std::size_t j = 0; j < height.size(); ++j)
                if (asked[j])
                    height[j] = static_cast<float>(
                        sea_height->at(frame.world(x, y_first + static_cast<double>(j) * frame.spacing)));
        };
        in.sea_height_bound = sea_height->highest;
    }
    return in;
}

/// The texels to fill (not land, not kept by `keep`) whose row (the march row just before
/// them) is from `first_row` on and whose first point across (the lower of the two they
/// lie between) is in [lo, hi], bucketed by row from `first_row`: a window's texels,
/// found row by row of the grid over the span the window crosses.
RowBuckets bucket_window(const PatchedDepths& depths, const MarchFrame& f, int first_row, int lo, int hi,
                         const std::function<bool(std::size_t)>& keep) {
    const ShoreField& field = *depths.field;
    const int n = field.resolution;
    RowBuckets b;
    b.first_row = first_row;
    const int rows = f.steps - 1 - first_row;
    b.offsets.assign(static_cast<std::size_t>(std::max(rows, 0)) + 1, 0);
    if (rows <= 0 || hi < lo) return b;
    const double s = f.spacing;
    // The window in the frame, a texel's reach wider: x >= x_lo, y_lo <= y <= y_hi.
    const double x_lo = f.x0 + first_row * s - field.texel, y_lo = f.y0 + lo * s - field.texel,
                 y_hi = f.y0 + (hi + 1) * s + field.texel;
    std::vector<std::pair<int, std::uint32_t>> found;  // (row, texel)
    for (int j = 0; j < n; ++j) {
        // Along grid row j, x and y are linear in i: the i where both lie in the window.
        double i_lo = 0.0, i_hi = n - 1.0;
        auto within = [&](glm::dvec2 axis, double lo_value, double hi_value) {
            const double at0 = glm::dot(field.texel_center(0, j), axis), slope = field.texel * axis.x;
            if (std::abs(slope) < 1e-12) {
                if (at0 < lo_value || at0 > hi_value) i_hi = -1.0;
                return;
            }
            double a = (lo_value - at0) / slope, c = (hi_value - at0) / slope;
            if (a > c) std::swap(a, c);
            i_lo = std::max(i_lo, std::floor(a));
            i_hi = std::min(i_hi, std::ceil(c));
        };
        within(f.along, x_lo, 1e300);
        within(f.across, y_lo, y_hi);
        for (int i = static_cast<int>(i_lo); i <= static_cast<int>(i_hi); ++i) {
            const std::size_t k = field.index(i, j);
            if (depths.at(i, j) <= 0.0f || keep(k)) continue;
            const glm::dvec2 p = field.texel_center(i, j);
            const int row = std::clamp(static_cast<int>(std::floor((glm::dot(p, f.along) - f.x0) / s)), 0, f.steps - 2);
            const int j0 =
                std::clamp(static_cast<int>(std::floor((glm::dot(p, f.across) - f.y0) / s)), 0, f.points - 2);
            if (row < first_row || j0 < lo || j0 > hi) continue;
            found.emplace_back(row - first_row, static_cast<std::uint32_t>(k));
        }
    }
    for (const auto& [row, k] : found) ++b.offsets[static_cast<std::size_t>(row) + 1];
    for (std::size_t r = 1; r < b.offsets.size(); ++r) b.offsets[r] += b.offsets[r - 1];
    b.texels.resize(found.size());
    std::vector<std::size_t> next(b.offsets.begin(), b.offsets.end() - 1);
    for (const auto& [row, k] : found) b.texels[next[static_cast<std::size_t>(row)]++] = k;
    return b;
}

}  // namespace

double ramp(double value, double none, double full) {
    return std::clamp((value - none) / (full - none), 0.0, 1.0);
}

double march_share(double angle, double wavelength, double spacing) {
    const double across = std::abs(std::sin(angle)) * spacing;  // the march's spacing along the crests' normal
    const double points = across > 0.0 ? wavelength / across : kFullPoints;
    return ramp(angle, kNoAngle, kFullAngle) * ramp(points, kNoPoints, kFullPoints);
}

std::uint8_t held_share(const Wave& wave, float kx, float kz, double spacing) {
    const double k = std::hypot(static_cast<double>(kx), static_cast<double>(kz));  // k(h)
    const double turned = std::acos(
        std::clamp((static_cast<double>(kx) * wave.dir_x + static_cast<double>(kz) * wave.dir_z) / k, -1.0, 1.0));
    return static_cast<std::uint8_t>(std::lround(255.0 * march_share(turned, kTwoPi / k, spacing)));
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

void KeptMarch::end_at(int last) {
    const auto rows_to = static_cast<std::size_t>(std::max(last - start + 1, 0));
    const std::size_t kept_rows = rows_to == 0 ? 0 : (rows_to - 1) / kKeptRowsEvery + 1;
    amplitude.resize(kept_rows * static_cast<std::size_t>(points));
    broken.resize(kept_rows * static_cast<std::size_t>(points));
    columns.amplitude.resize(rows_to * columns.count);
    columns.broken.resize(rows_to * columns.count);
    columns.phase.resize(rows_to);
}

DiffractedWave diffract_wave(const Wave& wave, const SeaState& sea, const ShoreField& field,
                             const std::function<bool(std::size_t)>& keep, const SeaHeight* sea_height,
                             KeptMarch* kept) {
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
    const auto depths = [&field](glm::dvec2 p) { return field.sample(field.depth, p); };
    ParabolicInput in = march_input(wave, sea, frame, start, 0, frame.points, depths, sea_height);
    // Past the row after the last texel to fill nothing reads the march.
    in.grid.steps = std::min(in.grid.steps, buckets.last_filled() + 2 - start);
    if (kept) {
        *kept = {};
        kept->start = start;
        kept->points = frame.points;
        kept->columns.every = KeptMarch::kKeptPointsEvery;
        in.keep_columns = &kept->columns;
    }

    KeptRow before, after;
    const double least = 1e-6 * wave.amplitude;
    ParabolicMarch march(in);
    for (bool more = march.started(); more; more = march.advance()) {
        const ParabolicRow row = march.row();
        after.keep(row);
        if (kept && row.step % KeptMarch::kKeptRowsEvery == 0) {
            kept->amplitude.insert(kept->amplitude.end(), row.amplitude.begin(), row.amplitude.end());
            kept->broken.insert(kept->broken.end(), row.broken.begin(), row.broken.end());
        }
        if (row.step > 0) {
            const int r = start + row.step - 1;  // the texels between the row before and this one
            for (std::size_t at = buckets.offsets[static_cast<std::size_t>(r)];
                 at < buckets.offsets[static_cast<std::size_t>(r) + 1]; ++at) {
                const std::size_t k = buckets.texels[at];
                const int i = static_cast<int>(k % static_cast<std::size_t>(field.resolution)),
                          jj = static_cast<int>(k / static_cast<std::size_t>(field.resolution));
                const TexelFromRows t = texel_from_rows(frame, field.texel_center(i, jj), r, before, after, 0, least);
                out.share[k] = t.reached ? 255 : 0;
                out.amplitude[k] = static_cast<float>(t.magnitude / wave.amplitude);
                out.broken[k] = t.broken ? 1 : 0;
            }
        }
        std::swap(before, after);
    }
    return out;
}

namespace {

/// Whether `march`, a whole row marched again, is at its frame's row `frame_row` the
/// first march's kept row there (in the phase it carries) to kSettledAmplitude of
/// `amplitude` at every point, breaking where it broke. False at a row not kept.
bool settled_at(const KeptMarch& kept, int frame_row, const ParabolicMarch& march, double amplitude) {
    const int since = frame_row - kept.start;
    if (since % KeptMarch::kKeptRowsEvery != 0) return false;
    const auto n = static_cast<std::size_t>(since / KeptMarch::kKeptRowsEvery);
    if (n >= kept.rows()) return false;
    const ParabolicRow row = march.row();
    const auto points = static_cast<std::size_t>(kept.points);
    if (row.amplitude.size() != points) return false;
    const std::complex<double> turn =
        std::polar(1.0, march.phase() - kept.columns.phase[static_cast<std::size_t>(since)]);
    const double limit = kSettledAmplitude * amplitude;
    for (std::size_t j = 0; j < points; ++j)
        if (std::abs(row.amplitude[j] * turn - kept.amplitude[n * points + j]) > limit ||
            row.broken[j] != kept.broken[n * points + j])
            return false;
    return true;
}

}  // namespace

DiffractionChange rediffract_wave(const Wave& wave, const SeaState& sea, const ShoreField& before,
                                  const PatchedDepths& after, const KeptMarch& kept, const WorldRect& changed,
                                  const std::function<bool(std::size_t)>& keep, const Remarch& how) {
    DiffractionChange out;
    if (kept.rows() == 0 || !(wave.amplitude > 0.0)) return out;
    const MarchFrame frame = march_frame(wave, before);
    if (frame.points != kept.points) return out;
    // The edit's reach in the frame's rows and points (an infinite side reaches the grid's end).
    double x_lo = 1e300, x_hi = -1e300, y_lo = 1e300, y_hi = -1e300;
    for (const glm::dvec2 c :
         {changed.lo, glm::dvec2(changed.hi.x, changed.lo.y), glm::dvec2(changed.lo.x, changed.hi.y), changed.hi}) {
        const glm::dvec2 clamped =
            glm::clamp(c, before.corner, before.corner + glm::dvec2(before.texel * before.resolution));
        const double x = (glm::dot(clamped, frame.along) - frame.x0) / frame.spacing;
        const double y = (glm::dot(clamped, frame.across) - frame.y0) / frame.spacing;
        x_lo = std::min(x_lo, x);
        x_hi = std::max(x_hi, x);
        y_lo = std::min(y_lo, y);
        y_hi = std::max(y_hi, y);
    }
    const int last_kept = kept.start + KeptMarch::kKeptRowsEvery * (static_cast<int>(kept.rows()) - 1);
    // Before the march's first row the depths are not read (open sea).
    if (x_hi + 1.0 < kept.start) return out;
    // Taken up again at the last kept row at least a row before the edit.
    const int edit_row = std::max(kept.start, static_cast<int>(std::floor(x_lo)) - 1);
    const int n_kept = std::min(static_cast<int>(kept.rows()) - 1, (edit_row - kept.start) / KeptMarch::kKeptRowsEvery);
    const int r0 = std::min(last_kept, kept.start + KeptMarch::kKeptRowsEvery * n_kept);
    const MarchColumns& columns = kept.columns;
    const double entering_phase = columns.phase[static_cast<std::size_t>(r0 - kept.start)];
    // The window's sides on kept columns, at least this many points from the edit; the
    // points next to each side whose difference is watched.
    constexpr int every = KeptMarch::kKeptPointsEvery, kSide = 3;
    const int last_column = static_cast<int>(columns.count) - 1;
    int column_lo = std::max(0, (static_cast<int>(std::floor(y_lo)) - kSide) / every - 1);
    int column_hi = std::min(last_column, (static_cast<int>(std::ceil(y_hi)) + kSide) / every + 2);
    // Past the first march's end no side is kept: an edit that reaches there is marched
    // across the whole row, as far as the new depths have texels to fill.
    const int kept_end = kept.end();
    if (x_hi + 2.0 >= kept_end) {
        column_lo = 0;
        column_hi = last_column;
    }
    // With what the first march left, a window as wide as a third of the march is the
    // whole row instead, marched over the new depths alone: two marches side by side in a
    // window (and each widening's again from its first row) cost more.
    const bool whole_rows = static_cast<bool>(how.marched_before);
    auto whole_if_wide = [&] {
        if (whole_rows && 3 * (column_hi - column_lo) * every >= frame.points) {
            column_lo = 0;
            column_hi = last_column;
        }
    };
    whole_if_wide();
    const double amplitude = wave.amplitude, least = 1e-6 * amplitude;
    const double side_limit = 0.05 * how.tolerance * amplitude;
    const std::size_t row_at = static_cast<std::size_t>(n_kept) * static_cast<std::size_t>(kept.points);

    for (;;) {
        ++out.windows;
        out.texels.clear();
        out.amplitude.clear();
        out.share.clear();
        out.broken.clear();
        // A side past the last kept column is the march's own wall.
        const bool wall_hi = column_hi == last_column && last_column * every < frame.points - 1;
        const int lo = column_lo * every, hi = wall_hi ? frame.points - 1 : column_hi * every;
        const int width = hi - lo + 1;
        // The whole row: no sides, and the first march's texels stand for the old march's.
        const bool whole = whole_rows && lo == 0 && hi == frame.points - 1;
        std::vector<std::complex<double>> entering(static_cast<std::size_t>(width));
        for (int j = 0; j < width; ++j)
            entering[static_cast<std::size_t>(j)] =
                std::complex<double>(kept.amplitude[row_at + static_cast<std::size_t>(lo + j)]);
        const std::span<const char> entering_broken(kept.broken.data() + row_at + lo, static_cast<std::size_t>(width));
        const auto old_depths = [&before](glm::dvec2 p) { return before.sample(before.depth, p); };
        const auto new_depths = [&after](glm::dvec2 p) { return after.sample(p); };
        ParabolicInput old_in = march_input(wave, sea, frame, r0, lo, width, old_depths, how.sea_before);
        ParabolicInput new_in = march_input(wave, sea, frame, r0, lo, width, new_depths, how.sea_after);
        for (ParabolicInput* in : {&old_in, &new_in}) {
            in->entering_amplitude = entering;
            in->entering_broken = entering_broken;
            in->entering_phase = entering_phase;
            in->sides = &columns;
            in->sides_first_row = r0 - kept.start;
            in->side_lo = lo > 0 ? static_cast<std::size_t>(column_lo) : ParabolicInput::kNoSide;
            in->side_hi =
                wall_hi || hi == frame.points - 1 ? ParabolicInput::kNoSide : static_cast<std::size_t>(column_hi);
        }
        const bool held_lo = old_in.side_lo != ParabolicInput::kNoSide,
                   held_hi = old_in.side_hi != ParabolicInput::kNoSide;
        const RowBuckets buckets = bucket_window(after, frame, r0, lo, hi - 1, keep);
        // A window with a side ends with the first march's rows; one with none at the row
        // after its last texel to fill. A window's texel past the first march's end (the
        // edit made it one to fill) is the whole row's to march.
        const bool sided = held_lo || held_hi;
        const int last_filled = buckets.last_filled();
        if (sided && last_filled + r0 + 1 > kept_end) {
            column_lo = 0;
            column_hi = last_column;
            continue;
        }
        const int steps = sided ? kept_end - r0 + 1 : std::max(last_filled + 2, 1);
        old_in.grid.steps = new_in.grid.steps = std::min(new_in.grid.steps, steps);
        // What the new march leaves for `updated`, written once the window holds: its kept
        // columns inside the window after each step, and its kept rows, turned to the
        // phase the first march's carry.
        struct Kept {
            std::size_t at;
            std::complex<double> amplitude;
            char broken;
        };
        std::vector<Kept> new_columns, new_rows;
        // Past the first march's end the rows carry the new march's own phase.
        std::vector<std::pair<std::size_t, double>> new_phases;
        auto phase_of = [&](std::size_t t, double own) { return t < columns.phase.size() ? columns.phase[t] : own; };
        double new_phase = entering_phase;
        const std::size_t first_inside = static_cast<std::size_t>(held_lo ? column_lo + 1 : column_lo);
        const std::size_t last_inside = static_cast<std::size_t>(held_hi ? column_hi - 1 : column_hi);
        if (how.updated)
            new_in.advanced = [&](std::size_t t, std::span<const std::complex<double>> a, std::span<const char> broken,
                                  double phase) {
                new_phase = phase;
                if (t >= columns.phase.size()) new_phases.emplace_back(t, phase);
                const std::complex<double> turn = std::polar(1.0, phase - phase_of(t, phase));
                for (std::size_t c = first_inside; c <= last_inside; ++c) {
                    const std::size_t j = c * static_cast<std::size_t>(every) - static_cast<std::size_t>(lo);
                    if (j >= a.size()) break;
                    new_columns.push_back({t * columns.count + c, std::complex<double>(a[j] * turn), broken[j]});
                }
            };
        std::optional<ParabolicMarch> old_march;
        if (!whole) old_march.emplace(old_in);
        ParabolicMarch new_march(new_in);
        KeptRow old_before, old_after, new_before, new_after;
        if (old_march) old_before.keep(old_march->row());
        new_before.keep(new_march.row());
        bool widen_lo = false, widen_hi = false;
        while ((!old_march || old_march->advance()) && new_march.advance()) {
            out.points_visited += (old_march ? 2 : 1) * static_cast<std::size_t>(width);
            new_after.keep(new_march.row());
            double largest = 0.0;
            bool same_breaking = true;
            if (old_march) {
                old_after.keep(old_march->row());
                for (int j = 0; j < width; ++j) {
                    const auto ju = static_cast<std::size_t>(j);
                    const double d = std::abs(new_after.magnitude[ju] - old_after.magnitude[ju]);
                    largest = std::max(largest, d);
                    same_breaking = same_breaking && new_after.broken[ju] == old_after.broken[ju];
                }
                // Next to a held side the new march must be the old one there, in phase too
                // (the side holds the old one's value): else the window is too narrow on
                // that side.
                const std::complex<double> to_old = std::polar(1.0, new_march.phase() - old_march->phase());
                const ParabolicRow old_row = old_march->row(), new_row = new_march.row();
                auto apart = [&](int j) {
                    const auto ju = static_cast<std::size_t>(j);
                    return std::abs(new_row.amplitude[ju] * to_old - old_row.amplitude[ju]) > side_limit ||
                           new_row.broken[ju] != old_row.broken[ju];
                };
                for (int j = 0; j <= kSide && j < width; ++j) widen_lo = widen_lo || (held_lo && apart(j));
                for (int j = std::max(0, width - 1 - kSide); j < width; ++j)
                    widen_hi = widen_hi || (held_hi && apart(j));
                if (widen_lo || widen_hi) break;
            }
            const int step = new_march.row().step;
            const int r = step - 1;  // of the window's march; r0 + r of the frame
            for (std::size_t at = buckets.offsets[static_cast<std::size_t>(r)];
                 at < buckets.offsets[static_cast<std::size_t>(r) + 1]; ++at) {
                const std::uint32_t k = buckets.texels[at];
                const int i = static_cast<int>(k % static_cast<std::uint32_t>(before.resolution)),
                          jj = static_cast<int>(k / static_cast<std::uint32_t>(before.resolution));
                const glm::dvec2 p = before.texel_center(i, jj);
                const TexelFromRows is = texel_from_rows(frame, p, r0 + r, new_before, new_after, lo, least);
                MarchedTexel was;
                if (old_march) {
                    const TexelFromRows t = texel_from_rows(frame, p, r0 + r, old_before, old_after, lo, least);
                    was = {static_cast<float>(t.magnitude / amplitude), t.reached, t.broken};
                } else if (const std::optional<MarchedTexel> held = how.marched_before(k)) {
                    was = *held;
                } else {
                    continue;  // nothing reads it
                }
                const double factor = is.magnitude / amplitude;
                if (std::abs(factor - static_cast<double>(was.amplitude)) <= how.tolerance + was.rounding &&
                    is.reached == was.reached && (!is.reached || !was.broken || is.broken == *was.broken))
                    continue;
                out.texels.push_back(k);
                out.amplitude.push_back(static_cast<float>(factor));
                out.share.push_back(is.reached ? 255 : 0);
                out.broken.push_back(is.broken ? 1 : 0);
            }
            const int frame_row = r0 + step;
            if (how.updated && (frame_row - kept.start) % KeptMarch::kKeptRowsEvery == 0) {
                const auto n = static_cast<std::size_t>((frame_row - kept.start) / KeptMarch::kKeptRowsEvery);
                const double row_phase = phase_of(static_cast<std::size_t>(frame_row - kept.start), new_phase);
                const std::complex<double> turn = std::polar(1.0, new_phase - row_phase);
                const ParabolicRow row = new_march.row();
                for (int j = 0; j < width; ++j)
                    new_rows.push_back({n * static_cast<std::size_t>(kept.points) + static_cast<std::size_t>(lo + j),
                                        std::complex<double>(row.amplitude[static_cast<std::size_t>(j)] * turn),
                                        row.broken[static_cast<std::size_t>(j)]});
            }
            std::swap(old_before, old_after);
            std::swap(new_before, new_after);
            const bool past_edit = frame_row > static_cast<int>(std::ceil(x_hi)) + 1;
            // Past the edit, over the same depths and sea, two marches that agree exactly
            // stay so: the edit's wake has died out. (Anything short of exact may yet tip a
            // point over breaking's threshold further on.)
            if (old_march && largest == 0.0 && same_breaking && past_edit) break;
            // A whole row alone: against the first march's kept row, where it has one.
            if (whole && how.settles && past_edit && settled_at(kept, frame_row, new_march, amplitude)) break;
        }
        if (!widen_lo && !widen_hi) {
            if (how.updated) {
                // A march without sides that ran to its last row, or past the first
                // march's end, ends the kept march where it stopped: past there the
                // first march's rows are not this march's, and nothing reads them.
                const int last_row = r0 + new_march.row().step;
                if (!sided && (new_march.row().step + 1 >= new_in.grid.steps || last_row > kept_end))
                    how.updated->end_at(last_row);
                for (const auto& [t, phase] : new_phases) how.updated->columns.phase[t] = phase;
                for (const Kept& k : new_columns) {
                    how.updated->columns.amplitude[k.at] = k.amplitude;
                    how.updated->columns.broken[k.at] = k.broken;
                }
                for (const Kept& k : new_rows) {
                    how.updated->amplitude[k.at] = k.amplitude;
                    how.updated->broken[k.at] = k.broken;
                }
            }
            return out;
        }
        // Marched again from r0, twice as wide on the side that was reached.
        const int columns_wide = column_hi - column_lo;
        if (widen_lo) column_lo = std::max(0, column_lo - columns_wide);
        if (widen_hi) column_hi = std::min(last_column, column_hi + columns_wide);
        whole_if_wide();
    }
}

double PatchedDepths::sample(glm::dvec2 p) const {
    const ShoreField& f = *field;
    const GridTaps t = grid_taps(f.corner, f.texel, f.resolution, p);
    const auto n = static_cast<std::size_t>(f.resolution);
    // The march asks at every point of its rows, nearly all off the patch: the field's
    // depths are read there without finding each tap's texel.
    const bool off_patch =
        width <= 0 || height <= 0 || t.i + 1 < i0 || t.i >= i0 + width || t.j + 1 < j0 || t.j >= j0 + height;
    auto tap = [&](std::size_t k) {
        return static_cast<double>(off_patch ? f.depth[k] : at(static_cast<int>(k % n), static_cast<int>(k / n)));
    };
    return t.w00 * tap(t.k00) + t.w10 * tap(t.k10) + t.w01 * tap(t.k01) + t.w11 * tap(t.k11);
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

std::optional<Wave> whole_sea_wave(std::span<const Wave> waves, const SeaState& sea) {
    glm::dvec2 heading(0.0);
    for (const Wave& w : waves) heading += w.amplitude * w.amplitude * glm::dvec2(w.dir_x, w.dir_z);
    const double length = glm::length(heading);
    if (sea.components < 2 || !(sea.mean_period > 0.0) || !(length > 0.0)) return std::nullopt;
    Wave whole;
    whole.dir_x = heading.x / length;
    whole.dir_z = heading.y / length;
    whole.omega = kTwoPi / sea.mean_period;
    whole.k = whole.omega * whole.omega / kGravity;
    whole.amplitude = std::sqrt(sea.energy);
    return whole;
}

SeaHeight march_sea(std::span<const Wave> waves, const SeaState& sea, std::shared_ptr<const ShoreField> grid,
                    KeptMarch* kept) {
    SeaHeight out;
    if (!grid) return out;
    const ShoreField& field = *grid;
    out.field = std::move(grid);
    const std::optional<Wave> whole = whole_sea_wave(waves, sea);
    if (!whole) return out;
    const DiffractedWave marched = diffract_wave(
        *whole, sea, field,
        [&](std::size_t k) { return sea_leaves(*whole, static_cast<double>(field.depth.values()[k])); }, nullptr, kept);
    out.height.assign(marched.amplitude.size(), 0.0f);
    for (std::size_t k = 0; k < out.height.size(); ++k)
        if (marched.share[k] > 0)
            out.set(k, static_cast<float>(2.0 * whole->amplitude * static_cast<double>(marched.amplitude[k])));
    return out;
}

}  // namespace tidewater::detail
