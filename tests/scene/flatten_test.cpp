// Flattening and the BVH: layouts, values carried over, every primitive in exactly one leaf,
// and every box containing its contents.
#include <algorithm>
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "support/test_support.h"
#include "scene/flatten.h"
#include "scene/parse.h"
#include "scene/shapes/sphere.h"

using namespace vkrt;

namespace {

SceneDesc randomScene(int triangles, int spheres, unsigned seed) {
  std::string text = "size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\n";
  auto next = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return static_cast<double>(seed >> 8) / static_cast<double>(1u << 24) * 20.0 - 10.0;
  };
  for (int i = 0; i < triangles; ++i) {
    double x = next(), y = next(), z = next();
    for (int k = 0; k < 3; ++k)
      text += "vertex " + std::to_string(x + next() * 0.05) + " " + std::to_string(y + next() * 0.05) + " " +
              std::to_string(z + next() * 0.05) + "\n";
    text += "tri " + std::to_string(3 * i) + " " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + "\n";
  }
  for (int i = 0; i < spheres; ++i) {
    text += "pushTransform\nrotate 1 2 3 " + std::to_string(next() * 10) + "\nscale 1 2 0.5\n";
    text += "sphere " + std::to_string(next()) + " " + std::to_string(next()) + " " + std::to_string(next()) +
            " 0.3\npopTransform\n";
  }
  return parseScene(text, "random");
}

bool boxContains(const gpu::GpuBvhNode& n, const dvec3& lo, const dvec3& hi) {
  return n.minX <= lo.x && n.minY <= lo.y && n.minZ <= lo.z && n.maxX >= hi.x && n.maxY >= hi.y && n.maxZ >= hi.z;
}

TEST(Flatten, CarriesValuesIntoGpuLayouts) {
  SceneDesc s = parseScene(
      "size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\nattenuation 1 2 3\npoint 1 2 3 0.1 0.2 0.3\n"
      "directional 0 0 2 1 1 1\ndiffuse 0.5 0.25 0.125\nspecular 1 1 1\nshininess 12\n"
      "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\ntri 0 1 2\nvertexnormal 0 0 0 0 0 1\ntrinormal 0 0 0\n"
      "translate 1 0 0\nsphere 0 0 0 2\n",
      "t");
  GpuScene g = flatten(s);
  ASSERT_EQ(g.triangles.size(), 2u);
  EXPECT_EQ(g.triangles[0].normalsIndex, gpu::kNoNormals);
  EXPECT_EQ(g.triangles[1].normalsIndex, 0u);
  ASSERT_EQ(g.triangleNormals.size(), 1u);
  EXPECT_EQ(g.triangleNormals[0].n2.z, 1.0f);
  // Float32 coordinates are relative to the centre of the geometry's box, which the sphere
  // (radius 2 at x = 1) sets: (1, 0, 0).
  EXPECT_EQ(g.origin, dvec3(1.0, 0.0, 0.0));
  EXPECT_EQ(g.triangles[0].p1.x, 0.0f);
  EXPECT_EQ(g.triangles[0].p2.y, 1.0f);
  EXPECT_EQ(g.camera.origin.z, 5.0f);
  EXPECT_EQ(g.camera.origin.x, -1.0f);
  ASSERT_EQ(g.lights.size(), 2u);
  EXPECT_EQ(g.lights[0].kind, gpu::kLightPoint);
  EXPECT_EQ(g.lights[0].attenuation2, 3.0f);
  EXPECT_EQ(g.lights[1].kind, gpu::kLightDirectional);
  EXPECT_EQ(g.lights[1].positionOrDirection.z, 1.0f);   // normalised
  ASSERT_EQ(g.spheres.size(), 1u);
  EXPECT_EQ(g.spheres[0].centerRadius.w, 2.0f);
  EXPECT_EQ(g.spheres[0].objectFromWorld[3].x, 0.0f);   // inverse of translate 1 0 0, from the frame at x = 1
  const gpu::GpuMaterial& m = g.materials[g.triangles[0].materialIndex];
  EXPECT_EQ(m.diffuse.y, 0.25f);
  EXPECT_EQ(m.specular.w, 12.0f);
  EXPECT_EQ(m.ambient.x, 0.2f);
}

