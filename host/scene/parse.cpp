// Scene file parser: .test text -> SceneDesc (doc/scene-format.md; doc/path-tracing.md,
// "Commands" and "Quad lights"). The tokenizer gives each line's words, this file dispatches
// each command to its handler, and finish_scene.cpp ends the scene after the last one; the
// diagnostics of all three go to one DiagnosticLog. Parser-only state (transform stack,
// current material, vertex lists) stays in this file.
#include "scene/parse.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>

#include "util/hash.h"
#include "scene/arguments.h"
#include "scene/commands.h"
#include "scene/diagnostic_log.h"
#include "scene/finish_scene.h"
#include "scene/integrator_table.h"
#include "scene/linear_map.h"
#include "scene/scene_file.h"
#include "scene/shapes/shape_command.h"
#include "scene/shapes/shape_list.h"
#include "scene/tokenizer.h"
#include "scene/unit_vector.h"
#include "util/suggest.h"

namespace vkrt {
namespace {

// Values that render finite on both backends (doc/robustness.md, "Numerical robustness"): a colour or
// radiance channel beyond float32 (the Vulkan backend's precision) is clamped to the largest
// float; a GGX roughness above kMaxRoughness (alpha^4 would overflow float32; the lobe is as
// flat at 1e4 as beyond) is clamped to that, one above 0 but below kMinRoughness raised to it,
// and so, for the path integrators, is a Phong exponent above kMaxPathShininess
// (finish_scene.h) clamped. Each with a warning at its line.
constexpr double kMaxColour = 3.4028234663852886e38;   // the largest float
constexpr double kMaxRoughness = 1e4;
// Below this a GGX lobe is narrower than float32 resolves: the Vulkan backend's D overflowed
// to NaN pixels (1e-22 to 1e-12) or drew the lobe dark (1e-6; measured: the two backends agree
// to 0/255 at 1e-5 with BRDF sampling). At 1e-4 the lobe is already narrower than a pixel
// of any usual view (0 stays 0: no lobe, doc/path-tracing.md).
constexpr double kMinRoughness = 1e-4;

// The path integrators' settings that hold for the whole scene, whose last line counts (the
// material commands `brdf` and `roughness` are state, and `quadLight` adds a light each time);
// all are among kIntegratorSettings, whose lines the parser keeps.
constexpr CommandSet kSceneSettings = commandSet({Command::Spp, Command::LightSamples, Command::LightStratify,
                                                  Command::NextEventEstimation, Command::RussianRoulette,
                                                  Command::ImportanceSampling, Command::Gamma});
static_assert((kSceneSettings & ~kIntegratorSettings) == 0, "a scene setting whose lines the parser keeps");

// The keyword values of doc/path-tracing.md, "Commands", in the order of their enums (those of
// `integrator`: kIntegratorNames, integrator_table.h; kNextEventNames, kSamplingNames:
// scene_desc.h).
constexpr std::string_view kBrdfNames[] = {"phong", "ggx"};
constexpr std::string_view kOnOffNames[] = {"on", "off"};

// Beyond this magnitude, squares and products of lengths come near the largest double
// (1.8e308, the square of 1.34e154), and the picture no longer follows the scene
// (doc/robustness.md, "Where and how big a scene may be"). Measured: a sphere around the
// camera and a scene scaled up render as they should up to 1e154 and are wrong from 2e154
// (the CPU backend first); a margin of 10 leaves room for differences and sums of squares.
constexpr double kMaxExactMagnitude = 1e153;
// The other end: a shape less than this across has squares of lengths below the smallest
// normal double (2.2e-308, the square of 1.5e-154), which lose their bits and then vanish.
// Measured: a sphere of radius 1e-161 around the camera renders right on the CPU backend, one
// of 1e-162 wrong (its squares below the smallest double); the Vulkan backend's float frame
// is scaled to the scene and renders both right.
constexpr double kMinExactSize = 1e-153;

// The largest magnitude among the coordinates of box (lo, hi): infinite when one is not finite.
double largestMagnitude(const dvec3& lo, const dvec3& hi) {
  double m = 0.0;
  for (int i = 0; i < 3; ++i)
    for (double v : {lo[i], hi[i]}) m = std::isfinite(v) ? std::max(m, std::abs(v)) : HUGE_VAL;
  return m;
}

// What a shape's box says of its precision: the largest magnitude among its coordinates, and
// its largest side.
struct ShapeExtent {
  double magnitude = 0.0, size = 0.0;
};
template <class Shape>
ShapeExtent shapeExtent(const Shape& shape) {
  dvec3 lo, hi;
  shapes::bounds(shape, lo, hi);
  const dvec3 side = hi - lo;
  return {largestMagnitude(lo, hi), std::max({side.x, side.y, side.z})};
}

// The shapes' own commands (shapes/shape_list.h): each reads its shape in the shape's file
// and adds it to its array, and returns the extent of the shape's box (0 when it added none).
struct ShapeCommandRow {
  std::string_view name;
  ShapeExtent (*read)(const ShapeCommand&, SceneDesc&);
};
#define VKRT_SHAPE_COMMAND(name, read, member)                                 \
  ShapeCommandRow{name, [](const ShapeCommand& c, SceneDesc& s) -> ShapeExtent { \
    auto shape = read(c);                                                       \
    if (!shape) return {};                                                      \
    s.member.push_back(*shape);                                                 \
    return shapeExtent(*shape);                                                 \
  }},
constexpr ShapeCommandRow kShapeCommands[] = {VKRT_SHAPE_COMMANDS(VKRT_SHAPE_COMMAND)};
#undef VKRT_SHAPE_COMMAND

// Every command's name, for lookup and suggestions: kCommandNames with the shapes' commands
// between `camera` and `maxverts`, where the format lists `sphere` (a suggestion breaks a tie
// by this order: `spare` is nearest to `sphere`, and as near to `scale`).
constexpr std::size_t kCommandCount = std::size(kCommandNames);
constexpr std::size_t kShapeCommandCount = std::size(kShapeCommands);
constexpr std::size_t kShapeCommandsAt = static_cast<std::size_t>(Command::MaxVerts);
constexpr auto kAllCommandNames = [] {
  std::array<std::string_view, kCommandCount + kShapeCommandCount> names{};
  std::size_t i = 0;
  for (std::size_t c = 0; c < kCommandCount; ++c) {
    if (c == kShapeCommandsAt)
      for (const ShapeCommandRow& row : kShapeCommands) names[i++] = row.name;
    names[i++] = kCommandNames[c];
  }
  return names;
}();

// What index i of kAllCommandNames names: a Command, or a row of kShapeCommands.
bool isShapeCommand(std::size_t i) { return i >= kShapeCommandsAt && i < kShapeCommandsAt + kShapeCommandCount; }
const ShapeCommandRow& shapeCommandAt(std::size_t i) { return kShapeCommands[i - kShapeCommandsAt]; }
Command commandAt(std::size_t i) { return static_cast<Command>(i < kShapeCommandsAt ? i : i - kShapeCommandCount); }

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
  // `crLineEnds`: the text's lone CRs were made line ends (parseSceneWithWarnings), which the
  // parser warns of.
  Parser(std::string_view text, const std::string& fileName, const ParseOptions& options, bool crLineEnds = false)
      : text_(text),
        tokenizer_(text),
        log_(fileName, options.strict),
        args_(log_),
        outputOverridden_(options.outputOverridden),
        outputNameProblem_(options.outputNameProblem),
        crLineEnds_(crLineEnds) {
    scene_.sourcePath = fileName;
  }

