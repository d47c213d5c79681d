#pragma once
// One exception type crosses every confvis boundary (Embree style: clear errors at the edge).
// The message names the culprit (file, wall, vertex, option) so a user can fix the input.
#include <stdexcept>
#include <string>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

enum class ErrorCode {
  InvalidInput,     // malformed config, degenerate geometry, non-disk mesh, bad option
  FileNotFound,     // a named file does not exist or cannot be opened
  IoFailure,        // reading or writing a file failed part-way
  Unreachable,      // a curvature target cannot be reached (Gauss-Bonnet, divergence)
  DeviceUnsupported,// a rendering device lacks a required feature
  Internal,         // a broken invariant inside confvis: a bug
};

// Thread-safety: an immutable value; copy and read it from any thread.
class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ErrorCode code() const noexcept { return code_; }

 private:
  ErrorCode code_;
};

const char* toString(ErrorCode code) noexcept;

}  // namespace confvis
