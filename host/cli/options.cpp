// Command-line parsing for `vkrt`.
#include "cli/options.h"

#include <algorithm>
#include <filesystem>
#include <charconv>
#include <cmath>
#include <functional>
#include <cstdlib>
#include <span>
#include <string_view>

#include <sys/stat.h>

#include "cli/image_argument.h"
#include "image/crop.h"
#include "image/image_file.h"
#include "scene/diagnostic.h"   // echoed, abbreviated
#include "scene/parse.h"        // kMaxImageEdge
#include "suggest.h"

namespace vkrt {

namespace {

constexpr std::size_t kHelpWidth = 88;
const std::string kHelpIndent(25, ' ');

// `text` filled into lines of at most kHelpWidth characters (a longer word alone on its
// line), the first after `first`, the others after `indent`; each line ends in a newline.
std::string filled(const std::string& first, const std::string& indent, const std::string& text) {
  std::string out, line = first;
  bool empty = true;   // no word on `line` yet
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t space = std::min(text.find(' ', at), text.size());
    const std::string word = text.substr(at, space - at);
    at = space + 1;
    if (!empty && line.size() + 1 + word.size() > kHelpWidth) {
      out += line + "\n";
      line = indent, empty = true;
    }
    line += (empty ? "" : " ") + word;
    empty = false;
  }
  return out + line + "\n";
}

// "PNG/PPM": the names of `which` joined by '/'.
std::string slashed(FormatsOf which) {
  std::string text;
  for (const std::string& name : imageFormatNames(which)) text += (text.empty() ? "" : "/") + name;
  return text;
}

// The first linear-float format's extension: a float file's name in the examples.
std::string floatExtension() {
  for (const ImageFormat& format : imageFormats())
    if (format.linearFloat) return "." + std::string(format.extensions.front());
  return "";
}

// "PNG, or PPM for FILE.ppm": what the 8-bit heatmap is written as, by name.
std::string heatmapNamesText() {
  std::string others;
  for (const ImageFormat& format : imageFormats())
    if (!format.linearFloat && &format != &imageFormats().front())
      others += (others.empty() ? "" : ", ") + std::string(format.name) + " for FILE." +
                std::string(format.extensions.front());
  return std::string(imageFormats().front().name) + (others.empty() ? "" : ", or " + others);
}

std::string makeUsageText() {
  const std::string ext = defaultImageExtension(), floatExt = floatExtension();
  const std::string floats = imageFormatNamesText(FormatsOf::LinearFloat), standard = imageFormatNames().front();
  return "usage: vkrt [options] SCENE.test [SCENE.test ...]\n"
         "       vkrt diff [comparison options] A" + ext + " B" + ext + "\n"
         "       vkrt merge [--allow-gaps] [--strict] -o OUT" + ext + "|OUT" + floatExt + " TILE [TILE ...]   (all " +
         slashed(FormatsOf::Bytes) + " or all " + slashed(FormatsOf::LinearFloat) + ")\n"
         "       vkrt merge -o OUT" + floatExt + "|OUT" + ext + " BATCH" + floatExt + " [BATCH" + floatExt + " ...]\n"
         "       vkrt convert IN OUT   (any of " + imageExtensionsText() + " to any; JPEG in)\n"
         "       vkrt grade [grade options] REFS/ SUBMISSIONS/|SCENE.test ... -o REPORT/\n"
         "\n"
         "Renders CSE167 (and CSE168) scene files to " + imageFormatNamesText() + " images;\n"
         "compares and converts images.\n"
         "Several scenes are rendered in one run, one line each, then a summary; the exit\n"
         "status is then the highest of theirs.\n"
         "\n"
         "options:\n"
         "  -o, --output FILE      write the image to FILE (overrides the scene's 'output');\n" +
         filled(kHelpIndent, kHelpIndent,
                imageNamesHelpText("FILE") +
                    ". An existing FILE is replaced whole, keeping its permissions; a symbolic link is "
                    "written through. Refused: '-', a file the run reads, a device, FIFO or directory, a "
                    "file with several hard links") +
         "  -o, --output DIR/      write each image into DIR (a trailing '/'): under the file name\n"
         "                         of the scene's 'output', or the scene's stem + " + ext + " without one\n"
         "  --size WxH             render at W x H pixels instead of the scene's size (same camera)\n"
         "  --scale F              render at the scene's size times F (rounded, at least 1x1)\n"
         "  --crop X0,Y0,X1,Y1     render only the pixels [X0,X1) x [Y0,Y1) of the full image (the\n"
         "                         same pixels as a full render), as an image of the crop's size\n"
         "                         that records where it lies, for vkrt merge\n"
         "  --backend vulkan|cpu   renderer: 'vulkan' (default: a compute shader on a GPU, or on\n"
         "                         the CPU through lavapipe) or 'cpu' (the double-precision reference)\n"
         "  --device N|NAME        Vulkan device by index or part of its name (see --list-devices);\n"
         "                         default: a discrete or integrated GPU if present, else the CPU\n"
         "  --list-devices         list the Vulkan devices and exit\n"
         "  --validation           enable the Vulkan validation layer (also VKRT_VALIDATION=1)\n"
         "  --reads auto|texel|storage  how the shader reads the scene (default auto: texel\n"
         "                         buffers, faster on lavapipe, where the device's limits allow)\n"
         "  --variant auto|specialized|general  the compiled shader: default auto, specialised\n"
         "                         where worth its compile (or, on a CPU device, compiled before)\n"
         "  --maxdepth N           override the scene's maxdepth (fewer reflections: faster, less exact)\n"
         "  --spp N                path integrators: N samples per pixel instead of the scene's spp\n"
         "  --seed N               path integrators: the random numbers' seed, 0 to 4294967295\n"
         "                         (default 0); another seed gives independent samples\n"
         "  --sampler independent|stratified  path integrators: each sample's numbers independent\n"
         "                         (default, as the scene rules say) or stratified across a pixel's\n"
         "                         samples (camera jitter, each bounce's direction and first light\n"
         "                         sample): less noise\n"
         "  --estimator scene|best  pathtracer: the scene's importancesampling and\n"
         "                         nexteventestimation (default), or BRDF sampling and MIS: the\n"
         "                         same image, usually less noisy\n"
         "  --time SECONDS         path integrators: render batches of samples until the time is up,\n"
         "                         then write (at most --spp samples when given, else no limit);\n"
         "                         the samples taken are reported\n"
         "  --cutoff auto|on|off   Vulkan: stop mirror paths that can no longer change the 8-bit\n"
         "                         result (same image); auto: where it can stop paths early\n"
         "  --no-cutoff            the same as --cutoff off\n"
         "  --threads N            worker threads for the CPU backend (default: all cores)\n"
         "  --stats                print a timing breakdown and ray counts on stderr\n"
         "  --check REF" + ext + "        compare the rendered image with REF" + ext + " (exit 5 when it fails);\n"
         "                         REF is read before the render (exit 4 when it cannot be)\n"
         "  --compare              render with both backends (nothing written) and print each\n"
         "                         one's times and the difference between their images\n"
         "  --watch                render, then render again each time the scene file changes (one\n"
         "                         process: the device and compiled shaders kept); a path-traced\n"
         "                         scene refines with more samples until the next change; Ctrl-C ends\n"
         "  --dry-run              parse each scene and check its output as a render would (the\n"
         "                         same errors and exit status), print where its image would go;\n"
         "                         open no device, render and write nothing\n"
         "  --strict               every warning is an error, nothing written: the scene's (exit 2:\n"
         "                         unknown commands, repeated commands and the like, NaN pixels)\n"
         "                         and the command line's (exit 1: --spp for a Whitted scene, an\n" +
         filled(kHelpIndent, kHelpIndent, "output name not " + imageExtensionsText() + ")") +
         "\n"
         "comparison options (diff, --check and --compare):\n"
         "  --max-pixels-over S:L  fail when more than L pixels (a count, or a share with %,\n"
         "                         e.g. 2:0.1%) differ by more than S/255; may be repeated\n"
         "  --max-diff N           fail when any channel differs by more than N/255\n"
         "                         (with neither, any difference fails)\n"
         "  --json                 print the metrics as one JSON object on stdout\n" +
         filled("  --diff FILE" + ext + "        ", kHelpIndent,
                "write a heatmap of the differences, with its legend (" + heatmapNamesText() + ")") +
         "  --diff-scale N         differences of N/255 or more are red in the heatmap (default 16)\n"
         "\n"
         "merge: puts crops (--crop) back together into their full image, each where its record\n"
         "says; tiles of different full images, overlapping tiles, pixels no tile covers (unless\n"
         "--allow-gaps: they stay black) and a tile without a record are usage errors (1).\n" +
         filled("", "",
                floats + " crops merge into linear float (" + floats + ", or " + standard +
                    " with the recorded gamma); the tiles must be of one kind, and " + floats +
                    " tiles of one render (the same vkrt-samples record).") +
         filled("", "",
                "With sample batches of one path-traced render (" + floats +
                    " images carrying a vkrt-samples record, rendered with different --seed), merge averages "
                    "them weighted by their sample counts, into " + floats + " or " + standard +
                    " (the recorded gamma); batches of different sizes, places or gammas, or sharing samples, "
                    "are usage errors (1).") +
         "\n"
         "grade: each submitted image against the reference of its scene (matched by file name,\n"
         "any case; a reference may be named ref_SCENE), into a report folder to open in a browser\n"
         "(REPORT/index.html: a sortable table, a page per comparison) with summary.json and\n"
         "summary.csv. SUBMISSIONS/ holds a folder per student, or is one student's folder of\n"
         "images; a SCENE.test given instead is rendered in the run and graded. A new REPORT/, an\n"
         "empty one or an earlier report is written whole; any other folder is refused.\n"
         "  --max-pixels-over S:L, --max-diff N   as for diff (with no threshold: any difference fails)\n"
         "  --max-bias B           fail when |mean(reference - image)| exceeds B (8-bit units)\n"
         "  --max-variance V       fail when the variance of (image - reference) exceeds V\n"
         "  --thresholds FILE      per scene: lines 'SCENE OPTIONS...' replace the ones above\n"
         "  --diff-scale N         as for diff; --backend, --device, --spp, --seed, --threads: for\n"
         "                         the scenes rendered (--threads also grades on that many)\n"
         "  exit status: 5 when an image fails or is missing, 4 when one cannot be read, else a\n"
         "  rendered scene's own (the highest)\n"
         "\n"
         "  -q, --quiet            print nothing but errors (no warnings, no progress)\n"
         "  -h, --help             show this help\n"
         "  --version              show the version\n"
         "\n"
         "exit status:\n"
         "  0    ok (warnings, if any, on stderr)\n"
         "  1    usage error: the command line (with --strict: its warnings too), or an output\n"
         "       that is a file the run reads or writes already (that scene not rendered)\n"
         "  2    scene error: the scene file cannot be rendered as meant (with --strict: any of\n"
         "       its warnings); a line over 1 MiB, a file over 1 GiB, a byte that is not text\n"
         "  3    device error: the Vulkan backend cannot render here (no driver or device, a failed\n"
         "       call, a scene beyond its limits); --backend cpu may\n"
         "  4    I/O error: a file cannot be read or written (also an output refused by what it\n"
         "       is: a directory, device, FIFO, a file with several hard links)\n"
         "  5    images differ beyond the thresholds (diff, --check, --compare, grade)\n"
         "  6    out of memory (host or device), also when found before allocating\n"
         "  70   internal error: a bug in vkrt\n"
         "  128+N  stopped by signal N (130: Ctrl-C, 143: SIGTERM, 129: SIGHUP); nothing written,\n"
         "       no temporary file left\n"
         "  several scenes: the highest of their statuses (a signal stops the run)\n";
}

}  // namespace