  ParsedScene run() {
    reserveArrays();
    if (crLineEnds_)
      log_.warn(1, WarningKind::LineEnds,
                "the lines end in CR alone (classic Mac OS), not LF or CRLF: each CR read as a line end");
    parseLines();
    std::vector<Diagnostic> warnings = log_.close();
    return {std::move(scene_), std::move(warnings)};
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

  // Each line's command, until the end of the text (then the scene is finished), the first
  // byte that is not text, or too many errors.
  void parseLines() {
    TokenLine line;
    while (!log_.full()) {
      switch (tokenizer_.next(line)) {
        case Tokenizer::Status::Line: dispatch(line); break;
        case Tokenizer::Status::End:
          return finishScene(scene_, deferred_, std::max(tokenizer_.lineNumber(), 1), log_);
        case Tokenizer::Status::NotText: return log_.onlyError(tokenizer_.lineNumber(), tokenizer_.notTextMessage());
      }
    }
  }

  void error(std::string message) { log_.error(line_, std::move(message)); }
  void warn(WarningKind kind, std::string message) { log_.warn(line_, kind, std::move(message)); }

  // Commands of other courses' extensions are skipped, and a known keyword in another case
  // is read as that keyword, each with a warning (doc/scene-format.md, "Warnings"). The
  // warning for an unknown command names the nearest command when one is near enough to be a
  // typo (`sphre`). A settings command's line is kept for the end of file, where the
  // integrator is known (finish_scene.cpp).
  void dispatch(const TokenLine& line) {
    line_ = line.number;
    args_.of(line);
    const std::string_view name = line.command();
    std::optional<std::size_t> known = indexNamed(kAllCommandNames, name);
    if (!known) {
      known = indexNamedIgnoringCase(kAllCommandNames, name);
      if (!known)
        return warn(WarningKind::UnknownCommand,
                    "unknown command " + quoted(name) + " (line skipped)" + didYouMean(name, kAllCommandNames));
      warn(WarningKind::KeywordCase, quoted(name) + " read as '" + std::string(kAllCommandNames[*known]) +
                                         "' (keywords are case-sensitive)");
    }
    const bool shape = isShapeCommand(*known);
    const bool size = !shape && commandAt(*known) == Command::Size;
    if (deferred_.firstSizeLine == 0 && deferred_.beforeSizeLine == 0 && !size) {
      deferred_.beforeSizeLine = line_;
      deferred_.beforeSizeCommand = kAllCommandNames[*known];
    }
    if (shape) return readShape(shapeCommandAt(*known));
    const Command cmd = commandAt(*known);
    if (contains(kSceneSettings, cmd)) noteRepeat(nameOf(cmd), lastSettingLine(cmd));
    if (contains(kIntegratorSettings, cmd)) deferred_.settings.push_back({cmd, line_});
    switch (cmd) {
      case Command::Vertex: return cmdVertex();
      case Command::Tri: return cmdTri();
      case Command::VertexNormal: return cmdVertexNormal();
      case Command::TriNormal: return cmdTriNormal();
      case Command::Size: return cmdSize();
      case Command::MaxDepth: return cmdMaxDepth();
      case Command::Output: return cmdOutput();
      case Command::Camera: return cmdCamera();
      case Command::MaxVerts:
      case Command::MaxVertNorms: return cmdSizeHint(nameOf(cmd));
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
        if (cmdSampleCount(cmd, scene_.path.lightSamples)) deferred_.lightSamplesLine = line_;
        return;
      case Command::Spp: return static_cast<void>(cmdSampleCount(cmd, scene_.path.spp));
      case Command::LightStratify:
        if (cmdOnOff(cmd, scene_.path.lightStratify)) deferred_.lightStratifyLine = scene_.path.lightStratify ? line_ : 0;
        return;
      case Command::RussianRoulette: return static_cast<void>(cmdOnOff(cmd, scene_.path.russianRoulette));
      case Command::NextEventEstimation:
        return static_cast<void>(args_.keyword(nameOf(cmd), kNextEventNames, scene_.path.nextEvent));
      case Command::ImportanceSampling:
        return static_cast<void>(args_.keyword(nameOf(cmd), kSamplingNames, scene_.path.sampling));
      case Command::Brdf: return static_cast<void>(args_.keyword(nameOf(cmd), kBrdfNames, material_.brdf));
      case Command::Roughness: return cmdRoughness();
      case Command::Gamma: return cmdGamma();
      case Command::Count: break;
    }
  }

  // A repeated `size`, `camera`, `maxdepth`, `output`, `integrator` or scene-wide path setting
  // (kSceneSettings): the last one counts. `previousLine` is the line of the one before (0: none).
  void noteRepeat(std::string_view cmd, int previousLine) {
    if (previousLine > 0)
      warn(WarningKind::Repeated, "'" + std::string(cmd) + "' given again (before at line " +
                                      std::to_string(previousLine) + "): the last one counts");
  }

  // The line of the last settings command `cmd` so far (deferred_.settings), or 0.
  int lastSettingLine(Command cmd) const {
    for (auto s = deferred_.settings.rbegin(); s != deferred_.settings.rend(); ++s)
      if (s->command == cmd) return s->line;
    return 0;
  }

  // ---- commands ---------------------------------------------------------------------------
  void cmdSize() {
    double a[2];
    noteRepeat("size", scene_.sizeLine);
    if (deferred_.firstSizeLine == 0) deferred_.firstSizeLine = line_;
    scene_.sizeLine = line_;
    if (!args_.numbers("size", 2, "width height", a)) return;
    const std::string range = "an integer from 1 to " + std::to_string(kMaxImageEdge);
    auto w = args_.integer("size", a[0], 0, range.c_str(), 1, kMaxImageEdge);
    auto h = args_.integer("size", a[1], 1, range.c_str(), 1, kMaxImageEdge);
    if (w && h) {
      scene_.width = static_cast<int>(*w);
      scene_.height = static_cast<int>(*h);
    }
  }

  void cmdMaxDepth() {
    double a[1];
    noteRepeat("maxdepth", maxDepthLine_);
    maxDepthLine_ = line_;
    if (!args_.numbers("maxdepth", 1, "depth", a)) return;
    // -1 (no limit) is for the path integrators; the integrator is known at the end of file.
    if (auto d = args_.integer("maxdepth", a[0], 0, "a non-negative integer, or -1 (no limit)", -1, 1'000'000)) {
      scene_.maxDepth = static_cast<int>(*d);
      deferred_.unlimitedDepthLine = *d == -1 ? line_ : 0;
    }
  }

  void cmdOutput() {
    const char* usage = "a file name without spaces";
    noteRepeat("output", scene_.outputLine);
    if (args_.count() < 1) {
      error(std::string("'output' expects 1 argument (") + usage + "), got 0");
      return;
    }
    args_.ignoreExtra("output", 1, usage);
    std::string_view name = args_[0];
    // (A scene file's name is an error at this line when the output is checked, and alone.)
    if (!outputOverridden_ && outputNameProblem_) {
      const std::string problem = outputNameProblem_(std::string(name));
      if (!problem.empty()) warn(WarningKind::OutputName, "output file " + quoted(name) + " " + problem);
    }
    scene_.output = std::string(name);
    scene_.outputLine = line_;
  }

  void cmdCamera() {
    double a[10];
    noteRepeat("camera", deferred_.cameraLine);
    deferred_.cameraLine = line_;
    if (!args_.numbers("camera", 10, "fromx fromy fromz atx aty atz upx upy upz fovy", a)) return;
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
    if (ok) {
      scene_.camera = c;
      warnBeyondExactRange("camera", largestMagnitude(glm::min(c.from, c.at), glm::max(c.from, c.at)));
    }
  }

  std::uint32_t currentMaterial() {
    if (deferred_.shadedSurfaceLine == 0 && (material_.diffuse != dvec3(0.0) || material_.specular != dvec3(0.0)))
      deferred_.shadedSurfaceLine = line_;
    if (scene_.materials.empty() || !(scene_.materials.back() == material_))
      scene_.materials.push_back(material_);
    return static_cast<std::uint32_t>(scene_.materials.size() - 1);
  }

  // A shape's own command, read in its file with what it takes of the parser's state.
  void readShape(const ShapeCommandRow& row) {
    const ShapeCommand command{args_, [this](std::string message) { error(std::move(message)); }, transform_,
                               [this] { return currentMaterial(); }};
    warnOutsideExactRange(row.name, row.read(command, scene_));
  }

  // A shape beyond kMaxExactMagnitude or smaller than kMinExactSize (a point, of size 0, is
  // another matter): rendered, with a warning.
  void warnOutsideExactRange(std::string_view what, const ShapeExtent& extent) {
    warnBeyondExactRange(what, extent.magnitude);
    if (!(extent.size > 0.0 && extent.size < kMinExactSize)) return;
    char m[32];
    std::snprintf(m, sizeof m, "%.3g", extent.size);
    warn(WarningKind::Magnitude, "'" + std::string(what) + "' is " + m +
                                     " across, below 1e-153, where squares of lengths fall below the smallest normal "
                                     "double: the picture may not show it; scale the scene up");
  }

  // A shape or camera whose coordinates lie beyond kMaxExactMagnitude: rendered, with a warning.
  void warnBeyondExactRange(std::string_view what, double magnitude) {
    if (!(magnitude > kMaxExactMagnitude)) return;
    char m[32];
    std::snprintf(m, sizeof m, "%.3g", magnitude);
    warn(WarningKind::Magnitude, "'" + std::string(what) + "' reaches coordinates of " + m +
                                     ", beyond 1e153, where squares of lengths come near the largest double: the "
                                     "picture may not show the scene; scale the scene down");
  }

  void cmdSizeHint(std::string_view cmd) {
    double a[1];
    if (!args_.numbers(cmd, 1, "count", a)) return;
    args_.integer(cmd, a[0], 0, "a non-negative integer", 0, 1LL << 40);
  }

  void cmdVertex() {
    double a[3];
    if (!args_.numbers("vertex", 3, "x y z", a)) return;
    vertices_.push_back({a[0], a[1], a[2]});
  }

  void cmdVertexNormal() {
    double a[6];
    if (!args_.numbers("vertexnormal", 6, "x y z nx ny nz", a)) return;
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
    if (!args_.numbers(cmd, 3, "i j k", a)) return false;
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
    addTriangle(t, "tri");
  }

  void addTriangle(Triangle& t, std::string_view cmd) {
    t.material = currentMaterial();
    warnOutsideExactRange(cmd, shapeExtent(t));
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
    addTriangle(t, "trinormal");
  }

  void cmdTranslate() {
    double a[3];
    if (!args_.numbers("translate", 3, "x y z", a)) return;
    applyTransform(glm::translate(transform_, dvec3(a[0], a[1], a[2])), "translate");
  }

  void cmdRotate() {
    double a[4];
    if (!args_.numbers("rotate", 4, "axisx axisy axisz angle", a)) return;
    dvec3 axis{a[0], a[1], a[2]};
    if (axis == dvec3(0.0)) {
      error("rotate axis must not be zero");
      return;
    }
    applyTransform(transform_ * rotation(unitVector(axis), glm::radians(a[3])), "rotate");
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
    if (!args_.numbers("scale", 3, "x y z", a)) return;
    applyTransform(glm::scale(transform_, dvec3(a[0], a[1], a[2])), "scale");
  }

  // The current transform becomes `next`, unless a product overflowed (a scale of 1e200 twice,
  // a translation beyond a double): an error at this line, and the transform stays as it was,
  // so that the shapes after it are not refused for what is this line's fault.
  void applyTransform(const dmat4& next, const char* command) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(next[c][r])) {
          error(std::string("'") + command + "' makes the current transform overflow (an entry beyond " +
                "1.8e308, the largest double): the shapes after it could not be placed");
          return;
        }
    transform_ = next;
  }

