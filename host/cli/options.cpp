// Command-line parsing for `vkrt`: each command's table of options (one row an option: its
// spellings, argument, --help text and setter) and what its operands must be.
#include "cli/options.h"

#include <cstdlib>
#include <initializer_list>
#include <string_view>
#include <utility>

#include "cli/image_argument.h"
#include "cli/option_rows.h"
#include "cli/option_values.h"
#include "image/crop.h"
#include "image/image_file.h"
#include "platform/file_status.h"
#include "render/techniques.h"
#include "util/text.h"   // echoed, abbreviated
#include "util/suggest.h"

namespace vkrt {

namespace {

using R = RenderCommandLine;
using V = OptionValue;

// `v` as one of `values`, or "unknown WHAT 'v' (expected: EXPECTED)".
template <class T>
T choice(const std::string& v, std::initializer_list<std::pair<std::string_view, T>> values, const std::string& what,
         const std::string& expected) {
  for (const auto& [name, value] : values)
    if (v == name) return value;
  throw UsageError("unknown " + what + " '" + echoed(v) + "' (expected: " + expected + ")");
}

// The options that several commands take, each for any command's options that have its field.
constexpr auto setQuiet = [](auto& o, const V&) { o.quiet = true; };
constexpr auto setHelp = [](auto& o, const V&) { o.help = true; };
constexpr auto setValidation = [](auto& o, const V&) { o.request.validation = true; };
constexpr auto setBackend = [](auto& o, const V& v) {
  o.request.backend = choice<Backend>(v(), {{"cpu", Backend::Cpu}, {"vulkan", Backend::Vulkan}}, "backend", "vulkan or cpu");
};
constexpr auto setDevice = [](auto& o, const V& v) {
  o.request.device = v();
  if (o.request.device.empty()) throw UsageError("--device needs an index or a name");
};
constexpr auto setSpp = [](auto& o, const V& v) {
  o.request.spp = static_cast<std::uint64_t>(integerValue(v.name, v(), 1, 1 << 30));
};
constexpr auto setSeed = [](auto& o, const V& v) { o.request.seed = seedValue(v()); };
constexpr auto setThreads = [](auto& o, const V& v) { o.request.threads = integerValue(v.name, v(), 1, 1024); };

void setOutput(R& o, const V& v) {
  if (o.output) throw UsageError("-o given twice ('" + abbreviated(*o.output) + "' and another): give it once");
  o.output = v();
  if (o.output->empty()) throw UsageError("option " + v.name + " needs a non-empty file name");
  refuseStandardOutput(v.name, *o.output);
}

// --view NAME: one of the views of render/techniques.cpp.
void setView(R& o, const V& v) {
  const std::string name = v();
  if (!viewNamed(name)) {
    std::string names;
    for (const Technique* t : views()) names += (names.empty() ? "" : ", ") + std::string(t->name);
    throw UsageError("unknown view '" + echoed(name) + "' (expected: " + names + ")");
  }
  o.request.view = name;
}

void setCrop(R& o, const V& v) {
  std::string text = v();
  o.request.crop = parseCropOption(text);
  if (!o.request.crop)
    throw UsageError("--crop expects X0,Y0,X1,Y1 (four whole numbers, the pixels [X0,X1) x [Y0,Y1)), got '" +
                     echoed(text) + "'");
}

void setHeatmap(R& o, const V& v) {
  o.comparison.heatmapPath = v();
  if (o.comparison.heatmapPath->empty()) throw UsageError("option --diff needs a non-empty file name");
  refuseStandardOutput(v.name, *o.comparison.heatmapPath);
}

void setFlipMap(R& o, const V& v) {
  o.comparison.flipMapPath = v();
  if (o.comparison.flipMapPath->empty()) throw UsageError("option --flip-map needs a non-empty file name");
  refuseStandardOutput(v.name, *o.comparison.flipMapPath);
}

using Section = HelpSection;

// The render command's options (and diff's), in --help's order; "did you mean" takes the
// first of equally near names. Help texts: cli/option_table.h.
const OptionRow<R> kRenderRows[] = {
    {"-o, --output", "FILE",
     "write the image to FILE (overrides the scene's 'output');\n"
     "\f{image names}. An existing FILE is replaced whole, keeping its permissions; a symbolic link is written "
     "through. Refused: '-', a file the run reads, a device, FIFO or directory, a file with several hard links",
     setOutput},
    {"-o, --output", "DIR/",
     "write each image into DIR (a trailing '/'): under the file name\n"
     "of the scene's 'output', or the scene's stem + {ext} without one",
     nullptr},
    {"--size", "WxH", "render at W x H pixels instead of the scene's size (same camera)",
     [](R& o, const V& v) { sizeValue(v(), o.request.width, o.request.height); }},
    {"--scale", "F", "render at the scene's size times F (rounded, at least 1x1)",
     [](R& o, const V& v) { o.request.scale = scaleValue(v()); }},
    {"--crop", "X0,Y0,X1,Y1",
     "render only the pixels [X0,X1) x [Y0,Y1) of the full image (the\n"
     "same pixels as a full render), as an image of the crop's size\n"
     "that records where it lies, for vkrt merge",
     setCrop},
    {"--backend", "vulkan|cpu",
     "renderer: 'vulkan' (default: a compute shader on a GPU, or on\n"
     "the CPU through lavapipe) or 'cpu' (the double-precision reference)",
     setBackend},
    {"--device", "N|NAME",
     "Vulkan device by index or part of its name (see --list-devices);\n"
     "default: a discrete or integrated GPU if present, else the CPU",
     setDevice},
    {"--list-devices", "", "list the Vulkan devices and exit", [](R& o, const V&) { o.listDevices = true; }},
    {"--validation", "", "enable the Vulkan validation layer (also VKRT_VALIDATION=1)", setValidation},
    {"--reads", "auto|texel|storage",
     "how the shader reads the scene (default auto: texel\n"
     "buffers, faster on lavapipe, where the device's limits allow)",
     [](R& o, const V& v) {
       o.request.reads = choice<SceneReads>(
           v(), {{"auto", SceneReads::Auto}, {"texel", SceneReads::Texel}, {"storage", SceneReads::Storage}},
           "--reads", "auto, texel or storage");
     }},
    {"--no-specialize", "", "the same as --variant general (for the benchmark and tests)",
     [](R& o, const V&) { o.request.variant = ShaderVariant::General; }, Section::Hidden},
    {"--variant", "auto|specialized|general",
     "the compiled shader: default auto, specialised\n"
     "where worth its compile (or, on a CPU device, compiled before)",
     [](R& o, const V& v) {
       o.request.variant = choice<ShaderVariant>(v(),
                                                 {{"auto", ShaderVariant::Auto},
                                                  {"specialized", ShaderVariant::Specialized},
                                                  {"general", ShaderVariant::General}},
                                                 "--variant", "auto, specialized or general");
     }},
    {"--maxdepth", "N", "override the scene's maxdepth (fewer reflections: faster, less exact)",
     [](R& o, const V& v) { o.request.maxDepth = integerValue(v.name, v(), 0, 1000000); }},
    {"--view", "NAME", "\frender a view of the scene instead of its image: {views}", setView},
    {"--spp", "N", "path integrators: N samples per pixel instead of the scene's spp", setSpp},
    {"--seed", "N",
     "path integrators: the random numbers' seed, 0 to 4294967295\n"
     "(default 0); another seed gives independent samples",
     setSeed},
    {"--sampler", "independent|stratified",
     "path integrators: each sample's numbers independent\n"
     "(default, as the scene rules say) or stratified across a pixel's\n"
     "samples (camera jitter, each bounce's direction and first light\n"
     "sample): less noise (why not the default: doc/path-tracing.md)",
     [](R& o, const V& v) {
       o.request.stratified =
           choice<bool>(v(), {{"stratified", true}, {"independent", false}}, "--sampler", "independent or stratified");
     }},
    {"--estimator", "scene|best",
     "pathtracer: the scene's importancesampling and\n"
     "nexteventestimation (default), or BRDF sampling and MIS: the\n"
     "same image, usually less noisy; with stratified samples it reaches\n"
     "the scene's error 1.2-6.8x sooner on the course's scenes, but the\n"
     "scene's noise is what a grader measures (doc/path-tracing.md)",
     [](R& o, const V& v) {
       o.request.estimator =
           choice<Estimator>(v(), {{"scene", Estimator::Scene}, {"best", Estimator::Best}}, "--estimator", "scene or best");
     }},
    {"--time", "SECONDS",
     "path integrators: render batches of samples until the time is up,\n"
     "then write (at most --spp samples when given, else no limit);\n"
     "the samples taken are reported",
     [](R& o, const V& v) { o.request.timeLimitSeconds = timeValue(v()); }},
    {"--cutoff", "auto|on|off",
     "Vulkan: stop mirror paths that can no longer change the 8-bit\n"
     "result (same image); auto: where it can stop paths early",
     [](R& o, const V& v) {
       o.request.cutoff = choice<Cutoff>(v(), {{"auto", Cutoff::Auto}, {"on", Cutoff::On}, {"off", Cutoff::Off}},
                                         "--cutoff", "auto, on or off");
     }},
    {"--no-cutoff", "", "the same as --cutoff off", [](R& o, const V&) { o.request.cutoff = Cutoff::Off; }},
    {"--bvh", "binary|wide", "Vulkan: the BVH the shader walks, two or four children a node (for the benchmark)",
     [](R& o, const V& v) {
       o.request.wideBvh = choice<bool>(v(), {{"binary", false}, {"wide", true}}, "--bvh", "binary or wide");
     },
     Section::Hidden},
    {"--threads", "N", "worker threads for the CPU backend (default: all cores)", setThreads},
    {"--step-budget", "N", "the loop budget of a dispatch (for the tests of the budget)",
     [](R& o, const V& v) { o.request.stepBudget = static_cast<std::uint32_t>(integerValue(v.name, v(), 1, 8192)); },
     Section::Hidden},
    {"--stats", "", "print a timing breakdown and ray counts on stderr", [](R& o, const V&) { o.stats = true; }},
    {"--check", "REF{ext}",
     "compare the rendered image with REF{ext} (exit 5 when it fails);\n"
     "REF is read before the render (exit 4 when it cannot be)",
     [](R& o, const V& v) { o.checkAgainst = v(); }},
    {"--compare", "",
     "render with both backends (nothing written) and print each\n"
     "one's times and the difference between their images",
     [](R& o, const V&) { o.compare = true; }},
    {"--display-server", "HOST:PORT",
     "show the render in tev (or HDRView) as it refines, over tev's\n"
     "protocol (tev listens on localhost:14158): bands and batches as\n"
     "they finish; a viewer not there costs a warning, never the render",
     [](R& o, const V& v) { o.display = parseDisplayAddress(v()); }},
    {"--watch", "",
     "render, then render again each time the scene file changes (one\n"
     "process: the device and compiled shaders kept); a path-traced\n"
     "scene refines with more samples until the next change; Ctrl-C ends",
     [](R& o, const V&) { o.watch = true; }},
    {"--bind", "ADDRESS",
     "listen on ADDRESS (default 127.0.0.1: this machine only; a name\n"
     "or an IPv4 or IPv6 address; 0.0.0.0 opens the page to the network)",
     [](R& o, const V& v) {
       o.bind = v();
       o.serverOptionGiven = true;
       if (o.bind.empty()) throw UsageError("option --bind needs an address");
     },
     Section::View},
    {"--port", "N", "listen on port N (default: a free one, in the address printed)",
     [](R& o, const V& v) {
       o.port = integerValue(v.name, v(), 1, 65535);
       o.serverOptionGiven = true;
     },
     Section::View},
    {"--dry-run", "",
     "parse each scene and check its output as a render would (the\n"
     "same errors and exit status), print where its image would go;\n"
     "open no device, render and write nothing",
     [](R& o, const V&) { o.request.dryRun = true; }},
    {"--strict", "",
     "every warning is an error, nothing written: the scene's (exit 2:\n"
     "unknown commands, repeated commands and the like, NaN pixels)\n"
     "and the command line's (exit 1: --spp for a Whitted scene, an\n"
     "\foutput name not {extensions})",
     [](R& o, const V&) { o.request.strict = true; }},
    {"--max-pixels-over", "S:L",
     "fail when more than L pixels (a count, or a share with %,\n"
     "e.g. 2:0.1%) differ by more than S/255; may be repeated",
     [](R& o, const V& v) { o.comparison.thresholds.pixelsOver.push_back(parsePixelThreshold(v())); },
     Section::Comparison},
    {"--max-diff", "N",
     "fail when any channel differs by more than N/255\n"
     "(with neither, any difference fails)",
     [](R& o, const V& v) { o.comparison.thresholds.maxDiff = integerValue(v.name, v(), 0, 255); },
     Section::Comparison},
    {"--max-flip", "X",
     "fail when the mean FLIP error exceeds X (0 to 1): LDR-FLIP of the\n"
     "8-bit images, HDR-FLIP of the radiance when the reference (and\n"
     "diff's other image) is float",
     [](R& o, const V& v) { o.comparison.thresholds.maxFlip = parseFlipThreshold(v()); }, Section::Comparison},
    {"--pixels-per-degree", "PPD",
     "the viewing condition FLIP is computed for: pixels per degree of\n"
     "visual angle (default 67: a 0.7 m wide 4K monitor seen from 0.7 m;\n"
     "a 0.5 m wide 1920-pixel screen from 0.6 m: 40)",
     [](R& o, const V& v) { o.comparison.thresholds.pixelsPerDegree = parsePixelsPerDegree(v()); },
     Section::Comparison},
    {"--json", "", "print the metrics as one JSON object on stdout", [](R& o, const V&) { o.comparison.json = true; },
     Section::Comparison},
    {"--diff", "FILE{ext}", "\fwrite a heatmap of the differences, with its legend ({heatmap names})", setHeatmap,
     Section::Comparison},
    {"--diff-scale", "N", "differences of N/255 or more are red in the heatmap (default 16)",
     [](R& o, const V& v) { o.comparison.heatmapScale = integerValue(v.name, v(), 1, 255); }, Section::Comparison},
    {"--flip-map", "FILE{ext}", "\fwrite FLIP's error map in its colour map, magma ({heatmap names})", setFlipMap,
     Section::Comparison},
    {"-q, --quiet", "", "print nothing but errors (no warnings, no progress)", setQuiet, Section::Last},
    {"-h, --help", "", "show this help", setHelp, Section::Last},
    {"--version", "", "show the version", [](R& o, const V&) { o.version = true; }, Section::Last},
};

// merge's options: its usage line and paragraphs in --help name them.
const OptionRow<MergeOptions> kMergeRows[] = {
    {"-o, --output", "OUT{ext}", "",
     [](MergeOptions& o, const V& v) {
       if (!o.output.empty())
         throw UsageError("-o given twice ('" + abbreviated(o.output) + "' and another): merge writes one image");
       o.output = v();
       if (o.output.empty()) throw UsageError("option -o needs a non-empty file name");
       refuseStandardOutput("-o", o.output);
     },
     Section::Elsewhere},
    {"--allow-gaps", "", "", [](MergeOptions& o, const V&) { o.allowGaps = true; }, Section::Elsewhere},
    {"--strict", "", "", [](MergeOptions& o, const V&) { o.strict = true; }, Section::Elsewhere},
    {"-q, --quiet", "", "", setQuiet, Section::Elsewhere},
    {"-h, --help", "", "", setHelp, Section::Elsewhere},
};

// convert's options: -q and -h, as the render command's.
const OptionRow<ConvertOptions> kConvertRows[] = {
    {"-q, --quiet", "", "", setQuiet, Section::Elsewhere},
    {"-h, --help", "", "", setHelp, Section::Elsewhere},
};

// grade's options; those of the render it shares are in the render command's part of --help.
const OptionRow<GradeOptions> kGradeRows[] = {
    {"-o, --output", "REPORT/", "",
     [](GradeOptions& o, const V& v) {
       o.output = v();
       if (o.output.empty()) throw UsageError("option -o needs a non-empty folder name");
     },
     Section::Elsewhere},
    {"--max-pixels-over", "S:L", "as for diff (no threshold: any difference fails,\nbut a path-traced scene defaults to --max-bias-z 6)",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade,
     "--max-pixels-over S:L, --max-diff N"},
    {"--max-diff", "N", "", [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); },
     Section::Grade},
    {"--max-flip", "X", "fail when the mean FLIP error exceeds X (0 to 1): HDR-FLIP where\n"
     "both images are float, else LDR-FLIP",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade},
    {"--pixels-per-degree", "PPD", "FLIP's viewing condition, as for diff (default 67)",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade},
    {"--max-bias", "B", "fail when |mean(reference - image)| exceeds B (8-bit units)",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade},
    {"--max-variance", "V", "fail when the variance of (image - reference) exceeds V",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade},
    {"--max-bias-z", "Z",
     "fail when the mean of (image - reference) over a 16x16 square, in\n"
     "a channel, is more than half a level plus Z of its standard errors\n"
     "from 0: passes a Monte Carlo image's noise, fails its bias. The\n"
     "default (6) of a path-traced scene (rendered here, or its SCENE.test\n"
     "beside the reference) when no other threshold judges it",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade},
    {"--limit-time", "S", "a scene file rendered fails when it takes over S seconds\n(default 40; 0: no limit),",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade},
    {"--limit-spp", "N", "asks for over N samples per pixel (default 16384),",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade},
    {"--limit-pixels", "N", "over N pixels (default: its reference's),",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade},
    {"--limit-depth", "D", "or a maxdepth over D (default 100)",
     [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); }, Section::Grade},
    {"--thresholds", "FILE", "per scene: lines 'SCENE OPTIONS...' replace the ones above",
     [](GradeOptions& o, const V& v) { o.thresholdsFile = v(); }, Section::Grade},
    {"--gradescope", "FILE",
     "also write Gradescope's results.json to FILE: a test per scene (and\n"
     "per student), worth --points P (default 1; per scene in FILE of\n"
     "--thresholds) when it passes, its output what failed and where",
     [](GradeOptions& o, const V& v) {
       o.gradescopePath = v();
       if (o.gradescopePath->empty()) throw UsageError("option --gradescope needs a non-empty file name");
     },
     Section::Grade},
    {"--points", "P", "", [](GradeOptions& o, const V& v) { applyThresholdOption(v.name, v(), o.thresholds); },
     Section::Elsewhere},
    {"--one-student", "", "each SUBMISSIONS/ given is one student's, its images looked for\n"
     "four levels down, whatever its folders are named (Gradescope's)",
     [](GradeOptions& o, const V&) { o.oneStudent = true; }, Section::Grade},
    {"--strict", "", "an input of the teacher's that would be set aside (a scene file\n"
     "beside the references that cannot be read, a file there that is\n"
     "not used) is an error, not a warning",
     [](GradeOptions& o, const V&) { o.strict = true; }, Section::Grade},
    {"--diff-scale", "N",
     "as for diff; --backend, --device, --spp, --seed, --threads: for\n"
     "the scenes rendered (--threads also grades on that many)",
     [](GradeOptions& o, const V& v) { o.heatmapScale = integerValue(v.name, v(), 1, 255); }, Section::Grade},
    {"--backend", "vulkan|cpu", "", setBackend, Section::Elsewhere},
    {"--device", "N|NAME", "", setDevice, Section::Elsewhere},
    {"--spp", "N", "", setSpp, Section::Elsewhere},
    {"--seed", "N", "", setSeed, Section::Elsewhere},
    {"--threads", "N", "", setThreads, Section::Elsewhere},
    {"--validation", "", "", setValidation, Section::Elsewhere},
    {"-q, --quiet", "", "", setQuiet, Section::Elsewhere},
    {"-h, --help", "", "", setHelp, Section::Elsewhere},
};

