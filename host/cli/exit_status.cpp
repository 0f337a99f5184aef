// Exceptions -> messages and exit statuses, for main() and its tests.
#include "cli/exit_status.h"

#include <cstdarg>
#include <cstdlib>

#include <initializer_list>
#include <new>
#include <string>
#include <utility>

#include "platform/process.h"

#include "cli/run_files.h"
#include "util/errors.h"
#include "gpu/device_error.h"
#include "util/interrupt.h"
#include "render/render.h"
#include "scene/diagnostic.h"

namespace vkrt {
namespace {

// printf into `text`.
[[gnu::format(printf, 2, 3)]] void append(std::string& text, const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  if (n > 0) {
    const std::size_t at = text.size();
    text.resize(at + static_cast<std::size_t>(n) + 1);
    std::vsnprintf(text.data() + at, static_cast<std::size_t>(n) + 1, format, again);
    text.resize(at + static_cast<std::size_t>(n));
  }
  va_end(again);
}

// The message of `error` (with its newlines) into `text`, and its exit status.
int describeError(std::exception_ptr error, const ErrorContext& context, std::string& text) {
  try {
    std::rethrow_exception(error);
  } catch (const RefusedOutput& e) {   // the command line is well-formed: no pointer to --help
    append(text, "vkrt: error: %s\n", e.what());
    return kExitUsage;
  } catch (const UsageError& e) {   // one line, and where the whole usage is (not the text itself)
    append(text, "vkrt: error: %s\nsee 'vkrt --help'\n", e.what());
    return kExitUsage;
  } catch (const Interrupted& e) {
    append(text, "\nvkrt: interrupted; nothing written\n");
    return kExitSignalBase + e.signal();
  } catch (const SceneError& e) {
    for (const Diagnostic& d : e.diagnostics())
      if (d.isError() || !context.quiet) append(text, "%s\n", d.format().c_str());
    return kExitScene;
  } catch (const DeviceError& e) {
    append(text, "vkrt: error: %s\n", e.what());
    return kExitDevice;
  } catch (const IoError& e) {
    append(text, "vkrt: error: %s\n", e.what());
    return kExitIo;
  } catch (const OutOfMemory& e) {
    append(text, "vkrt: error: out of memory: %s\n", e.what());
    return kExitOutOfMemory;
  } catch (const std::bad_alloc&) {
    // How much was asked for is not known here: say what failed and the limits there are,
    // not a need that the numbers cannot show.
    const std::string what = context.scenePath.empty() ? "this command" : context.scenePath;
    std::string limits = platform::memoryLimitText();
    if (unsigned long long mb = availableMemoryBytes() >> 20)
      limits += "; the machine has " + std::to_string(mb) + " MB available";
    append(text, "vkrt: error: out of memory: an allocation for %s failed%s\n", what.c_str(), limits.c_str());
    return kExitOutOfMemory;
  } catch (const std::exception& e) {   // InternalError, and whatever else a bug lets through
    append(text, "vkrt: internal error (a bug in vkrt): %s\n", e.what());
    return kExitInternal;
  } catch (...) {
    append(text, "vkrt: internal error (a bug in vkrt): an exception of unknown type\n");
    return kExitInternal;
  }
}

}  // namespace

int reportError(std::exception_ptr error, const ErrorContext& context, std::FILE* err) {
  std::string text;
  const int status = describeError(error, context, text);
  std::fputs(text.c_str(), err);
  return status;
}

int reportErrorKeepingText(std::exception_ptr error, const ErrorContext& context, std::string& text) {
  text.clear();
  const int status = describeError(error, context, text);
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
