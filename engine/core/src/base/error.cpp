#include "confvis/base/error.hpp"

namespace confvis {

const char* toString(ErrorCode code) noexcept {
  switch (code) {
    case ErrorCode::InvalidInput: return "invalid input";
    case ErrorCode::FileNotFound: return "file not found";
    case ErrorCode::IoFailure: return "I/O failure";
    case ErrorCode::Unreachable: return "unreachable target";
    case ErrorCode::DeviceUnsupported: return "device unsupported";
    case ErrorCode::Internal: return "internal error";
  }
  return "unknown error";
}

}  // namespace confvis