// Many triangles are converted in two halves on two threads: each triangle keeps its index
// and its own vertex normals, numbered in triangle order.
TEST(Flatten, ManyTrianglesKeepTheirOrderAndTheirNormals) {
  SceneDesc s = parseScene("size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\n", "many");
  for (int i = 0; i < 120000; ++i) {
    Triangle t;
    const double x = 0.001 * i;
    t.p[0] = dvec3(x, 0.0, 0.0);
    t.p[1] = dvec3(x + 1.0, 0.0, 0.0);
    t.p[2] = dvec3(x, 1.0, 0.0);
    t.smooth = i % 3 == 0;
    for (dvec3& n : t.n) n = glm::normalize(dvec3(1.0, static_cast<double>(i), 0.0));
    s.triangles.push_back(t);
  }
  GpuScene g = flatten(s);
  ASSERT_EQ(g.triangles.size(), s.triangles.size());
  ASSERT_EQ(g.triangleNormals.size(), 40000u);
  std::uint32_t next = 0;
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const gpu::GpuTriangle& t = g.triangles[i];
    ASSERT_EQ(t.p1.x, static_cast<float>(s.triangles[i].p[1].x - g.origin.x)) << "triangle " << i;
    if (!s.triangles[i].smooth) {
      ASSERT_EQ(t.normalsIndex, gpu::kNoNormals) << "triangle " << i;
      continue;
    }
    ASSERT_EQ(t.normalsIndex, next++) << "triangle " << i;
    ASSERT_EQ(g.triangleNormals[t.normalsIndex].n2.y, static_cast<float>(s.triangles[i].n[2].y)) << "triangle " << i;
  }
}

// Walks the tree with the chain of ancestors: every primitive (not dropped as degenerate) is
// in exactly one leaf of at most 4, inside every enclosing box. Returns the depth reached.
int checkTree(const SceneDesc& s, const Bvh& bvh) {
  std::vector<int> seen(s.triangles.size() + s.spheres.size(), 0);
  struct Item {
    std::uint32_t node;
    int depth;
  };
  std::vector<Item> stack{{0, 1}};
  std::vector<std::uint32_t> path(kMaxBvhDepth + 1);
  int maxDepth = 0;
  while (!stack.empty()) {
    Item it = stack.back();
    stack.pop_back();
    EXPECT_LE(it.depth, kMaxBvhDepth);
    if (it.depth > kMaxBvhDepth) return maxDepth;
    maxDepth = std::max(maxDepth, it.depth);
    path[it.depth - 1] = it.node;
    const gpu::GpuBvhNode& n = bvh.nodes[it.node];
    if (n.primCount == 0) {
      stack.push_back({n.leftOrFirst, it.depth + 1});
      stack.push_back({n.leftOrFirst + 1, it.depth + 1});
      continue;
    }
    EXPECT_LE(n.primCount, 4u);
    for (std::uint32_t i = 0; i < n.primCount; ++i) {
      std::uint32_t ref = bvh.primRefs[n.leftOrFirst + i];
      dvec3 lo, hi;
      std::size_t index;
      if (gpu::primKind(ref) == gpu::kPrimSphere) {
        index = s.triangles.size() + (gpu::primIndex(ref));
        shapes::bounds(s.spheres[gpu::primIndex(ref)], lo, hi);
      } else {
        index = ref;
        lo = glm::min(s.triangles[ref].p[0], glm::min(s.triangles[ref].p[1], s.triangles[ref].p[2]));
        hi = glm::max(s.triangles[ref].p[0], glm::max(s.triangles[ref].p[1], s.triangles[ref].p[2]));
      }
      ++seen[index];
      for (int d = 0; d < it.depth; ++d) EXPECT_TRUE(boxContains(bvh.nodes[path[d]], lo, hi)) << "prim " << ref;
    }
  }
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "primitive " << i;
  return maxDepth;
}

}  // namespace

TEST(Bvh, EveryPrimitiveInExactlyOneLeafInsideEveryEnclosingBox) {
  SceneDesc s = randomScene(3000, 200, 7);
  Bvh bvh = buildBvh(s);
  int maxDepth = checkTree(s, bvh);
  EXPECT_LT(maxDepth, 40);   // a balanced-ish tree for 3200 scattered primitives
  EXPECT_EQ(bvh.depth, maxDepth);
}

