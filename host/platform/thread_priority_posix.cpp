// thread_priority.h on POSIX: Linux gives each thread a nice value of its own.
#include "platform/thread_priority.h"

#ifdef __linux__
#  include <sys/resource.h>
#  include <unistd.h>
#endif

namespace vkrt::platform {

void lowerThisThreadsPriority() {
#ifdef __linux__
  ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 10);
#endif
}

}  // namespace vkrt::platform