  void cmdPush() {
    args_.ignoreExtra("pushTransform", 0, "");
    stack_.push_back(transform_);
  }

  void cmdPop() {
    args_.ignoreExtra("popTransform", 0, "");
    if (stack_.empty()) return error("popTransform with an empty transform stack (no matching pushTransform)");
    transform_ = stack_.back();
    stack_.pop_back();
  }

  void cmdLight(bool point) {
    double a[6];
    const char* cmd = point ? "point" : "directional";
    if (!args_.numbers(cmd, 6, "x y z r g b", a)) return;
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
    if (!args_.numbers("attenuation", 3, "constant linear quadratic", a)) return;
    if (a[0] < 0 || a[1] < 0 || a[2] < 0 || (a[0] == 0 && a[1] == 0 && a[2] == 0)) {
      error("attenuation terms must be non-negative and not all zero");
      return;
    }
    attenuation_ = {a[0], a[1], a[2]};
  }

  void cmdColor(std::string_view cmd, dvec3& target) {
    double a[3];
    if (!args_.numbers(cmd, 3, "r g b", a)) return;
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
    if (!args_.numbers("shininess", 1, "s", a)) return;
    if (a[0] < 0.0) return error("shininess must not be negative, got " + quoted(args_[0]));
    material_.shininess = a[0];
    // (clamped at the end of file for the path integrators)
    if (a[0] > kMaxPathShininess) deferred_.steepShininessLines.push_back(line_);
  }

