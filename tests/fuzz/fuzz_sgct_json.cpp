// SGCT JSON configs.
#include <cstdint>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)confvis::parseSgctJson(text, "fuzz.json", {}, nullptr);
  } catch (const confvis::Error&) {
  }
  return 0;
}
