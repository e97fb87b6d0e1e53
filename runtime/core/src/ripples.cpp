#include "tidewater/ripples.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tidewater/constants.hpp"

namespace tidewater {

namespace {

// The lattice repeats every kPeriod cells so that drift can be reduced
// modulo the period in double before it reaches float on the GPU.
constexpr std::int64_t kPeriod = 256;

std::uint32_t hash_cell(std::int64_t ix, std::int64_t iz, std::uint32_t seed) {
    const auto x = static_cast<std::uint32_t>(((ix % kPeriod) + kPeriod) % kPeriod);
    const auto z = static_cast<std::uint32_t>(((iz % kPeriod) + kPeriod) % kPeriod);
    std::uint32_t h = x * 0x8da6b343u ^ z * 0xd8163841u ^ seed * 0xcb1ab31fu;
    // murmur3 finaliser: every input bit affects every output bit.
    h ^= h >> 16;
    h *= 0x85ebca6bu;
    h ^= h >> 13;
    h *= 0xc2b2ae35u;
    h ^= h >> 16;
    return h;
}

glm::dvec2 gradient_of(std::uint32_t h) {
    constexpr double d = 0.70710678118654752;
    static constexpr glm::dvec2 kGradients[8] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {d, d}, {-d, d}, {d, -d}, {-d, -d}};
    return kGradients[h & 7u];
}

}  // namespace

NoiseSample gradient_noise(glm::dvec2 p, std::uint32_t seed) {
    const double fx = std::floor(p.x), fz = std::floor(p.y);
    const auto ix = static_cast<std::int64_t>(fx), iz = static_cast<std::int64_t>(fz);
    const double x = p.x - fx, z = p.y - fz;
    auto fade = [](double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); };
    auto dfade = [](double t) { return 30.0 * t * t * (t - 1.0) * (t - 1.0); };
    const glm::dvec2 g00 = gradient_of(hash_cell(ix, iz, seed));
    const glm::dvec2 g10 = gradient_of(hash_cell(ix + 1, iz, seed));
    const glm::dvec2 g01 = gradient_of(hash_cell(ix, iz + 1, seed));
    const glm::dvec2 g11 = gradient_of(hash_cell(ix + 1, iz + 1, seed));
    const double n00 = g00.x * x + g00.y * z;
    const double n10 = g10.x * (x - 1) + g10.y * z;
    const double n01 = g01.x * x + g01.y * (z - 1);
    const double n11 = g11.x * (x - 1) + g11.y * (z - 1);
    const double u = fade(x), v = fade(z), du = dfade(x), dv = dfade(z);
    const double nx0 = n00 + u * (n10 - n00);
    const double nx1 = n01 + u * (n11 - n01);
    NoiseSample out;
    // Scaled by sqrt(2) so the value spans about [-1, 1].
    constexpr double scale = 1.4142135623730951;
    out.value = scale * (nx0 + v * (nx1 - nx0));
    // Gradient: derivative of the bilinear blend of the corner ramps.
    const glm::dvec2 gx0 = g00 + u * (g10 - g00) + glm::dvec2(du * (n10 - n00), 0.0);
    const glm::dvec2 gx1 = g01 + u * (g11 - g01) + glm::dvec2(du * (n11 - n01), 0.0);
    out.gradient = scale * (gx0 + v * (gx1 - gx0) + glm::dvec2(0.0, dv * (nx1 - nx0)));
    return out;
}

Status validate(const RippleSpec& s, const std::string& context) {
    auto bad = [&](const char* field, double v, const char* range) {
        return Error{ErrorCode::schema_error,
                     fmt::format("{}/{}: {} is out of range (allowed: {})", context, field, v, range)};
    };
    if (!std::isfinite(s.amplitude) || s.amplitude < 0.0 || s.amplitude > 1.0)
        return bad("amplitude", s.amplitude, "0 <= amplitude <= 1 m");
    if (!std::isfinite(s.wavelength) || s.wavelength < 0.01 || s.wavelength > 100.0)
        return bad("wavelength", s.wavelength, "0.01 <= wavelength <= 100 m");
    if (s.octaves < 1 || s.octaves > 8) return bad("octaves", s.octaves, "1 <= octaves <= 8");
    if (!std::isfinite(s.speed) || s.speed < 0.0 || s.speed > 20.0)
        return bad("speed", s.speed, "0 <= speed <= 20 m/s");
    if (!std::isfinite(s.direction_deg) || std::abs(s.direction_deg) > 1e6)
        return bad("direction", s.direction_deg, "finite degrees");
    return {};
}

RippleSample RippleField::sample(glm::dvec2 p, double time) const {
    RippleSample out;
    if (!enabled()) return out;
    const double rad = spec_.direction_deg * (kPi / 180.0);
    // Drift in lattice units, reduced modulo the lattice period (exact for the noise).
    const double drift = std::fmod(time * spec_.speed / spec_.wavelength, static_cast<double>(kPeriod));
    const glm::dvec2 offset{drift * std::cos(rad), drift * std::sin(rad)};
    for (int i = 1; i <= spec_.octaves; ++i) {
        const double scale = static_cast<double>(i) / spec_.wavelength;
        const NoiseSample n = gradient_noise(p * scale + offset, spec_.seed + static_cast<std::uint32_t>(i));
        const double a = spec_.amplitude / i;
        out.height += a * n.value;
        out.slope += a * scale * n.gradient;
    }
    return out;
}

}  // namespace tidewater
