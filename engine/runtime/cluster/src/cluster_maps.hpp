#pragma once
// The state of map transfers in flight (cluster.hpp: shareMap / progressMaps).
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include <mpi.h>

#include "confvis/conformal/retarget_map.hpp"
#include "confvis/runtime/cluster.hpp"

namespace confvis {

// What travels before a map's texels: enough to allocate it.
struct MapHeader {
  std::uint64_t generation = 0;
  std::int32_t resolution = 0;
  double reference[3] = {0, 0, 0};
};

struct Cluster::MapTransfer {
  // Root: the share in flight (sends and acks) and the newest one waiting behind it.
  std::shared_ptr<const RetargetMap> sending;
  MapHeader sendingHeader;
  std::vector<MPI_Request> sends, acks;
  std::vector<char> ackBytes;
  bool delivered = false;  // the latest share reached every rank
  std::shared_ptr<const RetargetMap> queued;
  std::uint64_t queuedGeneration = 0;
  // Other ranks: the map being received, and its ack.
  std::shared_ptr<RetargetMap> receiving;
  MapHeader receivingHeader;
  std::vector<MPI_Request> receives;
  std::vector<MPI_Request> ackSend;
  char ack = 1;
  // Every rank: maps received (or shared) but not yet named by a frame state.
  std::map<std::uint64_t, std::shared_ptr<const RetargetMap>> ready;
};

}  // namespace confvis
