// The table of image formats, the writers and readers by format, and the texts that name
// formats. A format's own file (image/<format>.{h,cpp}) holds its bytes; here is its row.
#include "image/image_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "util/errors.h"
#include "image/atomic_file.h"
#include "image/encode.h"
#include "image/exr.h"
#include "image/jpeg.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/ppm.h"
#include "platform/file_status.h"
#include "platform/path_text.h"
#include "util/text.h"   // escapedBytes

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG   // stb decodes PNG alone: JPEG is libjpeg-turbo's (image/jpeg.h), the rest vkrt's own; none of stb's other decoders (GIF, PSD, BMP, ...) is reachable
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace vkrt {
namespace {

// The extension of the last path component, lower-cased, without the dot ("" when none).
std::string extensionOf(const std::string& path) {
  std::size_t slash = path.find_last_of(platform::kPathSeparators);
  std::size_t start = slash == std::string::npos ? 0 : slash + 1;
  std::size_t dot = path.rfind('.');
  if (dot == std::string::npos || dot < start) return {};
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The row of `path`'s extension, or nullptr.
const ImageFormat* formatNamed(const std::string& path) {
  const std::string ext = extensionOf(path);
  for (const ImageFormat& format : imageFormats())
    if (std::find(format.extensions.begin(), format.extensions.end(), ext) != format.extensions.end()) return &format;
  return nullptr;
}

bool isOf(const ImageFormat& format, FormatsOf which) {
  return which == FormatsOf::All || format.linearFloat == (which == FormatsOf::LinearFloat);
}

// "a", "a or b", "a, b or c".
std::string orList(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i)
    text += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
  return text;
}

std::string firstExtension(const ImageFormat& format) { return "." + std::string(format.extensions.front()); }

// An 8-bit band of `image`'s rows [y0, y0 + rows), encoded with `gamma`, into `band`.
void encodeBand(const RadianceImage& image, int y0, int rows, double gamma, Image& band) {
  band.width = image.width, band.height = rows;
  band.rgb.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(rows) * 3);
  encodeRow(image.pixel(0, y0), band.rgb.size(), gamma, band.rgb.data());
}

}  // namespace

void RowWriter::radianceRows(int, const RadianceImage&) {
  throw InternalError("RowWriter: radiance rows for an 8-bit format");
}

void RowWriter::byteRows(int, const Image&) { throw InternalError("RowWriter: 8-bit rows for a linear-float format"); }

// To add a format: its file image/<format>.{h,cpp} with the functions of a row, and the row.
const std::vector<ImageFormat>& imageFormats() {
  static const std::vector<ImageFormat> formats = {
      {.name = "PNG",
       .extensions = {"png"},
       .linearFloat = false,
       .description = "PNG",
       .isFile = isPngFile,
       .openRows = openPngRows,
       .readText = readPngText},
      {.name = "PPM",
       .extensions = {"ppm"},
       .linearFloat = false,
       .description = "binary PPM",
       .isFile = isPpmFile,
       .openRows = openPpmRows,
       .readText = readPpmText},
      {.name = "PFM",
       .extensions = {"pfm"},
       .linearFloat = true,
       .description = "linear float (PFM, no quantization or gamma)",
       .isFile = isPfmFile,
       .openRows = openPfmRows,
       .readText = readPfmText,
       .read = readPfm,
       .readInfo = readPfmInfo},
      {.name = "EXR",
       .extensions = {"exr"},
       .linearFloat = true,
       .description = "OpenEXR (32-bit float RGB, linear, with its records as header attributes)",
       .isFile = isExrFile,
       .openRows = openExrRows,
       .readText = readExrText,
       .read = readExr,
       .readInfo = readExrInfo},
  };
  return formats;
}

const ImageFormat& imageFormatFor(const std::string& path) {
  const ImageFormat* format = formatNamed(path);
  return format ? *format : imageFormats().front();
}

bool hasImageExtension(const std::string& path) { return formatNamed(path) != nullptr; }

std::string withArticle(const std::string& formatName) {
  const bool vowel = !formatName.empty() && std::string_view("AEIOU").find(formatName[0]) != std::string_view::npos;
  return (vowel ? "an " : "a ") + formatName;
}

