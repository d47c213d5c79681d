#include "confvis/base/json_text.hpp"

#include "confvis/base/error.hpp"
#include "confvis/base/input_limits.hpp"

namespace confvis {

nlohmann::json parseJsonText(const std::string& text, const std::string& sourceName) {
  requireJsonDepth(text, sourceName);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    // parse_error for syntax, out_of_range for numbers such as 1e999.
    throw Error(ErrorCode::InvalidInput, sourceName + ": invalid JSON: " + e.what());
  }
}

}  // namespace confvis
