#pragma once
// Guards for input that reaches the file system or the allocator: names read from files (walls,
// displays) that become file names, JSON nesting, and byte-range arithmetic that must not wrap.
// One place, so every reader refuses the same things with the same words.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// Longest name accepted as one path component (bytes); file systems allow 255 and the writers
// add suffixes such as "-left.exr".
inline constexpr std::size_t kMaxFileNameLength = 200;

// Deepest JSON nesting any confvis reader accepts (display configs, SGCT, bake.json, glTF).
// Real files nest fewer than 10 levels; deep nesting only exhausts the stack of recursive code.
inline constexpr int kMaxJsonDepth = 64;

// Throws Error(InvalidInput) "<field> '<name>' cannot be used as a file name: <reason>" unless
// `name` is one plain path component: not empty, not "." or "..", no '/' or '\\', no NUL or other
// control character, valid UTF-8, at most kMaxFileNameLength bytes. `field` names the culprit for the user
// ("cave5.json: wall name", "display name").
void requireFileNameSafe(std::string_view name, const std::string& field);

// directory / name after requireFileNameSafe(name, field): never a path outside `directory`.
std::filesystem::path childPath(const std::filesystem::path& directory, std::string_view name,
                                const std::string& field);

// `name` with control characters shown as \xNN, for error messages.
std::string printable(std::string_view name);

// Throws Error(InvalidInput) "<sourceName>: JSON nested deeper than kMaxJsonDepth levels" when
// arrays and objects in `text` nest deeper than `maxDepth` (strings are skipped). Linear, no
// recursion: run it before a parser or anything recursive sees the text.
void requireJsonDepth(std::string_view text, const std::string& sourceName,
                      int maxDepth = kMaxJsonDepth);

// True when [offset, offset + length) lies inside [0, size), computed without wrapping.
constexpr bool byteRangeFits(std::size_t offset, std::size_t length, std::size_t size) {
  return offset <= size && length <= size - offset;
}

// The bytes spanned by `count` elements of `elementSize` bytes, `stride` apart (the last one
// needs only elementSize); false when that overflows std::size_t.
constexpr bool stridedSpan(std::size_t count, std::size_t stride, std::size_t elementSize,
                           std::size_t& bytes) {
  if (count == 0) {
    bytes = 0;
    return true;
  }
  const std::size_t steps = count - 1;
  if (stride != 0 && steps > (static_cast<std::size_t>(-1) - elementSize) / stride) return false;
  bytes = steps * stride + elementSize;
  return true;
}

}  // namespace confvis
