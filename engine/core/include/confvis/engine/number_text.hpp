#pragma once
// Strict numbers from text: imported display files and recorded head
// paths must not turn "0/05" or "1.5m" into a silently truncated value.
#include <optional>
#include <string_view>

#include <glm/glm.hpp>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
namespace detail CONFVIS_API {

// The whole string (surrounding blanks allowed) must be one finite number; nullopt otherwise.
std::optional<double> parseNumber(std::string_view text);

// "x y z" separated by blanks (ParaView corners). nullopt unless exactly three finite numbers.
std::optional<glm::dvec3> parseTriple(std::string_view text);

}  // namespace detail
}  // namespace confvis
