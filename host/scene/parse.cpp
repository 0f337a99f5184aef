// Scene file parser: .test text -> SceneDesc (SPEC sections 1, 2, 4 and 8; SPEC-PATHTRACING
// sections 1 and 2).
// Parser-only state (transform stack, current material, vertex lists) stays in this file.
#include "scene/parse.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <memory>
#include <optional>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>

#include "counted.h"
#include "errors.h"
#include "image/image_file.h"
#include "image/render_identity.h"
#include "interrupt.h"
#include "scene/linear_map.h"
#include "scene/number.h"
#include "scene/unit_vector.h"
#include "suggest.h"

namespace vkrt {
namespace {

constexpr int kMaxErrors = 50;
constexpr int kMaxArgs = 12;   // quadLight has the most
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// The commands of the format. kCommandNames spells them as the format does, in this order,
// which is also the order of lookup: the commands of big meshes first.
enum class Command {
  Vertex, Tri, VertexNormal, TriNormal, Size, MaxDepth, Output, Camera, Sphere, MaxVerts, MaxVertNorms,
  Translate, Rotate, Scale, PushTransform, PopTransform, Directional, Point, Attenuation, Ambient, Diffuse,
  Specular, Emission, Shininess,
  // SPEC-PATHTRACING section 1
  Integrator, QuadLight, LightSamples, LightStratify, Spp, NextEventEstimation, RussianRoulette,
  ImportanceSampling, Brdf, Roughness, Gamma, Count
};
constexpr std::string_view kCommandNames[] = {
    "vertex", "tri", "vertexnormal", "trinormal", "size", "maxdepth", "output", "camera", "sphere", "maxverts",
    "maxvertnorms", "translate", "rotate", "scale", "pushTransform", "popTransform", "directional", "point",
    "attenuation", "ambient", "diffuse", "specular", "emission", "shininess", "integrator", "quadLight",
    "lightsamples", "lightstratify", "spp", "nexteventestimation", "russianroulette", "importancesampling", "brdf",
    "roughness", "gamma"};
static_assert(std::size(kCommandNames) == static_cast<std::size_t>(Command::Count));

std::string_view nameOf(Command c) { return kCommandNames[static_cast<std::size_t>(c)]; }

std::optional<Command> commandNamed(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kCommandNames); ++i)
    if (kCommandNames[i] == name) return static_cast<Command>(i);
  return std::nullopt;
}

char lowerAscii(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool equalIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                            [](char x, char y) { return lowerAscii(x) == lowerAscii(y); });
}

// `maxDepth`, `pushtransform`: a command in another case (no two commands differ only in case).
std::optional<Command> commandNamedIgnoringCase(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kCommandNames); ++i)
    if (equalIgnoringCase(kCommandNames[i], name)) return static_cast<Command>(i);
  return std::nullopt;
}

// A token as messages quote it: in quotes, its non-printable bytes escaped, a long one cut
// short (echoed()).
std::string quoted(std::string_view token) { return "'" + echoed(token) + "'"; }

// The kinds of warning (SPEC section 8); each kind is summarised after kMaxWarningsPerKind.
enum class WarningKind {
  UnknownCommand, KeywordCase, ExtraArguments, Repeated, BeforeSize, OutputName, NotForIntegrator, EndlessPaths,
  Clamped,
  NoLights,
  Count
};
constexpr const char* kWarningKindNames[] = {
    "unknown commands", "keywords in another case", "extra arguments", "repeated commands",
    "commands before 'size'", "output names", "commands the integrator does not use", "paths without an end",
    "values clamped",
    "scenes without lights"};
static_assert(std::size(kWarningKindNames) == static_cast<std::size_t>(WarningKind::Count));
constexpr std::size_t kWarningKinds = static_cast<std::size_t>(WarningKind::Count);

// Values that render finite on both backends (doc/robustness.md, "Numerical robustness"): a colour or
// radiance channel beyond float32 (the Vulkan backend's precision) is clamped to the largest
// float; a Phong exponent above kMaxPathShininess (path integrators: a lobe narrower than
// float32 resolves, whose normalisation (s + 2) / 2 pi squared by MIS would overflow) and a
// GGX roughness above kMaxRoughness (alpha^4 would overflow float32; the lobe is as flat at
// 1e4 as beyond) are clamped to those. Each with a warning at its line.
constexpr double kMaxColour = 3.4028234663852886e38;   // the largest float
constexpr double kMaxPathShininess = 1e9;
constexpr double kMaxRoughness = 1e4;

// The keyword values of SPEC-PATHTRACING section 1, in the order of their enums.
constexpr std::string_view kIntegratorNames[] = {"raytracer", "analyticdirect", "direct", "pathtracer"};
constexpr std::string_view kNextEventNames[] = {"off", "on", "mis"};
constexpr std::string_view kSamplingNames[] = {"hemisphere", "cosine", "brdf"};
constexpr std::string_view kBrdfNames[] = {"phong", "ggx"};
constexpr std::string_view kOnOffNames[] = {"on", "off"};

// Which integrators use a command of SPEC-PATHTRACING section 1 (a bit per Integrator). The
// others ignore it, with a warning: `raytracer` uses none of them, `analyticdirect` is exact
// and diffuse (it has no light samples and no BRDF), `direct` follows no paths.
using IntegratorSet = unsigned;
constexpr IntegratorSet bit(Integrator i) { return 1u << static_cast<unsigned>(i); }
constexpr IntegratorSet kAllPath = bit(Integrator::AnalyticDirect) | bit(Integrator::Direct) | bit(Integrator::PathTracer);
constexpr IntegratorSet kSampled = bit(Integrator::Direct) | bit(Integrator::PathTracer);
constexpr IntegratorSet kPathsOnly = bit(Integrator::PathTracer);

IntegratorSet integratorsUsing(Command c) {
  switch (c) {
    case Command::QuadLight:
    case Command::Spp:
    case Command::Gamma: return kAllPath;
    case Command::LightSamples:
    case Command::LightStratify:
    case Command::Brdf:
    case Command::Roughness: return kSampled;
    case Command::NextEventEstimation:
    case Command::RussianRoulette:
    case Command::ImportanceSampling: return kPathsOnly;
    default: return ~0u;
  }
}