// The surface-area cost of the tree (one per interior node, a leaf's count, each weighted by
// its box's area relative to the root's): what a traversal expects to test per ray. Pins the
// tree's quality: a faster build must not make a worse tree.
TEST(Bvh, SurfaceAreaCostOfARandomSceneStaysAtTheBinnedSahTree) {
  SceneDesc s = randomScene(3000, 200, 7);
  Bvh bvh = buildBvh(s);
  auto area = [](const gpu::GpuBvhNode& n) {
    double x = n.maxX - n.minX, y = n.maxY - n.minY, z = n.maxZ - n.minZ;
    return 2.0 * (x * y + y * z + z * x);
  };
  double cost = 0.0;
  for (const gpu::GpuBvhNode& n : bvh.nodes) cost += area(n) / area(bvh.nodes[0]) * (n.primCount > 0 ? n.primCount : 1);
  EXPECT_LE(cost, 20.67);   // 20.667 with 16 bins, both for the sweep over all bins and the sparse one
  EXPECT_GT(cost, 15.0);    // (a much lower figure would mean that the cost is measured wrongly)
}

// Subtrees built on other threads are appended in the order one thread writes them.
TEST(Bvh, SameTreeForEveryThreadCount) {
  SceneDesc s = randomScene(30000, 50, 11);
  const Bvh one = buildBvh(s, dvec3(0.0), 1);
  checkTree(s, one);
  for (int threads : {2, 3, 8}) {
    const Bvh many = buildBvh(s, dvec3(0.0), threads);
    ASSERT_EQ(many.nodes.size(), one.nodes.size()) << threads << " threads";
    EXPECT_EQ(std::memcmp(many.nodes.data(), one.nodes.data(), one.nodes.size() * sizeof(gpu::GpuBvhNode)), 0)
        << threads << " threads";
    EXPECT_EQ(many.primRefs, one.primRefs) << threads << " threads";
    EXPECT_EQ(many.depth, one.depth) << threads << " threads";
  }
}

// Centroids that span the whole float range: a sum or difference of two of them overflows.
// The build once binned them through an undefined NaN-to-int conversion (found by the fuzzer).
TEST(Bvh, CoordinatesSpanningTheFloatRangeStillBuildAValidTree) {
  std::string text = "size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\n";
  int vertices = 0;
  for (double x : {-3.3e38, -3e38, -1e30, 0.0, 1.0, 1e30, 3e38, 3.3e38}) {
    for (int k = 0; k < 3; ++k) {
      double y = 10.0 * k;
      text += "vertex " + std::to_string(x) + " " + std::to_string(y) + " 0\nvertex " + std::to_string(x) + " " +
              std::to_string(y + 1) + " 1\nvertex " + std::to_string(x * 0.999) + " " + std::to_string(y) + " 1\n";
      text += "tri " + std::to_string(vertices) + " " + std::to_string(vertices + 1) + " " +
              std::to_string(vertices + 2) + "\n";
      vertices += 3;
    }
  }
  SceneDesc s = parseScene(text, "float-range");
  Bvh bvh = buildBvh(s);
  checkTree(s, bvh);
  EXPECT_GT(bvh.nodes.size(), 1u);   // it split, rather than give up on one leaf
}

TEST(Bvh, IdenticalPrimitivesStillSplit) {
  std::string text = "size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n";
  for (int i = 0; i < 1000; ++i) text += "tri 0 1 2\n";
  Bvh bvh = buildBvh(parseScene(text, "same"));
  for (const auto& n : bvh.nodes) EXPECT_LE(n.primCount, 4u);
}

TEST(Bvh, EmptySceneHasOneEmptyLeaf) {
  Bvh bvh = buildBvh(parseScene("size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\n", "empty"));
  ASSERT_EQ(bvh.nodes.size(), 1u);
  EXPECT_EQ(bvh.nodes[0].primCount, 0u);
  EXPECT_GT(bvh.nodes[0].minX, bvh.nodes[0].maxX);   // inverted box: nothing enters
}