// The subcommands, for "did you mean" after a typo.
constexpr std::string_view kSubcommands[] = {"diff", "merge", "convert", "grade", "view"};

bool exists(const std::string& path) { return platform::statusOf(path).found(); }

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

// VKRT_VALIDATION=1 is --validation.
bool validationFromEnvironment() {
  const char* v = std::getenv("VKRT_VALIDATION");
  return v && std::string(v) == "1";
}

// args[first...] against `rows`; an unknown option is "unknown WHAT '...' NOTE; did you mean".
template <class Options>
Options parsedWith(std::span<const OptionRow<Options>> rows, const std::vector<std::string>& args, std::size_t first,
                   std::vector<std::string>& operands, const std::string& what, const std::string& note) {
  Options o;
  const std::vector<std::string_view> names = suggestedNames(rows);
  parseArguments<Options>(
      args, first, rows, o, [&](const std::string& a) { operands.push_back(a); },
      [&](const std::string& a) { throw UsageError(unknownOption(what, a, note, names)); });
  return o;
}

// The render command line (also diff's, from args[first]): the options, the heatmap checked.
R parseRenderArguments(const std::vector<std::string>& args, std::size_t first, std::vector<std::string>& operands) {
  R o = parsedWith(renderOptionRows(), args, first, operands, "option", "");
  if (validationFromEnvironment()) o.request.validation = true;
  if (const std::optional<std::string>& heatmap = o.comparison.heatmapPath) {
    if (holdsLinearFloat(*heatmap))
      throw UsageError("--diff " + abbreviated(*heatmap) + ": the heatmap is an 8-bit image; name it " +
                       imageExtensionsText(FormatsOf::Bytes));
    warnOfItsName("heatmap file", *heatmap, FormatsOf::Bytes, o.request.strict, o.warnings);
  }
  if (const std::optional<std::string>& map = o.comparison.flipMapPath) {
    if (holdsLinearFloat(*map))
      throw UsageError("--flip-map " + abbreviated(*map) + ": the FLIP map is an 8-bit image; name it " +
                       imageExtensionsText(FormatsOf::Bytes));
    warnOfItsName("FLIP map file", *map, FormatsOf::Bytes, o.request.strict, o.warnings);
  }
  return o;
}

