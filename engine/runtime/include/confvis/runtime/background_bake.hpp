#pragma once
// The bake a MapFollower of a live display runs in the background: bakeDisplay
// (conformal/bake_display.hpp) without the on-disk cache (every head position is a new config:
// the cache would only fill up), on fewer threads than the machine has, so that the render thread
// and the backend's own workers keep cores while a re-bake runs (issue 25 measured a render
// node's Embree frames going from 1.6 to 2.5 s while a bake took every core).
//
// example: background_bake (compiled and run by the test suite, tests/examples/)
//   MapFollower follower(display, backgroundBake());  // half the hardware threads
//   MapFollower gentle(display, backgroundBake(1));   // one thread: frames lose least
//   const int all = static_cast<int>(std::thread::hardware_concurrency());
//   MapFollower greedy(display, backgroundBake(all));  // every core: bakes finish soonest
//
// Thread-safety: the returned function may be called from any thread (the follower calls it on
// its bake thread), several calls at once included.
#include <thread>

#include "confvis/base/export.hpp"
#include "confvis/runtime/map_follower.hpp"

namespace confvis CONFVIS_API {

// Half the hardware threads, at least one: the default thread count of backgroundBake().
int defaultBackgroundBakeThreads();

// bakeDisplay(config, {.useCache = false, .threads = threads}); threads 0 means
// defaultBackgroundBakeThreads(). Throws Error(InvalidInput) for a negative thread count.
BakeFunction backgroundBake(int threads = 0);

}  // namespace confvis
