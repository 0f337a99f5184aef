// The path integrators on the CPU. One path's loop follows pbrt-v4's PathIntegrator::Li: the
// throughput `beta`, next-event estimation at each vertex, BRDF sampling for the next
// direction, MIS weights by the power heuristic, then Russian roulette. Double precision; the
// random numbers are gpu_rng.h's, drawn by the rules of doc/design.md, "Random numbers and
// sampling rules".
#include "cpu/path_reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "cpu/path_brdf.h"
#include "cpu/pixel_tiles.h"
#include "cpu/sample_numbers.h"
#include "cpu/scene_query.h"
#include "gpu_types.h"
#include "scene/emitters.h"
#include "scene/shapes/shape.h"
#include "scene/unit_vector.h"

namespace vkrt {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A quad light as the integrators sample it.
struct AreaLight {
  dvec3 a, ab, ac;
  dvec3 normal;            // n_L = normalize(cross(ac, ab)): the emitting side
  double area = 0.0;       // |cross(ab, ac)|
  dvec3 radiance;
  int triangle = -1;       // one of its two triangles (for the shadow rays' offset at its end), or -1
};

// Emissive triangles and spheres (`emission`, not quad lights) as one more light for
// next-event estimation (beyond the course): each light sample picks one of them with
// probability proportional to area x sum(|emission|) (scene/emitters.h), then a point on it,
// by the rules and from the slots of gpu_types.h (sample_numbers.h: emitterPointSlot, emitterPickSlot),
// the point as its shape samples one (scene/shapes/shape.h: samplePoint, densityAt).

// A scattering point of a path.
struct Vertex {
  dvec3 p, n, wo;          // point, unit normal (not flipped), unit direction toward the viewer
  const Material* m;
  SecondaryRayOffsets offset;
};

class PathIntegrator {
 public:
  // `stop` (may be empty) is polled every kLightSamplesPerPoll light samples of a vertex, so
  // that a scene of many light samples stops within a pixel (the image then incomplete).
  PathIntegrator(const SceneDesc& scene, const Bvh& bvh, const std::function<bool()>& stop)
      : scene_(scene), query_(scene, bvh), stop_(stop) {
    for (const QuadLight& q : scene.quadLights) {
      dvec3 c = glm::cross(q.ac, q.ab);
      lights_.push_back({q.a, q.ab, q.ac, glm::normalize(c), glm::length(c), q.radiance, -1});
    }
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
      int j = scene.materials[scene.triangles[i].material].quadLight;
      if (j >= 0 && j < static_cast<int>(lights_.size()) && lights_[j].triangle < 0) lights_[j].triangle = static_cast<int>(i);
    }
    collectEmitters();
  }

  // The radiance of one camera sample through image position (px, py).
  dvec3 sampleRadiance(double px, double py, const SampleNumbers& rng, RayCounts& counts) const {
    ++counts.primary;
    const Ray ray = query_.cameraRay(px, py);
    switch (scene_.path.integrator) {
      case Integrator::AnalyticDirect: return analyticDirect(ray);
      case Integrator::Direct: return direct(ray, rng, counts);
      case Integrator::PathTracer: break;
      case Integrator::Raytracer: break;   // never here: renderPathReference refuses it
    }
    return path(ray, rng, counts);
  }

 private:
  // The emissive triangles and spheres, and the probability with which a light sample picks each.
  void collectEmitters() {
    const EmitterTable table = vkrt::collectEmitters(scene_);
    emitters_ = table.prims;
    emitterCdf_ = table.cdf;
    for (std::uint32_t kind = 0; kind < shapes::kKinds; ++kind) pick_[kind].assign(shapes::count(scene_, kind), 0.0);
    for (std::size_t e = 0; e < emitters_.size(); ++e) pickProbability(emitters_[e]) = table.pick[e];
  }

  double& pickProbability(std::uint32_t prim) { return pick_[gpu::primKind(prim)][gpu::primIndex(prim)]; }
  double pickProbability(std::uint32_t prim) const { return pick_[gpu::primKind(prim)][gpu::primIndex(prim)]; }

