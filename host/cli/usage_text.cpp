// The text of `vkrt --help`: the usage lines and paragraphs, and each command's options from
// its table (cli/option_rows.h). No parsing here.
#include <algorithm>
#include <string>
#include <string_view>
#include <utility>

#include "cli/option_rows.h"
#include "cli/option_values.h"   // floatExtension
#include "image/image_file.h"
#include "render/techniques.h"

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

// "PNG, or PPM for FILE.ppm": what the 8-bit heatmap is written as, by name.
std::string heatmapNamesText() {
  std::string others;
  for (const ImageFormat& format : imageFormats())
    if (!format.linearFloat && &format != &imageFormats().front())
      others += (others.empty() ? "" : ", ") + std::string(format.name) + " for FILE." +
                std::string(format.extensions.front());
  return std::string(imageFormats().front().name) + (others.empty() ? "" : ", or " + others);
}

// "normals (each pixel's surface normal ...)": the views, each with what it shows.
std::string viewsText() {
  std::string text;
  for (const Technique* t : views()) text += (text.empty() ? "" : "; ") + std::string(t->name) + " (" + t->view + ")";
  return text;
}

// The placeholders of a help text, replaced: {ext} (".png"), {extensions} (".png, .ppm, .pfm
// or .exr"), {image names} (imageNamesHelpText("FILE")), {heatmap names} (heatmapNamesText()),
// {views} (viewsText()).
std::string expanded(std::string_view text) {
  const std::pair<std::string_view, std::string> values[] = {
      {"{ext}", defaultImageExtension()},
      {"{extensions}", imageExtensionsText()},
      {"{image names}", imageNamesHelpText("FILE")},
      {"{heatmap names}", heatmapNamesText()},
      {"{views}", viewsText()}};
  std::string out(text);
  for (const auto& [key, value] : values)
    for (std::size_t at = out.find(key); at != std::string::npos; at = out.find(key, at + value.size()))
      out.replace(at, key.size(), value);
  return out;
}

// One option's entry: "  HEAD" and its text from column 25 (two spaces after a longer head),
// its further lines at column 25; a line that starts with '\f' is filled.
std::string helpEntry(std::string_view head, std::string_view help) {
  std::string lead = "  " + expanded(head);
  lead += std::string(lead.size() + 2 <= kHelpIndent.size() ? kHelpIndent.size() - lead.size() : 2, ' ');
  std::string out;
  const std::string text = expanded(help);
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at, end - at);
    if (!line.empty() && line[0] == '\f')
      out += filled(lead, kHelpIndent, line.substr(1));
    else
      out += lead + line + "\n";
    lead = kHelpIndent;
    at = end + 1;
  }
  return out;
}

// The entries of the rows of `section`, in the table's order.
template <class Options>
std::string helpRows(std::span<const OptionRow<Options>> rows, HelpSection section) {
  std::string out;
  for (const OptionRow<Options>& row : rows) {
    if (row.section != section || row.help.empty()) continue;
    const std::string head = row.shownAs.empty()
                                 ? std::string(row.names) + (row.argument.empty() ? "" : " " + std::string(row.argument))
                                 : std::string(row.shownAs);
    out += helpEntry(head, row.help);
  }
  return out;
}

// The usage lines and what vkrt does.
std::string usageHeader() {
  const std::string ext = defaultImageExtension(), floatExt = floatExtension();
  return "usage: vkrt [options] SCENE.test [SCENE.test ...]\n"
         "       vkrt diff [comparison options] A" + ext + " B" + ext + "\n"
         "       vkrt merge [--allow-gaps] [--strict] -o OUT" + ext + "|OUT" + floatExt + " TILE [TILE ...]   (all " +
         slashed(FormatsOf::Bytes) + " or all " + slashed(FormatsOf::LinearFloat) + ")\n"
         "       vkrt merge -o OUT" + floatExt + "|OUT" + ext + " BATCH" + floatExt + " [BATCH" + floatExt + " ...]\n"
         "       vkrt convert IN OUT   (any of " + imageExtensionsText() + " to any; JPEG in)\n"
         "       vkrt grade [grade options] REFS/ SUBMISSIONS/|SCENE.test ... -o REPORT/\n"
         "       vkrt view [options] [--bind ADDRESS] [--port N] SCENE.test\n"
         "\n"
         "Renders CSE167 (and CSE168) scene files to " + imageFormatNamesText() + " images;\n"
         "compares and converts images.\n"
         "Several scenes are rendered in one run, one line each, then a summary; the exit\n"
         "status is then the highest of theirs.\n"
         "\n";
}

// merge's paragraphs.
std::string mergeText() {
  const std::string floats = imageFormatNamesText(FormatsOf::LinearFloat), standard = imageFormatNames().front();
  return "merge: puts crops (--crop) back together into their full image, each where its record\n"
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
         "\n";
}

// grade's paragraph, options and exit status.
std::string gradeText() {
  return "grade: each submitted image against the reference of its scene (matched by file name,\n"
         "any case; a reference may be named ref_SCENE), into a report folder to open in a browser\n"
         "(REPORT/index.html: a sortable table, a page per comparison) with summary.json and\n"
         "summary.csv. SUBMISSIONS/ holds a folder per student, or is one student's folder of\n"
         "images; a SCENE.test given instead is rendered in the run and graded. A new REPORT/, an\n"
         "empty one or an earlier report is written whole; any other folder is refused.\n" +
         helpRows(gradeOptionRows(), HelpSection::Grade) +
         "  exit status: 5 when an image fails or is missing, 4 when one cannot be read, else a\n"
         "  rendered scene's own (the highest)\n"
         "\n";
}

// view's paragraph and options.
std::string viewText() {
  return "view: --watch in a web browser. Prints the page's address (with its token) as the first\n"
         "line on stdout; the page shows the image as it refines (bands, batches), rendered again\n"
         "at each save of the scene, with its warnings and errors at their lines, the samples and\n"
         "time, and with --check REF the error against time. The image is written as --watch\n"
         "writes it. Without the token: 403. From another machine: ssh -L N:localhost:N HOST,\n"
         "then open the address printed. Ctrl-C ends.\n" +
         helpRows(renderOptionRows(), HelpSection::View) + "\n";
}

std::string exitStatusText() {
  return "exit status:\n"
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

std::string makeUsageText() {
  return usageHeader() + "options:\n" + helpRows(renderOptionRows(), HelpSection::Options) +
         "\ncomparison options (diff, --check and --compare):\n" +
         helpRows(renderOptionRows(), HelpSection::Comparison) + "\n" + mergeText() + gradeText() + viewText() +
         helpRows(renderOptionRows(), HelpSection::Last) + "\n" + exitStatusText();
}

}  // namespace

const char* usageText() {
  static const std::string text = makeUsageText();
  return text.c_str();
}

}  // namespace vkrt
