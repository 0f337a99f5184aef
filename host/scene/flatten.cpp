// SceneDesc -> GpuScene. The only place where double-precision scene data becomes float32 (a
// shape's by its toGpu, in its own file, the triangles' here), and where the world is moved
// into the float32 frame (ray_offset.h, floatFrameOrigin and floatFrameScale; in double,
// before rounding): the origin at the centre of the scene's geometry (or at the camera, when
// a far object would put that centre far from what the camera sees nearby), and lengths
// multiplied by a power of two that brings a vast or tiny scene's size near 1. Float32 then
// sees the same numbers wherever the scene is and however large it is; a power of two
// changes no rounding, so a scene of ordinary size (scale 1) and the same scene scaled by 2^k
// give the same bits.
#include "scene/flatten.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>

#include "scene/emitters.h"
#include "scene/ray_offset.h"
#include "scene/unit_vector.h"

namespace vkrt {
namespace {

// Triangles are converted on two threads from this many on.
constexpr std::size_t kParallelMinTriangles = 50000;

gpu::vec4 f4(const dvec3& v, float w = 0.0f) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), w};
}

// The camera basis in double, then float: a per-pixel step right and up, and the back vector.
gpu::GpuCamera cameraConstants(const SceneDesc& scene, const dvec3& origin, double scale) {
  const Camera& c = scene.camera;
  dvec3 w = unitVector(c.from - c.at);
  dvec3 u = unitVector(glm::cross(scaledForSquares(c.up), w));
  dvec3 v = glm::cross(w, u);
  double tanY = std::tan(glm::radians(c.fovyDegrees) / 2.0);
  double tanX = tanY * scene.width / scene.height;
  gpu::GpuCamera p{};
  p.origin = f4((c.from - origin) * scale);
  p.right = f4(u * (tanX / (scene.width / 2.0)));
  p.up = f4(v * (tanY / (scene.height / 2.0)));
  p.back = f4(w);
  return p;
}

// The exactness cut-off's bounds (gpu_types.h, GpuCutoff): what one hit can send at
// most, per channel, in absolute value, and the largest mirror weight. A channel without a
// bound is +infinity, and the shader never cuts a path by it. Unbounded are: a point light
// whose attenuation divisor c0 + c1 r + c2 r^2 can come near 0 for some r >= 0 (c0 = 0, or a
// negative coefficient), and sums beyond float. A zero factor stays an exact 0 (never
// 0 * infinity, which is NaN and which max() would drop, leaving an unbounded light out).
gpu::GpuCutoff cutoffConstants(const SceneDesc& scene) {
  bool nonNegative = true;
  auto track = [&nonNegative](const dvec3& c) {
    nonNegative = nonNegative && c.x >= 0.0 && c.y >= 0.0 && c.z >= 0.0;
    return glm::abs(c);
  };
  auto product = [](const dvec3& a, const dvec3& b) {
    dvec3 r;
    for (int c = 0; c < 3; ++c) r[c] = a[c] == 0.0 || b[c] == 0.0 ? 0.0 : a[c] * b[c];
    return r;
  };
  dvec3 lightSum(0.0);
  for (const Light& l : scene.lights) {
    bool keepsSign = true;
    const double strongest = strongestDivisorInverse(l, keepsSign);   // the largest 1 / attenuation divisor
    nonNegative = nonNegative && keepsSign;
    lightSum += product(track(l.color), dvec3(strongest));
  }
  dvec3 bound(0.0), specular(0.0);
  for (const Material& m : scene.materials) {
    // N.L <= 1 and max(N.H, 0)^s <= 1, also for s = 0 (the shader clamps N.H to [0, 1]).
    dvec3 hit = track(m.ambient) + track(m.emission) + product(lightSum, track(m.diffuse) + track(m.specular));
    bound = glm::max(bound, hit);
    specular = glm::max(specular, glm::abs(m.specular));
  }
  // Beyond float: +infinity, "no bound" (the shader then never cuts by that channel).
  auto toFloat = [](double v) {
    return v < double{std::numeric_limits<float>::max()} ? static_cast<float>(v) : std::numeric_limits<float>::infinity();
  };
  gpu::GpuCutoff p{};
  p.bound = {toFloat(bound.x), toFloat(bound.y), toFloat(bound.z), nonNegative ? 1.0f : 0.0f};
  p.specular = {toFloat(specular.x), toFloat(specular.y), toFloat(specular.z), 0.0f};
  return p;
}

