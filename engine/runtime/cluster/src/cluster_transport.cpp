#include "cluster_transport.hpp"

#include <thread>

#include "confvis/runtime/cluster.hpp"

namespace confvis::detail {

ClusterClock::time_point deadlineIn(double seconds) {
  return ClusterClock::now() +
         std::chrono::duration_cast<ClusterClock::duration>(std::chrono::duration<double>(seconds));
}

void checkMpi(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw ClusterError(ErrorCode::IoFailure,
                     std::string("MPI failed in ") + what + ": " + std::string(text, length));
}

namespace {
// Spin briefly (a frame's messages arrive within microseconds on one host), then nap so a rank
// waiting for a slow one leaves the cores to the renderers.
void pause(int& spins) {
  if (++spins < 200) std::this_thread::yield();
  else std::this_thread::sleep_for(std::chrono::microseconds(200));
}
}  // namespace

bool testAll(std::vector<MPI_Request>& requests) {
  bool all = true;
  for (MPI_Request& request : requests) {
    if (request == MPI_REQUEST_NULL) continue;
    int done = 0;
    checkMpi(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
    all = all && done;
  }
  return all;
}

int waitUntil(std::vector<MPI_Request>& requests, ClusterClock::time_point deadline,
              const std::function<void()>& meanwhile) {
  for (int spins = 0;; pause(spins)) {
    if (testAll(requests)) return -1;
    if (meanwhile) meanwhile();
    if (ClusterClock::now() > deadline)
      for (std::size_t i = 0; i < requests.size(); ++i)
        if (requests[i] != MPI_REQUEST_NULL) return static_cast<int>(i);
  }
}

std::optional<std::string> receiveBytes(MPI_Comm comm, int source, int tag,
                                        ClusterClock::time_point deadline) {
  for (int spins = 0;; pause(spins)) {
    int found = 0;
    MPI_Status status;
    checkMpi(MPI_Iprobe(source, tag, comm, &found, &status), "MPI_Iprobe");
    if (found) {
      int count = 0;
      checkMpi(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
      std::string bytes(static_cast<std::size_t>(count), '\0');
      // Probed: the message is here, so this receive does not wait for the sender.
      checkMpi(MPI_Recv(bytes.data(), count, MPI_BYTE, source, tag, comm, MPI_STATUS_IGNORE),
               "MPI_Recv");
      return bytes;
    }
    if (ClusterClock::now() > deadline) return std::nullopt;
  }
}

}  // namespace confvis::detail