// vkrt diff [options] A B
DiffOptions parseDiffOptions(const std::vector<std::string>& args) {
  std::vector<std::string> images;
  R o = parseRenderArguments(args, 1, images);
  if (images.size() != 2)
    throw UsageError("diff needs two images: vkrt diff A" + defaultImageExtension() + " B" + defaultImageExtension());
  DiffOptions d;
  static_cast<CommonOptions&>(d) = o;
  d.comparison = o.comparison;
  d.a = images[0];
  d.b = images[1];
  return d;
}

// The options that do not go together, and the comparison options without a comparison.
void refuseCombinations(const R& o, const std::vector<std::string>& scenes) {
  const bool comparing =
      o.comparison.thresholds.any() || o.comparison.json || o.comparison.heatmapPath || o.comparison.flipMapPath ||
      o.comparison.thresholds.pixelsPerDegree != kFlipDefaultPixelsPerDegree;
  if (comparing && !o.checkAgainst && !o.compare)
    throw UsageError("--max-pixels-over, --max-diff, --max-flip, --pixels-per-degree, --json, --diff and --flip-map "
                     "need --check REF" +
                     defaultImageExtension() +
                     " or --compare (or vkrt diff)");
  if (o.compare && o.checkAgainst) throw UsageError("--compare and --check do not go together");
  if (o.compare && o.output)
    throw UsageError("--compare writes no image (it renders with both backends and compares them): -o " +
                     abbreviated(*o.output) + " does not go with it");
  if (o.request.width > 0 && o.request.scale > 0) throw UsageError("--size and --scale do not go together");
  if (o.output && !endsInSeparator(*o.output) && scenes.size() > 1)
    throw UsageError("-o " + abbreviated(*o.output) + " names one file, for " + std::to_string(scenes.size()) +
                     " scenes: give a folder (-o DIR/, with the '/') or leave -o out");
}