std::string_view nameOf(Integrator i) { return kIntegratorNames[static_cast<std::size_t>(i)]; }

bool isPerfectSquare(int n) {
  int r = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
  return r * r == n;
}

// What each byte is to the tokenizer: one table lookup per byte.
enum ByteClass : unsigned char { kToken, kBlank, kComment, kBinary };
constexpr std::array<ByteClass, 256> makeByteClasses() {
  std::array<ByteClass, 256> t{};
  for (int c = 0; c < 0x20; ++c) t[c] = kBinary;   // NUL and C0 controls never occur in text...
  for (int c : {' ', '\t', '\r', '\v', '\f'}) t[c] = kBlank;   // ...but for the blanks
  t['#'] = kComment;
  t[0x7F] = kBinary;
  return t;
}
constexpr std::array<ByteClass, 256> kByteClass = makeByteClasses();
ByteClass byteClass(char c) { return kByteClass[static_cast<unsigned char>(c)]; }

struct VertexWithNormal {
  dvec3 position;
  dvec3 normal;
};

// Transform of normals: inverse transpose of the linear part. For a singular matrix (a
// `scale 0`, whose triangles are degenerate anyway) the cofactor matrix keeps a direction.
glm::dmat3 normalMatrix(const dmat4& m) {
  glm::dmat3 a(m);
  if (!isSingular(a)) return glm::transpose(inverseLinear(a));
  return glm::dmat3(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1]));
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& fileName, const ParseOptions& options)
      : text_(text), options_(options) {
    scene_.sourcePath = fileName;
  }

  ParsedScene run() {
    reserveArrays();
    parseLines();
    if (!binary_) summariseWarnings();
    // Deferred diagnostics (the end of file, summaries) go to their lines.
    std::stable_sort(diagnostics_.begin(), diagnostics_.end(),
                     [](const Diagnostic& a, const Diagnostic& b) { return a.line < b.line; });
    if (errorCount_ > 0) throw SceneError(std::move(diagnostics_));
    return {std::move(scene_), std::move(diagnostics_)};
  }

 private:
  // Sizes the big arrays from the lines that start with "tri" and "vertex" (memchr is fast).
  void reserveArrays() {
    std::size_t tris = 0, vertices = 0;
    const char* p = text_.data();
    const char* end = p + text_.size();
    while (p < end) {
      tris += *p == 't' && end - p > 3 && p[1] == 'r' && p[2] == 'i';
      vertices += *p == 'v' && end - p > 6 && std::memcmp(p, "vertex", 6) == 0;
      const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
      p = nl ? nl + 1 : end;
    }
    scene_.triangles.reserve(tris);
    vertices_.reserve(vertices);
  }

  // A binary file would give an error per line: drop what was found so far and say once
  // that it is not text, and where.
  void notText(std::size_t column, unsigned char c) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", c);
    diagnostics_.clear();
    errorCount_ = 0;
    error(std::string("file is not text (byte ") + hex + " in column " + std::to_string(column) +
          "); expected a CSE167 scene file");
    binary_ = true;
  }

  void parseLines() {
    // A UTF-8 byte-order mark (some Windows editors write one) is not part of the first line.
    std::size_t pos = text_.substr(0, kByteOrderMark.size()) == kByteOrderMark ? kByteOrderMark.size() : 0;
    while (pos < text_.size() && !tooMany()) {
      std::size_t end = text_.find('\n', pos);
      if (end == std::string_view::npos) end = text_.size();
      ++line_;
      parseLine(text_.substr(pos, end - pos));
      if (binary_) return;
      pos = end + 1;
    }
    if (!tooMany()) finish();
  }

  // ---- diagnostics --------------------------------------------------------------------------
  bool tooMany() const { return errorCount_ >= kMaxErrors; }

  void error(std::string message) { errorAt(line_, std::move(message)); }
  void errorAt(int line, std::string message) {
    if (tooMany()) return;
    diagnostics_.push_back({scene_.sourcePath, line, std::move(message), Severity::Error});
    if (++errorCount_ == kMaxErrors)
      diagnostics_.push_back({scene_.sourcePath, line, "too many errors; stopping here", Severity::Error});
  }

  // A warning (with --strict, an error). After kMaxWarningsPerKind of its kind, only counted.
  void warn(WarningKind kind, std::string message) { warnAt(line_, kind, std::move(message)); }
  void warnAt(int line, WarningKind kind, std::string message) {
    const auto k = static_cast<std::size_t>(kind);
    if (++warnings_[k] > kMaxWarningsPerKind) {
      if (suppressedFrom_[k] == 0) suppressedFrom_[k] = line;
      suppressedTo_[k] = line;
      return;
    }
    if (options_.strict) return errorAt(line, std::move(message) + " [--strict]");
    diagnostics_.push_back({scene_.sourcePath, line, std::move(message), Severity::Warning});
  }

  // "... and N more of this kind", one per kind that went over the limit, at the first line
  // not listed.
  void summariseWarnings() {
    for (std::size_t k = 0; k < kWarningKinds; ++k) {
      if (warnings_[k] <= kMaxWarningsPerKind) continue;
      const int more = warnings_[k] - kMaxWarningsPerKind;
      std::string lines = more == 1 ? "on line " + std::to_string(suppressedFrom_[k])
                                    : "on lines " + std::to_string(suppressedFrom_[k]) + " to " +
                                          std::to_string(suppressedTo_[k]);
      diagnostics_.push_back({scene_.sourcePath, suppressedFrom_[k],
                              "... and " + std::to_string(more) + " more of this kind (" + kWarningKindNames[k] +
                                  "), " + lines + (options_.strict ? " [--strict]" : ""),
                              options_.strict ? Severity::Error : Severity::Warning});
      if (options_.strict) ++errorCount_;
    }
  }

  // ---- one line -------------------------------------------------------------------------------
  void parseLine(std::string_view line) {
    std::string_view tokens[kMaxArgs + 2];
    int count = 0;
    std::size_t i = 0;
    while (i < line.size()) {
      ByteClass k = byteClass(line[i]);
      if (k == kBlank) {
        ++i;
      } else if (k == kToken) {
        std::size_t start = i;
        while (i < line.size() && byteClass(line[i]) == kToken) ++i;
        if (count < kMaxArgs + 2) tokens[count] = line.substr(start, i - start);
        ++count;
      } else if (k == kComment) {   // the whole line, or the rest of it; still text
        for (; i < line.size(); ++i)
          if (byteClass(line[i]) == kBinary) return notText(i + 1, static_cast<unsigned char>(line[i]));
      } else {
        return notText(i + 1, static_cast<unsigned char>(line[i]));
      }
    }
    if (count == 0) return;
    std::string_view command = tokens[0];
    args_ = tokens + 1;
    argCount_ = count - 1;
    dispatch(command);
  }

  // Commands of other courses' extensions are skipped, and a known keyword in another case
  // is read as that keyword, each with a warning (SPEC section 8). The warning for an unknown
  // command names the nearest command when one is near enough to be a typo (`sphre`).
  void dispatch(std::string_view name) {
    std::optional<Command> cmd = commandNamed(name);
    if (!cmd) {
      cmd = commandNamedIgnoringCase(name);
      if (!cmd)
        return warn(WarningKind::UnknownCommand,
                    "unknown command " + quoted(name) + " (line skipped)" + didYouMean(name, kCommandNames));
      warn(WarningKind::KeywordCase, quoted(name) + " read as '" + std::string(nameOf(*cmd)) +
                                         "' (keywords are case-sensitive)");
    }
    if (!sawSize_ && beforeSizeLine_ == 0 && *cmd != Command::Size) {
      beforeSizeLine_ = line_;
      beforeSizeCommand_ = nameOf(*cmd);
    }
    if (integratorsUsing(*cmd) != ~0u) integratorCommands_.push_back({*cmd, line_});
    switch (*cmd) {
      case Command::Vertex: return cmdVertex();
      case Command::Tri: return cmdTri();
      case Command::VertexNormal: return cmdVertexNormal();
      case Command::TriNormal: return cmdTriNormal();
      case Command::Size: return cmdSize();
      case Command::MaxDepth: return cmdMaxDepth();
      case Command::Output: return cmdOutput();
      case Command::Camera: return cmdCamera();
      case Command::Sphere: return cmdSphere();
      case Command::MaxVerts:
      case Command::MaxVertNorms: return cmdSizeHint(nameOf(*cmd));
      case Command::Translate: return cmdTranslate();
      case Command::Rotate: return cmdRotate();
      case Command::Scale: return cmdScale();
      case Command::PushTransform: return cmdPush();
      case Command::PopTransform: return cmdPop();
      case Command::Directional: return cmdLight(false);
      case Command::Point: return cmdLight(true);
      case Command::Attenuation: return cmdAttenuation();
      case Command::Ambient: return cmdColor("ambient", material_.ambient);
      case Command::Diffuse: return cmdColor("diffuse", material_.diffuse);
      case Command::Specular: return cmdColor("specular", material_.specular);
      case Command::Emission: return cmdColor("emission", material_.emission);
      case Command::Shininess: return cmdShininess();
      case Command::Integrator: return cmdIntegrator();
      case Command::QuadLight: return cmdQuadLight();
      case Command::LightSamples:
        if (cmdSampleCount(*cmd, scene_.path.lightSamples)) lightSamplesLine_ = line_;
        return;
      case Command::Spp: return static_cast<void>(cmdSampleCount(*cmd, scene_.path.spp));
      case Command::LightStratify:
        if (cmdOnOff(*cmd, scene_.path.lightStratify)) lightStratifyLine_ = scene_.path.lightStratify ? line_ : 0;
        return;
      case Command::RussianRoulette: return static_cast<void>(cmdOnOff(*cmd, scene_.path.russianRoulette));
      case Command::NextEventEstimation:
        return static_cast<void>(cmdKeyword(*cmd, kNextEventNames, scene_.path.nextEvent));
      case Command::ImportanceSampling:
        return static_cast<void>(cmdKeyword(*cmd, kSamplingNames, scene_.path.sampling));
      case Command::Brdf: return static_cast<void>(cmdKeyword(*cmd, kBrdfNames, material_.brdf));
      case Command::Roughness: return cmdRoughness();
      case Command::Gamma: return cmdGamma();
      case Command::Count: break;
    }
  }

  // A repeated `size`, `camera`, `maxdepth`, `output` or `integrator`: the last one counts. `previousLine`
  // is the line of the one before (0: none).
  void noteRepeat(std::string_view cmd, int previousLine) {
    if (previousLine > 0)
      warn(WarningKind::Repeated, "'" + std::string(cmd) + "' given again (before at line " +
                                      std::to_string(previousLine) + "): the last one counts");
  }

  // ---- arguments --------------------------------------------------------------------------
  // More arguments than `cmd` takes: the first `n` are read, the rest ignored.
  void ignoreExtraArguments(std::string_view cmd, int n, const char* usage) {
    if (argCount_ <= n) return;
    const int extra = argCount_ - n;
    std::string takes = n == 0 ? "takes no arguments"
                               : "takes " + counted(n, "argument", "arguments") + " (" + usage + ")";
    std::string ignored = extra == 1 ? std::string("the extra one is ignored")
                                     : "the extra " + std::to_string(extra) + " are ignored";
    warn(WarningKind::ExtraArguments,
         "'" + std::string(cmd) + "' " + takes + ", got " + std::to_string(argCount_) + ": " + ignored);
  }

  // Checks the argument count and parses the first `n` arguments as finite numbers.
  bool numbers(std::string_view cmd, int n, const char* usage, double* out) {
    if (argCount_ < n) {
      error("'" + std::string(cmd) + "' expects " + counted(n, "argument", "arguments") + " (" + usage + "), got " +
            std::to_string(argCount_));
      return false;
    }
    ignoreExtraArguments(cmd, n, usage);
    bool ok = true;
    for (int k = 0; k < n; ++k) {
      switch (parseNumber(args_[k], out[k])) {
        case NumberStatus::Ok: break;
        case NumberStatus::NotANumber:
          error("'" + std::string(cmd) + "' argument " + std::to_string(k + 1) + ": expected a number, got " +
                quoted(args_[k]));
          ok = false;
          break;
        case NumberStatus::NotFinite:
          error("'" + std::string(cmd) + "' argument " + std::to_string(k + 1) +
                ": expected a finite number, got " + quoted(args_[k]));
          ok = false;
          break;
        case NumberStatus::TooSmall:
          error("'" + std::string(cmd) + "' argument " + std::to_string(k + 1) + ": " + quoted(args_[k]) +
                " is too small: below 4.9e-324, the smallest positive double, it would be 0 (write 0)");
          ok = false;
          break;
      }
    }
    return ok;
  }

  // An integer in [lo, hi], given as a number with no fractional part.
  std::optional<long long> integer(std::string_view cmd, double v, int argIndex, const char* what, long long lo,
                                   long long hi) {
    if (v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi)) {
      error("'" + std::string(cmd) + "' argument " + std::to_string(argIndex + 1) + ": expected " + what +
            ", got " + quoted(args_[argIndex]));
      return std::nullopt;
    }
    return static_cast<long long>(v);
  }

  // ---- commands ---------------------------------------------------------------------------
  void cmdSize() {
    double a[2];
    noteRepeat("size", scene_.sizeLine);
    if (!sawSize_) firstSizeLine_ = line_;
    sawSize_ = true;
    scene_.sizeLine = line_;
    if (!numbers("size", 2, "width height", a)) return;
    const std::string range = "an integer from 1 to " + std::to_string(kMaxImageEdge);
    auto w = integer("size", a[0], 0, range.c_str(), 1, kMaxImageEdge);
    auto h = integer("size", a[1], 1, range.c_str(), 1, kMaxImageEdge);
    if (w && h) {
      scene_.width = static_cast<int>(*w);
      scene_.height = static_cast<int>(*h);
    }
  }

  void cmdMaxDepth() {
    double a[1];
    noteRepeat("maxdepth", maxDepthLine_);
    maxDepthLine_ = line_;
    if (!numbers("maxdepth", 1, "depth", a)) return;
    // -1 (no limit) is for the path integrators; the integrator is known at the end of file.
    if (auto d = integer("maxdepth", a[0], 0, "a non-negative integer, or -1 (no limit)", -1, 1'000'000)) {
      scene_.maxDepth = static_cast<int>(*d);
      unlimitedDepthLine_ = *d == -1 ? line_ : 0;
    }
  }

  void cmdOutput() {
    const char* usage = "a file name without spaces";
    noteRepeat("output", scene_.outputLine);
    if (argCount_ < 1) {
      error(std::string("'output' expects 1 argument (") + usage + "), got 0");
      return;
    }
    ignoreExtraArguments("output", 1, usage);
    std::string_view name = args_[0];
    if (!hasImageExtension(std::string(name)))
      warn(WarningKind::OutputName, "output file " + quoted(name) +
                                        " is not named .png or .ppm: vkrt writes PNG, under that name");
    scene_.output = std::string(name);
    scene_.outputLine = line_;
  }

  void cmdCamera() {
    double a[10];
    noteRepeat("camera", cameraLine_);
    cameraLine_ = line_;
    if (!numbers("camera", 10, "fromx fromy fromz atx aty atz upx upy upz fovy", a)) return;
    Camera c{{a[0], a[1], a[2]}, {a[3], a[4], a[5]}, {a[6], a[7], a[8]}, a[9]};
    bool ok = true;
    dvec3 view = c.from - c.at;
    if (view == dvec3(0.0)) {
      error("degenerate camera: look-from equals look-at");
      ok = false;
    } else if (!std::isfinite(view.x) || !std::isfinite(view.y) || !std::isfinite(view.z)) {
      error("look-from and look-at are too far apart: their difference overflows double precision");
      ok = false;
    } else if (c.up == dvec3(0.0)) {
      error("degenerate camera: the up vector is zero");
      ok = false;
    } else if (glm::length(glm::cross(unitVector(c.up), unitVector(view))) <= 1e-12) {
      error("degenerate camera: the up vector is parallel to the view direction");
      ok = false;
    }
    if (!(c.fovyDegrees > 0.0 && c.fovyDegrees < 180.0)) {
      error("camera field of view must be in (0, 180) degrees, got " + quoted(args_[9]));
      ok = false;
    }
    if (ok) scene_.camera = c;
  }

  std::uint32_t currentMaterial() {
    if (shadedSurfaceLine_ == 0 && (material_.diffuse != dvec3(0.0) || material_.specular != dvec3(0.0)))
      shadedSurfaceLine_ = line_;
    if (scene_.materials.empty() || !(scene_.materials.back() == material_))
      scene_.materials.push_back(material_);
    return static_cast<std::uint32_t>(scene_.materials.size() - 1);
  }

  void cmdSphere() {
    double a[4];
    if (!numbers("sphere", 4, "x y z radius", a)) return;
    if (a[3] < 0.0) {
      error("sphere radius must not be negative, got " + quoted(args_[3]));
      return;
    }
    if (isSingular(glm::dmat3(transform_))) {
      error("sphere under a singular transform (a scale of 0): it has no volume and no normal");
      return;
    }
    Sphere s;
    s.worldFromObject = transform_;
    s.objectFromWorld = inverseAffine(transform_);
    s.center = {a[0], a[1], a[2]};
    s.radius = a[3];
    s.material = currentMaterial();
    scene_.spheres.push_back(s);
  }

  void cmdSizeHint(std::string_view cmd) {
    double a[1];
    if (!numbers(cmd, 1, "count", a)) return;
    integer(cmd, a[0], 0, "a non-negative integer", 0, 1LL << 40);
  }

  void cmdVertex() {
    double a[3];
    if (!numbers("vertex", 3, "x y z", a)) return;
    vertices_.push_back({a[0], a[1], a[2]});
  }

  void cmdVertexNormal() {
    double a[6];
    if (!numbers("vertexnormal", 6, "x y z nx ny nz", a)) return;
    dvec3 n{a[3], a[4], a[5]};
    if (n == dvec3(0.0)) {
      error("vertexnormal normal must not be zero");
      n = dvec3(0.0, 0.0, 1.0);   // keeps later indices right; the scene is rejected anyway
    }
    vertexNormals_.push_back({{a[0], a[1], a[2]}, n});
  }

  // Reads three vertex indices into `idx`, each checked against `available`.
  bool indices(std::string_view cmd, std::size_t available, const char* listName, std::uint32_t idx[3]) {
    double a[3];
    if (!numbers(cmd, 3, "i j k", a)) return false;
    bool ok = true;
    for (int k = 0; k < 3; ++k) {
      if (a[k] != std::floor(a[k]) || a[k] < 0.0 || a[k] >= static_cast<double>(available)) {
        error("'" + std::string(cmd) + "' index " + escapedBytes(args_[k]) + " out of range (" +
              std::to_string(available) + " " + listName + " defined so far)");
        ok = false;
      } else {
        idx[k] = static_cast<std::uint32_t>(a[k]);
      }
    }
    return ok;
  }

  dvec3 toWorldPoint(const dvec3& p) const { return dvec3(transform_ * glm::dvec4(p, 1.0)); }

  void cmdTri() {
    std::uint32_t idx[3];
    if (!indices("tri", vertices_.size(), "vertices", idx)) return;
    Triangle t;
    for (int k = 0; k < 3; ++k) t.p[k] = toWorldPoint(vertices_[idx[k]]);
    t.material = currentMaterial();
    scene_.triangles.push_back(t);
  }

  void cmdTriNormal() {
    std::uint32_t idx[3];
    if (!indices("trinormal", vertexNormals_.size(), "vertexnormals", idx)) return;
    glm::dmat3 nm = normalMatrix(transform_);
    Triangle t;
    t.smooth = true;
    for (int k = 0; k < 3; ++k) {
      t.p[k] = toWorldPoint(vertexNormals_[idx[k]].position);
      dvec3 n = nm * vertexNormals_[idx[k]].normal;
      double len = glm::length(n);
      // A normal or transform so small or large that the length underflows or overflows:
      // the same direction through unitVector.
      if (!(len > 0.0) || !std::isfinite(len)) n = unitVector(nm * unitVector(vertexNormals_[idx[k]].normal));
      else n /= len;
      t.n[k] = n != dvec3(0.0) ? n : dvec3(0.0, 0.0, 1.0);
    }
    t.material = currentMaterial();
    scene_.triangles.push_back(t);
  }

  void cmdTranslate() {
    double a[3];
    if (!numbers("translate", 3, "x y z", a)) return;
    transform_ = glm::translate(transform_, dvec3(a[0], a[1], a[2]));
  }

  void cmdRotate() {
    double a[4];
    if (!numbers("rotate", 4, "axisx axisy axisz angle", a)) return;
    dvec3 axis{a[0], a[1], a[2]};
    if (axis == dvec3(0.0)) {
      error("rotate axis must not be zero");
      return;
    }
    transform_ = transform_ * rotation(unitVector(axis), glm::radians(a[3]));
  }

  // Rodrigues' rotation about a unit axis, right-handed, as a 4x4 matrix.
  static dmat4 rotation(const dvec3& k, double angle) {
    double c = std::cos(angle), s = std::sin(angle);
    glm::dmat3 kk = glm::outerProduct(k, k);
    glm::dmat3 cross(0.0, k.z, -k.y,   // columns of the cross-product matrix [k]x
                     -k.z, 0.0, k.x,
                     k.y, -k.x, 0.0);
    glm::dmat3 r = c * glm::dmat3(1.0) + (1.0 - c) * kk + s * cross;
    return dmat4(r);
  }

  void cmdScale() {
    double a[3];
    if (!numbers("scale", 3, "x y z", a)) return;
    transform_ = glm::scale(transform_, dvec3(a[0], a[1], a[2]));
  }

  void cmdPush() {
    ignoreExtraArguments("pushTransform", 0, "");
    stack_.push_back(transform_);
  }

  void cmdPop() {
    ignoreExtraArguments("popTransform", 0, "");
    if (stack_.empty()) return error("popTransform with an empty transform stack (no matching pushTransform)");
    transform_ = stack_.back();
    stack_.pop_back();
  }

  void cmdLight(bool point) {
    double a[6];
    const char* cmd = point ? "point" : "directional";
    if (!numbers(cmd, 6, "x y z r g b", a)) return;
    Light l;
    l.color = withinFloat(cmd, {a[3], a[4], a[5]}, 3);
    if (point) {
      l.type = LightType::Point;
      l.vec = toWorldPoint({a[0], a[1], a[2]});
      l.attenuation = attenuation_;
    } else {
      l.type = LightType::Directional;
      dvec3 d{a[0], a[1], a[2]};
      if (d == dvec3(0.0)) return error("directional light direction must not be zero");
      // Scaled by powers of two before and after the transform: a tiny or vast direction
      // neither underflows nor overflows (and one of ordinary size keeps its bits).
      l.vec = unitVector(dvec3(transform_ * glm::dvec4(scaledForSquares(d), 0.0)));
      if (l.vec == dvec3(0.0))
        return error("directional light direction vanishes under the current transform (a scale of 0)");
    }
    scene_.lights.push_back(l);
  }

  void cmdAttenuation() {
    double a[3];
    if (!numbers("attenuation", 3, "constant linear quadratic", a)) return;
    if (a[0] < 0 || a[1] < 0 || a[2] < 0 || (a[0] == 0 && a[1] == 0 && a[2] == 0)) {
      error("attenuation terms must be non-negative and not all zero");
      return;
    }
    attenuation_ = {a[0], a[1], a[2]};
  }

  void cmdColor(std::string_view cmd, dvec3& target) {
    double a[3];
    if (!numbers(cmd, 3, "r g b", a)) return;
    target = withinFloat(cmd, {a[0], a[1], a[2]}, 0);
  }

  // A colour whose channels (arguments first.. first + 2) lie beyond float32: clamped to the
  // largest float, with a warning naming the first such argument.
  dvec3 withinFloat(std::string_view cmd, dvec3 c, int first) {
    for (int k = 0; k < 3; ++k) {
      if (std::abs(c[k]) <= kMaxColour) continue;
      warn(WarningKind::Clamped, "'" + std::string(cmd) + "' argument " + std::to_string(first + k + 1) + " " +
                                     quoted(args_[first + k]) +
                                     " is beyond the largest float32 value (3.4028235e38), in which the Vulkan backend "
                                     "computes: clamped to it on both backends");
      return glm::clamp(c, dvec3(-kMaxColour), dvec3(kMaxColour));
    }
    return c;
  }

  void cmdShininess() {
    double a[1];
    if (!numbers("shininess", 1, "s", a)) return;
    if (a[0] < 0.0) return error("shininess must not be negative, got " + quoted(args_[0]));
    material_.shininess = a[0];
    if (a[0] > kMaxPathShininess) steepShininessLines_.push_back(line_);   // (clamped for the path integrators)
  }

  // ---- path tracing (SPEC-PATHTRACING section 1) ----------------------------------------------
  // Reads one keyword argument of `names` into `value` (an enum in the order of `names`). A
  // keyword in another case is read as that keyword, with a warning, as commands are.
  template <typename Enum, std::size_t N>
  bool cmdKeyword(Command cmd, const std::string_view (&names)[N], Enum& value) {
    std::string usage;
    for (std::size_t i = 0; i < N; ++i) usage += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(names[i]);
    std::string name(nameOf(cmd));
    if (argCount_ < 1) {
      error("'" + name + "' expects 1 argument (" + usage + "), got 0");
      return false;
    }
    ignoreExtraArguments(name, 1, usage.c_str());
    for (std::size_t i = 0; i < N; ++i) {
      if (names[i] == args_[0]) {
        value = static_cast<Enum>(i);
        return true;
      }
    }
    for (std::size_t i = 0; i < N; ++i) {
      if (equalIgnoringCase(names[i], args_[0])) {
        warn(WarningKind::KeywordCase,
             quoted(args_[0]) + " read as '" + std::string(names[i]) + "' (keywords are case-sensitive)");
        value = static_cast<Enum>(i);
        return true;
      }
    }
    error("'" + name + "' argument 1: expected " + usage + ", got " + quoted(args_[0]));
    return false;
  }

  bool cmdOnOff(Command cmd, bool& value) {
    int v = value ? 0 : 1;   // the index in kOnOffNames
    if (!cmdKeyword(cmd, kOnOffNames, v)) return false;
    value = v == 0;
    return true;
  }

  void cmdIntegrator() {
    noteRepeat("integrator", integratorLine_);
    Integrator i = scene_.path.integrator;
    if (cmdKeyword(Command::Integrator, kIntegratorNames, i)) {
      scene_.path.integrator = i;
      integratorLine_ = line_;
    }
  }

  // `spp`, `lightsamples`: a count of samples, at least 1.
  bool cmdSampleCount(Command cmd, int& value) {
    double a[1];
    std::string name(nameOf(cmd));
    if (!numbers(name, 1, "N", a)) return false;
    auto n = integer(name, a[0], 0, "an integer from 1 to 1000000000", 1, 1'000'000'000);
    if (n) value = static_cast<int>(*n);
    return n.has_value();
  }

  void cmdRoughness() {
    double a[1];
    if (!numbers("roughness", 1, "alpha", a)) return;
    if (a[0] < 0.0) return error("roughness must not be negative, got " + quoted(args_[0]));
    material_.roughness = a[0];
    if (a[0] > kMaxRoughness) {
      warn(WarningKind::Clamped, "roughness " + quoted(args_[0]) +
                                     " clamped to 1e4 (GGX is as flat there as beyond, and float32 would overflow)");
      material_.roughness = kMaxRoughness;
    }
  }

  void cmdGamma() {
    double a[1];
    if (!numbers("gamma", 1, "g", a)) return;
    if (!(a[0] > 0.0)) return error("gamma must be positive, got " + quoted(args_[0]));
    scene_.path.gamma = a[0];
  }

  // The light is kept here and becomes geometry at the end of file, when the integrator is
  // known (under `raytracer` it is ignored).
  void cmdQuadLight() {
    double a[12];
    if (!numbers("quadLight", 12, "ax ay az abx aby abz acx acy acz r g b", a)) return;
    QuadLight q;
    dvec3 corner{a[0], a[1], a[2]}, ab{a[3], a[4], a[5]}, ac{a[6], a[7], a[8]};
    q.a = toWorldPoint(corner);
    q.ab = toWorldPoint(corner + ab) - q.a;
    q.ac = toWorldPoint(corner + ac) - q.a;
    q.radiance = withinFloat("quadLight", {a[9], a[10], a[11]}, 9);
    q.line = line_;
    if (glm::cross(q.ac, q.ab) == dvec3(0.0))
      return error("degenerate quadLight: its sides ab and ac span no area" +
                   std::string(transform_ == dmat4(1.0) ? "" : " (under the current transform)"));
    pendingQuadLights_.push_back(q);
  }

  // What the integrator, known only now, does not use is ignored, with a warning at its line;
  // quad lights become two triangles each.
  void applyIntegrator() {
    const Integrator integrator = scene_.path.integrator;
    const std::string which = "integrator " + std::string(nameOf(integrator)) +
                              (integratorLine_ > 0 ? " (line " + std::to_string(integratorLine_) + ")" : " (the default)");
    IntegratorSet ignored = 0;   // bits per Command
    for (const auto& [cmd, line] : integratorCommands_) {
      if (integratorsUsing(cmd) & bit(integrator)) continue;
      ignored |= 1u << (static_cast<unsigned>(cmd) - static_cast<unsigned>(Command::Integrator));
      std::string why = cmd == Command::QuadLight && integrator == Integrator::Raytracer
                            ? " (the Whitted model has no area lights)"
                            : "";
      warnAt(line, WarningKind::NotForIntegrator,
             "'" + std::string(nameOf(cmd)) + "' ignored: " + which + " does not use it" + why);
    }
    auto isIgnored = [&](Command c) {
      return (ignored >> (static_cast<unsigned>(c) - static_cast<unsigned>(Command::Integrator))) & 1u;
    };
    // An ignored setting keeps the format's default, so that the scene says what is rendered.
    const PathSettings defaults;
    const Material defaultMaterial;
    if (isIgnored(Command::Spp)) scene_.path.spp = defaults.spp;
    if (isIgnored(Command::Gamma)) scene_.path.gamma = defaults.gamma;
    if (isIgnored(Command::LightSamples)) scene_.path.lightSamples = defaults.lightSamples;
    if (isIgnored(Command::LightStratify)) scene_.path.lightStratify = defaults.lightStratify;
    if (isIgnored(Command::NextEventEstimation)) scene_.path.nextEvent = defaults.nextEvent;
    if (isIgnored(Command::RussianRoulette)) scene_.path.russianRoulette = defaults.russianRoulette;
    if (isIgnored(Command::ImportanceSampling)) scene_.path.sampling = defaults.sampling;
    for (Material& m : scene_.materials) {
      if (isIgnored(Command::Brdf)) m.brdf = defaultMaterial.brdf;
      if (isIgnored(Command::Roughness)) m.roughness = defaultMaterial.roughness;
    }
    // The path integrators' Phong lobe, beyond what float32 resolves (kMaxPathShininess).
    if (integrator != Integrator::Raytracer) {
      for (int line : steepShininessLines_)
        warnAt(line, WarningKind::Clamped,
               "shininess clamped to 1e9 for " + which +
                   " (a lobe narrower than float32 resolves: the same picture, and finite)");
      for (Material& m : scene_.materials) m.shininess = std::min(m.shininess, kMaxPathShininess);
    }

    // `lightstratify on` cuts the light into sqrt(N) x sqrt(N) cells.
    if (lightStratifyLine_ > 0 && !isIgnored(Command::LightStratify) && !isPerfectSquare(scene_.path.lightSamples))
      errorAt(lightStratifyLine_, "'lightstratify on' needs a perfect square 'lightsamples', got " +
                                      std::to_string(scene_.path.lightSamples) + " (line " +
                                      std::to_string(lightSamplesLine_) + ")");

    // -1 (no limit) means nothing to the Whitted model: primary hit plus D reflections.
    if (unlimitedDepthLine_ > 0 && integrator == Integrator::Raytracer)
      errorAt(unlimitedDepthLine_, "'maxdepth' argument 1: expected a non-negative integer, got '-1': -1 (no limit) "
                                   "is for the path integrators, and " + which + " is the Whitted model");
    // -1 under the path tracer leaves Russian roulette as the only end of a path that stays in
    // the scene: without it, each such sample runs to the renderers' bounce limit.
    if (unlimitedDepthLine_ > 0 && integrator == Integrator::PathTracer && !scene_.path.russianRoulette)
      warnAt(unlimitedDepthLine_, WarningKind::EndlessPaths,
             "'maxdepth -1' (no limit) with 'russianroulette off': a path ends only when it leaves the scene, so in "
             "a closed scene every sample runs to the renderers' limit of tens of thousands of bounces; add "
             "'russianroulette on'");

    if (isIgnored(Command::QuadLight)) return;
    for (const QuadLight& q : pendingQuadLights_) addQuadLight(q);
  }

  // The light, its own material (emission L and nothing else), and two triangles a, a+ac,
  // a+ab+ac and a, a+ab+ac, a+ab: each has face normal cross(p1 - p0, p2 - p0) along
  // cross(ac, ab), the side that emits.
  void addQuadLight(const QuadLight& q) {
    const int index = static_cast<int>(scene_.quadLights.size());
    scene_.quadLights.push_back(q);
    Material m;
    m.ambient = m.diffuse = m.specular = dvec3(0.0);
    m.emission = q.radiance;
    m.quadLight = index;
    scene_.materials.push_back(m);
    const auto material = static_cast<std::uint32_t>(scene_.materials.size() - 1);
    const dvec3 a = q.a, b = q.a + q.ab, c = q.a + q.ab + q.ac, d = q.a + q.ac;
    for (const auto& corners : {std::array<dvec3, 3>{a, d, c}, std::array<dvec3, 3>{a, c, b}}) {
      Triangle t;
      for (int k = 0; k < 3; ++k) t.p[k] = corners[k];
      t.material = material;
      scene_.triangles.push_back(t);
    }
  }

  // A Whitted scene with no point or directional light shows only ambient and emission. Said
  // when a light would change the image: some surface has a diffuse or specular colour (the
  // course's scene2 and scene3 colour theirs with ambient alone, as their authors meant). At
  // the `size` line, as the scene's other whole-file diagnostics; quad lights are no light here.
  void warnIfUnlit() {
    if (!sawSize_ || scene_.path.integrator != Integrator::Raytracer || !scene_.lights.empty() ||
        shadedSurfaceLine_ == 0)
      return;
    const std::string ignoredQuads =
        pendingQuadLights_.empty()
            ? ""
            : " (its " + counted(pendingQuadLights_.size(), "quad light is", "quad lights are") +
                  " ignored: the Whitted model has no area lights; use 'point' or 'directional', or a path "
                  "integrator)";
    warnAt(firstSizeLine_, WarningKind::NoLights,
           "the scene has no lights: only ambient and emission light it" + ignoredQuads +
               "; the diffuse and specular colours of its surfaces (the first at line " +
               std::to_string(shadedSurfaceLine_) + ") stay dark");
  }

  // ---- end of file ------------------------------------------------------------------------
  void finish() {
    int last = line_ > 0 ? line_ : 1;
    if (!sawSize_) errorAt(1, "no 'size' command: the image size must be given ('size WIDTH HEIGHT')");
    if (cameraLine_ == 0) errorAt(last, "no 'camera' command in the scene");
    // The course's files put `size` first; its absence altogether is the error above.
    if (sawSize_ && beforeSizeLine_ > 0)
      warnAt(beforeSizeLine_, WarningKind::BeforeSize,
             "'" + std::string(beforeSizeCommand_) + "' before 'size' (line " + std::to_string(firstSizeLine_) +
                 "): accepted, though the format puts 'size' first");
    applyIntegrator();
    warnIfUnlit();
    // Unbalanced pushTransforms at the end are valid (SPEC section 8).
  }

  std::string_view text_;
  ParseOptions options_;
  SceneDesc scene_;
  std::vector<Diagnostic> diagnostics_;   // errors and warnings, as found
  int errorCount_ = 0;
  std::array<int, kWarningKinds> warnings_{}, suppressedFrom_{}, suppressedTo_{};   // per WarningKind
  int line_ = 0;
  bool binary_ = false;
  bool sawSize_ = false;
  int firstSizeLine_ = 0;
  int cameraLine_ = 0, maxDepthLine_ = 0;   // 0: not seen yet (the scene keeps the others)
  std::vector<int> steepShininessLines_;      // `shininess` lines above kMaxPathShininess
  int beforeSizeLine_ = 0;                  // the first command before `size`
  int shadedSurfaceLine_ = 0;               // the first object with a diffuse or specular colour
  int integratorLine_ = 0, lightSamplesLine_ = 0;
  int lightStratifyLine_ = 0;               // of the last `lightstratify`, when it said `on`
  int unlimitedDepthLine_ = 0;              // of the last `maxdepth`, when it said -1
  struct CommandLine {
    Command command;
    int line;
  };
  std::vector<CommandLine> integratorCommands_;   // the commands of SPEC-PATHTRACING section 1 but `integrator`
  std::vector<QuadLight> pendingQuadLights_;
  std::string_view beforeSizeCommand_;
  const std::string_view* args_ = nullptr;
  int argCount_ = 0;

  dmat4 transform_{1.0};
  std::vector<dmat4> stack_;
  Material material_;
  dvec3 attenuation_{1.0, 0.0, 0.0};
  std::vector<dvec3> vertices_;
  std::vector<VertexWithNormal> vertexNormals_;
};

}  // namespace