const char* usageText() {
  static const std::string text = makeUsageText();
  return text.c_str();
}

namespace {

// The subcommands, and the long options of --help (without their dashes), for "did you
// mean" after a typo.
constexpr std::string_view kSubcommands[] = {"diff", "merge", "convert", "grade"};
constexpr std::string_view kLongOptions[] = {
    "output", "size", "scale", "crop", "backend", "device", "list-devices", "validation", "reads", "variant",
    "maxdepth", "spp", "seed", "sampler", "estimator", "time", "cutoff", "no-cutoff", "threads", "stats", "check", "compare", "strict",
    "max-pixels-over", "max-diff", "json", "diff", "diff-scale", "quiet", "help", "version", "watch", "dry-run"};
constexpr std::string_view kMergeLongOptions[] = {"output", "allow-gaps", "strict", "quiet", "help"};
constexpr std::string_view kConvertLongOptions[] = {"quiet", "help"};
constexpr std::string_view kGradeLongOptions[] = {"output", "thresholds", "max-pixels-over", "max-diff", "max-bias",
                                                  "max-variance", "diff-scale", "backend", "device", "spp", "seed",
                                                  "threads", "validation", "quiet", "help"};

// "unknown option '--bakcend'; did you mean '--backend'?": the option without its dashes
// (and without =VALUE) against the long options.
std::string unknownOption(const std::string& what, const std::string& option, const std::string& note,
                          std::span<const std::string_view> known) {
  std::string_view name = option;
  name = name.substr(0, name.find('='));
  name.remove_prefix(std::min(name.find_first_not_of('-'), name.size()));
  return "unknown " + what + " '" + echoed(option) + "'" + (note.empty() ? "" : " " + note) +
         didYouMean(name, known, "--");
}

bool exists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}