  // The solid-angle density with which the emitter light sample finds point p of primitive
  // `prim` from a vertex at distance `distance` along unit `dir`.
  double emitterSolidAnglePdf(std::uint32_t prim, const dvec3& p, double distance, const dvec3& dir) const {
    const SurfacePoint point = shapes::densityAt(scene_, prim, p);
    const double cosine = std::abs(glm::dot(point.normal, dir));
    return cosine > 0.0 ? pickProbability(prim) * point.areaPdf * distance * distance / cosine : 0.0;
  }

  // Next-event estimation of the emissive triangles and spheres at vertex v (lightsamples
  // samples, stratified like a quad light's).
  dvec3 emitterLights(const Vertex& v, std::uint32_t bounce, bool mis, const SampleNumbers& rng, RayCounts& counts) const {
    if (emitters_.empty()) return dvec3(0.0);
    const std::uint32_t n = static_cast<std::uint32_t>(std::max(scene_.path.lightSamples, 1));
    const std::uint32_t quads = static_cast<std::uint32_t>(lights_.size());
    const int m = scene_.path.lightStratify ? static_cast<int>(std::lround(std::sqrt(static_cast<double>(n)))) : 0;
    dvec3 sum(0.0);
    for (std::uint32_t k = 0; k < n; ++k) {
      if (stopAfter(k)) return sum;
      const std::uint64_t slot = emitterPointSlot(quads, n, k);
      double s = rng.at(bounce, slot), t = rng.at(bounce, slot + 1u);
      if (m > 0) {
        s = (static_cast<int>(k) % m + s) / m;
        t = (static_cast<int>(k) / m + t) / m;
      }
      // Pick an emitter, then a point on it.
      const double pick = rng.at(bounce, emitterPickSlot(quads, n, k));
      const std::size_t e = std::min<std::size_t>(
          static_cast<std::size_t>(std::upper_bound(emitterCdf_.begin(), emitterCdf_.end(), pick) - emitterCdf_.begin()),
          emitters_.size() - 1);
      const std::uint32_t prim = emitters_[e];
      const SurfacePoint point = shapes::samplePoint(scene_, prim, s, t);
      const dvec3 d = point.x - v.p;
      const double dist2 = glm::dot(d, d), dist = std::sqrt(dist2);
      if (dist == 0.0) continue;
      const dvec3 wi = d / dist;
      const double cosLight = std::abs(glm::dot(point.normal, wi)), nDotI = glm::dot(v.n, wi);
      if (cosLight <= 0.0 || nDotI <= 0.0) continue;
      const dvec3 f = evalBrdf(*v.m, v.n, wi, v.wo);
      if (f == dvec3(0.0)) continue;
      Hit at;
      at.prim = prim;
      const double tMax = dist - query_.offsetsAt(at, point.x).at(cosLight);
      if (!unoccluded(v.p, wi, v.offset.at(nDotI), tMax, counts)) continue;
      const double lightPdf = pickProbability(prim) * point.areaPdf * dist2 / cosLight;
      dvec3 contribution = scene_.materials[shapes::material(scene_, prim)].emission * f * (nDotI / (lightPdf * n));
      if (mis) contribution *= powerHeuristic(lightPdf, directionPdf(scene_.path.sampling, *v.m, v.n, wi, v.wo));
      sum += contribution;
    }
    return sum;
  }

  // Intersects `ray`; on a hit fills the vertex (wo = -dir) and returns true.
  bool hitVertex(const Ray& ray, double tMin, Hit& hit, Vertex& v) const {
    if (!query_.intersect(ray, tMin, kInfinity, false, hit)) return false;
    v.p = ray.origin + hit.t * ray.dir;
    v.m = &scene_.materials[query_.surfaceAt(hit, v.p, v.n)];
    v.wo = -ray.dir;
    v.offset = query_.offsetsAt(hit, v.p);
    return true;
  }

  // Le(x, w_o): a quad light's radiance on its front side (black behind), or the surface's
  // `emission` (both sides, as in the Whitted model).
  dvec3 emitted(const Vertex& v) const {
    if (v.m->quadLight >= 0) {
      const AreaLight& light = lights_[v.m->quadLight];
      return glm::dot(light.normal, v.wo) > 0.0 ? light.radiance : dvec3(0.0);
    }
    return v.m->emission;
  }

  bool unoccluded(const dvec3& p, const dvec3& dir, double tMin, double tMax, RayCounts& counts) const {
    ++counts.shadow;
    Hit blocker;
    return !(tMin < tMax && query_.intersect({p, dir}, tMin, tMax, true, blocker));
  }

