// Random valid scenes for differential testing, as `.test` text (so the parser is exercised
// too), deterministic from a seed; and the metamorphic rewrites of a scene's text. Depends on
// the scene description only (no rendering, no Vulkan, no gtest).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "scene/scene_desc.h"

namespace vkrt::difftest {

// splitmix64: a tiny generator whose output is fixed by its definition (std's distributions
// differ between standard libraries, so a seed would not name the same scene everywhere).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  double uniform();                          // [0, 1), 53 bits
  double uniform(double lo, double hi);      // [lo, hi)
  double logUniform(double lo, double hi);   // lo, hi > 0
  int range(int lo, int hi);                 // [lo, hi], both included
  bool chance(double p);

 private:
  std::uint64_t state_;
};

// A random scene: ellipsoids under rotation and non-uniform scale, spheres, flat boxes and
// smooth (`trinormal`) balls standing on or piercing a floor (sometimes a vast one), loose
// triangles seen from either side, 1 to 250 point and directional lights with every
// attenuation form, emission, shininess 0 to 1e4, mirrors, maxdepth 0 to 12, odd image sizes,
// and a camera that sees the objects. The image is kept small enough that one Vulkan render on
// lavapipe takes about a second at most. The first line names the seed and the kind of scene.
std::string generateScene(std::uint64_t seed);

// The kind generateScene(seed) chose ("mixed", "mirror-hall", "vast-floor").
std::string sceneKind(std::uint64_t seed);

// The same scene with every length multiplied by k and moved by `offset`: the whole scene is
// put under `translate offset` and `scale k k k` (inserted after `size`), the camera's
// look-from and look-at are moved by hand (the camera is not under the transform), and each
// `attenuation c0 c1 c2` becomes `c0 c1/k c2/k^2`, so that every light's divisor at the scaled
// distances is what it was. Point lights follow the transform (doc/scene-format.md, "Conventions"). The picture
// must be the same.
std::string scaledAndMoved(std::string_view text, double k, const dvec3& offset);

// The same scene with a vast black ground added just below it: a flat ellipsoid 2,000 times
// the scene's size across, with no ambient, emission, diffuse or specular term, placed below
// the camera, every light and every primitive, on the side away from every directional light.
// Whatever sees it sees black, as it would see nothing; no shadow ray can reach it (it lies
// beyond the plane below everything, and every shadow ray leaves away from that plane). So the
// picture must be the same. Returns nothing when no axis has every directional light on its
// positive side (then a shadow ray could reach the ground).
std::optional<std::string> withVastBlackGround(std::string_view text, const SceneDesc& scene);

}  // namespace vkrt::difftest
