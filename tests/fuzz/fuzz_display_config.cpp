// confvis display config JSON: parseJsonText + parseDisplayConfig.
#include <cstdint>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/base/json_text.hpp"
#include "confvis/engine/display_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)confvis::parseDisplayConfig(confvis::parseJsonText(text, "fuzz.json"), "fuzz.json");
  } catch (const confvis::Error&) {
  }
  return 0;
}
