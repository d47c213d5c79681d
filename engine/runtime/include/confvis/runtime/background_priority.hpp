#pragma once
// Re-bakes share the machine's cores with the live renderer; left at the renderer's priority,
// the bake's threads and the renderer's worker threads take turns and frames slow down while a
// bake runs. A bake run through this wrapper lowers its thread's priority first (Linux nice
// values are per thread, and the bake's own worker threads inherit it), so frames keep their
// cores and the bake takes what is left (it then takes longer on a busy machine).
#include "confvis/base/export.hpp"
#include "confvis/runtime/map_follower.hpp"

namespace confvis CONFVIS_API {

// `niceness`: 0 (unchanged) .. 19 (lowest). Failing to lower it is not an error (the bake runs
// as before).
BakeFunction inBackground(BakeFunction bake, int niceness = 10);

}  // namespace confvis