bool isDirectory(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// `vkrt dif a.png b.png`: a first argument near a subcommand, and no file of that name, is a
// mistyped subcommand (not a scene file that cannot be opened).
void refuseMistypedSubcommand(const std::vector<std::string>& args) {
  if (args.empty() || args[0].empty() || args[0][0] == '-' || exists(args[0])) return;
  for (std::string_view command : kSubcommands)
    if (args[0] == command) return;
  if (std::optional<std::string_view> match = closestMatch(args[0], kSubcommands))
    throw UsageError("unknown command '" + echoed(args[0]) + "'; did you mean '" + std::string(*match) + "'?");
}

// An image given as a scene: said in one line, before anything reads it as one.
void refuseImagesAsScenes(const std::vector<std::string>& scenes) {
  for (const std::string& scene : scenes)
    if (std::optional<std::string> kind = imageKind(scene))
      throw UsageError(abbreviated(scene) + " is " + withArticle(*kind) +
                       " image, not a scene file (to compare images: vkrt diff A B; to merge tiles: "
                       "vkrt merge -o OUT TILE ...)");
}

// An integer option value in [lo, hi].
int integerValue(const std::string& option, const std::string& v, int lo, int hi) {
  int n = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (ec != std::errc() || end != v.data() + v.size() || n < lo || n > hi)
    throw UsageError(option + " expects an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                     ", got '" + echoed(v) + "'");
  return n;
}

// --size WxH, each side from 1 to kMaxImageEdge.
void sizeValue(const std::string& v, int& width, int& height) {
  auto x = v.find('x');
  auto side = [&](const std::string& s) {
    int n = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    return ec == std::errc() && end == s.data() + s.size() && n >= 1 && n <= kMaxImageEdge ? n : 0;
  };
  if (x != std::string::npos) {
    width = side(v.substr(0, x));
    height = side(v.substr(x + 1));
  }
  if (x == std::string::npos || width == 0 || height == 0)
    throw UsageError("--size expects WIDTHxHEIGHT, each from 1 to " + std::to_string(kMaxImageEdge) +
                     " (e.g. 320x240), got '" + echoed(v) + "'");
}

// --scale F: a finite number greater than 0.
double scaleValue(const std::string& v) {
  double f = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), f);
  if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(f) || !(f > 0))
    throw UsageError("--scale expects a number greater than 0 (e.g. 0.5), got '" + echoed(v) + "'");
  return f;
}

