// Reading query points from CSV: a header naming columns x and z (other
// columns are allowed and ignored), then one point per line.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "tidewater/result.hpp"

namespace tidewater::cli {

Result<std::vector<glm::dvec2>> read_points_csv(const std::string& path);
/// Parses CSV text; `source` names it in messages.
Result<std::vector<glm::dvec2>> parse_points_csv(const std::string& text, const std::string& source);

}  // namespace tidewater::cli
