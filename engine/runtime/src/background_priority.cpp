#include "confvis/runtime/background_priority.hpp"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <utility>

namespace confvis {

BakeFunction inBackground(BakeFunction bake, int niceness) {
  return [bake = std::move(bake), niceness](const DisplayConfig& config,
                                            const glm::dvec3& reference) {
    // PRIO_PROCESS with a thread id sets that thread's nice value alone (Linux).
    const auto thread = static_cast<id_t>(::syscall(SYS_gettid));
    (void)::setpriority(PRIO_PROCESS, thread, niceness);
    return bake(config, reference);
  };
}

}  // namespace confvis