// Triangles [begin, end) into their GPU layout at the same indices; the normals of smooth
// ones are appended to `normals`, their normalsIndex counted from its size.
void convertTriangles(const std::vector<Triangle>& triangles, const dvec3& origin, double scale,
                      const std::vector<double>& offsets, std::size_t begin, std::size_t end,
                      std::vector<gpu::GpuTriangle>& out, std::vector<gpu::GpuTriangleNormals>& normals) {
  for (std::size_t i = begin; i < end; ++i) {
    const Triangle& t = triangles[i];
    gpu::GpuTriangle gt{};
    gt.rayOffset = static_cast<float>(offsets[i] * scale);
    // The plane, in double: the shader measures t from it, so that a vast triangle's float32
    // corners do not make its hits less exact than the ray's own origin allows.
    const dvec3 a = (t.p[0] - origin) * scale, b = (t.p[1] - origin) * scale, c = (t.p[2] - origin) * scale;
    dvec3 normal = glm::cross(b - a, c - a);
    const double area2 = glm::length(normal);
    normal = area2 > 0.0 && std::isfinite(area2) ? normal / area2 : dvec3(0.0);
    gt.p0 = f4(a, static_cast<float>(normal.x));
    gt.p1 = f4(b, static_cast<float>(normal.y));
    gt.p2 = f4(c, static_cast<float>(normal.z));
    const dvec3 normalAsStored(gt.p0.w, gt.p1.w, gt.p2.w);
    gt.planeOffset = static_cast<float>(glm::dot(normalAsStored, a));
    gt.materialIndex = t.material;
    gt.normalsIndex = gpu::kNoNormals;
    if (t.smooth) {
      gt.normalsIndex = static_cast<gpu::uint>(normals.size());
      normals.push_back({f4(t.n[0]), f4(t.n[1]), f4(t.n[2])});
    }
    out[i] = gt;
  }
}

// Every shape of one kind into its GPU layout, at the same indices: the shape's toGpu, given
// its offset (ray_offset.h) in world units.
template <class Shape, class GpuShape>
void convertKind(const std::vector<Shape>& shapes, const std::vector<double>& offsets, const dvec3& origin,
                 double scale, std::vector<GpuShape>& out, std::vector<gpu::GpuTriangleNormals>&) {
  out.reserve(shapes.size());
  for (std::size_t i = 0; i < shapes.size(); ++i) out.push_back(shapes::toGpu(shapes[i], origin, scale, offsets[i]));
}

// The triangles, and the normals of the smooth ones: in two halves, the second on another
// thread when there are many; each half numbers its smooth triangles' normals from 0, and the
// second's are moved after the first's.
void convertKind(const std::vector<Triangle>& triangles, const std::vector<double>& offsets, const dvec3& origin,
                 double scale, std::vector<gpu::GpuTriangle>& out, std::vector<gpu::GpuTriangleNormals>& normals) {
  const std::size_t nt = triangles.size();
  out.resize(nt);
  std::vector<gpu::GpuTriangleNormals> secondNormals;
  const std::size_t half = nt >= kParallelMinTriangles ? nt / 2 : nt;
  auto secondHalf = std::async(nt >= kParallelMinTriangles ? std::launch::async : std::launch::deferred,
                               [&] { convertTriangles(triangles, origin, scale, offsets, half, nt, out, secondNormals); });
  convertTriangles(triangles, origin, scale, offsets, 0, half, out, normals);
  secondHalf.get();
  if (!secondNormals.empty()) {
    const auto shift = static_cast<gpu::uint>(normals.size());
    for (std::size_t i = half; i < nt; ++i)
      if (out[i].normalsIndex != gpu::kNoNormals) out[i].normalsIndex += shift;
    normals.insert(normals.end(), secondNormals.begin(), secondNormals.end());
  }
}