std::string outputNameProblem(const std::string& name) {
  if (hasImageExtension(name) || namedAsSceneFile(name)) return "";
  return "is not named " + imageExtensionsText() + ": vkrt writes " + std::string(imageFormats().front().name) +
         ", under that name";
}

bool namedAsSceneFile(const std::string& path) {
  std::string ext = platform::utf8FromPath(platform::pathFromUtf8(path).extension());
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".test";
}

std::optional<std::string> imageKindByName(const std::string& path) {
  if (const ImageFormat* format = formatNamed(path)) return std::string(format->name);
  std::string ext = platform::utf8FromPath(platform::pathFromUtf8(path).extension());
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".jpg" || ext == ".jpeg") return std::string("JPEG");
  return std::nullopt;
}

bool holdsLinearFloat(const std::string& path) { return imageFormatFor(path).linearFloat; }

std::vector<std::string> imageFormatNames(FormatsOf which) {
  std::vector<std::string> names;
  for (const ImageFormat& format : imageFormats())
    if (isOf(format, which)) names.emplace_back(format.name);
  return names;
}

std::string imageExtensionsText(FormatsOf which) {
  std::vector<std::string> extensions;
  for (const ImageFormat& format : imageFormats())
    if (isOf(format, which)) extensions.push_back(firstExtension(format));
  return orList(extensions);
}

std::string imageFormatNamesText(FormatsOf which) { return orList(imageFormatNames(which)); }

std::string defaultImageExtension() { return firstExtension(imageFormats().front()); }

std::string imageNamesHelpText(const std::string& stem) {
  std::string text;
  for (const ImageFormat& format : imageFormats()) {
    if (&format == &imageFormats().front()) continue;
    text += (text.empty() ? "" : ", ") + stem + firstExtension(format) + (text.empty() ? " writes " : " ") +
            std::string(format.description);
  }
  return text + (text.empty() ? "" : ", ") + "any other name " + std::string(imageFormats().front().name);
}

std::string bytesAsFloatMessage(const std::string& path) {
  return "'" + path + "': a " + firstExtension(imageFormatFor(path)) +
         " holds linear radiance, and this image is 8-bit; write " + imageExtensionsText(FormatsOf::Bytes);
}

void writeRowsAtomic(const std::string& path, const ImageFormat& format, int width, int height,
                     const ImageRecords& records, const std::function<void(RowWriter&)>& write) {
  const std::string suffix = firstExtension(format) + ".tmp";
  writeFileAtomic(path, suffix.c_str(), [&](ByteSink& file) {
    std::unique_ptr<RowWriter> writer = format.openRows(file, width, height, records, path);
    write(*writer);
    writer->finish();
  });
}

void writeImageAtomic(const Image& image, const std::string& path) {
  const ImageFormat& format = imageFormatFor(path);
  if (format.linearFloat) throw UsageError(bytesAsFloatMessage(path));
  writeRowsAtomic(path, format, image.width, image.height, image.text,
                  [&](RowWriter& writer) { writer.byteRows(0, image); });
}

void writeImageAtomic(const RadianceImage& image, const std::string& path, double gamma) {
  const ImageFormat& format = imageFormatFor(path);
  writeRowsAtomic(path, format, image.width, image.height, image.text, [&](RowWriter& writer) {
    if (format.linearFloat) return writer.radianceRows(0, image);
    // A band at a time: no 8-bit copy of the whole image.
    constexpr int kBandRows = 64;
    Image band;
    for (int y = 0; y < image.height; y += kBandRows) {
      encodeBand(image, y, std::min(kBandRows, image.height - y), gamma, band);
      writer.byteRows(y, band);
    }
  });
}

const ImageFormat* floatImageFormatOf(const std::string& path) {
  for (const ImageFormat& format : imageFormats())
    if (format.linearFloat && format.isFile(path)) return &format;
  return nullptr;
}

bool isFloatImageFile(const std::string& path) { return floatImageFormatOf(path) != nullptr; }

