// Hand-built scenes and statistics for the path integrators' tests.
#include "path_scenes.h"

#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/finish_scene.h"

namespace vkrt::test {

std::uint32_t addMaterial(SceneDesc& scene, const Material& m) {
  scene.materials.push_back(m);
  return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

void addQuad(SceneDesc& scene, const dvec3& a, const dvec3& ab, const dvec3& ac, std::uint32_t material) {
  // cross(p1 - p0, p2 - p0) = cross(ac, ab) for both triangles.
  Triangle t1, t2;
  t1.p[0] = a, t1.p[1] = a + ac, t1.p[2] = a + ab;
  t2.p[0] = a + ac, t2.p[1] = a + ab + ac, t2.p[2] = a + ab;
  t1.material = t2.material = material;
  scene.triangles.push_back(t1);
  scene.triangles.push_back(t2);
}

void addQuadLight(SceneDesc& scene, const dvec3& a, const dvec3& ab, const dvec3& ac, const dvec3& radiance) {
  QuadLight q;
  q.a = a, q.ab = ab, q.ac = ac, q.radiance = radiance;
  vkrt::addQuadLight(scene, q);
}

void setCamera(SceneDesc& scene, const dvec3& from, const dvec3& at, double fovyDegrees, int w, int h) {
  scene.camera.from = from;
  scene.camera.at = at;
  scene.camera.up = std::abs(glm::normalize(at - from).y) > 0.99 ? dvec3(0, 0, 1) : dvec3(0, 1, 0);
  scene.camera.fovyDegrees = fovyDegrees;
  scene.width = w;
  scene.height = h;
}

SceneDesc furnaceBox(double albedo, double emission, int size) {
  SceneDesc s;
  Material m;
  m.ambient = dvec3(0.0);
  m.diffuse = dvec3(albedo);
  m.emission = dvec3(emission);
  const std::uint32_t mat = addMaterial(s, m);
  // Each face: corner a and edges with cross(ac, ab) pointing into the cube.
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      dvec3 e1(0.0), e2(0.0), a(-1.0);
      e1[(axis + 1) % 3] = 2.0;
      e2[(axis + 2) % 3] = 2.0;
      a[axis] = side;
      // cross(e2, e1) points along -axis (for axis order x, y, z): inward at side +1.
      if (side > 0) addQuad(s, a, e1, e2, mat);
      else addQuad(s, a, e2, e1, mat);
    }
  setCamera(s, dvec3(0.1, 0.2, 0.3), dvec3(1.0, 0.5, -0.7), 90.0, size, size);
  s.path.integrator = Integrator::PathTracer;
  s.maxDepth = -1;
  return s;
}

SceneDesc cornellLikeBox(int size, int maxDepth) {
  SceneDesc s;
  auto diffuse = [&](dvec3 kd) {
    Material m;
    m.ambient = dvec3(0.0);
    m.diffuse = kd;
    return addMaterial(s, m);
  };
  const std::uint32_t white = diffuse(dvec3(0.7)), red = diffuse(dvec3(0.7, 0.1, 0.1)),
                      green = diffuse(dvec3(0.1, 0.7, 0.1));
  // The box [-1, 1] x [0, 2] x [-1, 1], open toward +z, walls facing in.
  addQuad(s, dvec3(-1, 0, -1), dvec3(2, 0, 0), dvec3(0, 0, 2), white);    // floor, up
  addQuad(s, dvec3(-1, 2, -1), dvec3(0, 0, 2), dvec3(2, 0, 0), white);    // ceiling, down
  addQuad(s, dvec3(-1, 0, -1), dvec3(0, 2, 0), dvec3(2, 0, 0), white);    // back, +z
  addQuad(s, dvec3(-1, 0, -1), dvec3(0, 0, 2), dvec3(0, 2, 0), red);      // left, +x
  addQuad(s, dvec3(1, 0, -1), dvec3(0, 2, 0), dvec3(0, 0, 2), green);     // right, -x
  addQuadLight(s, dvec3(-0.35, 1.99, -0.35), dvec3(0, 0, 0.7), dvec3(0.7, 0, 0), dvec3(8.0, 7.0, 6.0));
  // A glossy Phong block's top and front, and a GGX sphere.
  Material phong;
  phong.ambient = dvec3(0.0);
  phong.diffuse = dvec3(0.3, 0.3, 0.5);
  phong.specular = dvec3(0.4);
  phong.shininess = 20.0;
  const std::uint32_t glossy = addMaterial(s, phong);
  addQuad(s, dvec3(-0.8, 0.6, -0.6), dvec3(0.6, 0, 0), dvec3(0, 0, 0.6), glossy);   // top, up
  addQuad(s, dvec3(-0.8, 0.0, 0.0), dvec3(0, 0.6, 0), dvec3(0.6, 0, 0), glossy);    // front, +z
  Material ggx;
  ggx.ambient = dvec3(0.0);
  ggx.diffuse = dvec3(0.2, 0.4, 0.2);
  ggx.specular = dvec3(0.5, 0.4, 0.3);
  ggx.brdf = BrdfModel::Ggx;
  ggx.roughness = 0.3;
  Sphere ball;
  ball.center = dvec3(0.45, 0.4, 0.1);
  ball.radius = 0.4;
  ball.material = addMaterial(s, ggx);
  s.spheres.push_back(ball);
  setCamera(s, dvec3(0, 1, 3.2), dvec3(0, 1, 0), 45.0, size, size);
  s.path.integrator = Integrator::PathTracer;
  s.maxDepth = maxDepth;
  return s;
}

SceneDesc emissiveSurfacesBox(int size, int maxDepth) {
  SceneDesc s = cornellLikeBox(size, maxDepth);
  // Take out the quad light: its two triangles are the 11th and 12th, its material the 4th.
  s.quadLights.clear();
  s.triangles.erase(s.triangles.begin() + 10, s.triangles.begin() + 12);
  s.materials[3].quadLight = -1;
  Material glow;
  glow.ambient = dvec3(0.0);
  glow.diffuse = dvec3(0.2);
  glow.emission = dvec3(3.0, 3.0, 2.5);
  Sphere ellipsoid;
  ellipsoid.worldFromObject = glm::translate(dmat4(1.0), dvec3(-0.2, 1.7, -0.1)) *
                              glm::rotate(dmat4(1.0), glm::radians(30.0), dvec3(0, 0, 1)) *
                              glm::scale(dmat4(1.0), dvec3(0.35, 0.12, 0.25));
  ellipsoid.objectFromWorld = glm::inverse(ellipsoid.worldFromObject);
  ellipsoid.material = addMaterial(s, glow);
  s.spheres.push_back(ellipsoid);
  Material panel;
  panel.ambient = dvec3(0.0);
  panel.emission = dvec3(2.0, 1.0, 0.5);
  Triangle t;
  t.p[0] = dvec3(0.2, 1.2, -0.98), t.p[1] = dvec3(0.8, 1.2, -0.98), t.p[2] = dvec3(0.5, 1.7, -0.98);   // facing +z
  t.material = addMaterial(s, panel);
  s.triangles.push_back(t);
  return s;
}

SceneDesc glossyFloorUnderLargeLight(int size) {
  SceneDesc s;
  Material phong;
  phong.ambient = dvec3(0.0);
  phong.diffuse = dvec3(0.2, 0.3, 0.4);
  phong.specular = dvec3(0.5);
  phong.shininess = 30.0;
  Material ggx = phong;
  ggx.brdf = BrdfModel::Ggx;
  ggx.roughness = 0.2;
  addQuad(s, dvec3(-2, 0, -2), dvec3(2, 0, 0), dvec3(0, 0, 4), addMaterial(s, phong));   // x < 0, up
  addQuad(s, dvec3(0, 0, -2), dvec3(2, 0, 0), dvec3(0, 0, 4), addMaterial(s, ggx));      // x > 0, up
  addQuadLight(s, dvec3(-0.8, 0.6, -1.2), dvec3(0, 0, 1.6), dvec3(1.6, 0, 0), dvec3(2.0, 2.5, 3.0));   // facing down
  setCamera(s, dvec3(0, 0.45, 2.0), dvec3(0, 0, -0.3), 60.0, size, size);
  s.path.integrator = Integrator::PathTracer;
  s.maxDepth = 1;
  return s;
}

SceneDesc floorBesideMirrorSphere(int size, int maxDepth) {
  SceneDesc s;
  Material floor;
  floor.ambient = dvec3(0.0);
  floor.diffuse = dvec3(0.8);
  Material glossy;
  glossy.ambient = dvec3(0.0);
  glossy.diffuse = dvec3(0.2);
  glossy.specular = dvec3(0.8);
  glossy.shininess = 1000.0;
  addQuad(s, dvec3(-3, 0, -3), dvec3(6, 0, 0), dvec3(0, 0, 6), addMaterial(s, floor));   // up
  Sphere ball;
  ball.center = dvec3(0, 0.5, 0);
  ball.radius = 0.5;
  ball.material = addMaterial(s, glossy);
  s.spheres.push_back(ball);
  addQuadLight(s, dvec3(-1, 0.2, -0.3), dvec3(0, 0, 0.6), dvec3(0, 0.6, 0), dvec3(30.0, 25.0, 20.0));   // facing +x
  setCamera(s, dvec3(-2.6, 1.0, 0.0), dvec3(-1.6, 0, 0), 40.0, size, size);
  s.path.integrator = Integrator::PathTracer;
  s.maxDepth = maxDepth;
  return s;
}

namespace {

// The continued fraction of the regularized incomplete beta function (Numerical Recipes'
// betacf, modified Lentz).
double betaContinuedFraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300, kEps = 1e-15;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::abs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 10000; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((a - 1.0 + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + 1.0 + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kEps) return h;
  }
  throw std::runtime_error("betaContinuedFraction did not converge");
}

// I_x(a, b).
double regularizedBeta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) +
                                b * std::log(1.0 - x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * betaContinuedFraction(a, b, x) / a;
  return 1.0 - front * betaContinuedFraction(b, a, 1.0 - x) / b;
}

}  // namespace

double studentTwoSidedTail(double t, double dof) {
  // P(|T| > t) = I_{dof / (dof + t^2)}(dof / 2, 1 / 2).
  return regularizedBeta(dof / 2.0, 0.5, dof / (dof + t * t));
}

double welchPValue(double m1, double v1, int n1, double m2, double v2, int n2) {
  const double v = v1 + v2;
  if (!(v > 0.0)) return m1 == m2 ? 1.0 : 0.0;
  const double t = (m1 - m2) / std::sqrt(v);
  // Welch-Satterthwaite degrees of freedom.
  const double dof = v * v / (v1 * v1 / (n1 - 1) + v2 * v2 / (n2 - 1));
  return studentTwoSidedTail(t, dof);
}

}  // namespace vkrt::test