  // Point and directional lights (doc/path-tracing.md, "Emission and the other lights": always
  // sampled explicitly): f I cos / attenuation behind a shadow ray, the attenuation of
  // doc/scene-format.md, "Shading".
  dvec3 pointLights(const Vertex& v, RayCounts& counts) const {
    dvec3 sum(0.0);
    for (const Light& light : scene_.lights) {
      LightArrival arrival;
      if (!arrivalAt(light, v.p, arrival)) continue;
      const dvec3& toLight = arrival.toLight;
      const double distance = arrival.distance, divisor = arrival.divisor;
      double nDotL = glm::dot(v.n, toLight);
      if (nDotL <= 0.0) continue;
      dvec3 f = evalBrdf(*v.m, v.n, toLight, v.wo);
      if (f == dvec3(0.0) || !unoccluded(v.p, toLight, v.offset.at(nDotL), distance, counts)) continue;
      sum += f * (light.color / divisor) * nDotL;
    }
    return sum;
  }

  // Next-event estimation of every quad light at vertex v of bounce b: lightsamples points on
  // each (stratified or not), each behind a shadow ray; with `mis`, each weighted by the power
  // heuristic against the BRDF sampling that could have found it.
  dvec3 quadLights(const Vertex& v, std::uint32_t bounce, bool mis, const SampleNumbers& rng, RayCounts& counts) const {
    const int n = std::max(scene_.path.lightSamples, 1);
    const int m = scene_.path.lightStratify ? static_cast<int>(std::lround(std::sqrt(static_cast<double>(n)))) : 0;
    dvec3 sum(0.0);
    for (std::size_t j = 0; j < lights_.size(); ++j) {
      const AreaLight& light = lights_[j];
      for (int k = 0; k < n; ++k) {
        if (stopAfter(j * static_cast<std::size_t>(n) + static_cast<std::size_t>(k))) return sum;
        // Sample a point x' on the light.
        const std::uint64_t slot = quadLightSlot(j, static_cast<std::uint64_t>(n), static_cast<std::uint64_t>(k));
        double s = rng.at(bounce, slot), t = rng.at(bounce, slot + 1u);
        if (m > 0) {
          s = (k % m + s) / m;
          t = (k / m + t) / m;
        }
        const dvec3 x = light.a + s * light.ab + t * light.ac;
        const dvec3 d = x - v.p;
        const double dist2 = glm::dot(d, d), dist = std::sqrt(dist2);
        if (dist == 0.0) continue;
        const dvec3 wi = d / dist;
        const double cosLight = -glm::dot(light.normal, wi), nDotI = glm::dot(v.n, wi);
        if (cosLight <= 0.0 || nDotI <= 0.0) continue;   // the light's back, or below the surface
        const dvec3 f = evalBrdf(*v.m, v.n, wi, v.wo);
        if (f == dvec3(0.0)) continue;
        // The shadow ray stops short of the light by the offset policy at the light's end.
        const double tMax = light.triangle >= 0 ? dist - query_.triangleOffsetsAt(light.triangle, x).at(cosLight)
                                                : dist - gpu::kSecondaryRayTMin;
        if (!unoccluded(v.p, wi, v.offset.at(nDotI), tMax, counts)) continue;
        const double g = nDotI * cosLight / dist2;
        dvec3 contribution = light.radiance * f * (g * light.area / n);
        if (mis) {
          const double lightPdf = dist2 / (light.area * cosLight);
          contribution *= powerHeuristic(lightPdf, directionPdf(scene_.path.sampling, *v.m, v.n, wi, v.wo));
        }
        sum += contribution;
      }
    }
    return sum;
  }

  // analyticdirect: Le + sum over quad lights of kd / pi L (Phi . n); point and directional
  // lights diffuse and unshadowed like it.
  dvec3 analyticDirect(const Ray& ray) const {
    Hit hit;
    Vertex v;
    if (!hitVertex(ray, 0.0, hit, v)) return dvec3(0.0);
    dvec3 radiance = emitted(v);
    if (v.m->quadLight >= 0) return radiance;
    for (const QuadLight& q : scene_.quadLights)
      radiance += v.m->diffuse / kPi * q.radiance * analyticQuadFactor(q, v.p, v.n);
    for (const Light& light : scene_.lights) {
      LightArrival arrival;
      if (!arrivalAt(light, v.p, arrival)) continue;
      radiance += v.m->diffuse / kPi * (light.color / arrival.divisor) * std::max(glm::dot(v.n, arrival.toLight), 0.0);
    }
    return radiance;
  }

