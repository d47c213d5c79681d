#pragma once
// JSON text from files, parsed the same way by every reader: nesting bounded before the parser
// runs (input_limits.hpp), syntax errors and out-of-range numbers as Error(InvalidInput) naming
// the file.
#include <string>

#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

nlohmann::json parseJsonText(const std::string& text, const std::string& sourceName);

}  // namespace confvis