ParsedScene parseSceneWithWarnings(std::string_view text, const std::string& fileName, const ParseOptions& options) {
  ParsedScene parsed = Parser(text, fileName, options).run();
  Fnv1a64 hash;
  hash.add(text);
  parsed.scene.sourceHash = hash.value();
  return parsed;
}

SceneDesc parseScene(std::string_view text, const std::string& fileName) {
  return parseSceneWithWarnings(text, fileName).scene;
}

SceneDesc parseSceneFile(const std::string& path) { return parseSceneFileWithWarnings(path).scene; }

namespace {

// Closes a file descriptor when it goes out of scope.
struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

SceneError readLimitError(const std::string& path, int line, std::string message) {
  return SceneError({{path, line, std::move(message) + "; is this a scene file?", Severity::Error}});
}

// The text of the scene file `path`, read with read(2) in chunks of at most a mebibyte:
//  - a signal that interrupts an open or a read (Ctrl-C while a FIFO waits for its writer)
//    ends it as Interrupted (interrupt.h), where vkrt's handler caught it; any other
//    interruption is retried;
//  - reading stops at the first byte that is not text, kept as the last byte, so that the
//    parser says where it is (a device like /dev/zero: at once);
//  - a line longer than kMaxSceneLineBytes, or a file longer than kMaxSceneFileBytes, is a
//    SceneError at that line, found as soon as the bytes past the limit are read (a regular
//    file's size is checked before reading).
std::string readSceneText(const std::string& path) {
  const std::string name = abbreviated(path);
  FileDescriptor file;
  while ((file.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC)) < 0) {
    if (errno != EINTR) throw IoError("cannot open scene file '" + name + "': " + std::strerror(errno));
    throwIfInterrupted();
  }
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) throw IoError("cannot read scene file '" + name + "': " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw IoError("cannot read scene file '" + name + "': " + std::strerror(EISDIR));
  std::string text;
  if (S_ISREG(st.st_mode)) {
    if (static_cast<unsigned long long>(st.st_size) > kMaxSceneFileBytes)
      throw readLimitError(path, 0,
                           "the file is " + std::to_string(st.st_size) + " bytes, more than the " +
                               std::to_string(kMaxSceneFileBytes) + " (1 GiB) a scene file may hold");
    text.reserve(static_cast<std::size_t>(st.st_size));   // one buffer of its size: no regrowth, no copies
  }
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  std::size_t scanned = 0, lineStart = 0;
  int line = 1;
  char probe[1 << 16];   // the read that finds the end of a buffer filled to its reserved size
  for (;;) {
    throwIfInterrupted();
    const std::size_t size = text.size();
    const std::size_t room = std::min(text.capacity() - size, kChunk);
    ssize_t n = 0;
    int readError = 0;
    if (room > 0) {
      text.resize(size + room);
      n = ::read(file.fd, text.data() + size, room);
      readError = errno;
      text.resize(size + static_cast<std::size_t>(std::max<ssize_t>(n, 0)));
    } else {
      n = ::read(file.fd, probe, sizeof probe);
      readError = errno;
      if (n > 0) {
        // A stream (or a file that grew): grow by doubling, never much past the limit.
        std::size_t want = std::max(text.capacity() * 2, size + kChunk);
        text.reserve(std::min(want, kMaxSceneFileBytes + kChunk));
        text.append(probe, static_cast<std::size_t>(n));
      }
    }
    if (n < 0) {
      if (readError == EINTR) continue;   // the loop's first line ends it when a signal asked to stop
      throw IoError("cannot read scene file '" + name + "': " + std::strerror(readError));
    }
    if (n == 0) break;
    // Up to the first byte past the file's limit, whose line is then the one reported.
    const std::size_t end = std::min(text.size(), kMaxSceneFileBytes);
    bool longLine = false;
    for (; scanned < end; ++scanned) {
      const char c = text[scanned];
      if (c == '\n') {
        if ((longLine = scanned - lineStart > kMaxSceneLineBytes)) break;
        ++line;
        lineStart = scanned + 1;
      } else if (byteClass(c) == kBinary) {
        text.resize(scanned + 1);   // the parser reports it
        return text;
      }
    }
    if (longLine || scanned - lineStart > kMaxSceneLineBytes)
      throw readLimitError(path, line,
                           "the line is longer than " + std::to_string(kMaxSceneLineBytes) +
                               " bytes (1 MiB), the most a line of a scene file may hold");
    if (text.size() > kMaxSceneFileBytes)
      throw readLimitError(path, line,
                           "the file goes on past " + std::to_string(kMaxSceneFileBytes) +
                               " bytes (1 GiB), the most a scene file may hold");
  }
  return text;
}

}  // namespace

ParsedScene parseSceneFileWithWarnings(const std::string& path, const ParseOptions& options) {
  return parseSceneWithWarnings(readSceneText(path), path, options);
}

}  // namespace vkrt