// The modes that take one scene, or that do not go with others.
void refuseModeCombinations(const R& o, const std::vector<std::string>& scenes) {
  if (scenes.size() > 1 && (o.compare || o.checkAgainst || o.watch))
    throw UsageError(std::string(o.compare ? "--compare" : o.watch ? "--watch" : "--check") + " takes one scene, got " +
                     std::to_string(scenes.size()));
  if (o.watch && (o.compare || o.checkAgainst || o.comparison.json || o.comparison.heatmapPath ||
                  o.comparison.flipMapPath))
    throw UsageError(std::string("--watch renders and writes the image at each change; ") +
                     (o.compare               ? "--compare"
                      : o.checkAgainst        ? "--check"
                      : o.comparison.json     ? "--json"
                      : o.comparison.heatmapPath ? "--diff"
                                                 : "--flip-map") +
                     " does not go with it");
  if (o.request.dryRun && (o.watch || o.compare || o.checkAgainst))
    throw UsageError(std::string("--dry-run renders nothing; ") +
                     (o.watch ? "--watch" : o.compare ? "--compare" : "--check") + " does not go with it");
  if (o.compare && o.request.timeLimitSeconds > 0)
    throw UsageError("--compare compares the two backends' renders of the same samples; under --time each would "
                     "render as many as it can in the time: give --spp instead");
  if (o.watch && o.request.timeLimitSeconds > 0)
    throw UsageError("--watch refines a path-traced image until the next change; --time does not go with it");
}

