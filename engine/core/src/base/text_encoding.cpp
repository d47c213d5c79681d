#include "confvis/base/text_encoding.hpp"

#include <algorithm>
#include <cstdint>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw Error(ErrorCode::InvalidInput, "text file '" + path.string() + "' " + what);
}

void appendUtf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
}

std::string fromUtf16(const std::string& bytes, std::size_t start, bool bigEndian,
                      const std::filesystem::path& path) {
  if ((bytes.size() - start) % 2 != 0) fail(path, "is UTF-16 with an odd number of bytes");
  std::string out;
  out.reserve((bytes.size() - start) / 2);
  const auto unit = [&](std::size_t i) -> std::uint32_t {
    const auto a = static_cast<unsigned char>(bytes[i]), b = static_cast<unsigned char>(bytes[i + 1]);
    return bigEndian ? (a << 8 | b) : (b << 8 | a);
  };
  for (std::size_t i = start; i < bytes.size(); i += 2) {
    std::uint32_t code = unit(i);
    if (code >= 0xD800 && code < 0xDC00) {  // a surrogate pair
      const std::uint32_t low = i + 3 < bytes.size() ? unit(i + 2) : 0;
      if (low < 0xDC00 || low >= 0xE000) fail(path, "is malformed UTF-16 (a lone surrogate)");
      code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
      i += 2;
    } else if (code >= 0xDC00 && code < 0xE000) {
      fail(path, "is malformed UTF-16 (a lone surrogate)");
    }
    if (code == 0) fail(path, "holds a NUL character: binary data, not text");
    appendUtf8(out, code);
  }
  return out;
}

// UTF-16 without a byte-order mark: ASCII text then has every other byte NUL.
bool looksLikeUtf16(const std::string& bytes, bool& bigEndian) {
  const std::size_t n = std::min<std::size_t>(bytes.size(), 512) & ~std::size_t{1};
  if (n < 4) return false;
  std::size_t evenNul = 0, oddNul = 0;
  for (std::size_t i = 0; i < n; i += 2) {
    evenNul += bytes[i] == '\0';
    oddNul += bytes[i + 1] == '\0';
  }
  bigEndian = evenNul > oddNul;
  return std::max(evenNul, oddNul) * 10 >= n / 2 * 9 && std::min(evenNul, oddNul) == 0;
}

}  // namespace

std::string decodeTextFile(const std::string& bytes, const std::filesystem::path& path) {
  std::string text;
  bool bigEndian = false;
  if (bytes.size() >= 2 && bytes[0] == '\xFF' && bytes[1] == '\xFE') {
    text = fromUtf16(bytes, 2, false, path);
  } else if (bytes.size() >= 2 && bytes[0] == '\xFE' && bytes[1] == '\xFF') {
    text = fromUtf16(bytes, 2, true, path);
  } else if (looksLikeUtf16(bytes, bigEndian)) {
    text = fromUtf16(bytes, 0, bigEndian, path);
  } else {
    const std::size_t start = bytes.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    if (bytes.find('\0', start) != std::string::npos)
      fail(path, "holds NUL bytes: binary data, not text");
    text = bytes.substr(start);
  }
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\r') out += text[i];
    else if (i + 1 >= text.size() || text[i + 1] != '\n') out += '\n';
  }
  return out;
}

}  // namespace confvis