  // direct: Le + one bounce of light sampling at the camera's hit.
  dvec3 direct(const Ray& ray, const SampleNumbers& rng, RayCounts& counts) const {
    Hit hit;
    Vertex v;
    if (!hitVertex(ray, 0.0, hit, v)) return dvec3(0.0);
    dvec3 radiance = emitted(v);
    if (v.m->quadLight >= 0) return radiance;   // a light's triangles reflect nothing
    return radiance + pointLights(v, counts) + quadLights(v, 0, false, rng, counts);
  }

  // pathtracer (doc/path-tracing.md, "Depth" and "Estimators"). Vertex b = 0 is the camera
  // ray's hit; vertices b < maxdepth scatter, and light reaching the last of them (by NEE or
  // by hitting) counts.
  dvec3 path(Ray ray, const SampleNumbers& rng, RayCounts& counts) const {
    const PathSettings& settings = scene_.path;
    const NextEvent nee = settings.nextEvent;
    const int maxDepth = scene_.maxDepth;
    dvec3 radiance(0.0), beta(1.0);
    double tMin = 0.0;              // the camera ray takes every hit with t > 0
    double previousPdf = 0.0;       // the BRDF-sampling density of the ray being traced (MIS)
    for (std::uint32_t bounce = 0;; ++bounce) {
      Hit hit;
      Vertex v;
      if (!hitVertex(ray, tMin, hit, v)) break;   // a miss is black

      // Add the emission the ray found: camera rays always; indirect rays unless next-event
      // estimation has already counted this light (on), or weighted against it (mis).
      const dvec3 le = emitted(v);
      if (le != dvec3(0.0)) {
        const bool isQuad = v.m->quadLight >= 0;
        const bool sampledByNee = isQuad || pickProbability(hit.prim) > 0.0;
        if (bounce == 0 || nee == NextEvent::Off || !sampledByNee) {
          radiance += beta * le;
        } else if (nee == NextEvent::Mis) {
          double lightPdf;
          if (isQuad) {
            const AreaLight& light = lights_[v.m->quadLight];
            lightPdf = hit.t * hit.t / (light.area * glm::dot(light.normal, v.wo));
          } else {
            lightPdf = emitterSolidAnglePdf(hit.prim, v.p, hit.t, v.wo);
          }
          radiance += beta * le * powerHeuristic(previousPdf, lightPdf);
        }
      }
      // A quad light's triangles reflect nothing; the depth rule stops the rest.
      if (v.m->quadLight >= 0) break;
      if ((maxDepth >= 0 && bounce >= static_cast<std::uint32_t>(maxDepth)) || bounce >= gpu::kMaxBounces) break;

      // Sample direct illumination: point and directional lights always, quad lights by NEE.
      radiance += beta * pointLights(v, counts);
      if (nee != NextEvent::Off) {
        radiance += beta * quadLights(v, bounce, nee == NextEvent::Mis, rng, counts);
        radiance += beta * emitterLights(v, bounce, nee == NextEvent::Mis, rng, counts);
      }

      // Sample the next direction and update the throughput.
      const dvec3 wi = glm::normalize(sampleDirection(settings.sampling, *v.m, v.n, v.wo,
                                                      rng.at(bounce, gpu::kRngSlotDirectionU),
                                                      rng.at(bounce, gpu::kRngSlotDirectionV),
                                                      rng.at(bounce, gpu::kRngSlotLobe)));
      const double pdf = directionPdf(settings.sampling, *v.m, v.n, wi, v.wo);
      const dvec3 f = evalBrdf(*v.m, v.n, wi, v.wo);
      if (!(pdf > 0.0) || f == dvec3(0.0)) break;
      const double nDotI = glm::dot(v.n, wi);
      beta *= f * (nDotI / pdf);
      previousPdf = pdf;

      // Possibly terminate the path with Russian roulette.
      if (settings.russianRoulette) {
        const double p = std::min(std::max({beta.x, beta.y, beta.z}), 1.0);
        if (!(rng.at(bounce, gpu::kRngSlotRoulette) < p)) break;
        beta /= p;
      }
      ++counts.secondary;
      ray = {v.p, wi};
      tMin = v.offset.at(std::abs(nDotI));
    }
    return radiance;
  }