// -o as given: a folder (a trailing '/') or a file.
void applyOutput(R& o) {
  if (o.output && endsInSeparator(*o.output)) {
    o.request.outputDir = *o.output;
  } else if (o.output) {
    o.request.output = *o.output;
    warnOfItsName("output file", *o.output, FormatsOf::All, o.request.strict, o.warnings);
  }
}

// vkrt [options] SCENE.test ...
RenderOptions parseRenderOptions(const std::vector<std::string>& args) {
  refuseMistypedSubcommand(args);
  std::vector<std::string> scenes;
  R o = parseRenderArguments(args, 0, scenes);
  refuseImagesAsScenes(scenes);
  if (o.serverOptionGiven) throw UsageError("--bind and --port go with vkrt view (vkrt view [options] SCENE.test)");
  refuseCombinations(o, scenes);
  applyOutput(o);
  refuseModeCombinations(o, scenes);
  if (!o.help && !o.version && !o.listDevices) {
    if (scenes.empty()) throw UsageError("no scene file given");
    o.request.scenePath = scenes.front();
    o.scenes = scenes;
  }
  return std::move(static_cast<RenderOptions&>(o));
}

// vkrt view [options] SCENE.test: --watch, shown in the browser; --check REF adds the plot.
RenderOptions parseViewOptions(const std::vector<std::string>& args) {
  std::vector<std::string> scenes;
  R o = parseRenderArguments(args, 1, scenes);
  if (o.help || o.version) return std::move(static_cast<RenderOptions&>(o));
  if (scenes.size() != 1)
    throw UsageError("view takes one scene: vkrt view [options] SCENE.test" +
                     (scenes.empty() ? std::string() : " (got " + std::to_string(scenes.size()) + ")"));
  refuseImagesAsScenes(scenes);
  const char* refused = o.compare                               ? "--compare"
                        : o.watch                               ? "--watch (view watches the scene already)"
                        : o.listDevices                         ? "--list-devices"
                        : o.request.dryRun                      ? "--dry-run"
                        : o.request.timeLimitSeconds > 0        ? "--time"
                        : o.comparison.json                     ? "--json"
                        : o.comparison.heatmapPath              ? "--diff"
                        : o.comparison.flipMapPath              ? "--flip-map"
                        : o.comparison.thresholds.any()         ? "a threshold (--max-...)"
                        : o.comparison.thresholds.pixelsPerDegree != kFlipDefaultPixelsPerDegree
                            ? "--pixels-per-degree (the page plots RMSE)"
                                                                : nullptr;
  if (refused)
    throw UsageError(std::string("view renders at each change of the scene and shows it; ") + refused +
                     " does not go with it");
  applyOutput(o);
  o.view = o.watch = true;
  o.request.scenePath = scenes.front();
  o.scenes = scenes;
  return std::move(static_cast<RenderOptions&>(o));
}

