#pragma once
// A count of the bakes this process has run, for tests that check a map is baked only once
// (bakeDisplay's checks hand their bake on: bake_display.hpp). One relaxed atomic increment per
// bake.
#include <cstddef>

namespace confvis::detail {

// bakeRetargetMap / bakeRetargetMapInto calls that got past validation and baked.
std::size_t retargetBakeCount();

}  // namespace confvis::detail