// --seed N: a whole number from 0 to 2^32 - 1.
std::uint32_t seedValue(const std::string& v) {
  std::uint32_t n = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
  if (ec != std::errc() || end != v.data() + v.size())
    throw UsageError("--seed expects a whole number from 0 to 4294967295, got '" + echoed(v) + "'");
  return n;
}

// --time SECONDS: a finite number greater than 0, at most a year.
double timeValue(const std::string& v) {
  double f = 0;
  auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), f);
  if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(f) || !(f > 0) || f > 31536000.0)
    throw UsageError("--time expects seconds, a number greater than 0 and at most a year, 31536000 (e.g. 2.5), got '" +
                     echoed(v) + "'");
  return f;
}

// An output named '-': vkrt writes images into files only (its reports go to stdout).
void refuseStandardOutput(const std::string& option, const std::string& path) {
  if (path == "-")
    throw UsageError(option + " -: vkrt writes images into files, not to standard output (where its reports go); "
                     "name a file ('./-' for a file named '-')");
}

// "output file 'x.bmp' is not named .png, .ppm or .pfm: vkrt writes PNG, under that name":
// `what` at `path`, which may be named as any of `which`.
std::string unnamedWarning(const std::string& what, const std::string& path, FormatsOf which) {
  return what + " '" + abbreviated(path) + "' is not named " + imageExtensionsText(which) + ": vkrt writes " +
         std::string(imageFormats().front().name) + ", under that name";
}