// vkrt merge [--allow-gaps] -o OUT.png TILE.png ...
MergeOptions parseMergeOptions(const std::vector<std::string>& args) {
  std::vector<std::string> tiles;
  MergeOptions o = parsedWith(mergeOptionRows(), args, 1, tiles, "merge option",
                              "(merge takes -o OUT" + defaultImageExtension() + ", --allow-gaps, --strict, -q)");
  o.tiles = tiles;
  if (o.help) return o;
  const std::string ext = defaultImageExtension(), example = "vkrt merge -o OUT" + ext + " TILE" + ext + " ...";
  if (o.output.empty()) throw UsageError("merge needs the output image: " + example);
  if (o.tiles.empty()) throw UsageError("merge needs at least one tile: " + example);
  warnOfItsName("output file", o.output, FormatsOf::All, o.strict, o.warnings);
  return o;
}

// vkrt convert [-q] IN OUT
ConvertOptions parseConvertOptions(const std::vector<std::string>& args) {
  std::vector<std::string> files;
  ConvertOptions o = parsedWith(convertOptionRows(), args, 1, files, "convert option", "(convert takes -q)");
  if (o.help) return o;
  const std::string example = "vkrt convert IN" + floatExtension() + " OUT" + defaultImageExtension();
  if (files.size() != 2) throw UsageError("convert needs two images, the one to read and the one to write: " + example);
  o.input = files[0];
  o.output = files[1];
  for (const std::string& f : files) refuseStandardOutput("convert", f);
  if (!hasImageExtension(o.output))
    throw UsageError("convert: '" + echoed(o.output) + "' is not named " + imageExtensionsText() +
                     ": the name says which format to write");
  return o;
}

