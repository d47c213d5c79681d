// Cluster synchronisation costs, run by hand under mpirun (never in the test suite):
//   mpirun -np 6 build/confvis_bench_cluster            (as root: OMPI_ALLOW_RUN_AS_ROOT=1 ...)
//   mpirun -np 1 build/confvis_bench_cluster            (the single-process baseline)
// 1. Per frame: exchangeFrame (the frame state to every rank) + swapLock, no rendering: the
//    overhead a frame-locked cluster adds to every frame, in microseconds (median and p99).
// 2. One map to every rank (shareMapNow) at 256, 512 and 1024 texels per face.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include <mpi.h>

#include "confvis/base/stopwatch.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/runtime/cluster.hpp"

using namespace confvis;
using Clock = SteadyClock;

namespace {

double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(p * (values.size() - 1))];
}

}  // namespace

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  {
    const DisplayConfig display =
        loadDisplayConfig(std::string(CONFVIS_SOURCE_DIR) + "/configs/cave5.json");
    Cluster cluster(MPI_COMM_WORLD, display);
    const int frames = 2000;
    std::vector<double> micros;
    for (int i = 0; i < frames + 100; ++i) {
      const auto start = Clock::now();
      ClusterFrameState state;
      state.frame = static_cast<std::uint64_t>(i);
      cluster.exchangeFrame(state);
      cluster.swapLock();
      if (i >= 100)  // after warm-up
        micros.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
    }
    if (cluster.isRoot())
      std::printf("ranks %d: frame state + swap lock: median %.1f us, p99 %.1f us (%d frames)\n",
                  cluster.size(), percentile(micros, 0.5), percentile(micros, 0.99), frames);
    std::uint64_t generation = 0;
    for (const int resolution : {256, 512, 1024}) {
      std::shared_ptr<const RetargetMap> map;
      if (cluster.isRoot()) map = std::make_shared<RetargetMap>(RetargetMap::identity(resolution));
      const double bytes = 2.0 * 6 * resolution * resolution * 4 * sizeof(float);
      std::vector<double> seconds;
      for (int repeat = 0; repeat < 3; ++repeat) {
        MPI_Barrier(MPI_COMM_WORLD);
        const auto start = Clock::now();
        cluster.shareMapNow(map, ++generation);
        ClusterFrameState state;  // the frame that names the map: everyone swaps to it
        state.mapGeneration = generation;
        cluster.exchangeFrame(state);
        cluster.swapLock();
        seconds.push_back(secondsSince(start));
      }
      if (cluster.isRoot())
        std::printf("ranks %d: map %4d texels/face (%.0f MB) to every rank: %.1f ms (best of 3)\n",
                    cluster.size(), resolution, bytes / 1e6,
                    1e3 * *std::min_element(seconds.begin(), seconds.end()));
    }
  }
  MPI_Finalize();
  return 0;
}
