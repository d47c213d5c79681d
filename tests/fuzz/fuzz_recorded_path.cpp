// Recorded head paths (CSV).
#include <cstdint>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/runtime/tracker.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)confvis::RecordedPath::parse(text, "fuzz.csv");
  } catch (const confvis::Error&) {
  }
  return 0;
}
