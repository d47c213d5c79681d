// Built by a parent project against confvis::base from add_subdirectory(confvis).
#include <confvis/base/error.hpp>

#include <cstdio>

int main() {
  const confvis::Error error(confvis::ErrorCode::InvalidInput, "wall 'front': no resolution");
  std::printf("parent app: %s: %s\n", confvis::toString(error.code()), error.what());
  return error.code() == confvis::ErrorCode::InvalidInput ? 0 : 1;
}
