#include "confvis/base/checksum.hpp"

#include <cstdio>
#include <fstream>
#include <vector>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

std::string hex(std::uint64_t h) {
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(h));
  return buffer;
}

}  // namespace

std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t hash) {
  for (const unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  return hash;
}

std::string fnv1a64Hex(std::string_view bytes) { return hex(fnv1a64(bytes)); }

std::string fileChecksum(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorCode::FileNotFound, "cannot open '" + path.string() + "'");
  std::vector<char> block(1 << 16);
  std::uint64_t hash = fnv1a64({});
  while (in) {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    hash = fnv1a64(std::string_view(block.data(), static_cast<std::size_t>(in.gcount())), hash);
  }
  if (in.bad()) throw Error(ErrorCode::IoFailure, "cannot read '" + path.string() + "'");
  return hex(hash);
}

}  // namespace confvis
