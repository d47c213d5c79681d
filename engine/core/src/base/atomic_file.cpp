#include "confvis/base/atomic_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <system_error>

#include "confvis/base/error.hpp"

namespace confvis {
namespace fs = std::filesystem;

void writeFileAtomically(const fs::path& path, const std::function<void(const fs::path&)>& write) {
  std::error_code ec;
  // A device or pipe (/dev/stdout, /dev/full) cannot be replaced by a rename: it is written in
  // place, and its failures are the writer's to report like any other.
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec) && !fs::is_directory(path, ec)) {
    try {
      write(path);
    } catch (const Error&) {
      throw;
    } catch (const std::exception& e) {
      throw Error(ErrorCode::IoFailure, "writing '" + path.string() + "' failed: " + e.what());
    }
    return;
  }
  if (path.has_parent_path()) {
    fs::create_directories(path.parent_path(), ec);
    if (ec)
      throw Error(ErrorCode::IoFailure,
                  "cannot create directory '" + path.parent_path().string() + "': " + ec.message());
  }
  // The temporary keeps the destination's extension: some writers (OpenEXR, PNG) pick nothing
  // by extension, but people listing a directory mid-write should see what it will become.
  std::random_device rd;
  const fs::path temp = path.parent_path() /
                        ("." + path.filename().string() + ".tmp" + std::to_string(rd() % 1000000));
  try {
    write(temp);
  } catch (const Error&) {
    fs::remove(temp, ec);
    throw;
  } catch (const std::exception& e) {
    fs::remove(temp, ec);
    throw Error(ErrorCode::IoFailure, "writing '" + path.string() + "' failed: " + e.what());
  }
  if (!fs::exists(temp, ec))
    throw Error(ErrorCode::Internal, "writer produced no file for '" + path.string() + "'");
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw Error(ErrorCode::IoFailure, "cannot move output into place at '" + path.string() + "'");
  }
}

void writeTextAtomically(const fs::path& path, const std::string& contents) {
  writeFileAtomically(path, [&](const fs::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.close();
    if (!out)
      throw Error(ErrorCode::IoFailure, "cannot write '" + path.string() + "' (" +
                                            std::strerror(errno) + ")");
  });
}

std::string readTextFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorCode::FileNotFound, "cannot open '" + path.string() + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw Error(ErrorCode::IoFailure, "cannot read '" + path.string() + "'");
  return ss.str();
}

}  // namespace confvis