// The exactness cut-off's bound per channel: one hit's ambient + emission + every light at
// full strength times (diffuse + specular); +infinity where a light has no bound, but a zero
// factor keeps its channel finite; a negative attenuation term makes the bound two-sided.
TEST(Flatten, CutoffBoundFollowsTheLights) {
  auto bound = [](const std::string& lights, dvec3 attenuation = dvec3(0.0)) {
    SceneDesc s = parseScene("size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\nambient 0.1 0.1 0.1\n" + lights +
                                 "diffuse 0.5 0.5 0.5\nspecular 0.25 0.25 0.25\nsphere 0 0 0 1\n",
                             "bound.test");
    if (attenuation != dvec3(0.0)) s.lights[0].attenuation = attenuation;   // (the parser refuses these)
    return flatten(s).cutoff.bound;
  };
  gpu::vec4 b = bound("attenuation 2 1 1\npoint 0 0 3 1 2 0\ndirectional 0 0 1 1 1 1\n");
  EXPECT_FLOAT_EQ(b.x, 0.1f + (0.5f + 1.0f) * 0.75f);
  EXPECT_FLOAT_EQ(b.y, 0.1f + (1.0f + 1.0f) * 0.75f);
  EXPECT_FLOAT_EQ(b.z, 0.1f + 1.0f * 0.75f);
  EXPECT_EQ(b.w, 1.0f);
  b = bound("attenuation 0 0 1\npoint 0 0 3 1 0 0\n");   // no constant term: red unbounded
  EXPECT_TRUE(std::isinf(b.x));
  EXPECT_FLOAT_EQ(b.y, 0.1f);
  EXPECT_FLOAT_EQ(b.z, 0.1f);
  b = bound("point 0 0 3 1 1 1\n", dvec3(1, -0.5, 0));   // the divisor crosses 0
  EXPECT_TRUE(std::isinf(b.x) && std::isinf(b.y) && std::isinf(b.z));
  EXPECT_EQ(b.w, 0.0f) << "a negative term can make the light negative";
}

// The path integrators' data: quad lights in the scene-centred frame with their area and
// normal, the material w fields, and the settings in the shader's ids.
TEST(Flatten, QuadLightsMaterialFieldsAndPathSettings) {
  SceneDesc s = parseScene("size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\nvertex 10 0 0\nvertex 12 0 0\nvertex 10 2 0\n"
                           "tri 0 1 2\n",
                           "t.test");
  Material ggx = s.materials.at(0);
  ggx.brdf = BrdfModel::Ggx;
  ggx.roughness = 0.25;
  s.materials.push_back(ggx);
  Material light;
  light.emission = dvec3(5, 4, 3);
  light.quadLight = 0;
  s.materials.push_back(light);
  QuadLight q;
  q.a = dvec3(10, 3, 0);
  q.ab = dvec3(0, 0, 2);
  q.ac = dvec3(3, 0, 0);
  q.radiance = dvec3(5, 4, 3);
  s.quadLights.push_back(q);
  s.maxDepth = -1;
  s.path.integrator = Integrator::PathTracer;
  s.path.nextEvent = NextEvent::Mis;
  s.path.sampling = Sampling::Brdf;
  s.path.russianRoulette = true;
  s.path.lightSamples = 9;
  s.path.lightStratify = true;
  s.path.spp = 16;
  GpuScene g = flatten(s);
  ASSERT_EQ(g.quadLights.size(), 1u);
  const gpu::GpuQuadLight& gq = g.quadLights[0];
  EXPECT_FLOAT_EQ(gq.corner.x, static_cast<float>(10 - g.origin.x));
  EXPECT_FLOAT_EQ(gq.corner.y, static_cast<float>(3 - g.origin.y));
  EXPECT_FLOAT_EQ(gq.corner.w, 6.0f);                          // area
  EXPECT_EQ(gq.normal.y, -1.0f);                               // normalize(cross(ac, ab))
  EXPECT_EQ(gq.edgeAB.z, 2.0f);
  EXPECT_EQ(gq.radiance.x, 5.0f);
  EXPECT_EQ(g.materials[0].ambient.w, gpu::kBrdfPhong);
  EXPECT_EQ(g.materials[0].emission.w, gpu::kNoQuadLight);
  EXPECT_EQ(g.materials[1].ambient.w, gpu::kBrdfGgx);
  EXPECT_EQ(g.materials[1].diffuse.w, 0.25f);
  EXPECT_EQ(g.materials[2].emission.w, 0.0f);
  EXPECT_EQ(g.path.integrator, gpu::kIntegratorPathTracer);
  EXPECT_EQ(g.path.nextEvent, gpu::kNextEventMis);
  EXPECT_EQ(g.path.sampling, gpu::kSamplingBrdf);
  EXPECT_EQ(g.path.russianRoulette, 1u);
  EXPECT_EQ(g.path.maxDepth, gpu::kUnlimitedDepth);
  EXPECT_EQ(g.path.lightSamples, 9u);
  EXPECT_EQ(g.path.lightStrata, 3u);
  EXPECT_EQ(g.path.quadLightCount, 1u);
  EXPECT_EQ(g.spp, 16u);
  EXPECT_EQ(g.path.camera.origin.x, g.camera.origin.x);
}

