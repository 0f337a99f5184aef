// The secondary-ray offset policy (doc/design.md, "The secondary-ray offsets"): objects, their
// offsets, the offsets lowered near smaller objects, and pictures that a vast floor must not change.
#include <cmath>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "gpu_types.h"
#include "scene/parse.h"
#include "scene/ray_offset.h"
#include "test_support.h"

using namespace vkrt;
using namespace vkrt::test;

namespace {

const double kCourse = gpu::kSecondaryRayTMin;

std::string header(const std::string& camera = "camera 0 3 3 0 0 0 0 1 0 40") {
  return "size 8 8\n" + camera + "\n";
}

// An axis-aligned box of 12 triangles sharing 8 vertices (indices from `first`).
std::string box(int first, double x0, double y0, double z0, double x1, double y1, double z1) {
  std::string s;
  for (int i = 0; i < 8; ++i)
    s += "vertex " + std::to_string(i & 1 ? x1 : x0) + " " + std::to_string(i & 2 ? y1 : y0) + " " +
         std::to_string(i & 4 ? z1 : z0) + "\n";
  const int faces[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const auto& f : faces)
    s += "tri " + std::to_string(first + f[0]) + " " + std::to_string(first + f[1]) + " " +
         std::to_string(first + f[2]) + "\n";
  return s;
}

// A square floor at y = 0, half as wide as `half`, two triangles sharing an edge (vertices
// from `first`).
std::string floorQuad(int first, double half) {
  std::string h = std::to_string(half);
  return "vertex -" + h + " 0 -" + h + "\nvertex " + h + " 0 -" + h + "\nvertex " + h + " 0 " + h + "\nvertex -" + h +
         " 0 " + h + "\ntri " + std::to_string(first) + " " + std::to_string(first + 2) + " " +
         std::to_string(first + 1) + "\ntri " + std::to_string(first) + " " + std::to_string(first + 3) + " " +
         std::to_string(first + 2) + "\n";
}

}  // namespace

TEST(RayOffset, ObjectsOfTheCourseSizesKeepTheCourseOffsetAndOthersScaleByDecades) {
  EXPECT_EQ(offsetForSize(gpu::kCourseSizeLow), kCourse);
  EXPECT_EQ(offsetForSize(1.5), kCourse) << "a 1.5-unit object is of the course's size";
  EXPECT_EQ(offsetForSize(gpu::kCourseSizeHigh), kCourse);
  EXPECT_DOUBLE_EQ(offsetForSize(0.3e-3), kCourse * 1e-3);
  EXPECT_DOUBLE_EQ(offsetForSize(30e4), kCourse * 1e4);
  EXPECT_DOUBLE_EQ(offsetForSize(0.1), kCourse * 0.1);
  EXPECT_DOUBLE_EQ(offsetForSize(283), kCourse * 10);
  EXPECT_EQ(offsetForSize(0.0), kCourse) << "a point has no size of its own";
}

TEST(RayOffset, TrianglesConnectedThroughSharedVerticesAreOneObject) {
  // One box (12 triangles), the same box again under another transform (its own object), a
  // quad whose two triangles share an edge, and a sphere: four objects.
  std::string s = header() + box(0, 0, 0, 0, 1, 1, 1) + "pushTransform\ntranslate 5 0 0\n" + box(0, 0, 0, 0, 1, 1, 1) +
                  "popTransform\n" + floorQuad(16, 2) + "sphere 0 3 0 0.5\n";
  PrimitiveOffsets o = primitiveOffsets(parseScene(s, "objects.test"));
  EXPECT_EQ(o.objects, 4);
  ASSERT_EQ(o.triangles.size(), 26u);
  for (double v : o.triangles) EXPECT_EQ(v, kCourse);
  // The same vertex positions written twice (a triangle soup) still join.
  std::string soup = header() + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n"
                                "tri 0 1 2\ntri 3 5 4\n";
  EXPECT_EQ(primitiveOffsets(parseScene(soup, "soup.test")).objects, 1);
}

