// The shaders as embedded: the build's spirv-opt passes (cmake/embed_header.cmake) must keep
// the watertight triangle test's `precise` arithmetic (NoContraction decorations), without
// which the driver may fuse its multiply-adds and rays slip between triangles.
#include <cstddef>
#include <cstdint>

#include <gtest/gtest.h>

#include "pathtrace.comp.h"
#include "pathtrace_quad.comp.h"
#include "pathtrace_quad_texel.comp.h"
#include "pathtrace_texel.comp.h"
#include "raytrace.comp.h"
#include "raytrace_texel.comp.h"

namespace {

constexpr std::uint32_t kSpirvMagic = 0x07230203u;
constexpr std::uint32_t kOpDecorate = 71;
constexpr std::uint32_t kDecorationNoContraction = 42;

// NoContraction decorations in a SPIR-V module (words after the 5-word header; each
// instruction's first word holds its word count above its opcode). -1: not a valid stream.
int noContractionCount(const std::uint32_t* words, std::size_t bytes) {
  const std::size_t n = bytes / 4;
  if (n < 5 || words[0] != kSpirvMagic) return -1;
  int count = 0;
  for (std::size_t i = 5; i < n;) {
    const std::uint32_t length = words[i] >> 16, opcode = words[i] & 0xFFFFu;
    if (length == 0 || i + length > n) return -1;
    if (opcode == kOpDecorate && length >= 3 && words[i + 2] == kDecorationNoContraction) ++count;
    i += length;
  }
  return count;
}

}  // namespace

TEST(EmbeddedShaders, KeepThePreciseArithmeticOfTheWatertightTest) {
  // intersect.glsl's hitTriangle: six `precise` a - b * c (two operations each) and three
  // a * b - c * d (three each): at least 21 decorated operations in every shader.
  constexpr int kPreciseOperations = 6 * 2 + 3 * 3;
  EXPECT_GE(noContractionCount(kRaytraceSpirv, sizeof kRaytraceSpirv), kPreciseOperations);
  EXPECT_GE(noContractionCount(kRaytraceTexelSpirv, sizeof kRaytraceTexelSpirv), kPreciseOperations);
  EXPECT_GE(noContractionCount(kPathtraceSpirv, sizeof kPathtraceSpirv), kPreciseOperations);
  EXPECT_GE(noContractionCount(kPathtraceTexelSpirv, sizeof kPathtraceTexelSpirv), kPreciseOperations);
  EXPECT_GE(noContractionCount(kPathtraceQuadSpirv, sizeof kPathtraceQuadSpirv), kPreciseOperations);
  EXPECT_GE(noContractionCount(kPathtraceQuadTexelSpirv, sizeof kPathtraceQuadTexelSpirv), kPreciseOperations);
}
