// One map for all: the root's maps travel to every rank in chunks while frames go on.
#include <algorithm>

#include "cluster_maps.hpp"
#include "cluster_transport.hpp"

namespace confvis {
namespace {

using namespace detail;

// A map's texels in the order they travel: the ray map's faces, then the geom map's.
template <class Map>
auto texelBuffers(Map& map) {
  std::vector<decltype(&map.ray.faces[0].pixels)> buffers;
  for (auto& face : map.ray.faces) buffers.push_back(&face.pixels);
  for (auto& face : map.geom.faces) buffers.push_back(&face.pixels);
  return buffers;
}

// Calls post(offset, count) for every chunk of `floats` floats, chunkBytes at most each.
template <class Post>
void forEachChunk(std::size_t floats, std::size_t chunkBytes, Post&& post) {
  const std::size_t chunk = std::max<std::size_t>(1, chunkBytes / sizeof(float));
  for (std::size_t offset = 0; offset < floats; offset += chunk)
    post(offset, static_cast<int>(std::min(chunk, floats - offset)));
}

}  // namespace

void Cluster::shareMap(std::shared_ptr<const RetargetMap> map, std::uint64_t generation) {
  if (!isRoot()) throw Error(ErrorCode::InvalidInput, "cluster: only rank 0 shares maps");
  if (!map) throw Error(ErrorCode::InvalidInput, "cluster: shareMap needs a map");
  MapTransfer& t = *transfer_;
  t.ready[generation] = map;
  if (t.sending) {  // one share in flight at a time: the newest waits behind it
    t.queued = std::move(map);
    t.queuedGeneration = generation;
    return;
  }
  t.sending = std::move(map);
  t.delivered = size() == 1;
  t.sendingHeader = {generation, t.sending->resolution(),
                     {t.sending->reference.x, t.sending->reference.y, t.sending->reference.z}};
  t.sends.clear();
  t.acks.assign(size() - 1, MPI_REQUEST_NULL);
  t.ackBytes.assign(size(), 0);
  for (int r = 1; r < size(); ++r) {
    t.sends.emplace_back();
    checkMpi(MPI_Isend(&t.sendingHeader, sizeof(MapHeader), MPI_BYTE, r, kTagMapHeader, comm_,
                       &t.sends.back()),
             "MPI_Isend");
    for (const std::vector<float>* buffer : texelBuffers(*t.sending))
      forEachChunk(buffer->size(), options_.mapChunkBytes, [&](std::size_t offset, int count) {
        t.sends.emplace_back();
        checkMpi(MPI_Isend(buffer->data() + offset, count, MPI_FLOAT, r, kTagMapChunk, comm_,
                           &t.sends.back()),
                 "MPI_Isend");
      });
    checkMpi(MPI_Irecv(&t.ackBytes[r], 1, MPI_BYTE, r, kTagMapAck, comm_, &t.acks[r - 1]),
             "MPI_Irecv");
  }
  if (t.delivered) t.sending.reset();
}

bool Cluster::progressMaps() {
  MapTransfer& t = *transfer_;
  if (isRoot()) {
    if (!t.sending) return true;
    const bool sent = testAll(t.sends);
    if (!(testAll(t.acks) && sent)) return false;
    t.sending.reset();
    if (t.queued) {
      auto next = std::move(t.queued);
      t.queued.reset();
      t.ready.erase(t.queuedGeneration);
      shareMap(std::move(next), t.queuedGeneration);
      return !t.sending;
    }
    return true;
  }
  testAll(t.ackSend);
  if (!t.receiving) {
    int found = 0;
    checkMpi(MPI_Iprobe(0, kTagMapHeader, comm_, &found, MPI_STATUS_IGNORE), "MPI_Iprobe");
    if (!found) return false;
    checkMpi(MPI_Recv(&t.receivingHeader, sizeof(MapHeader), MPI_BYTE, 0, kTagMapHeader, comm_,
                      MPI_STATUS_IGNORE),
             "MPI_Recv");
    const MapHeader& h = t.receivingHeader;
    if (h.resolution < 1 || h.resolution > 16384)
      throw ClusterError(ErrorCode::Internal, "cluster: a map header from rank 0 is corrupt");
    t.receiving = std::make_shared<RetargetMap>();
    t.receiving->reference.x = h.reference[0];
    t.receiving->reference.y = h.reference[1];
    t.receiving->reference.z = h.reference[2];
    t.receiving->ray = CubeMap(h.resolution);
    t.receiving->geom = CubeMap(h.resolution);
    t.receives.clear();
    for (std::vector<float>* buffer : texelBuffers(*t.receiving))
      forEachChunk(buffer->size(), options_.mapChunkBytes, [&](std::size_t offset, int count) {
        t.receives.emplace_back();
        checkMpi(MPI_Irecv(buffer->data() + offset, count, MPI_FLOAT, 0, kTagMapChunk, comm_,
                           &t.receives.back()),
                 "MPI_Irecv");
      });
  }
  if (!testAll(t.receives)) return false;
  t.ready[t.receivingHeader.generation] = std::move(t.receiving);
  t.receiving.reset();
  t.ackSend.assign(1, MPI_REQUEST_NULL);
  checkMpi(MPI_Isend(&t.ack, 1, MPI_BYTE, 0, kTagMapAck, comm_, &t.ackSend[0]), "MPI_Isend");
  return true;
}

void Cluster::shareMapNow(std::shared_ptr<const RetargetMap> map, std::uint64_t generation,
                          double patienceSeconds) {
  if (isRoot()) {
    shareMap(std::move(map), generation);
    const auto deadline = deadlineIn(options_.timeoutSeconds);
    while (!progressMaps())
      if (ClusterClock::now() > deadline) {
        for (int r = 1; r < size(); ++r)
          if (transfer_->acks[r - 1] != MPI_REQUEST_NULL) lost(r, "the map's broadcast");
        lost(1, "the map's broadcast");
      }
  } else {
    const auto deadline = deadlineIn(2 * options_.timeoutSeconds + patienceSeconds);
    while (!progressMaps())
      if (ClusterClock::now() > deadline) lost(0, "the map's broadcast");
    generation = transfer_->ready.rbegin()->first;
  }
  adoptMap(generation);
  if (isRoot()) return;
  // The ack must leave before the root can finish: wait for it here too.
  if (waitUntil(transfer_->ackSend, deadlineIn(options_.timeoutSeconds)) >= 0)
    lost(0, "the map's broadcast");
}

void Cluster::adoptMap(std::uint64_t generation) {
  if (map_ && generation == mapGeneration_) return;
  auto& ready = transfer_->ready;
  if (!map_ && ready.empty()) return;  // no map shared yet (plain rendering)
  const auto it = ready.find(generation);
  if (it == ready.end())
    throw ClusterError(ErrorCode::Internal, "cluster: rank " + std::to_string(rank_) +
                                                " was told to render with map generation " +
                                                std::to_string(generation) +
                                                ", which never reached it");
  map_ = it->second;
  mapGeneration_ = generation;
  ready.erase(ready.begin(), std::next(it));
}

}  // namespace confvis