// Whether an output path gets unnamedWarning: named as no image format, and not a folder
// (ends in '/', or is one) or a scene file, whose refusal by the write says so alone.
bool warnsOfItsName(const std::string& path) {
  std::error_code ec;
  return !hasImageExtension(path) && path.back() != '/' && !std::filesystem::is_directory(path, ec) &&
         !namedAsSceneFile(path);
}

// vkrt merge [--allow-gaps] -o OUT.png TILE.png ...
Options parseMergeOptions(const std::vector<std::string>& args) {
  Options o;
  o.mergeCommand = true;
  bool endOfOptions = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (endOfOptions || a.empty() || a[0] != '-' || a == "-") {
      o.mergeTiles.push_back(a);
    } else if (a == "--") {
      endOfOptions = true;
    } else if (a == "-o" || a == "--output" || a.rfind("--output=", 0) == 0) {
      if (!o.mergeOutput.empty())
        throw UsageError("-o given twice ('" + abbreviated(o.mergeOutput) + "' and another): merge writes one image");
      if (a.rfind("--output=", 0) == 0) {
        o.mergeOutput = a.substr(9);
      } else {
        if (i + 1 >= args.size()) throw UsageError("option " + echoed(a) + " needs a value");
        o.mergeOutput = args[++i];
      }
      if (o.mergeOutput.empty()) throw UsageError("option -o needs a non-empty file name");
      refuseStandardOutput("-o", o.mergeOutput);
    } else if (a == "--allow-gaps") {
      o.allowGaps = true;
    } else if (a == "--strict") {
      o.request.strict = true;
    } else if (a == "-q" || a == "--quiet") {
      o.quiet = true;
    } else if (a == "-h" || a == "--help") {
      o.help = true;
    } else {
      throw UsageError(unknownOption("merge option", a,
                                     "(merge takes -o OUT" + defaultImageExtension() + ", --allow-gaps, --strict, -q)",
                                     kMergeLongOptions));
    }
  }
  if (o.help) return o;
  const std::string ext = defaultImageExtension(), example = "vkrt merge -o OUT" + ext + " TILE" + ext + " ...";
  if (o.mergeOutput.empty()) throw UsageError("merge needs the output image: " + example);
  if (o.mergeTiles.empty()) throw UsageError("merge needs at least one tile: " + example);
  if (warnsOfItsName(o.mergeOutput)) {
    std::string w = unnamedWarning("output file", o.mergeOutput, FormatsOf::All);
    if (o.request.strict) throw UsageError(w + " [--strict]");
    o.warnings.push_back(w);
  }
  return o;
}

// vkrt convert [-q] IN OUT
Options parseConvertOptions(const std::vector<std::string>& args) {
  Options o;
  o.convertCommand = true;
  std::vector<std::string> files;
  bool endOfOptions = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (endOfOptions || a.empty() || a[0] != '-' || a == "-") {
      files.push_back(a);
    } else if (a == "--") {
      endOfOptions = true;
    } else if (a == "-q" || a == "--quiet") {
      o.quiet = true;
    } else if (a == "-h" || a == "--help") {
      o.help = true;
    } else {
      throw UsageError(unknownOption("convert option", a, "(convert takes -q)", kConvertLongOptions));
    }
  }
  if (o.help) return o;
  const std::string example = "vkrt convert IN" + floatExtension() + " OUT" + defaultImageExtension();
  if (files.size() != 2) throw UsageError("convert needs two images, the one to read and the one to write: " + example);
  o.convertInput = files[0];
  o.convertOutput = files[1];
  for (const std::string& f : files) refuseStandardOutput("convert", f);
  if (!hasImageExtension(o.convertOutput))
    throw UsageError("convert: '" + echoed(o.convertOutput) + "' is not named " + imageExtensionsText() +
                     ": the name says which format to write");
  return o;
}

// The options of the render that both the render commands and grade take: --backend,
// --device, --spp, --seed, --threads; `value()` takes the option's value. False for another
// option.
bool applyRenderOption(const std::string& name, const std::function<std::string()>& value, RenderRequest& request) {
  if (name == "--backend") {
    std::string b = value();
    if (b == "cpu")
      request.backend = Backend::Cpu;
    else if (b == "vulkan")
      request.backend = Backend::Vulkan;
    else
      throw UsageError("unknown backend '" + echoed(b) + "' (expected: vulkan or cpu)");
  } else if (name == "--device") {
    request.device = value();
    if (request.device.empty()) throw UsageError("--device needs an index or a name");
  } else if (name == "--spp") {
    request.spp = static_cast<std::uint64_t>(integerValue(name, value(), 1, 1 << 30));
  } else if (name == "--seed") {
    request.seed = seedValue(value());
  } else if (name == "--threads") {
    request.threads = integerValue(name, value(), 1, 1024);
  } else {
    return false;
  }
  return true;
}

