// Random scenes for differential testing, and their metamorphic rewrites (scene_generator.h).
#include "scene_generator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "scene/bvh.h"
#include "scene/shapes/sphere.h"

namespace vkrt::difftest {

std::uint64_t Rng::next() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double Rng::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
double Rng::uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
double Rng::logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
int Rng::range(int lo, int hi) {
  return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
}
bool Rng::chance(double p) { return uniform() < p; }

namespace {

constexpr double kPi = 3.14159265358979323846;

enum class Kind { Mixed, MirrorHall, VastFloor };

Kind kindOf(std::uint64_t seed) {
  // A generator of its own, so that the kind does not shift the scene's other choices.
  double u = Rng(seed ^ 0x6B696E64ull).uniform();
  return u < 0.6 ? Kind::Mixed : u < 0.8 ? Kind::MirrorHall : Kind::VastFloor;
}

const char* kindName(Kind k) {
  return k == Kind::Mixed ? "mixed" : k == Kind::MirrorHall ? "mirror-hall" : "vast-floor";
}

// Writes commands. Some scenes are written the way people write them (tabs, `+1`, `1e-3`,
// comments after commands, CRLF), which the parser must read as the plain form.
class Writer {
 public:
  Writer(Rng& rng, bool varied) : rng_(rng), varied_(varied), crlf_(varied && rng.chance(0.3)) {}

  std::string num(double v) {
    char buf[48];
    if (varied_ && rng_.chance(0.15))
      std::snprintf(buf, sizeof buf, "%.6e", v);
    else
      std::snprintf(buf, sizeof buf, "%.7g", v);
    std::string s = buf;
    if (s == "-0") s = "0";
    if (varied_ && v > 0 && rng_.chance(0.1)) s = "+" + s;
    return s;
  }

  void cmd(const std::string& name, std::initializer_list<double> args) {
    std::string line = name;
    for (double a : args) line += (varied_ && rng_.chance(0.1) ? "\t" : " ") + num(a);
    raw(line);
  }
  void cmd(const std::string& name, const dvec3& v) { cmd(name, {v.x, v.y, v.z}); }
  void indices(const std::string& name, int a, int b, int c) {
    raw(name + " " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c));
  }
  void raw(std::string line) {
    if (varied_ && rng_.chance(0.05)) line += "   ";
    if (varied_ && rng_.chance(0.03)) line += " # a comment after a command";
    text_ += line + (crlf_ ? "\r\n" : "\n");
  }
  void comment(const std::string& what) { raw("# " + what); }
  const std::string& text() const { return text_; }

