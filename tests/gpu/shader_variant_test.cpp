// Which shader variant a render compiles (host/gpu/shader_variant.h): the rule, the index of
// the variants compiled on this machine, and, end to end, what `vkrt --stats` says it ran.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "gpu/shader_variant.h"
#include "test_support.h"

namespace vkrt {
namespace {

TEST(ShaderVariant, SpecializingPaysOnlyForLongRendersOnACpu) {
  EXPECT_FALSE(specializationPays(true, 640.0 * 480 * 3, false));   // a course scene
  EXPECT_FALSE(specializationPays(true, kSpecializeWhittedAboveRays, false));
  EXPECT_TRUE(specializationPays(true, 2 * kSpecializeWhittedAboveRays, false));
  EXPECT_FALSE(specializationPays(true, 240.0 * 240 * 2 * 5, true));  // a preview of a cornell box
  // Previews of the CSE 168 scenes (2 samples at half size), whose compile of 0.3-0.5 s would
  // save 40-180 ms of tracing: hw2/direct3x3 (a camera ray and 18 light samples a sample),
  // hw2/sphere as estimated.
  EXPECT_FALSE(specializationPays(true, 320.0 * 240 * 2 * 19, true));
  EXPECT_FALSE(specializationPays(true, 15.5e6, true));
  EXPECT_TRUE(specializationPays(true, 480.0 * 480 * 64 * 9, true));  // cornellNEE at 64 spp
  EXPECT_TRUE(specializationPays(false, 1.0, false));                 // a GPU compiles in milliseconds
  EXPECT_TRUE(specializationPays(false, 1.0, true));
}

TEST(ShaderVariant, KeysTellVariantsApart) {
  VkPhysicalDeviceProperties device{};
  const std::uint32_t a[] = {1, 2, 3}, b[] = {1, 2, 4};
  const std::uint64_t k = variantKey(device, a, sizeof a, {1, 0});
  EXPECT_EQ(k, variantKey(device, a, sizeof a, {1, 0}));
  EXPECT_NE(k, variantKey(device, a, sizeof a, {1, 1}));
  EXPECT_NE(k, variantKey(device, b, sizeof b, {1, 0}));
  device.driverVersion = 7;
  EXPECT_NE(k, variantKey(device, a, sizeof a, {1, 0}));
}

// Environment variables of one test, put back after it.
struct ScopedEnv {
  std::string name, old;
  bool had;
  ScopedEnv(const char* n, const char* value) : name(n), had(std::getenv(n) != nullptr) {
    if (had) old = std::getenv(n);
    if (value)
      ::setenv(n, value, 1);
    else
      ::unsetenv(n);
  }
  ~ScopedEnv() {
    if (had)
      ::setenv(name.c_str(), old.c_str(), 1);
    else
      ::unsetenv(name.c_str());
  }
};

// The index belongs to one driver cache: a variant recorded under one is unknown under
// another (an emptied or other MESA_SHADER_CACHE_DIR) and to a disabled cache.
TEST(ShaderVariant, TheIndexBelongsToOneDriverCache) {
  const std::string dir = test::freshDir("shader-variant/index");
  ScopedEnv xdg("XDG_CACHE_HOME", dir.c_str());
  ScopedEnv disable("MESA_SHADER_CACHE_DISABLE", nullptr);
  ScopedEnv mesa("MESA_SHADER_CACHE_DIR", (dir + "/mesa-a").c_str());
  const std::string pathA = variantIndexPath();
  EXPECT_EQ(pathA.rfind(dir + "/vkrt/compiled-variants-", 0), 0u) << pathA;
  EXPECT_FALSE(variantCompiled(42));
  recordVariantCompiled(42);
  recordVariantCompiled(42);   // once in the file
  EXPECT_TRUE(variantCompiled(42));
  EXPECT_EQ(test::readFile(pathA), "000000000000002a\n");
  {
    ScopedEnv other("MESA_SHADER_CACHE_DIR", (dir + "/mesa-b").c_str());
    EXPECT_NE(variantIndexPath(), pathA);
    EXPECT_FALSE(variantCompiled(42));
  }
  {
    ScopedEnv off("MESA_SHADER_CACHE_DISABLE", "true");
    EXPECT_EQ(variantIndexPath(), "");
    EXPECT_FALSE(variantCompiled(42));
  }
  EXPECT_TRUE(variantCompiled(42));
}

// End to end: a small scene renders with the general variant until its specialised one has
// been compiled on this machine (here forced once), then with that one; a long render
// specialises at once. Both variants give the same bytes.
TEST(ShaderVariant, AutoTakesTheSpecialisedVariantOnceCompiledOrWhenItPays) {
  VKRT_REQUIRE_GPU(ctx);
  (void)ctx;
  const std::string dir = test::freshDir("shader-variant/auto");
  const std::string env = "XDG_CACHE_HOME=" + dir + " MESA_SHADER_CACHE_DIR=" + dir + "/mesa";
  test::writeFile(dir + "/s.test", "size 32 24\ncamera 0 0 4 0 0 0 0 1 0 45\ndiffuse 0.5 0.5 0.5\nsphere 0 0 0 1\n"
                                   "point 1 2 3 1 1 1\n");
  auto shaderLine = [&](const std::string& args) {
    test::RunResult r = test::runVkrt("--stats " + args + " -o " + dir + "/o.pfm " + dir + "/s.test", env);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const auto at = r.output.find("shader: ");
    return at == std::string::npos ? r.output : r.output.substr(at, r.output.find('\n', at) - at);
  };
  EXPECT_NE(shaderLine("").find("the general variant"), std::string::npos);
  const std::string general = test::readFile(dir + "/o.pfm");
  EXPECT_NE(shaderLine("--variant specialized").find("the specialised variant"), std::string::npos);
  EXPECT_EQ(test::readFile(dir + "/o.pfm"), general) << "the two variants' pictures differ";
  EXPECT_NE(shaderLine("").find("the specialised variant"), std::string::npos) << "the index did not keep it";
  EXPECT_NE(shaderLine("--variant general").find("the general variant"), std::string::npos);
  // A preview at a hundredth of the size of a long render (a million pixels, six lights,
  // mirrors: about 35 M rays) takes the general variant; the long render specialises at once.
  test::writeFile(dir + "/long.test", "size 1000 1000\nmaxdepth 8\ncamera 0 0 4 0 0 0 0 1 0 45\n"
                                      "specular 0.5 0.5 0.5\nsphere 0 0 0 1\nsphere 2 0 0 1\npoint 1 2 3 1 1 1\n"
                                      "point -1 2 3 1 1 1\npoint 0 -2 3 1 1 1\npoint 0 2 -3 1 1 1\n"
                                      "point 3 2 3 1 1 1\npoint -3 2 3 1 1 1\n");
  for (const char* scale : {"0.1", "1"}) {
    test::RunResult r = test::runVkrt("--stats --scale " + std::string(scale) + " -o " + dir + "/l.png " + dir +
                                      "/long.test", env);
    EXPECT_NE(r.output.find(scale[0] == '1' ? "the specialised variant" : "the general variant"), std::string::npos)
        << "--scale " << scale << ": " << r.output;
  }
}

}  // namespace
}  // namespace vkrt