// Every array of `g` but the BVH, in the frame of g.origin and g.scale: the shapes, their
// ray offsets and smooth normals, the lights, materials and quad lights, the emitters and the
// path integrators' parameters.
void makeArrays(const SceneDesc& scene, GpuScene& g) {
  const dvec3 origin = g.origin;
  const double scale = g.scale;
  const PrimitiveOffsets offsets = primitiveOffsets(scene);
#define VKRT_SHAPE_CONVERT(Type, member, name, kind, GpuType, binding) \
  convertKind(scene.member, offsets.member, origin, scale, g.member, g.triangleNormals);
  VKRT_SHAPES(VKRT_SHAPE_CONVERT)
#undef VKRT_SHAPE_CONVERT
  for (const Light& l : scene.lights) g.lights.push_back(toGpu(l, origin, scale));
  for (const Material& m : scene.materials) {
    g.materials.push_back({f4(m.ambient, m.brdf == BrdfModel::Ggx ? gpu::kBrdfGgx : gpu::kBrdfPhong),
                           f4(m.diffuse, static_cast<float>(m.roughness)),
                           f4(m.specular, static_cast<float>(m.shininess)),
                           f4(m.emission, m.quadLight >= 0 ? static_cast<float>(m.quadLight) : gpu::kNoQuadLight)});
  }
  for (const QuadLight& q : scene.quadLights) {
    const dvec3 ab = q.ab * scale, ac = q.ac * scale;
    const dvec3 across = glm::cross(ac, ab);   // |cross(ac, ab)| = |cross(ab, ac)|: the area
    const double area = glm::length(across);
    gpu::GpuQuadLight gq{};
    gq.corner = f4((q.a - origin) * scale, static_cast<float>(area));
    gq.edgeAB = f4(ab);
    gq.edgeAC = f4(ac);
    gq.normal = f4(area > 0.0 ? across / area : dvec3(0.0));
    gq.radiance = f4(q.radiance);
    g.quadLights.push_back(gq);
  }
  g.path = pathParams(scene, g.camera);
  const EmitterTable table = collectEmitters(scene);
  for (std::size_t e = 0; e < table.prims.size(); ++e)
    g.emitters.push_back({table.prims[e], static_cast<float>(table.cdf[e])});
  g.path.emitterCount = static_cast<gpu::uint>(g.emitters.size());
  // The weights are areas (times emission): in the frame's units, scale^2 times the world's.
  g.path.emitterWeightScale =
      g.emitters.empty() ? 0.0f : static_cast<float>(1.0 / table.totalWeight / scale / scale);
  g.spp = static_cast<std::uint32_t>(std::max(scene.path.spp, 1));
}

}  // namespace

// The settings of doc/path-tracing.md, "Commands" in the shader's terms, and the camera.
gpu::GpuPathParams pathParams(const SceneDesc& scene, const gpu::GpuCamera& camera) {
  const PathSettings& s = scene.path;
  gpu::GpuPathParams p{};
  p.camera = camera;
  p.integrator = static_cast<gpu::uint>(s.integrator);   // the GPU id (integrator_table.h)
  p.nextEvent = s.nextEvent == NextEvent::On ? gpu::kNextEventOn
                : s.nextEvent == NextEvent::Mis ? gpu::kNextEventMis
                                                : gpu::kNextEventOff;
  p.sampling = s.sampling == Sampling::Brdf ? gpu::kSamplingBrdf
               : s.sampling == Sampling::Cosine ? gpu::kSamplingCosine
                                                : gpu::kSamplingHemisphere;
  p.russianRoulette = s.russianRoulette ? 1u : 0u;
  p.maxDepth = scene.maxDepth < 0 ? gpu::kUnlimitedDepth : static_cast<gpu::uint>(scene.maxDepth);
  p.lightSamples = static_cast<gpu::uint>(std::max(s.lightSamples, 1));
  // The parser accepts `lightstratify on` only with a perfect square.
  p.lightStrata = s.lightStratify ? static_cast<gpu::uint>(std::lround(std::sqrt(double(p.lightSamples)))) : 0u;
  p.quadLightCount = static_cast<gpu::uint>(scene.quadLights.size());
  p.lightCount = static_cast<gpu::uint>(scene.lights.size());
  return p;
}

GpuScene flatten(const SceneDesc& scene, const std::function<void(const GpuScene&)>& arraysMade) {
  GpuScene g;
  g.width = static_cast<std::uint32_t>(scene.width);
  g.height = static_cast<std::uint32_t>(scene.height);
  g.maxDepth = static_cast<std::uint32_t>(scene.maxDepth);
  const dvec3 origin = floatFrameOrigin(scene);
  const double scale = floatFrameScale(scene, origin);
  g.origin = origin;
  g.scale = scale;
  g.camera = cameraConstants(scene, origin, scale);
  g.cutoff = cutoffConstants(scene);
  checkPrimitiveCounts(scene);   // (before any array: too many of a kind is an error at once)
  // Every array but the BVH on another thread, while this one builds the BVH; then
  // `arraysMade` there, while the BVH may still build. The two write different members of g.
  // (The peak of memory then holds the BVH's build records, 32 bytes a primitive, beside the
  // converted arrays.)
  std::future<void> arrays = std::async(std::launch::async, [&] {
    makeArrays(scene, g);
    if (arraysMade) arraysMade(g);
  });
  g.bvh = buildBvh(scene, origin, 0, scale);
  arrays.get();
  return g;
}

}  // namespace vkrt
