#include "confvis/base/input_limits.hpp"

#include <cstdint>
#include <cstdio>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

// Well-formed UTF-8 (no overlong forms, surrogates or code points past U+10FFFF). Names from XML
// are not checked by the parser, and JSON output (the config hash) throws on invalid UTF-8.
bool validUtf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (length == 0 || i + length > s.size()) return false;
    std::uint32_t code = length == 1 ? c : c & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(s[i + k]);
      if ((next >> 6) != 0x2) return false;
      code = code << 6 | (next & 0x3F);
    }
    constexpr std::uint32_t kSmallest[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < kSmallest[length] || code > 0x10FFFF || (code >= 0xD800 && code < 0xE000))
      return false;
    i += length;
  }
  return true;
}

}  // namespace

std::string printable(std::string_view name) {
  std::string out;
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", u);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out;
}

void requireFileNameSafe(std::string_view name, const std::string& field) {
  const auto fail = [&](const std::string& reason) {
    const std::string shown = name.size() > 60 ? printable(name.substr(0, 60)) + "..." : printable(name);
    throw Error(ErrorCode::InvalidInput,
                field + " '" + shown + "' cannot be used as a file name: " + reason);
  };
  if (name.empty()) fail("it is empty");
  if (name == "." || name == "..") fail("it names a directory ('.' or '..')");
  if (name.size() > kMaxFileNameLength)
    fail("it is " + std::to_string(name.size()) + " bytes long (at most " +
         std::to_string(kMaxFileNameLength) + ")");
  for (const char c : name) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '/' || c == '\\') fail("it contains a path separator ('/' or '\\')");
    if (u < 0x20 || u == 0x7f)
      fail(u == 0 ? std::string("it contains a NUL character")
                  : "it contains a control character");
  }
  if (!validUtf8(name)) fail("it is not valid UTF-8");
}

std::filesystem::path childPath(const std::filesystem::path& directory, std::string_view name,
                                const std::string& field) {
  requireFileNameSafe(name, field);
  return directory / std::string(name);
}

void requireJsonDepth(std::string_view text, const std::string& sourceName, int maxDepth) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (const char c : text) {
    if (inString) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') inString = false;
      continue;
    }
    if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > maxDepth)
        throw Error(ErrorCode::InvalidInput, sourceName + ": JSON nested deeper than " +
                                                 std::to_string(maxDepth) + " levels");
    } else if (c == ']' || c == '}') {
      --depth;  // unbalanced brackets are the parser's to report
    }
  }
}

}  // namespace confvis
