#include "tidewater/water_optics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace tidewater {

namespace {

struct NamedType {
    JerlovType type;
    const char* name;
    glm::dvec3 kd;  // 1/m at 650, 550, 450 nm (Jerlov 1976, table XXVII)
};

constexpr std::array<NamedType, 10> kJerlovTable{{
    {JerlovType::I, "I", {0.36, 0.063, 0.019}},
    {JerlovType::IA, "IA", {0.37, 0.067, 0.026}},
    {JerlovType::IB, "IB", {0.375, 0.072, 0.036}},
    {JerlovType::II, "II", {0.40, 0.089, 0.068}},
    {JerlovType::III, "III", {0.445, 0.12, 0.135}},
    {JerlovType::C1, "1C", {0.45, 0.12, 0.25}},
    {JerlovType::C3, "3C", {0.46, 0.19, 0.39}},
    {JerlovType::C5, "5C", {0.54, 0.30, 0.56}},
    {JerlovType::C7, "7C", {0.63, 0.46, 0.89}},
    {JerlovType::C9, "9C", {0.76, 0.63, 1.6}},
}};

}  // namespace

glm::dvec3 deep_water_color(glm::dvec3 extinction) {
    const double clearest = std::min({extinction.x, extinction.y, extinction.z});
    return kDeepWaterBrightness * clearest / extinction;
}

WaterOptics jerlov_optics(JerlovType type) {
    const auto it =
        std::find_if(kJerlovTable.begin(), kJerlovTable.end(), [type](const NamedType& t) { return t.type == type; });
    WaterOptics optics;
    optics.extinction = it->kd;
    optics.color = deep_water_color(it->kd);
    return optics;
}

std::optional<JerlovType> jerlov_type_named(std::string_view name) {
    for (const NamedType& t : kJerlovTable)
        if (name == t.name) return t.type;
    return std::nullopt;
}

std::vector<std::string> jerlov_type_names() {
    std::vector<std::string> names;
    for (const NamedType& t : kJerlovTable) names.emplace_back(t.name);
    return names;
}

Status validate(const WaterOptics& optics, const std::string& context) {
    for (int c = 0; c < 3; ++c) {
        const double k = optics.extinction[c];
        if (!(k > 0.0 && k <= 100.0))
            return Error{
                ErrorCode::schema_error,
                fmt::format("{}/extinction/{}: {} is out of range (allowed: 0 < k <= 100 per metre)", context, c, k)};
        const double v = optics.color[c];
        if (!(v >= 0.0 && v <= 1.0))
            return Error{ErrorCode::schema_error,
                         fmt::format("{}/color/{}: {} is out of range (allowed: 0 to 1)", context, c, v)};
    }
    return {};
}

}  // namespace tidewater