// vkrt grade [options] REFS/ SUBMISSIONS/|SCENE.test ... -o REPORT/
Options parseGradeOptions(const std::vector<std::string>& args) {
  Options o;
  o.gradeCommand = true;
  o.request.variant = ShaderVariant::Auto;
  std::vector<std::string> operands;
  bool endOfOptions = false;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (endOfOptions || a.empty() || a[0] != '-' || a == "-") {
      operands.push_back(a);
      continue;
    }
    if (a == "--") {
      endOfOptions = true;
      continue;
    }
    std::string name = a, inlineValue;
    bool hasInline = false;
    if (auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
      name = a.substr(0, eq), inlineValue = a.substr(eq + 1), hasInline = true;
    }
    auto take = [&]() -> std::string {
      if (hasInline) return inlineValue;
      if (i + 1 >= args.size()) throw UsageError("option " + echoed(name) + " needs a value");
      return args[++i];
    };
    if (name == "-o" || name == "--output") {
      o.gradeOutput = take();
      if (o.gradeOutput.empty()) throw UsageError("option -o needs a non-empty folder name");
    } else if (name == "--thresholds") {
      o.gradeThresholdsFile = take();
    } else if (name == "--max-pixels-over" || name == "--max-diff" || name == "--max-bias" ||
               name == "--max-variance") {
      applyThresholdOption(name, take(), o.gradeThresholds);
    } else if (name == "--diff-scale") {
      o.heatmapScale = integerValue(name, take(), 1, 255);
    } else if (applyRenderOption(name, take, o.request)) {
    } else if (a == "--validation") {
      o.request.validation = true;
    } else if (a == "-q" || a == "--quiet") {
      o.quiet = true;
    } else if (a == "-h" || a == "--help") {
      o.help = true;
    } else {
      throw UsageError(unknownOption("grade option", a, "", kGradeLongOptions));
    }
  }
  if (const char* v = std::getenv("VKRT_VALIDATION"); v && std::string(v) == "1") o.request.validation = true;
  if (o.help) return o;
  const std::string example = "vkrt grade REFS/ SUBMISSIONS/ -o REPORT/";
  if (operands.size() < 2)
    throw UsageError("grade needs the references' folder and at least one folder of submissions (or scene files): " +
                     example);
  if (o.gradeOutput.empty()) throw UsageError("grade needs the report's folder: " + example);
  refuseStandardOutput("-o", o.gradeOutput);
  o.gradeReferences = operands[0];
  o.gradeInputs.assign(operands.begin() + 1, operands.end());
  for (const std::string& in : o.gradeInputs)
    if (std::optional<std::string> kind = imageKind(in); kind && !isDirectory(in))
      throw UsageError("grade: " + abbreviated(in) + " is " + withArticle(*kind) +
                       " image; give the folder that holds the submission's images (or a scene file to render)");
  return o;
}

}  // namespace