// The emitter table: emissive triangles and spheres (not a quad light's triangles, not
// non-emitters), triangles first, picked in proportion to area x sum(|emission|), with the
// cumulative probabilities in float and 1 / the total weight.
TEST(Flatten, EmitterTableWeighsAreaTimesEmission) {
  SceneDesc s = parseScene("size 8 8\ncamera 0 0 5 0 0 0 0 1 0 45\nvertex 0 0 0\nvertex 2 0 0\nvertex 0 2 0\n"
                           "tri 0 1 2\n"                       // material 0: no emission
                           "emission 1 2 -1\ntri 0 1 2\n"      // area 2, weight 2 x 4
                           "pushTransform\nscale 2 2 2\nsphere 0 0 0 0.5\npopTransform\n"   // area 4 pi, weight 4 pi x 4
                           "emission 0 0 0\nsphere 3 0 0 1\n",
                           "e.test");
  Material light;
  light.emission = dvec3(5, 4, 3);
  light.quadLight = 0;
  s.materials.push_back(light);
  Triangle quadHalf = s.triangles[0];
  quadHalf.material = static_cast<std::uint32_t>(s.materials.size() - 1);
  s.triangles.push_back(quadHalf);
  QuadLight q;
  q.radiance = dvec3(5, 4, 3);
  s.quadLights.push_back(q);
  GpuScene g = flatten(s);
  ASSERT_EQ(g.emitters.size(), 2u);
  EXPECT_EQ(g.path.emitterCount, 2u);
  EXPECT_EQ(g.emitters[0].primRef, 1u);
  EXPECT_EQ(g.emitters[1].primRef, gpu::primRef(gpu::kPrimSphere, 0u));
  const double pi = 3.14159265358979323846, total = 8.0 + 16.0 * pi;
  EXPECT_FLOAT_EQ(g.emitters[0].cdf, static_cast<float>(8.0 / total));
  EXPECT_EQ(g.emitters[1].cdf, 1.0f);
  EXPECT_FLOAT_EQ(g.path.emitterWeightScale, static_cast<float>(1.0 / total));
  // No emitters: an empty table.
  EXPECT_TRUE(flatten(randomScene(10, 3, 7)).emitters.empty());
}

// The SAH's trade of a traversal step against primitive tests (bvh.cpp, kTraversalCost = 1, one
// primitive test's cost), in closed form on two unit spheres (cube boxes of area 24) d apart
// along x, whose parent box has area 24 + 8d: the two split when 2 > cost + 48 / (24 + 8d).
// Touching (d = 2: 48 / 40 = 1.2) they stay one leaf for any cost of at least 0.8; 100 apart
// (48 / 824) they split for any cost below 1.94.
TEST(Bvh, TwoSpheresSplitOrShareALeafAsTheTraversalCostSays) {
  const Bvh touching = buildBvh(test::parseBody("sphere 0 0 0 1\nsphere 2 0 0 1\n"));
  EXPECT_EQ(touching.nodes.size(), 1u);
  EXPECT_EQ(touching.nodes[0].primCount, 2u);
  const Bvh apart = buildBvh(test::parseBody("sphere 0 0 0 1\nsphere 100 0 0 1\n"));
  ASSERT_EQ(apart.nodes.size(), 3u);
  EXPECT_EQ(apart.nodes[0].primCount, 0u);
  EXPECT_EQ(apart.nodes[1].primCount + apart.nodes[2].primCount, 2u);
}
