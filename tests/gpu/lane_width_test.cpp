// The shaders give the same bits whatever the device's lane count. A GPU runs 32 or 64 lanes
// a subgroup; lavapipe runs 4, 8 or 16 (LP_NATIVE_VECTOR_WIDTH = 128, 256 or 512 bits, read
// when the driver loads, so each width is its own vkrt process). Each scene is rendered at
// the three widths into PFM (linear float32, no rounding to 8 bits) and the files must be
// the same bytes: any dependence of a result on the lane count (subgroup operations, an order
// of work that follows the lane count into an accumulation, a suspended state sized by it)
// shows here. Tolerance: none, the bits must be equal.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.h"

namespace vkrt::test {
namespace {

const char* const kWidths[] = {"128", "256", "512"};

struct LaneScene {
  const char* name;
  const char* file;   // under the source tree
  const char* args;   // a small render, quick at every width
};

// The Whitted shader over triangles, spheres, shadows and mirrors; the path shader with its
// default settings (and suspension, at a small step budget, in the Whitted case through
// deep_mirrors' many bounces).
const LaneScene kScenes[] = {
    {"showcase", "scenes/showcase.test", "--size 96x72"},
    {"deep_mirrors", "scenes/deep_mirrors.test", "--size 64x64"},
    {"gi_box", "scenes/gi/box.test", "--size 48x48 --spp 4 --seed 7"},
};

// Whether lavapipe is among the devices (it is where only the CPU renders; a GPU machine may
// lack it).
bool haveLavapipe() {
  RunResult r = runVkrt("--list-devices");
  return r.exitCode == 0 && r.output.find("llvmpipe") != std::string::npos;
}

TEST(LaneWidth, LavapipeAt4And8And16LanesGivesTheSameBytes) {
  if (!haveLavapipe()) VKRT_SKIP_UNLESS_CI("no lavapipe (llvmpipe) Vulkan device to vary the lane count on");
  const std::string dir = freshDir("lane-width");
  for (const LaneScene& scene : kScenes) {
    SCOPED_TRACE(scene.name);
    std::vector<std::string> files;
    for (const char* width : kWidths) {
      std::string out = dir + "/" + scene.name + "-" + width + ".pfm";
      RunResult r = runVkrt(std::string("-q --device llvmpipe ") + scene.args + " -o '" + out + "' '" +
                                sourcePath(scene.file) + "'",
                            std::string("LP_NATIVE_VECTOR_WIDTH=") + width);
      ASSERT_EQ(r.exitCode, 0) << "width " << width << ": " << r.output;
      files.push_back(readFile(out));
      ASSERT_FALSE(files.back().empty()) << out;
    }
    for (std::size_t i = 1; i < files.size(); ++i)
      EXPECT_TRUE(files[i] == files[0]) << scene.name << ": " << kWidths[i] << "-bit lanes differ from "
                                        << kWidths[0] << "-bit lanes (" << dir << "/" << scene.name
                                        << "-*.pfm; vkrt diff compares them)";
  }
}

// The width really reaches the driver: lavapipe names its vector width in the device name, so
// a test that passed because the variable was ignored would show one name three times.
TEST(LaneWidth, TheDriverSeesEachWidth) {
  if (!haveLavapipe()) VKRT_SKIP_UNLESS_CI("no lavapipe (llvmpipe) Vulkan device to vary the lane count on");
  for (const char* width : kWidths) {
    RunResult r = runVkrt("--list-devices", std::string("LP_NATIVE_VECTOR_WIDTH=") + width);
    EXPECT_NE(r.output.find(std::string(width) + " bits"), std::string::npos) << width << ": " << r.output;
  }
}

}  // namespace
}  // namespace vkrt::test
