// How light travels through a body's water: its extinction per colour channel and the
// colour deep water sends back up. The renderer draws every path through the water with
// them (Beer-Lambert per channel, shaders/water_medium.glsl): the seabed and the host's
// geometry fading with distance above and under the surface, and the sun fading with
// depth.
//
// The channels are red, green and blue, taken at 650, 550 and 450 nm. The water types are
// Jerlov's (Marine Optics, 2nd ed., 1976, table XXVII): the diffuse attenuation
// coefficient K_d of downwelling light measured across the world's oceans (types I to III)
// and coastal waters (1C to 9C), used as the extinction along every path.
//
// Units: extinction 1/m; colours linear RGB relative to the light that falls on the water.
// Threading: plain values.
#pragma once

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater {

/// Jerlov's water types, clearest first: the open ocean's I, IA, IB, II, III and the
/// coastal 1C, 3C, 5C, 7C, 9C.
enum class JerlovType { I, IA, IB, II, III, C1, C3, C5, C7, C9 };

struct WaterOptics {
    glm::dvec3 extinction{0.0};  ///< 1/m per channel (red, green, blue)
    /// What deep water sends up under full light, per channel: the water's colour from above
    /// and what it scatters toward an eye under it.
    glm::dvec3 color{0.0};

    bool operator==(const WaterOptics&) const = default;
};

/// The colour deep water of a given extinction shows: R ~ b_b / K (Gordon et al., 1988)
/// with a backscatter even across the channels, so each channel goes as 1 / K, the
/// brightest at kDeepWaterBrightness. Every extinction must be > 0.
glm::dvec3 deep_water_color(glm::dvec3 extinction);
inline constexpr double kDeepWaterBrightness = 0.13;

/// A Jerlov type's optics: its K_d at 650, 550 and 450 nm and deep_water_color of them.
WaterOptics jerlov_optics(JerlovType type);

/// The type named "I", "IA", "IB", "II", "III", "1C", "3C", "5C", "7C" or "9C".
std::optional<JerlovType> jerlov_type_named(std::string_view name);
/// Every name jerlov_type_named takes, clearest first.
std::vector<std::string> jerlov_type_names();

/// The optics a body takes when its preset gives none: the open ocean's type II for the
/// ocean (a blue ocean near land), coastal type 3C for lakes and rivers (inland water carries
/// more of what the land washes in).
inline constexpr JerlovType kDefaultOceanWaterType = JerlovType::II;
inline constexpr JerlovType kDefaultInlandWaterType = JerlovType::C3;

/// Fails unless every extinction lies in (0, 100] 1/m and every colour in [0, 1];
/// `context` names the field in the message.
Status validate(const WaterOptics& optics, const std::string& context);

}  // namespace tidewater
