// Which shader variant a render compiles (host/gpu/shader_variant.h): the rule, the index of
// the variants compiled on this machine, and, end to end, what `vkrt --stats` says it ran and
// that the general variants are compiled once for every scene (the driver's cache entries).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "gpu/shader_variant.h"
#include "test_support.h"

namespace vkrt {
namespace {

TEST(ShaderVariant, SpecializingPaysOnlyForLongRenders) {
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
  // A GPU: a compile of 0.2-0.4 s against 5-8 ps of trace saved per estimated ray.
  EXPECT_FALSE(specializationPays(false, 640.0 * 480 * 3, false));
  EXPECT_FALSE(specializationPays(false, 480.0 * 480 * 64 * 16, true));  // cornellNEE at 64 spp: 2 ms saved
  EXPECT_FALSE(specializationPays(false, 640.0 * 480 * 128 * 21, true));  // the hw4 dragon: 4 ms saved
  EXPECT_FALSE(specializationPays(false, kSpecializeGpuAboveRays, true));
  EXPECT_TRUE(specializationPays(false, 2 * kSpecializeGpuAboveRays, false));
  EXPECT_FALSE(specializationPays(false, 480.0 * 480 * 1024 * 16, true));  // cornellNEE at 1024 spp: 30 ms
  EXPECT_TRUE(specializationPays(false, 480.0 * 480 * 65536 * 16, true));  // at 65536 spp: 2 s
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

// A CPU device takes a specialised variant that the index knows, whatever the render's size;
// a GPU goes by the size alone, so that a command's variant (and bits) are its own.
TEST(ShaderVariant, OnlyACpuDeviceTakesAVariantForBeingCompiled) {
  const std::string dir = test::freshDir("shader-variant/auto-rule");
  ScopedEnv xdg("XDG_CACHE_HOME", dir.c_str());
  ScopedEnv disable("MESA_SHADER_CACHE_DISABLE", nullptr);
  ScopedEnv mesa("MESA_SHADER_CACHE_DIR", (dir + "/mesa").c_str());
  const double preview = 1e6;
  for (bool path : {false, true}) {
    EXPECT_FALSE(autoTakesSpecialised(true, preview, path, 7));
    EXPECT_FALSE(autoTakesSpecialised(false, preview, path, 7));
  }
  recordVariantCompiled(7);
  for (bool path : {false, true}) {
    EXPECT_TRUE(autoTakesSpecialised(true, preview, path, 7));
    EXPECT_FALSE(autoTakesSpecialised(false, preview, path, 7));
    EXPECT_TRUE(autoTakesSpecialised(false, 2 * kSpecializeGpuAboveRays, path, 8));
    EXPECT_TRUE(autoTakesSpecialised(true, 2 * kSpecializeWhittedAboveRays, path, 8));
  }
}

// End to end: a small scene renders with the general variant until its specialised one has
// been compiled on this machine (here forced once), then with that one on a CPU device; a
// long render specialises at once there. Both variants give the same bytes. (A GPU keeps to
// the general variant below 40 billion rays.)
TEST(ShaderVariant, AutoTakesTheSpecialisedVariantOnceCompiledOrWhenItPays) {
  VKRT_REQUIRE_GPU(ctx);
  const bool cpuDevice = ctx->isCpuDevice();
  const std::string dir = test::freshDir("shader-variant/auto");
  const std::string env =
      "XDG_CACHE_HOME=" + dir + " MESA_SHADER_CACHE_DIR=" + dir + "/mesa MESA_SHADER_CACHE_DISABLE=false";
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
  EXPECT_NE(shaderLine("").find(cpuDevice ? "the specialised variant" : "the general variant"), std::string::npos)
      << (cpuDevice ? "the index did not keep it" : "a GPU took it for being compiled");
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
    EXPECT_NE(r.output.find(scale[0] == '1' && cpuDevice ? "the specialised variant" : "the general variant"),
              std::string::npos)
        << "--scale " << scale << ": " << r.output;
  }
}

// The general variant is one compiled shader for every scene: the driver's cache gains no
// entry for a second scene that differs in everything the parameter buffers carry (camera,
// size, crop, light counts and samples, depth, integrator settings), nor for one whose arrays
// are of another size (of those whose rays walk the BVH; small scenes, whose rays test every
// primitive, have a general variant of their own). It fails where the
// shaders read those from uniform blocks, some of whose values lavapipe 22.3 inlines, compiling
// the shader again for each new set (shaders/params.glsl).
TEST(ShaderVariant, TheGeneralVariantIsCompiledOnceForEveryScene) {
  VKRT_REQUIRE_GPU(ctx);
  if (!ctx->isCpuDevice())
    GTEST_SKIP() << "counts the entries of lavapipe's shader cache; this device is not a CPU";
  const std::string dir = test::freshDir("shader-variant/general-once");
  // Mesa's cache on, one file per entry (the layouts of one file or a database would hide a
  // new entry).
  const std::string env = "XDG_CACHE_HOME=" + dir + " MESA_SHADER_CACHE_DIR=" + dir +
                          "/mesa MESA_SHADER_CACHE_DISABLE=false MESA_DISK_CACHE_SINGLE_FILE=false "
                          "MESA_DISK_CACHE_DATABASE=false MESA_DISK_CACHE_MULTI_FILE=true";
  auto cacheEntries = [&] {
    std::size_t n = 0;
    std::error_code error;
    for (std::filesystem::recursive_directory_iterator it(dir + "/mesa", error), end; !error && it != end;
         it.increment(error))
      n += it->is_regular_file() && it->path().filename() != "index";
    return n;
  };
  auto render = [&](const std::string& name, const std::string& text, const std::string& args) {
    test::writeFile(dir + "/" + name, text);
    test::RunResult r = test::runVkrt("--variant general " + args + " -o " + dir + "/o.png " + dir + "/" + name, env);
    EXPECT_EQ(r.exitCode, 0) << r.output;
  };
  const std::string box = "vertex -1 0 -1\nvertex 1 0 -1\nvertex 1 0 1\nvertex -1 0 1\ndiffuse 0.5 0.5 0.5\n"
                          "tri 0 2 1\ntri 0 3 2\nsphere 0 0.5 0 0.4\n";
  render("path-a.test",
         "size 24 16\nintegrator pathtracer\nnexteventestimation on\nspp 2\nmaxdepth 5\ncamera 0 1 3 0 0.5 0 0 1 0 45\n"
         "quadLight -0.25 1.9 -0.25 0 0 0.5 0.5 0 0 10 10 10\n" + box,
         "");
  const std::size_t afterFirst = cacheEntries();
  ASSERT_GE(afterFirst, 1u) << "the render left no entry in the shader cache " << dir << "/mesa";
  render("path-b.test",
         "size 40 30\nintegrator pathtracer\nnexteventestimation mis\nimportancesampling brdf\nrussianroulette on\n"
         "spp 3\nmaxdepth 2\nlightsamples 4\nlightstratify on\ncamera 0.3 1.2 2.5 0.1 0.4 0 0 1 0 60\n"
         "quadLight -0.5 1.5 -0.5 0 0 1 1 0 0 5 4 3\nquadLight 0 2 0 0 0 0.2 0.2 0 0 1 1 1\n" + box,
         "--crop 4,2,36,28 --seed 9");
  render("direct.test",
         "size 16 16\nintegrator direct\nlightsamples 9\ncamera 0 2 2 0 0 0 0 1 0 30\n"
         "quadLight -0.25 1.9 -0.25 0 0 0.5 0.5 0 0 10 10 10\n" + box,
         "");
  EXPECT_EQ(cacheEntries(), afterFirst) << "the general path variant was compiled again for another scene";

  render("whitted-a.test", "size 24 16\ncamera 0 1 3 0 0 0 0 1 0 45\npoint 1 2 3 1 1 1\n" + box, "");
  const std::size_t afterWhitted = cacheEntries();
  EXPECT_GT(afterWhitted, afterFirst) << "the Whitted render left no entry of its own";
  render("whitted-b.test",
         "size 40 30\nmaxdepth 3\ncamera 0.5 2 2 0 0.2 0 0 1 0 70\nspecular 0.3 0.3 0.3\n"
         "point 1 2 3 1 1 1\ndirectional 0 1 1 0.5 0.5 0.5\npoint -1 2 3 0.2 0.2 0.2\n" + box,
         "--crop 2,2,30,20");
  // Scenes too large to test every primitive (meshes of (n - 1)^2 quads) take the general
  // variant that walks the BVH: compiled once for arrays of every size. Lavapipe keys its code
  // on whether a texel buffer's size is a power of two, which the padding of the arrays to a
  // count of 64 KiB blocks never makes it: 2,048 triangles are 8,192 texels.
  auto grid = [](int n) {
    std::string text = "size 32 24\ncamera 0 3 3 0 0 0 0 1 0 50\npoint 1 2 3 1 1 1\n";
    for (int z = 0; z < n; ++z)
      for (int x = 0; x < n; ++x)
        text += "vertex " + std::to_string(x - n / 2) + " 0 " + std::to_string(z - n / 2) + "\n";
    for (int z = 0; z + 1 < n; ++z)
      for (int x = 0; x + 1 < n; ++x) {
        const int a = z * n + x, b = a + 1, c = a + n, d = c + 1;
        text += "tri " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(b) + "\ntri " +
                std::to_string(b) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
      }
    return text + "sphere 0 0.5 0 0.4\n";
  };
  render("whitted-mesh-5000.test", grid(51), "");
  const std::size_t afterWalk = cacheEntries();
  EXPECT_GT(afterWalk, afterWhitted) << "the BVH-walking general variant left no entry of its own";
  render("whitted-mesh-2048.test", grid(33), "");
  EXPECT_EQ(cacheEntries(), afterWalk) << "the general Whitted variant was compiled again for a larger scene";
}

}  // namespace
}  // namespace vkrt