namespace {

// The linear-float format of the file at `path`. Throws IoError for any other file.
const ImageFormat& floatFormatOrThrow(const std::string& path) {
  if (const ImageFormat* format = floatImageFormatOf(path)) return *format;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw imageReadError(path, std::strerror(errno));
  throw imageReadError(path, "not a linear-float image (" + imageFormatNamesText(FormatsOf::LinearFloat) + ")");
}

}  // namespace

RadianceImage readFloatImage(const std::string& path) { return floatFormatOrThrow(path).read(path); }

RadianceImage readFloatImageInfo(const std::string& path) { return floatFormatOrThrow(path).readInfo(path); }

ImageRecords readFloatImageText(const std::string& path) { return floatFormatOrThrow(path).readText(path); }

ImageRecords readImageFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw imageReadError(path, std::strerror(errno));
  if (in.peek() == std::ifstream::traits_type::eof()) throw imageReadError(path, "the file is empty");
  for (const ImageFormat& format : imageFormats())
    if (format.isFile(path)) return format.readText(path);
  return {};
}

IoError imageReadError(const std::string& path, const std::string& why) {
  return IoError("cannot read image '" + path + "': " + why);
}

ImageFileHandle openImageFile(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw imageReadError(path, std::strerror(errno));
  return ImageFileHandle(file, std::fclose);
}

void checkImageHasPixels(const std::string& path, std::int64_t width, std::int64_t height) {
  if (width < 1 || height < 1)
    throw imageReadError(path, "it is " + std::to_string(width) + "x" + std::to_string(height) +
                         " pixels, and an image has at least one pixel");
}

namespace {

// A file read through stb_image's callbacks: first the bytes already read to tell its format
// (`head`), then the rest of the file. Opened once and never rewound, so a FIFO's bytes, which
// can be read once, all reach stb.
struct StbSource {
  explicit StbSource(std::FILE* f) : file(f) {}
  std::FILE* file;
  unsigned char head[24] = {};
  std::size_t headSize = 0, headUsed = 0;
  // stb asked for bytes past the end of the file (it then reads zeros): the file is cut short
  // of what its own headers say it holds.
  bool starved = false;

