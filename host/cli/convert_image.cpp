// vkrt convert IN OUT (host/cli/convert_image.h).
#include "cli/convert_image.h"

#include <cstdio>
#include <string>

#include "cli/exit_status.h"
#include "cli/run_files.h"
#include "image/atomic_file.h"
#include "image/image_file.h"
#include "image/image_read.h"

namespace vkrt {

// vkrt convert IN OUT: IN is an input, never written; OUT is written whole or not at all.
int convertImage(const ConvertOptions& options) {
  RunFiles files;
  files.addInput(options.input, "the image to convert");
  files.addOutput(options.output, "the converted image");
  checkOutputWritable(options.output);
  vkrt::convertImage(options.input, options.output);
  if (!options.quiet)
    std::fprintf(stderr, "vkrt: wrote %s (%s) from %s\n", options.output.c_str(),
                 std::string(imageFormatFor(options.output).name).c_str(), options.input.c_str());
  return kExitOk;
}

}  // namespace vkrt
