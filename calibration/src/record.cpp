#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tidewater/calibration/readers.hpp"

namespace tidewater::calibration {

const char* to_string(RecordKind kind) {
    switch (kind) {
        case RecordKind::gauge:
            return "gauge";
        case RecordKind::buoy:
            return "buoy";
        case RecordKind::profile:
            return "profile";
    }
    return "?";
}

double MeasuredRecord::median_spacing() const {
    if (axis.size() < 2) return 0.0;
    std::vector<double> d(axis.size() - 1);
    for (std::size_t k = 0; k + 1 < axis.size(); ++k) d[k] = axis[k + 1] - axis[k];
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    return d[d.size() / 2];
}

Status validate_record(const MeasuredRecord& r) {
    const char* unit = r.kind == RecordKind::profile ? "position" : "time";
    if (r.size() < 8)
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: {} usable samples ({} missing, {} flagged): a fit needs at least 8", r.source,
                                 r.size(), r.skipped_missing, r.skipped_flagged)};
    if (r.z.size() != r.size() ||
        (r.kind == RecordKind::buoy && (r.east.size() != r.size() || r.north.size() != r.size())))
        return Error{ErrorCode::invalid_argument, fmt::format("{}: columns of different lengths", r.source)};
    for (std::size_t k = 0; k + 1 < r.size(); ++k) {
        if (!(r.axis[k + 1] > r.axis[k]))
            return Error{
                ErrorCode::invalid_argument,
                fmt::format("{}: the {} is not strictly increasing at sample {} ({} then {}): sort the file and remove "
                            "duplicated rows",
                            r.source, unit, k + 1, r.axis[k] + r.axis_origin, r.axis[k + 1] + r.axis_origin)};
    }
    auto constant = [](const std::vector<double>& v) {
        return std::all_of(v.begin(), v.end(), [&](double x) { return x == v.front(); });
    };
    for (const auto* v : {&r.z, &r.east, &r.north})
        for (double x : *v)
            if (!std::isfinite(x))
                return Error{ErrorCode::invalid_argument, fmt::format("{}: a value is not finite", r.source)};
    if (constant(r.z))
        return Error{ErrorCode::invalid_argument,
                     fmt::format("{}: the elevation is constant: nothing to fit", r.source)};
    // Units: sea-surface elevations and displacements are metres, sample steps seconds.
    double largest = 0.0;
    for (const auto* v : {&r.z, &r.east, &r.north})
        for (double x : *v) largest = std::max(largest, std::abs(x));
    if (largest > 100.0)
        return Error{
            ErrorCode::invalid_argument,
            fmt::format("{}: displacements reach {:g} m, more than any sea: if the file is in cm or mm, scale it "
                        "(--scale z=0.01 or z=0.001, and the same for east and north)",
                        r.source, largest)};
    const double step = r.median_spacing();
    if (r.kind != RecordKind::profile && step > 60.0)
        return Error{
            ErrorCode::invalid_argument,
            fmt::format(
                "{}: samples are {:g} s apart, too far to resolve waves: if time is in ms, scale it (--scale t=0.001)",
                r.source, step)};
    return {};
}

}  // namespace tidewater::calibration