  // Whether to stop: after every kLightSamplesPerPoll light samples (k counts them from 0).
  static constexpr std::uint32_t kLightSamplesPerPoll = 4096;
  bool stopAfter(std::uint64_t k) const { return (k + 1) % kLightSamplesPerPoll == 0 && stop_ && stop_(); }

  const SceneDesc& scene_;
  SceneQuery query_;
  const std::function<bool()>& stop_;
  std::vector<AreaLight> lights_;
  std::vector<std::uint32_t> emitters_;   // primRefs of the emissive triangles and spheres
  std::vector<double> emitterCdf_;        // their cumulative pick probabilities
  std::vector<double> pick_[shapes::kKinds];   // each primitive's pick probability (0: none), by kind
};

}  // namespace

double analyticQuadFactor(const QuadLight& light, const dvec3& x, const dvec3& n) {
  const dvec3 lightNormal = glm::normalize(glm::cross(light.ac, light.ab));
  if (!(glm::dot(lightNormal, x - light.a) > 0.0)) return 0.0;   // behind the light (or in its plane)
  const dvec3 v[4] = {light.a, light.a + light.ab, light.a + light.ab + light.ac, light.a + light.ac};
  dvec3 phi(0.0);
  for (int k = 0; k < 4; ++k) {
    const dvec3 p = v[k] - x, q = v[(k + 1) % 4] - x;
    const double theta = std::acos(std::clamp(glm::dot(glm::normalize(p), glm::normalize(q)), -1.0, 1.0));
    phi += theta * glm::normalize(glm::cross(p, q));
  }
  return 0.5 * glm::dot(phi, n);
}

// How many camera samples of a pixel are taken between polls of PathOptions::stop.
constexpr std::uint32_t kSamplesPerPoll = 64;

RadianceImage renderPathReference(const SceneDesc& scene, const Bvh& bvh, const PathOptions& options,
                                  RayCounts* counts) {
  if (scene.path.integrator == Integrator::Raytracer)
    throw std::invalid_argument("renderPathReference: the raytracer integrator is the Whitted reference's");
  const PixelRect region = options.crop ? *options.crop : PixelRect{0, 0, scene.width, scene.height};
  const std::uint32_t totalSpp = static_cast<std::uint32_t>(std::max(scene.path.spp, 1));
  const std::uint32_t first = options.firstSample;
  const std::uint32_t count = options.sampleCount > 0 ? options.sampleCount
                              : totalSpp > first      ? totalSpp - first
                                                      : 0;
  RadianceImage image(region.width(), region.height());
  image.samples = count;
  PathIntegrator integrator(scene, bvh, options.stop);
  const std::uint32_t strataSide = options.stratified ? gpu::rngStrataSide(totalSpp) : 0u;
  shadeTiles(
      region, options.threads, count,
      [&](int x, int y, RayCounts& local) {
        const std::uint32_t pixel = static_cast<std::uint32_t>(y) * static_cast<std::uint32_t>(scene.width) +
                                    static_cast<std::uint32_t>(x);
        dvec3 sum(0.0);
        for (std::uint32_t s = first; s < first + count; ++s) {
          const SampleNumbers rng{options.seed, pixel, s, strataSide};
          // spp 1 samples the pixel's centre; otherwise a uniform point in the pixel.
          const double u = totalSpp == 1 ? 0.5 : rng.at(gpu::kRngPixelX);
          const double v = totalSpp == 1 ? 0.5 : rng.at(gpu::kRngPixelY);
          sum += integrator.sampleRadiance(x + u, y + v, rng, local);
          // A batch of many samples stops within a pixel too (the image is then incomplete).
          if ((s - first) % kSamplesPerPoll == kSamplesPerPoll - 1 && options.stop && options.stop()) break;
        }
        return count > 0 ? sum / static_cast<double>(count) : dvec3(0.0);
      },
      image, options.progress, options.stop, counts);
  return image;
}

}  // namespace vkrt
