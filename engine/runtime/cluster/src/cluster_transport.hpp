#pragma once
// Point-to-point MPI with deadlines: every wait of the cluster ends by a clock, never by hope.
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <mpi.h>

namespace confvis::detail {

using ClusterClock = std::chrono::steady_clock;

// Message tags of the cluster's protocol (on its own duplicated communicator).
enum ClusterTag : int {
  kTagHello = 100, kTagVerdict, kTagFrame, kTagReady, kTagGo,
  kTagMapHeader, kTagMapChunk, kTagMapAck, kTagImageHeader, kTagImage,
};

ClusterClock::time_point deadlineIn(double seconds);

// Throws ClusterError naming `what` and MPI's own message unless code is MPI_SUCCESS.
void checkMpi(int code, const char* what);

// Tests the requests until all completed (returns -1) or the deadline passed (returns the index
// of the first request still pending). Completed requests become MPI_REQUEST_NULL.
// `meanwhile`, when given, runs between tests (a rank waiting for a frame moves maps on).
int waitUntil(std::vector<MPI_Request>& requests, ClusterClock::time_point deadline,
              const std::function<void()>& meanwhile = {});
// Moves the requests on without waiting; true when all of them completed.
bool testAll(std::vector<MPI_Request>& requests);

// A whole message of bytes from `source` with `tag`, or nullopt at the deadline.
std::optional<std::string> receiveBytes(MPI_Comm comm, int source, int tag,
                                        ClusterClock::time_point deadline);

}  // namespace confvis::detail