// vkrt grade [options] REFS/ SUBMISSIONS/|SCENE.test ... -o REPORT/
GradeOptions parseGradeOptions(const std::vector<std::string>& args) {
  std::vector<std::string> operands;
  GradeOptions o = parsedWith(gradeOptionRows(), args, 1, operands, "grade option", "");
  if (validationFromEnvironment()) o.request.validation = true;
  if (o.help) return o;
  const std::string example = "vkrt grade REFS/ SUBMISSIONS/ -o REPORT/";
  if (operands.size() < 2)
    throw UsageError("grade needs the references' folder and at least one folder of submissions (or scene files): " +
                     example);
  if (o.output.empty()) throw UsageError("grade needs the report's folder: " + example);
  refuseStandardOutput("-o", o.output);
  o.references = operands[0];
  o.inputs.assign(operands.begin() + 1, operands.end());
  for (const std::string& in : o.inputs)
    if (std::optional<std::string> kind = imageKind(in); kind && !platform::isDirectory(in))
      throw UsageError("grade: " + abbreviated(in) + " is " + withArticle(*kind) +
                       " image; give the folder that holds the submission's images (or a scene file to render)");
  return o;
}

// Every spelling of each row that --help or a paragraph names, appended to `out`.
template <class Options>
void appendDocumented(std::span<const OptionRow<Options>> rows, std::vector<std::string>& out) {
  for (const OptionRow<Options>& row : rows) {
    if (!row.set || row.section == HelpSection::Hidden) continue;
    for (std::string_view names = row.names; !names.empty();) {
      const std::size_t comma = std::min(names.find(','), names.size());
      out.emplace_back(names.substr(0, comma));
      names.remove_prefix(std::min(comma + 2, names.size()));
    }
  }
}

}  // namespace

std::span<const OptionRow<RenderCommandLine>> renderOptionRows() { return kRenderRows; }
std::span<const OptionRow<MergeOptions>> mergeOptionRows() { return kMergeRows; }
std::span<const OptionRow<ConvertOptions>> convertOptionRows() { return kConvertRows; }
std::span<const OptionRow<GradeOptions>> gradeOptionRows() { return kGradeRows; }

CommandOptions parseOptions(const std::vector<std::string>& args) {
  const std::string first = args.empty() ? "" : args[0];
  if (first == "diff") return parseDiffOptions(args);
  if (first == "merge") return parseMergeOptions(args);
  if (first == "convert") return parseConvertOptions(args);
  if (first == "grade") return parseGradeOptions(args);
  if (first == "view") return parseViewOptions(args);
  return parseRenderOptions(args);
}

std::vector<std::string> documentedOptions() {
  std::vector<std::string> out;
  appendDocumented(renderOptionRows(), out);
  appendDocumented(mergeOptionRows(), out);
  appendDocumented(convertOptionRows(), out);
  appendDocumented(gradeOptionRows(), out);
  return out;
}

}  // namespace vkrt
