// CPU reference renderer. Double precision throughout; a plain loop over the mirror bounces
// (the shader's is a suspendable state machine in float, written apart on purpose).
#include "cpu/reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cpu/pixel_tiles.h"
#include "cpu/scene_query.h"
#include "scene/unit_vector.h"

namespace vkrt {
namespace {

constexpr double kInf = kInfinity;

class Tracer {
 public:
  Tracer(const SceneDesc& scene, const Bvh& bvh) : scene_(scene), query_(scene, bvh) {}

  bool intersect(const Ray& ray, double tMin, double tMax, bool anyHit, Hit& hit) const {
    return query_.intersect(ray, tMin, tMax, anyHit, hit);
  }

  // A hit's own colour, everything of doc/scene-format.md, "Shading" but the mirror term: A + Em + the lights, each
  // behind its shadow ray (which starts `offset` from p).
  dvec3 localShading(const Material& m, const dvec3& p, const dvec3& normal, const dvec3& eye,
                     const SecondaryRayOffsets& offset,
                     RayCounts& counts) const {
    dvec3 color = m.ambient + m.emission;
    for (const Light& light : scene_.lights) {
      LightArrival arrival;
      if (!arrivalAt(light, p, arrival)) continue;
      const dvec3& toLight = arrival.toLight;
      const double distance = arrival.distance, divisor = arrival.divisor;
      double nDotL = glm::dot(normal, toLight);
      if (nDotL <= 0.0) continue;   // doc/scene-format.md, "Conventions": no diffuse and no specular from behind
      ++counts.shadow;
      Hit blocker;
      if (intersect({p, toLight}, offset.at(nDotL), distance, true, blocker)) continue;
      dvec3 half = glm::normalize(toLight + eye);
      double nDotH = std::max(glm::dot(normal, half), 0.0);
      // pow(0, 0) = 1 (C's definition; the shader states the same).
      dvec3 lit = m.diffuse * nDotL + m.specular * std::pow(nDotH, m.shininess);
      // Finite even for a tiny divisor, so that a zero material term times it stays 0, not NaN.
      constexpr double kMax = std::numeric_limits<double>::max();
      color += glm::clamp(light.color / divisor, dvec3(-kMax), dvec3(kMax)) * lit;
    }
    return color;
  }

  // The colour seen along a camera ray: doc/scene-format.md, "Shading" with the mirror term unrolled into a
  // loop. Segment k adds throughput_k * local_k, where local_k is its hit's own shading and
  // throughput_k the product of the specular colours of the k hits before it, so
  //   radiance = local_0 + s_0 local_1 + s_0 s_1 local_2 + ...   (at most maxDepth + 1 segments)
  // which is the recursion I = local + S * I_R of doc/scene-format.md, "Shading", evaluated from the front (rounded
  // unlike the nested form only in the last bits: every course and project scene gives the
  // same bytes either way). The loop needs no stack, so every maxdepth the parser accepts
  // (up to 1,000,000) is safe.
  dvec3 trace(Ray ray, RayCounts& counts) const {
    dvec3 radiance(0.0), throughput(1.0);
    double tMin = 0.0;   // the primary ray starts at the camera; secondary rays at their offset
    for (int depth = 0;; ++depth) {
      Hit hit;
      if (!intersect(ray, tMin, kInf, false, hit)) break;   // a miss is black
      dvec3 p = ray.origin + hit.t * ray.dir;
      dvec3 normal;
      std::uint32_t materialIndex = query_.surfaceAt(hit, p, normal);
      const Material& m = scene_.materials[materialIndex];
      const SecondaryRayOffsets offset = query_.offsetsAt(hit, p);
      radiance += throughput * localShading(m, p, normal, -ray.dir, offset, counts);
      // Possibly continue along the mirror direction.
      if (depth >= scene_.maxDepth || m.specular == dvec3(0.0)) break;
      ++counts.secondary;
      throughput *= m.specular;
      dvec3 r = ray.dir - 2.0 * glm::dot(ray.dir, normal) * normal;
      ray = {p, glm::normalize(r)};
      tMin = offset.at(std::abs(glm::dot(ray.dir, normal)));
    }
    return radiance;
  }

  // doc/scene-format.md, "Camera": the ray through the centre of pixel (column, row).
  Ray cameraRay(int column, int row) const { return query_.cameraRay(column + 0.5, row + 0.5); }

 private:
  const SceneDesc& scene_;
  SceneQuery query_;
};

}  // namespace

RadianceImage shadeEachPixelOnce(const SceneDesc& scene, const CpuOptions& options,
                                 const std::function<dvec3(int x, int y, RayCounts& counts)>& shade,
                                 RayCounts* counts) {
  const PixelRect region = options.crop ? *options.crop : PixelRect{0, 0, scene.width, scene.height};
  if (!options.rows) {
    RadianceImage image(region.width(), region.height());
    image.samples = options.sampleCount;   // the mean of identical samples is the one traced
    shadeTiles(region, options.threads, 1, shade, image, options.progress, options.stop, counts);
    return image;
  }
  // Bands of about bandPixels pixels, a multiple of the 16-row tiles: a million gives every
  // thread tiles enough to share, in 12 MB of floats.
  const std::size_t perRow = static_cast<std::size_t>(std::max(1, region.width()));
  const int bandRows =
      static_cast<int>(std::clamp<std::size_t>((options.bandPixels / perRow + 15) / 16 * 16, 16, 1 << 16));
  const std::uint64_t total = static_cast<std::uint64_t>(region.width()) * static_cast<std::uint64_t>(region.height());
  RayCounts all;
  RadianceImage band;
  for (int y0 = region.y0; y0 < region.y1; y0 += bandRows) {
    if (options.stop && options.stop()) break;
    const PixelRect rows{region.x0, y0, region.x1, std::min(y0 + bandRows, region.y1)};
    if (band.height != rows.height()) band = RadianceImage(rows.width(), rows.height());
    band.samples = options.sampleCount;
    const std::uint64_t before =
        static_cast<std::uint64_t>(y0 - region.y0) * static_cast<std::uint64_t>(region.width());
    std::function<void(std::uint64_t, std::uint64_t)> progress;
    if (options.progress)
      progress = [&](std::uint64_t done, std::uint64_t) { options.progress(before + done, total); };
    RayCounts bandCounts;
    shadeTiles(rows, options.threads, 1, shade, band, progress, options.stop, &bandCounts);
    all += bandCounts;
    if (options.stop && options.stop()) break;   // the band may be incomplete
    options.rows(y0 - region.y0, band);
  }
  if (counts) *counts = all;
  RadianceImage empty;
  empty.samples = options.sampleCount;
  return empty;
}

RadianceImage renderReference(const SceneDesc& scene, const Bvh& bvh, const CpuOptions& options,
                              RayCounts* counts) {
  Tracer tracer(scene, bvh);
  return shadeEachPixelOnce(
      scene, options,
      [&](int x, int y, RayCounts& local) {
        ++local.primary;
        return tracer.trace(tracer.cameraRay(x, y), local);
      },
      counts);
}

}  // namespace vkrt