// More vertex positions than the table of positions first holds (it grows on the way): 2,000
// separate triangles, then one that shares vertex positions with the first and the last of
// them, are 1,999 objects.
TEST(RayOffset, PositionsSeenBeforeTheTableGrewStillJoin) {
  std::string s = header();
  for (int i = 0; i < 2000; ++i) {
    const std::string x0 = std::to_string(3 * i), x1 = std::to_string(3 * i + 1);
    s += "vertex " + x0 + " 0 0\nvertex " + x1 + " 0 0\nvertex " + x0 + " 1 0\n";
    s += "tri " + std::to_string(3 * i) + " " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + "\n";
  }
  s += "tri 0 1 5997\n";
  EXPECT_EQ(primitiveOffsets(parseScene(s, "separate.test")).objects, 1999);
}

// One vast object must not change the offset of the small ones on it: a ground plane 20,000
// units wide under spheres of radius 0.1 to 0.5 and a small box.
TEST(RayOffset, AVastFloorTakesTheOffsetOfTheSmallObjectsOnIt) {
  std::string s = header() + floorQuad(0, 10000) + box(4, -0.3, 0, -0.3, 0.3, 0.6, 0.3) + "sphere 1 0.1 0 0.1\n" +
                  "sphere -1 0.5 0 0.5\nsphere 5000 1 5000 0.5\n";
  PrimitiveOffsets o = primitiveOffsets(parseScene(s, "vast.test"));
  EXPECT_EQ(o.objects, 5);
  EXPECT_EQ(o.triangles[0], kCourse) << "the floor, where small objects stand on it";
  EXPECT_EQ(o.triangles[1], kCourse);
  for (std::size_t i = 2; i < o.triangles.size(); ++i) EXPECT_EQ(o.triangles[i], kCourse) << "the box";
  for (double v : o.spheres) EXPECT_EQ(v, kCourse) << "the spheres keep their own";
  // Alone, the floor keeps its own scale's offset (1e-3 * 10^3 for a 28,284-unit diagonal).
  PrimitiveOffsets alone = primitiveOffsets(parseScene(header() + floorQuad(0, 10000), "alone.test"));
  EXPECT_DOUBLE_EQ(alone.triangles[0], offsetForSize(std::sqrt(8.0) * 10000));
  EXPECT_DOUBLE_EQ(alone.triangles[0], kCourse * 1e3);
  // A tiny object far off on the floor lowers the floor's offset, but not the other objects'.
  std::string tiny = header() + floorQuad(0, 10000) + "sphere 0 1 0 0.5\nsphere 9000 0 9000 1e-4\n";
  PrimitiveOffsets t = primitiveOffsets(parseScene(tiny, "tiny.test"));
  EXPECT_DOUBLE_EQ(t.triangles[0], offsetForSize(std::sqrt(12.0) * 1e-4));
  EXPECT_EQ(t.spheres[0], kCourse);
}

TEST(RayOffset, CourseScenesKeepTheCourseOffsetEverywhere) {
  std::optional<std::string> dir = cse167Dir();
  if (!dir) VKRT_SKIP_UNLESS_CI(kNoCse167Data);
  for (const char* name : {"scene1", "scene2", "scene3", "scene4-specular", "scene5", "scene6", "scene7"}) {
    PrimitiveOffsets o = primitiveOffsets(parseScene(readFile(*dir + "/scenes/" + name + ".test"), name));
    for (double v : o.triangles) ASSERT_EQ(v, kCourse) << name;
    for (double v : o.spheres) ASSERT_EQ(v, kCourse) << name;
  }
}

