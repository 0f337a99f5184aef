// Exceptions -> messages and exit statuses, for main() and its tests.
#include "cli/exit_status.h"

#include <cstdlib>

#include <initializer_list>
#include <new>
#include <string>
#include <utility>

#include <sys/resource.h>

#include "cli/run_files.h"
#include "util/errors.h"
#include "gpu/device_error.h"
#include "util/interrupt.h"
#include "render/render.h"
#include "scene/diagnostic.h"

namespace vkrt {
namespace {

// " (this process may use at most N MB of address space: ulimit -v)" when such a limit is
// set, else "" : the limit an allocation meets first, where there is one.
std::string processMemoryLimit() {
  std::string s;
  for (auto [resource, name] : {std::pair{RLIMIT_AS, "address space: ulimit -v"}, std::pair{RLIMIT_DATA, "data: ulimit -d"}}) {
    struct rlimit limit {};
    if (::getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      s += "; this process may use at most " + std::to_string(static_cast<unsigned long long>(limit.rlim_cur) >> 20) +
           " MB of " + name;
  }
  return s;
}

}  // namespace

int reportError(std::exception_ptr error, const ErrorContext& context, std::FILE* err) {
  try {
    std::rethrow_exception(error);
  } catch (const RefusedOutput& e) {   // the command line is well-formed: no pointer to --help
    std::fprintf(err, "vkrt: error: %s\n", e.what());
    return kExitUsage;
  } catch (const UsageError& e) {   // one line, and where the whole usage is (not the text itself)
    std::fprintf(err, "vkrt: error: %s\nsee 'vkrt --help'\n", e.what());
    return kExitUsage;
  } catch (const Interrupted& e) {
    std::fprintf(err, "\nvkrt: interrupted; nothing written\n");
    return kExitSignalBase + e.signal();
  } catch (const SceneError& e) {
    for (const Diagnostic& d : e.diagnostics())
      if (d.isError() || !context.quiet) std::fprintf(err, "%s\n", d.format().c_str());
    return kExitScene;
  } catch (const DeviceError& e) {
    std::fprintf(err, "vkrt: error: %s\n", e.what());
    return kExitDevice;
  } catch (const IoError& e) {
    std::fprintf(err, "vkrt: error: %s\n", e.what());
    return kExitIo;
  } catch (const OutOfMemory& e) {
    std::fprintf(err, "vkrt: error: out of memory: %s\n", e.what());
    return kExitOutOfMemory;
  } catch (const std::bad_alloc&) {
    // How much was asked for is not known here: say what failed and the limits there are,
    // not a need that the numbers cannot show.
    const std::string what = context.scenePath.empty() ? "this command" : context.scenePath;
    std::string limits = processMemoryLimit();
    if (unsigned long long mb = availableMemoryBytes() >> 20)
      limits += "; the machine has " + std::to_string(mb) + " MB available";
    std::fprintf(err, "vkrt: error: out of memory: an allocation for %s failed%s\n", what.c_str(), limits.c_str());
    return kExitOutOfMemory;
  } catch (const std::exception& e) {   // InternalError, and whatever else a bug lets through
    std::fprintf(err, "vkrt: internal error (a bug in vkrt): %s\n", e.what());
    return kExitInternal;
  } catch (...) {
    std::fprintf(err, "vkrt: internal error (a bug in vkrt): an exception of unknown type\n");
    return kExitInternal;
  }
}

int reportErrorKeepingText(std::exception_ptr error, const ErrorContext& context, std::string& text) {
  text.clear();
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* memory = ::open_memstream(&buffer, &size);
  if (!memory) return reportError(error, context, stderr);
  const int status = reportError(error, context, memory);
  std::fclose(memory);
  text.assign(buffer, size);
  std::free(buffer);
  std::fputs(text.c_str(), stderr);
  return status;
}

std::string exitStatusName(int status) {
  switch (status) {
    case kExitOk: return "ok";
    case kExitUsage: return "usage error";
    case kExitScene: return "scene error";
    case kExitDevice: return "device error";
    case kExitIo: return "I/O error";
    case kExitDiffers: return "images differ";
    case kExitOutOfMemory: return "out of memory";
    case kExitInternal: return "internal error";
    default:
      if (status > kExitSignalBase) return "stopped by signal " + std::to_string(status - kExitSignalBase);
      return "status " + std::to_string(status);
  }
}

std::exception_ptr currentFailure() {
  if (int signal = pendingInterrupt()) return std::make_exception_ptr(Interrupted(signal));
  return std::current_exception();
}

}  // namespace vkrt