 private:
  Rng& rng_;
  bool varied_, crlf_;
  std::string text_;
};

// Rotation matrix about unit axis `k` by `degrees` (right-handed, as `rotate`).
glm::dmat3 rotation(dvec3 k, double degrees) {
  k = glm::normalize(k);
  double a = degrees * kPi / 180.0, c = std::cos(a), s = std::sin(a), t = 1.0 - c;
  glm::dmat3 r;   // column-major: r[col][row]
  r[0] = {c + t * k.x * k.x, t * k.x * k.y + s * k.z, t * k.x * k.z - s * k.y};
  r[1] = {t * k.x * k.y - s * k.z, c + t * k.y * k.y, t * k.y * k.z + s * k.x};
  r[2] = {t * k.x * k.z + s * k.y, t * k.y * k.z - s * k.x, c + t * k.z * k.z};
  return r;
}

dvec3 randomUnit(Rng& rng) {
  double z = rng.uniform(-1.0, 1.0), a = rng.uniform(0.0, 2.0 * kPi), r = std::sqrt(1.0 - z * z);
  return {r * std::cos(a), r * std::sin(a), z};
}

dvec3 randomColor(Rng& rng, double lo, double hi) {
  if (rng.chance(0.3)) {   // grey
    double g = rng.uniform(lo, hi);
    return dvec3(g);
  }
  return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

// A colour with one or two channels exactly zero (pure red, yellow, ...).
dvec3 saturatedColor(Rng& rng, double lo, double hi) {
  dvec3 c = randomColor(rng, lo, hi);
  int zeroed = rng.range(0, 5);   // one of the six non-empty proper subsets of channels
  const int masks[6] = {1, 2, 4, 3, 5, 6};
  for (int k = 0; k < 3; ++k)
    if (masks[zeroed] & (1 << k)) c[k] = 0.0;
  return c;
}

class Generator {
 public:
  explicit Generator(std::uint64_t seed)
      : seed_(seed), kind_(kindOf(seed)), rng_(seed), w_(rng_, rng_.chance(0.25)) {}

  std::string run() {
    w_.comment("vkrt differential scene, seed " + std::to_string(seed_) + " (" + kindName(kind_) + ")");
    chooseScale();
    chooseSettings();
    chooseImageSize();   // needs the light count and depth, to bound the work
    w_.cmd("size", {double(width_), double(height_)});
    if (maxDepth_ != 5 || rng_.chance(0.8)) w_.cmd("maxdepth", {double(maxDepth_)});
    if (rng_.chance(0.2)) w_.cmd("maxverts", {double(rng_.range(0, 400))});
    placeObjects();      // decided before the camera, which looks at them
    writeCamera();
    writeLights();
    writeObjects();
    return w_.text();
  }

 private:
  struct Object {
    enum Type { Sphere, Ellipsoid, Box, SmoothBall, LooseTriangle } type;
    dvec3 position{0.0};      // the centre, in world space
    dvec3 scale{1.0};         // half-extents before rotation (radius for a sphere)
    dvec3 axis{0, 1, 0};
    double degrees = 0.0;
    bool mirror = false;
    dvec3 tri[3];             // LooseTriangle: the vertices
  };

  void chooseScale() {
    // The objects' scale: course-sized, except on a vast floor, where they are small.
    unit_ = kind_ == Kind::VastFloor ? rng_.logUniform(0.02, 1.0) : 1.0;
    spread_ = unit_ * rng_.uniform(2.0, 5.0);
    if (kind_ == Kind::VastFloor) floorHalf_ = rng_.logUniform(100.0, 10000.0);
    else floorHalf_ = spread_ * rng_.uniform(1.5, 4.0);
    hasFloor_ = kind_ != Kind::Mixed || rng_.chance(0.85);
  }

  void chooseSettings() {
    switch (kind_) {
      case Kind::MirrorHall:
        maxDepth_ = rng_.range(5, 12);
        lightCount_ = rng_.range(100, 250);
        ambientMode_ = 0;   // ambient 0 0 0
        break;
      case Kind::VastFloor:
        maxDepth_ = rng_.range(0, 4);
        lightCount_ = rng_.range(1, 5);
        ambientMode_ = rng_.range(0, 2);
        break;
      case Kind::Mixed: {
        maxDepth_ = rng_.chance(0.1) ? 5 : rng_.range(0, 12);
        double u = rng_.uniform();
        lightCount_ = u < 0.45 ? rng_.range(1, 4) : u < 0.8 ? rng_.range(5, 40) : rng_.range(41, 250);
        ambientMode_ = rng_.range(0, 2);
        break;
      }
    }
    // Attenuation: 0 none written (1 0 0), 1 c0 + c1 r, 2 pure quadratic 0 0 1, 3 a mix of all
    // three terms, 4 a different form per light. In a mirror hall, never a constant term.
    attenuationMode_ = kind_ == Kind::MirrorHall ? (rng_.chance(0.7) ? 2 : 5) : rng_.range(0, 4);
    // 0: every light a point light, 1: every light directional, 2: both.
    lightTypes_ = kind_ == Kind::MirrorHall ? 0 : rng_.range(0, 2);
    // Most scenes light from above the floor; some from anywhere.
    skyOnly_ = rng_.chance(0.85);
    // Some scenes have lights of pure colours (channels exactly zero).
    colouredLights_ = rng_.chance(0.3);
  }

  void chooseImageSize() {
    static const int odd[][2] = {{1, 1}, {2, 1}, {1, 3}, {17, 9}, {9, 17}, {33, 20}, {31, 31},
                                 {64, 48}, {48, 64}, {40, 7}, {63, 47}, {13, 11}, {5, 48}, {64, 3}};
    if (rng_.chance(0.5)) {
      const auto& s = odd[rng_.range(0, int(std::size(odd)) - 1)];
      width_ = s[0];
      height_ = s[1];
    } else {
      width_ = rng_.range(1, 64);
      height_ = rng_.range(1, 48);
    }
    // Bound the work: pixels x ray segments x (lights + 1) shadow-ray setups.
    const double perPixel = (1.0 + maxDepth_) * (lightCount_ + 1.0);
    const double kMaxWork = 400000.0;
    double work = width_ * height_ * perPixel;
    if (work > kMaxWork) {
      double f = std::sqrt(kMaxWork / work);
      width_ = std::max(1, int(width_ * f));
      height_ = std::max(1, int(height_ * f));
    }
  }

  // Material commands for an object; `mirror` makes it a mirror (specular up to 0.9).
  void writeMaterial(bool mirror) {
    if (ambientMode_ == 2) w_.cmd("ambient", randomColor(rng_, 0.0, 0.25));
    w_.cmd("diffuse", mirror           ? randomColor(rng_, 0.0, 0.2)
                      : rng_.chance(0.15) ? saturatedColor(rng_, 0.05, 0.8)
                                          : randomColor(rng_, 0.05, 0.8));
    double u = rng_.uniform();
    dvec3 specular = mirror ? randomColor(rng_, 0.6, 0.9)
                     : u < 0.45 ? dvec3(0.0)
                     : u < 0.8  ? randomColor(rng_, 0.0, 0.5)
                                : randomColor(rng_, 0.5, 0.9);
    w_.cmd("specular", specular);
    double shininess = rng_.chance(0.15) ? 0.0 : rng_.chance(0.1) ? 10000.0 : rng_.logUniform(1.0, 10000.0);
    w_.cmd("shininess", {shininess});
    w_.cmd("emission", rng_.chance(0.15) ? randomColor(rng_, 0.0, 0.3) : dvec3(0.0));
  }

  // How far below y = 0 an object's lowest point goes: touching (0), piercing the floor, or
  // hovering just above it.
  double sink(double height) {
    double u = rng_.uniform();
    if (!hasFloor_ || u < 0.15) return -rng_.uniform(0.2, 1.0) * height;   // well above
    if (u < 0.55) return 0.0;
    if (u < 0.85) return rng_.uniform(0.0, 0.4) * height;
    return -rng_.logUniform(1e-4, 1e-2) * height;
  }

  void placeObjects() {
    int count = kind_ == Kind::MirrorHall ? rng_.range(3, 6) : rng_.range(1, 8);
    int mirrors = kind_ == Kind::MirrorHall ? 3 : 0;
    for (int i = 0; i < count; ++i) {
      Object o;
      double u = rng_.uniform();
      o.type = i < mirrors ? (rng_.chance(0.7) ? Object::Sphere : Object::Ellipsoid)
               : u < 0.2   ? Object::Sphere
               : u < 0.45  ? Object::Ellipsoid
               : u < 0.7   ? Object::Box
               : u < 0.87  ? Object::SmoothBall
                           : Object::LooseTriangle;
      o.mirror = i < mirrors;
      double angle = rng_.uniform(0.0, 2.0 * kPi), r = spread_ * std::sqrt(rng_.uniform());
      o.position = {r * std::cos(angle), 0.0, r * std::sin(angle)};
      double size = unit_ * rng_.uniform(0.3, 1.2);
      switch (o.type) {
        case Object::Sphere:
          o.scale = dvec3(size);
          o.position.y = size - sink(2 * size);
          break;
        case Object::Ellipsoid: {
          o.scale = {size * rng_.uniform(0.3, 1.5), size * rng_.uniform(0.3, 1.5), size * rng_.uniform(0.3, 1.5)};
          o.axis = randomUnit(rng_);
          o.degrees = rng_.uniform(-180.0, 180.0);
          // The half-extent along y of R S (unit sphere): the length of the y row of R S.
          glm::dmat3 m = rotation(o.axis, o.degrees);
          double h = std::sqrt(std::pow(m[0][1] * o.scale.x, 2) + std::pow(m[1][1] * o.scale.y, 2) +
                               std::pow(m[2][1] * o.scale.z, 2));
          o.position.y = h - sink(2 * h);
          break;
        }
        case Object::Box:
          o.scale = {size * rng_.uniform(0.4, 1.4), size * rng_.uniform(0.4, 2.0), size * rng_.uniform(0.4, 1.4)};
          o.axis = {0, 1, 0};
          o.degrees = rng_.uniform(-90.0, 90.0);
          o.position.y = o.scale.y - sink(2 * o.scale.y);
          break;
        case Object::SmoothBall:
          o.scale = {size, size * rng_.uniform(0.5, 1.5), size};
          o.position.y = o.scale.y - sink(2 * o.scale.y);
          break;
        case Object::LooseTriangle:
          o.position.y = size * rng_.uniform(0.3, 2.0);
          o.scale = dvec3(size * 1.2);
          for (dvec3& p : o.tri) p = o.position + randomUnit(rng_) * o.scale.x;
          for (dvec3& p : o.tri) p.y = std::max(p.y, 0.01 * unit_);
          break;
      }
      objects_.push_back(o);
    }
    lo_ = dvec3(std::numeric_limits<double>::infinity());
    hi_ = -lo_;
    for (const Object& o : objects_) {
      double e = glm::length(o.scale);
      lo_ = glm::min(lo_, o.position - e);
      hi_ = glm::max(hi_, o.position + e);
    }
  }

  void writeCamera() {
    dvec3 target = 0.5 * (lo_ + hi_);
    double radius = 0.5 * glm::length(hi_ - lo_);
    double fovy = rng_.uniform(25.0, 75.0);
    double aspect = double(width_) / height_;
    double tanY = std::tan(fovy * kPi / 360.0), tanX = tanY * aspect;
    double halfAngle = std::atan(std::min(tanX, tanY));
    double distance = radius / std::sin(halfAngle) * rng_.uniform(0.7, 1.2);
    double elevation = rng_.uniform(8.0, kind_ == Kind::VastFloor ? 50.0 : 70.0) * kPi / 180.0;
    double azimuth = rng_.uniform(0.0, 2.0 * kPi);
    dvec3 dir = {std::cos(elevation) * std::cos(azimuth), std::sin(elevation), std::cos(elevation) * std::sin(azimuth)};
    dvec3 from = target + dir * distance;
    dvec3 up = {0, 1, 0};
    if (rng_.chance(0.15)) {   // rolled; `up` need not be perpendicular to the view
      double roll = rng_.uniform(-0.6, 0.6);
      up = {std::sin(roll), std::cos(roll), std::sin(roll) * 0.5};
    }
    w_.cmd("camera", {from.x, from.y, from.z, target.x, target.y, target.z, up.x, up.y, up.z, fovy});
  }

  // One attenuation form: constant only, c0 + c1 r, 0 0 1, a mix, or no constant term.
  dvec3 attenuationForm(int mode) {
    switch (mode) {
      case 0: return {1, 0, 0};
      case 1: return {rng_.chance(0.3) ? 0.0 : rng_.uniform(0.2, 1.0), rng_.uniform(0.05, 1.0) / unit_, 0};
      case 2: return {0, 0, 1};
      case 3:
        return {rng_.uniform(0.0, 1.0), rng_.uniform(0.0, 0.5) / unit_, rng_.uniform(0.01, 0.5) / (unit_ * unit_)};
      default:   // no constant term
        return {0, rng_.uniform(0.0, 0.3) / unit_, rng_.uniform(0.05, 1.0) / (unit_ * unit_)};
    }
  }

  void writeLights() {
    if (ambientMode_ == 0) w_.cmd("ambient", {0, 0, 0});
    const double share = 1.2 / std::pow(double(lightCount_), 0.8);
    dvec3 current = {1, 0, 0};
    if (attenuationMode_ != 0 && attenuationMode_ != 4) {
      current = attenuationForm(attenuationMode_);
      w_.cmd("attenuation", current);
    }
    for (int i = 0; i < lightCount_; ++i) {
      bool point = lightTypes_ == 0 || (lightTypes_ == 2 && rng_.chance(0.5));
      dvec3 color = (colouredLights_ && rng_.chance(0.7) ? saturatedColor(rng_, 0.2, 1.0) : randomColor(rng_, 0.2, 1.0)) *
                    share;
      if (!point) {
        double elevation = skyOnly_ ? rng_.uniform(5.0, 85.0) : rng_.uniform(-60.0, 85.0);
        double azimuth = rng_.uniform(0.0, 360.0);
        elevation *= kPi / 180.0;
        azimuth *= kPi / 180.0;
        dvec3 d = {std::cos(elevation) * std::cos(azimuth), std::sin(elevation), std::cos(elevation) * std::sin(azimuth)};
        d *= rng_.uniform(0.5, 3.0);   // need not be unit length
        w_.cmd("directional", {d.x, d.y, d.z, color.x, color.y, color.z});
        continue;
      }
      if (attenuationMode_ == 4 && (i == 0 || rng_.chance(0.5))) {
        current = attenuationForm(rng_.range(0, 5));
        w_.cmd("attenuation", current);
      }
      double height = skyOnly_ ? rng_.uniform(0.3, 3.0) : rng_.uniform(-1.0, 3.0);
      dvec3 p = {rng_.uniform(-1.5, 1.5) * spread_, height * spread_, rng_.uniform(-1.5, 1.5) * spread_};
      // Brightness for the distance the light mostly works at.
      double r = std::max(glm::length(p - 0.5 * (lo_ + hi_)), 0.5 * spread_);
      color *= current.x + current.y * r + current.z * r * r;
      w_.cmd("point", {p.x, p.y, p.z, color.x, color.y, color.z});
    }
  }

  void writeFloor() {
    w_.comment("floor");
    bool mirror = rng_.chance(0.2);
    writeMaterial(false);
    if (mirror) w_.cmd("specular", randomColor(rng_, 0.3, 0.8));
    const dvec3 corners[4] = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
    bool scaled = rng_.chance(0.5);   // a unit quad under `scale`, or the numbers written out
    if (scaled) {
      w_.raw("pushTransform");
      w_.cmd("scale", {floorHalf_, 1.0, floorHalf_});
    }
    for (const dvec3& c : corners) w_.cmd("vertex", scaled ? c : c * dvec3(floorHalf_, 1, floorHalf_));
    w_.indices("tri", vertices_, vertices_ + 3, vertices_ + 2);
    w_.indices("tri", vertices_, vertices_ + 2, vertices_ + 1);
    vertices_ += 4;
    if (scaled) w_.raw("popTransform");
  }

  void writeObjects() {
    if (hasFloor_) writeFloor();
    for (const Object& o : objects_) {
      writeMaterial(o.mirror);
      switch (o.type) {
        case Object::Sphere:
          if (rng_.chance(0.5)) {
            w_.cmd("sphere", {o.position.x, o.position.y, o.position.z, o.scale.x});
          } else {   // the same through a transform
            w_.raw("pushTransform");
            w_.cmd("translate", o.position);
            w_.cmd("scale", dvec3(o.scale.x));
            w_.cmd("sphere", {0, 0, 0, 1});
            w_.raw("popTransform");
          }
          break;
        case Object::Ellipsoid:
          w_.raw("pushTransform");
          w_.cmd("translate", o.position);
          w_.cmd("rotate", {o.axis.x, o.axis.y, o.axis.z, o.degrees});
          w_.cmd("scale", o.scale);
          w_.cmd("sphere", {0, 0, 0, 1});
          w_.raw("popTransform");
          break;
        case Object::Box: writeBox(o); break;
        case Object::SmoothBall: writeSmoothBall(o); break;
        case Object::LooseTriangle:
          for (const dvec3& p : o.tri) w_.cmd("vertex", p);
          w_.indices("tri", vertices_, vertices_ + 1, vertices_ + 2);
          vertices_ += 3;
          break;
      }
    }
  }

  // A box of flat triangles, counter-clockwise seen from outside, standing on its base.
  void writeBox(const Object& o) {
    w_.raw("pushTransform");
    w_.cmd("translate", o.position);
    w_.cmd("rotate", {0, 1, 0, o.degrees});
    w_.cmd("scale", o.scale * 2.0);
    for (int i = 0; i < 8; ++i) w_.cmd("vertex", {(i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5});
    static const int faces[12][3] = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                                     {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    for (const auto& f : faces) w_.indices("tri", vertices_ + f[0], vertices_ + f[1], vertices_ + f[2]);
    vertices_ += 8;
    w_.raw("popTransform");
  }

  // A low-polygon ball of `trinormal` triangles with radial normals, under a non-uniform scale.
  void writeSmoothBall(const Object& o) {
    int rings = rng_.range(3, 7), segments = rng_.range(4, 10);
    w_.raw("pushTransform");
    w_.cmd("translate", o.position);
    w_.cmd("scale", o.scale);
    std::vector<dvec3> points;
    points.push_back({0, 1, 0});
    for (int i = 1; i < rings; ++i)
      for (int j = 0; j < segments; ++j) {
        double theta = kPi * i / rings, phi = 2.0 * kPi * j / segments;
        points.push_back({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
      }
    points.push_back({0, -1, 0});
    if (rng_.chance(0.3)) w_.cmd("maxvertnorms", {double(points.size())});
    for (const dvec3& p : points) w_.cmd("vertexnormal", {p.x, p.y, p.z, p.x, p.y, p.z});
    const int base = normalVertices_, last = int(points.size()) - 1;
    auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
    auto emit = [&](int a, int b, int c) {   // counter-clockwise seen from outside
      dvec3 n = glm::cross(points[b] - points[a], points[c] - points[a]);
      if (glm::dot(n, points[a] + points[b] + points[c]) < 0) std::swap(b, c);
      w_.indices("trinormal", base + a, base + b, base + c);
    };
    for (int j = 0; j < segments; ++j) {
      emit(0, ring(1, j), ring(1, j + 1));
      emit(last, ring(rings - 1, j), ring(rings - 1, j + 1));
      for (int i = 1; i + 1 < rings; ++i) {
        emit(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
        emit(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
      }
    }
    normalVertices_ += int(points.size());
    w_.raw("popTransform");
  }

  std::uint64_t seed_;
  Kind kind_;
  Rng rng_;
  Writer w_;
  int width_ = 1, height_ = 1, maxDepth_ = 5, lightCount_ = 1;
  int ambientMode_ = 1, attenuationMode_ = 0, lightTypes_ = 0;
  bool skyOnly_ = true, hasFloor_ = true, colouredLights_ = false;
  double unit_ = 1.0, spread_ = 3.0, floorHalf_ = 10.0;
  std::vector<Object> objects_;
  dvec3 lo_{0.0}, hi_{0.0};   // the box around the objects
  int vertices_ = 0, normalVertices_ = 0;
};

// ---- metamorphic rewrites -------------------------------------------------------------------

std::string fmt(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

struct Line {
  std::string_view text;     // without the end of line
  std::string_view ending;   // "\n", "\r\n" or "" (the last line)
};

std::vector<Line> splitLines(std::string_view text) {
  std::vector<Line> lines;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) {
      lines.push_back({text.substr(pos), ""});
      break;
    }
    std::size_t stop = end > pos && text[end - 1] == '\r' ? end - 1 : end;
    lines.push_back({text.substr(pos, stop - pos), text.substr(stop, end + 1 - stop)});
    pos = end + 1;
  }
  return lines;
}

// The command's words, without a trailing comment.
std::vector<std::string> words(std::string_view line) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < line.size() && line[i] != '#') {
    if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\v' || line[i] == '\f') {
      ++i;
      continue;
    }
    std::size_t start = i;
    while (i < line.size() && line[i] != '#' && line[i] != ' ' && line[i] != '\t' && line[i] != '\r' &&
           line[i] != '\v' && line[i] != '\f')
      ++i;
    out.emplace_back(line.substr(start, i - start));
  }
  return out;
}

double number(const std::string& word) { return std::strtod(word.c_str(), nullptr); }

// Inserts `insert` after the `size` line; rewrites lines through `rewrite` (which returns the
// replacement, or nothing to keep the line).
template <class Rewrite>
std::string rewriteScene(std::string_view text, const std::string& insert, Rewrite rewrite) {
  std::string out;
  bool inserted = false;
  for (const Line& line : splitLines(text)) {
    std::vector<std::string> w = words(line.text);
    std::optional<std::string> replaced = w.empty() ? std::nullopt : rewrite(w);
    out += replaced ? *replaced : std::string(line.text);
    std::string ending = line.ending.empty() ? "\n" : std::string(line.ending);
    out += ending;
    if (!inserted && !w.empty() && w[0] == "size") {
      inserted = true;
      for (const Line& extra : splitLines(insert)) out += std::string(extra.text) + ending;
    }
  }
  return out;
}

}  // namespace

std::string generateScene(std::uint64_t seed) { return Generator(seed).run(); }

std::string sceneKind(std::uint64_t seed) { return kindName(kindOf(seed)); }

std::string scaledAndMoved(std::string_view text, double k, const dvec3& offset) {
  std::string insert = "translate " + fmt(offset.x) + " " + fmt(offset.y) + " " + fmt(offset.z) + "\nscale " +
                       fmt(k) + " " + fmt(k) + " " + fmt(k) + "\n";
  return rewriteScene(text, insert, [&](const std::vector<std::string>& w) -> std::optional<std::string> {
    if (w[0] == "camera" && w.size() == 11) {
      dvec3 from(number(w[1]), number(w[2]), number(w[3])), at(number(w[4]), number(w[5]), number(w[6]));
      from = from * k + offset;
      at = at * k + offset;
      return "camera " + fmt(from.x) + " " + fmt(from.y) + " " + fmt(from.z) + " " + fmt(at.x) + " " + fmt(at.y) +
             " " + fmt(at.z) + " " + w[7] + " " + w[8] + " " + w[9] + " " + w[10];
    }
    if (w[0] == "attenuation" && w.size() == 4)
      return "attenuation " + w[1] + " " + fmt(number(w[2]) / k) + " " + fmt(number(w[3]) / (k * k));
    return std::nullopt;
  });
}

std::optional<std::string> withVastBlackGround(std::string_view text, const SceneDesc& scene) {
  // The axis along which the ground lies "below": every directional light on its positive side.
  const dvec3 axes[6] = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
  std::optional<dvec3> up;
  for (const dvec3& a : axes) {
    bool ok = true;
    for (const Light& l : scene.lights)
      if (l.type == LightType::Directional && !(glm::dot(l.vec, a) > 0.0)) ok = false;
    if (ok) {
      up = a;
      break;
    }
  }
  if (!up) return std::nullopt;
  // The box around everything a ray can start from or go to.
  dvec3 lo = scene.camera.from, hi = scene.camera.from;
  for (const Triangle& t : scene.triangles)
    for (const dvec3& p : t.p) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  for (const Sphere& s : scene.spheres) {
    dvec3 slo, shi;
    shapes::bounds(s, slo, shi);
    lo = glm::min(lo, slo);
    hi = glm::max(hi, shi);
  }
  for (const Light& l : scene.lights)
    if (l.type == LightType::Point) {
      lo = glm::min(lo, l.vec);
      hi = glm::max(hi, l.vec);
    }
  const double size = std::max(glm::length(hi - lo), 1e-300);
  const dvec3 centre = 0.5 * (lo + hi);
  // Its top 1% of the scene's size below the lowest point along `up`, its half-thickness 1%,
  // its radius 1,000 sizes. Thin and close, so that the centre of the box around the geometry
  // (the origin of the Vulkan backend's float32 coordinates) moves little.
  const double lowest = glm::dot(lo * glm::max(*up, dvec3(0.0)) - hi * glm::max(-*up, dvec3(0.0)), dvec3(1.0));
  const double along = lowest - 0.02 * size;   // the ground's centre, along `up`
  const dvec3 position = centre - *up * glm::dot(centre, *up) + *up * along;
  const dvec3 radii = glm::abs(*up) * (0.01 * size) + (dvec3(1.0) - glm::abs(*up)) * (1000.0 * size);
  std::string insert = "ambient 0 0 0\npushTransform\ntranslate " + fmt(position.x) + " " + fmt(position.y) + " " +
                       fmt(position.z) + "\nscale " + fmt(radii.x) + " " + fmt(radii.y) + " " + fmt(radii.z) +
                       "\nsphere 0 0 0 1\npopTransform\nambient 0.2 0.2 0.2\n";
  return rewriteScene(text, insert, [](const std::vector<std::string>&) { return std::nullopt; });
}

}  // namespace vkrt::difftest
