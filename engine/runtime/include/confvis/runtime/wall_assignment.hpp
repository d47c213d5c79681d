#pragma once
// Which cluster process draws which wall. MPI-free, so applications and tests can plan a
// cluster without one (confvis/runtime/cluster.hpp runs it).
#include <string>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

// Walls per rank, in config order. A wall's `node` names a rank ("3") or a host name: a host's
// walls are dealt in order to the ranks on that host. Walls without a node are dealt in config
// order to the ranks, starting with rank 0 and skipping none, so with more ranks than walls the
// last ranks draw nothing (a head node that only tracks and bakes is a rank without walls).
// rankHosts[r] names rank r's host: its host name first, then any other name a config may use
// for it (its IP addresses: SGCT configs name nodes by address). Error(InvalidInput) naming the
// wall when its node names a rank >= rankHosts.size() or a host no rank runs on (the hosts are
// listed).
std::vector<std::vector<std::string>> assignWalls(
    const DisplayConfig& display, const std::vector<std::vector<std::string>>& rankHosts);

}  // namespace confvis
