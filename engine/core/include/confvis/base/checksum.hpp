#pragma once
// FNV-1a 64: identifies display configs (the bake cache key) and checks the files of a baked map
// directory against bake.json. An integrity check against corruption and mix-ups (a flipped
// bit, swapped or stale files), not a defence against forgery.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash = 14695981039346656037ULL);

// 16 lower-case hex digits.
std::string fnv1a64Hex(std::string_view bytes);

// fnv1a64Hex of a whole file, read in blocks; Error(FileNotFound) naming it when it cannot be
// opened, Error(IoFailure) when reading fails part-way.
std::string fileChecksum(const std::filesystem::path& path);

}  // namespace confvis