TEST(RayOffset, FarFromTheFrameOrTheCameraAndNearGrazingTheOffsetGrows) {
  auto at = [](dvec3 fromOrigin, dvec3 fromCamera, double cosine) {
    return secondaryRayOffsets(kCourse, fromOrigin, fromCamera).at(cosine);
  };
  EXPECT_EQ(at(dvec3(1, -2, 3), dvec3(0.5, 0, 0), 1.0), kCourse);
  EXPECT_NEAR(at(dvec3(0, -1e6, 3), dvec3(1, 1, 1), 1.0), 1e6 * gpu::kOffsetPerMagnitude, 1e-9);
  EXPECT_NEAR(at(dvec3(1, 1, 1), dvec3(0, 0, 2e6), 1.0), 2e6 * gpu::kOffsetPerMagnitude, 1e-9);
  // Nearly along the surface: 8 float32 ulps of the magnitude, over the cosine.
  EXPECT_EQ(at(dvec3(3, 0, 0), dvec3(5, 0, 0), 0.1), kCourse);
  EXPECT_DOUBLE_EQ(at(dvec3(3, 0, 0), dvec3(5, 0, 0), 1e-4), 5 * gpu::kGrazingPerMagnitude / 1e-4);
  EXPECT_TRUE(std::isfinite(at(dvec3(0), dvec3(0), 0.0)));
}

// Pictures: the same small objects on a floor that fills the view, once 20 units wide and
// once vast (20,000 units, or a unit quad under `scale 100` as people write walls), must look
// the same. Contacts: spheres of radius 0.1 to 0.5 resting on the floor, a box standing on
// it; the floor is a dim mirror, so the contact reflections show.
namespace {

std::string contactScene(const std::string& floor) {
  return "size 160 120\ncamera 0 2.2 2.2 0 0 0 0 1 0 40\nmaxdepth 3\n"
         "directional 1 2 1 0.5 0.5 0.5\npoint 0.5 1.5 1 0.6 0.6 0.6\n"
         "ambient 0.05 0.05 0.05\ndiffuse 0.3 0.3 0.3\nspecular 0.5 0.5 0.5\nshininess 40\n" +
         floor + "ambient 0.1 0.05 0.05\ndiffuse 0.7 0.2 0.2\nspecular 0 0 0\n" +
         box(4, -0.3, 0, -0.3, 0.3, 0.6, 0.3) +
         "diffuse 0.2 0.6 0.2\nsphere 0.8 0.1 0.2 0.1\nsphere -0.9 0.5 0 0.5\nsphere 0.4 0.25 -0.7 0.25\n"
         "pushTransform\ntranslate 0.3 0.15 0.7\nscale 2 1 1\nsphere 0 0 0 0.15\npopTransform\n";
}

struct VastFloor {
  const char* name;
  std::string floor;
};
void PrintTo(const VastFloor& v, std::ostream* os) { *os << v.name; }
class VastFloorChangesNothing : public ::testing::TestWithParam<VastFloor> {};

}  // namespace

// Tolerance: at most 0.1% of pixels (19 of 19,200) off by more than 2/255 (the floor's far
// edge is out of view in both).
TEST_P(VastFloorChangesNothing, OnEitherBackend) {
  SceneDesc small = parseScene(contactScene(floorQuad(0, 10)), "small-floor.test");
  SceneDesc vast = parseScene(contactScene(GetParam().floor), "vast-floor.test");
  const long long allowed = 160 * 120 / 1000;
  EXPECT_TRUE(imagesClose(std::string("vast-floor-cpu/") + GetParam().name, renderScene(vast), renderScene(small), 2,
                          allowed));
  VKRT_REQUIRE_GPU(context);
  EXPECT_TRUE(imagesClose(std::string("vast-floor-gpu/") + GetParam().name, renderGpu(vast), renderGpu(small), 2,
                          allowed));
}

INSTANTIATE_TEST_SUITE_P(
    Floors, VastFloorChangesNothing,
    ::testing::Values(VastFloor{"groundPlane20000", floorQuad(0, 10000)},
                      VastFloor{"unitQuadScaled100", "pushTransform\nscale 100 100 100\n" + floorQuad(0, 1) +
                                                         "popTransform\n"}),
    [](const auto& p) { return std::string(p.param.name); });
