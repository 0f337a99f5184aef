// Command-line options of `vkrt`: argv -> Options. No rendering here.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/render.h"

namespace vkrt {

// A bad command line: exit status 1.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Options {
  RenderRequest request;
  bool stats = false;
  bool quiet = false;
  bool help = false;
  bool version = false;
  bool listDevices = false;
};

// Throws UsageError.
Options parseOptions(const std::vector<std::string>& args);

const char* usageText();

}  // namespace vkrt
