#pragma once
// What one frame of a frame-locked display is made of, as decided by the process that owns
// tracking, navigation and time (rank 0 of a cluster, cluster.hpp). MPI-free.
#include <cstdint>

#include "confvis/backends/render_backend.hpp"
#include "confvis/base/export.hpp"
#include "confvis/engine/viewer.hpp"

namespace confvis CONFVIS_API {

// A plain struct: an application extends it by deriving (struct MyState : ClusterFrameState
// { int level; };) and passing its own type to Cluster::exchangeFrame. Trivially copyable.
struct ClusterFrameState {
  std::uint64_t frame = 0;
  double seconds = 0.0;             // the root's clock
  HeadPose head;                    // tracked head, physical frame
  VirtualCamera camera;             // navigation
  std::uint64_t mapGeneration = 0;  // the map every rank renders this frame with
  double sceneSeconds = 0.0;        // animation time
  bool quit = false;                // the last frame: every rank leaves its loop after it
};

}  // namespace confvis