  // ---- path tracing (doc/path-tracing.md, "Commands") ----------------------------------------
  bool cmdOnOff(Command cmd, bool& value) {
    int v = value ? 0 : 1;   // the index in kOnOffNames
    if (!args_.keyword(nameOf(cmd), kOnOffNames, v)) return false;
    value = v == 0;
    return true;
  }

  void cmdIntegrator() {
    noteRepeat("integrator", deferred_.integratorLine);
    Integrator i = scene_.path.integrator;
    if (args_.keyword(nameOf(Command::Integrator), kIntegratorNames, i)) {
      scene_.path.integrator = i;
      deferred_.integratorLine = line_;
    }
  }

  // `spp`, `lightsamples`: a count of samples, at least 1.
  bool cmdSampleCount(Command cmd, int& value) {
    double a[1];
    std::string name(nameOf(cmd));
    if (!args_.numbers(name, 1, "N", a)) return false;
    auto n = args_.integer(name, a[0], 0, "an integer from 1 to 1000000000", 1, 1'000'000'000);
    if (n) value = static_cast<int>(*n);
    return n.has_value();
  }

  void cmdRoughness() {
    double a[1];
    if (!args_.numbers("roughness", 1, "alpha", a)) return;
    if (a[0] < 0.0) return error("roughness must not be negative, got " + quoted(args_[0]));
    material_.roughness = a[0];
    if (a[0] > kMaxRoughness) {
      warn(WarningKind::Clamped, "roughness " + quoted(args_[0]) +
                                     " clamped to 1e4 (GGX is as flat there as beyond, and float32 would overflow)");
      material_.roughness = kMaxRoughness;
    } else if (a[0] > 0.0 && a[0] < kMinRoughness) {
      warn(WarningKind::Clamped, "roughness " + quoted(args_[0]) +
                                     " clamped to 1e-4 (a lobe narrower than float32 resolves: the same picture, "
                                     "and finite)");
      material_.roughness = kMinRoughness;
    }
  }

  void cmdGamma() {
    double a[1];
    if (!args_.numbers("gamma", 1, "g", a)) return;
    if (!(a[0] > 0.0)) return error("gamma must be positive, got " + quoted(args_[0]));
    scene_.path.gamma = a[0];
  }

  // The light is kept here and becomes geometry at the end of file, when the integrator is
  // known (under `raytracer` it is ignored).
  void cmdQuadLight() {
    double a[12];
    if (!args_.numbers("quadLight", 12, "ax ay az abx aby abz acx acy acz r g b", a)) return;
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
    deferred_.quadLights.push_back(q);
  }

  std::string_view text_;
  Tokenizer tokenizer_;
  DiagnosticLog log_;
  Arguments args_;   // the arguments of the line being read
  bool outputOverridden_;   // ParseOptions::outputOverridden
  std::string (*outputNameProblem_)(const std::string&);   // ParseOptions::outputNameProblem
  bool crLineEnds_;
  SceneDesc scene_;
  Deferred deferred_;
  int line_ = 0;   // the line being read
  int maxDepthLine_ = 0;   // 0: not seen yet (the scene keeps the other commands' lines)

  dmat4 transform_{1.0};
  std::vector<dmat4> stack_;
  Material material_;
  dvec3 attenuation_{1.0, 0.0, 0.0};
  std::vector<dvec3> vertices_;
  std::vector<VertexWithNormal> vertexNormals_;
};

}  // namespace

ParsedScene parseSceneWithWarnings(std::string_view text, const std::string& fileName, const ParseOptions& options) {
  // A file without an LF whose lines end in CR alone would read as one line: its CRs end lines.
  const std::size_t firstCr = text.find('\r');
  const bool crLineEnds = firstCr != std::string_view::npos && firstCr + 1 < text.size() &&
                          text.find('\n') == std::string_view::npos;
  std::string lines;
  if (crLineEnds) {
    lines.assign(text);
    std::replace(lines.begin(), lines.end(), '\r', '\n');
  }
  ParsedScene parsed = Parser(crLineEnds ? std::string_view(lines) : text, fileName, options, crLineEnds).run();
  Fnv1a64 hash;
  hash.add(text);
  parsed.scene.sourceHash = hash.value();
  return parsed;
}

SceneDesc parseScene(std::string_view text, const std::string& fileName) {
  return parseSceneWithWarnings(text, fileName).scene;
}

SceneDesc parseSceneFile(const std::string& path) { return parseSceneFileWithWarnings(path).scene; }

ParsedScene parseSceneFileWithWarnings(const std::string& path, const ParseOptions& options) {
  return parseSceneWithWarnings(readSceneText(path), path, options);
}

}  // namespace vkrt