Options parseOptions(const std::vector<std::string>& args) {
  Options o;
  std::vector<std::string> scenes;
  std::optional<std::string> output;   // -o
  std::vector<std::string> images;   // diff's operands
  bool endOfOptions = false;
  std::size_t first = 0;
  if (!args.empty() && args[0] == "diff") {
    o.diffCommand = true;
    first = 1;
  }
  if (!args.empty() && args[0] == "merge") return parseMergeOptions(args);
  if (!args.empty() && args[0] == "convert") return parseConvertOptions(args);
  if (!args.empty() && args[0] == "grade") return parseGradeOptions(args);
  refuseMistypedSubcommand(args);
  for (std::size_t i = first; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&](const std::string& name) -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError("option " + echoed(name) + " needs a value");
      return args[++i];
    };
    // --name=value is accepted as well as --name value.
    std::string name = a, inlineValue;
    bool hasInline = false;
    if (!endOfOptions && a.rfind("--", 0) == 0) {
      auto eq = a.find('=');
      if (eq != std::string::npos) {
        name = a.substr(0, eq);
        inlineValue = a.substr(eq + 1);
        hasInline = true;
      }
    }
    auto take = [&](const std::string& n) -> std::string { return hasInline ? inlineValue : value(n); };
    if ((endOfOptions || a.empty() || a[0] != '-' || a == "-") && o.diffCommand) {
      images.push_back(a);
    } else if (endOfOptions || a.empty() || a[0] != '-' || a == "-") {
      scenes.push_back(a);
    } else if (a == "--") {
      endOfOptions = true;
    } else if (name == "-o" || name == "--output") {
      if (output) throw UsageError("-o given twice ('" + abbreviated(*output) + "' and another): give it once");
      output = take(name);
      if (output->empty()) throw UsageError("option " + name + " needs a non-empty file name");
      refuseStandardOutput(name, *output);
    } else if (name == "--size") {
      sizeValue(take(name), o.request.width, o.request.height);
    } else if (name == "--scale") {
      o.request.scale = scaleValue(take(name));
    } else if (name == "--crop") {
      std::string v = take(name);
      o.request.crop = parseCropOption(v);
      if (!o.request.crop)
        throw UsageError("--crop expects X0,Y0,X1,Y1 (four whole numbers, the pixels [X0,X1) x [Y0,Y1)), got '" +
                         echoed(v) + "'");
    } else if (applyRenderOption(name, [&] { return take(name); }, o.request)) {
    } else if (a == "--list-devices") {
      o.listDevices = true;
    } else if (name == "--reads") {
      std::string r = take(name);
      if (r == "auto")
        o.request.reads = SceneReads::Auto;
      else if (r == "texel")
        o.request.reads = SceneReads::Texel;
      else if (r == "storage")
        o.request.reads = SceneReads::Storage;
      else
        throw UsageError("unknown --reads '" + echoed(r) + "' (expected: auto, texel or storage)");
    } else if (a == "--no-specialize") {   // for the benchmark and tests; not in --help
      o.request.variant = ShaderVariant::General;
    } else if (name == "--variant") {
      std::string v = take(name);
      if (v == "auto")
        o.request.variant = ShaderVariant::Auto;
      else if (v == "specialized")
        o.request.variant = ShaderVariant::Specialized;
      else if (v == "general")
        o.request.variant = ShaderVariant::General;
      else
        throw UsageError("unknown --variant '" + echoed(v) + "' (expected: auto, specialized or general)");
    } else if (name == "--sampler") {
      std::string v = take(name);
      if (v == "stratified")
        o.request.stratified = true;
      else if (v == "independent")
        o.request.stratified = false;
      else
        throw UsageError("unknown --sampler '" + echoed(v) + "' (expected: independent or stratified)");
    } else if (name == "--estimator") {
      std::string v = take(name);
      if (v == "scene")
        o.request.estimator = Estimator::Scene;
      else if (v == "best")
        o.request.estimator = Estimator::Best;
      else
        throw UsageError("unknown --estimator '" + echoed(v) + "' (expected: scene or best)");
    } else if (name == "--time") {
      o.request.timeLimitSeconds = timeValue(take(name));
    } else if (name == "--maxdepth") {
      o.request.maxDepth = integerValue(name, take(name), 0, 1000000);
    } else if (a == "--no-cutoff") {
      o.request.cutoff = Cutoff::Off;
    } else if (name == "--cutoff") {
      std::string c = take(name);
      if (c == "auto") o.request.cutoff = Cutoff::Auto;
      else if (c == "on") o.request.cutoff = Cutoff::On;
      else if (c == "off") o.request.cutoff = Cutoff::Off;
      else throw UsageError("unknown --cutoff '" + echoed(c) + "' (expected: auto, on or off)");
    } else if (a == "--validation") {
      o.request.validation = true;
    } else if (name == "--step-budget") {   // for tests of the loop budget; not in --help
      o.request.stepBudget = static_cast<std::uint32_t>(integerValue(name, take(name), 1, 8192));
    } else if (a == "--compare") {
      o.compare = true;
    } else if (a == "--watch") {
      o.watch = true;
    } else if (a == "--dry-run") {
      o.request.dryRun = true;
    } else if (name == "--check") {
      o.checkAgainst = take(name);
    } else if (name == "--max-pixels-over") {
      o.thresholds.pixelsOver.push_back(parsePixelThreshold(take(name)));
    } else if (name == "--max-diff") {
      o.thresholds.maxDiff = integerValue(name, take(name), 0, 255);
    } else if (a == "--json") {
      o.json = true;
    } else if (name == "--diff") {
      o.heatmapPath = take(name);
      if (o.heatmapPath->empty()) throw UsageError("option --diff needs a non-empty file name");
      refuseStandardOutput(name, *o.heatmapPath);
    } else if (name == "--diff-scale") {
      o.heatmapScale = integerValue(name, take(name), 1, 255);
    } else if (a == "--strict") {
      o.request.strict = true;
    } else if (a == "--stats") {
      o.stats = true;
    } else if (a == "-q" || a == "--quiet") {
      o.quiet = true;
    } else if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--version") {
      o.version = true;
    } else {
      throw UsageError(unknownOption("option", a, "", kLongOptions));
    }
  }
  if (const char* v = std::getenv("VKRT_VALIDATION"); v && std::string(v) == "1") o.request.validation = true;
  if (o.heatmapPath) {
    if (holdsLinearFloat(*o.heatmapPath))
      throw UsageError("--diff " + abbreviated(*o.heatmapPath) + ": the heatmap is an 8-bit image; name it " +
                       imageExtensionsText(FormatsOf::Bytes));
    if (warnsOfItsName(*o.heatmapPath)) {
      std::string w = unnamedWarning("heatmap file", *o.heatmapPath, FormatsOf::Bytes);
      if (o.request.strict) throw UsageError(w + " [--strict]");
      o.warnings.push_back(w);
    }
  }
  if (o.diffCommand) {
    if (images.size() != 2)
      throw UsageError("diff needs two images: vkrt diff A" + defaultImageExtension() + " B" + defaultImageExtension());
    o.diffA = images[0];
    o.diffB = images[1];
    return o;
  }
  refuseImagesAsScenes(scenes);
  bool comparing = o.thresholds.any() || o.json || o.heatmapPath;
  if (comparing && !o.checkAgainst && !o.compare)
    throw UsageError("--max-pixels-over, --max-diff, --json and --diff need --check REF" + defaultImageExtension() +
                     " or --compare (or vkrt diff)");
  if (o.compare && o.checkAgainst) throw UsageError("--compare and --check do not go together");
  if (o.compare && output)
    throw UsageError("--compare writes no image (it renders with both backends and compares them): -o " +
                     abbreviated(*output) + " does not go with it");
  if (o.request.width > 0 && o.request.scale > 0) throw UsageError("--size and --scale do not go together");
  if (output && output->back() == '/') {
    o.request.outputDir = *output;
  } else if (output) {
    if (scenes.size() > 1)
      throw UsageError("-o " + abbreviated(*output) + " names one file, for " + std::to_string(scenes.size()) +
                       " scenes: give a folder (-o DIR/, with the '/') or leave -o out");
    o.request.output = *output;
    if (warnsOfItsName(*output)) {
      std::string w = unnamedWarning("output file", *output, FormatsOf::All);
      if (o.request.strict) throw UsageError(w + " [--strict]");
      o.warnings.push_back(w);
    }
  }
  if (scenes.size() > 1 && (o.compare || o.checkAgainst || o.watch))
    throw UsageError(std::string(o.compare ? "--compare" : o.watch ? "--watch" : "--check") + " takes one scene, got " +
                     std::to_string(scenes.size()));
  if (o.watch && (o.compare || o.checkAgainst || o.json || o.heatmapPath))
    throw UsageError(std::string("--watch renders and writes the image at each change; ") +
                     (o.compare ? "--compare" : o.checkAgainst ? "--check" : o.json ? "--json" : "--diff") +
                     " does not go with it");
  if (o.request.dryRun && (o.watch || o.compare || o.checkAgainst))
    throw UsageError(std::string("--dry-run renders nothing; ") +
                     (o.watch ? "--watch" : o.compare ? "--compare" : "--check") + " does not go with it");
  if (o.compare && o.request.timeLimitSeconds > 0)
    throw UsageError("--compare compares the two backends' renders of the same samples; under --time each would "
                     "render as many as it can in the time: give --spp instead");
  if (o.watch && o.request.timeLimitSeconds > 0)
    throw UsageError("--watch refines a path-traced image until the next change; --time does not go with it");
  if (!o.help && !o.version && !o.listDevices) {
    if (scenes.empty()) throw UsageError("no scene file given");
    o.request.scenePath = scenes.front();
    o.scenes = scenes;
  }
  return o;
}

}  // namespace vkrt
