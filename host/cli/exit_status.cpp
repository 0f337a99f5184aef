// Exceptions -> messages and exit statuses, for main() and its tests.
#include "cli/exit_status.h"

#include <new>

#include "cli/options.h"
#include "errors.h"
#include "gpu/device_error.h"
#include "interrupt.h"
#include "render/render.h"
#include "scene/diagnostic.h"

namespace vkrt {

int reportError(std::exception_ptr error, const ErrorContext& context, std::FILE* err) {
  try {
    std::rethrow_exception(error);
  } catch (const UsageError& e) {
    std::fprintf(err, "vkrt: error: %s\n\n%s", e.what(), usageText());
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
    const char* what = context.scenePath.empty() ? "this command" : context.scenePath.c_str();
    if (unsigned long long mb = availableMemoryBytes() >> 20)
      std::fprintf(err, "vkrt: error: out of memory: %s needs more than the %llu MB this machine has available\n",
                   what, mb);
    else
      std::fprintf(err, "vkrt: error: out of memory: %s needs more memory than this machine has\n", what);
    return kExitOutOfMemory;
  } catch (const std::exception& e) {   // InternalError, and whatever else a bug lets through
    std::fprintf(err, "vkrt: internal error (a bug in vkrt): %s\n", e.what());
    return kExitInternal;
  } catch (...) {
    std::fprintf(err, "vkrt: internal error (a bug in vkrt): an exception of unknown type\n");
    return kExitInternal;
  }
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

}  // namespace vkrt