  static int read(void* user, char* data, int size) {
    auto* s = static_cast<StbSource*>(user);
    const std::size_t fromHead = std::min(s->headSize - s->headUsed, static_cast<std::size_t>(size));
    std::memcpy(data, s->head + s->headUsed, fromHead);
    s->headUsed += fromHead;
    const std::size_t got = fromHead + std::fread(data + fromHead, 1, static_cast<std::size_t>(size) - fromHead, s->file);
    if (got == 0 && size > 0) s->starved = true;
    return static_cast<int>(got);
  }
  // stb skips forward only. A FIFO cannot seek: its bytes are read and dropped.
  static void skip(void* user, int n) {
    auto* s = static_cast<StbSource*>(user);
    const std::size_t fromHead = std::min(s->headSize - s->headUsed, static_cast<std::size_t>(n));
    s->headUsed += fromHead;
    std::size_t rest = static_cast<std::size_t>(n) - fromHead;
    if (rest == 0 || std::fseek(s->file, static_cast<long>(rest), SEEK_CUR) == 0) return;
    char dropped[4096];
    while (rest > 0) {
      const std::size_t got = std::fread(dropped, 1, std::min(rest, sizeof dropped), s->file);
      if (got == 0) return;
      rest -= got;
    }
  }
  // At the end once a read found nothing more: the end-of-file flag alone does not say so after
  // a skip past the end (fseek clears it), and stb's JPEG reader then looked for a marker in
  // the zeros it reads past the end for ever (a JPEG cut at 6 to 10 bytes hung vkrt).
  static int eof(void* user) {
    auto* s = static_cast<StbSource*>(user);
    return s->headUsed == s->headSize && (s->starved || std::feof(s->file) || std::ferror(s->file));
  }
};

constexpr stbi_io_callbacks kStbCallbacks = {StbSource::read, StbSource::skip, StbSource::eof};

// Reads the file's first bytes into the head, up to `size` in all (at most 24: a PNG's
// signature and the size in its IHDR chunk). A failed read says the system's reason.
void readHead(StbSource& source, std::size_t size, const std::string& path) {
  source.headSize += std::fread(source.head + source.headSize, 1, size - source.headSize, source.file);
  if (std::ferror(source.file)) throw imageReadError(path, std::strerror(errno));
  if (source.headSize == 0) throw imageReadError(path, "the file is empty");
}

// A PNG's size is the first thing in it (the IHDR chunk, which must come first): checked
// here so that an image of no pixels is refused in the words of every format.
void checkPngHasPixels(const StbSource& source, const std::string& path) {
  constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (source.headSize < 24 || std::memcmp(source.head, kPngSignature, 8) != 0 ||
      std::memcmp(source.head + 12, "IHDR", 4) != 0)
    return;
  auto bigEndian = [](const unsigned char* p) {
    return std::int64_t{p[0]} << 24 | std::int64_t{p[1]} << 16 | std::int64_t{p[2]} << 8 | std::int64_t{p[3]};
  };
  checkImageHasPixels(path, bigEndian(source.head + 16), bigEndian(source.head + 20));
}

// Why stb_image failed, in plain words where its terse reason is known, and always with a
// reason. A failed read gives the system's reason whatever stb made of the bytes it got; a
// file of no format stb knows is not an image; one that ended where stb wanted more is truncated, whatever stb then made of the zeros it
// read instead (a chunk "first not IHDR", a bit depth, a chunk type of no letters); another
// reason is named as stb's, escaped ("a damaged or unsupported PNG or JPEG (stb_image: ...)").
IoError stbFailure(const StbSource& source, const std::string& path) {
  const std::string reason = stbi_failure_reason() ? stbi_failure_reason() : "";
  std::string why;
  if (std::ferror(source.file))
    why = std::strerror(errno);
  else if (reason == "outofmem")
    why = "out of memory";
  else if (reason == "unknown image type")
    why = "not an image vkrt reads (PNG, PPM, PFM, EXR or JPEG)";
  else if (reason == "outofdata" || source.starved)
    why = "the file ends early (it is truncated)";
  else
    why = "a damaged or unsupported PNG" + (reason.empty() ? std::string() : " (stb_image: '" + escapedBytes(reason) + "')");
  return imageReadError(path, why);
}

}  // namespace

Image readImage(const std::string& path) {
  ImageFileHandle file = openImageFile(path);
  StbSource source(file.get());
  // Two bytes tell a binary Netpbm image, which is read on from there (never by stb_image).
  readHead(source, 2, path);
  if (isBinaryNetpbm(source.head, source.headSize))
    return readBinaryNetpbm(file.get(), static_cast<char>(source.head[1]), path);
  readHead(source, sizeof source.head, path);
  if (isJpegHead(source.head, source.headSize)) return readJpeg(file.get(), source.head, source.headSize, path);
  checkPngHasPixels(source, path);
  if (platform::isRegularFile(path)) checkPngInflatesToItsPixels(path);   // (a FIFO's bytes can be read once)
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load_from_callbacks(&kStbCallbacks, &source, &w, &h, &channels, 3);
  if (!data) throw stbFailure(source, path);
  Image img(w, h);
  std::memcpy(img.rgb.data(), data, img.rgb.size());
  stbi_image_free(data);
  return img;
}

void readImageSize(const std::string& path, int& width, int& height) {
  ImageFileHandle file = openImageFile(path);
  StbSource source(file.get());
  readHead(source, 2, path);
  if (isBinaryNetpbm(source.head, source.headSize))
    return readBinaryNetpbmSize(file.get(), static_cast<char>(source.head[1]), path, width, height);
  readHead(source, sizeof source.head, path);
  if (isJpegHead(source.head, source.headSize))
    return readJpegSize(file.get(), source.head, source.headSize, path, width, height);
  checkPngHasPixels(source, path);
  int channels = 0;
  if (!stbi_info_from_callbacks(&kStbCallbacks, &source, &width, &height, &channels)) throw stbFailure(source, path);
  checkImageHasPixels(path, width, height);
}

}  // namespace vkrt
