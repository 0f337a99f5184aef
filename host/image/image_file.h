// Image files by format: one table of the formats vkrt writes (PNG, the default for a name it
// does not know, PPM, PFM: see image_file.cpp), each row a format's name, extensions, what its
// pixels hold, and its writer and readers. The one place that decides which writer a path
// gets and which reader a file needs; the rest of vkrt asks the questions below and names no
// format. Knows nothing of rendering.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "util/errors.h"
#include "image/byte_sink.h"
#include "image/image.h"
#include "image/radiance_image.h"

namespace vkrt {

using ImageRecords = std::vector<std::pair<std::string, std::string>>;

// A format's writer into a ByteSink (writeFileAtomic's temporary file, or memory), made by
// its ImageFormat::openRows, which writes the header. Rows come top first, each once, as
// bands of whole rows; then finish(). A linear-float format takes radiance rows, an 8-bit one
// byte rows: callers ask ImageFormat::linearFloat, and the other kind is an InternalError.
// Throws IoError, Interrupted (polled at least every 64 rows), InternalError for rows
// outside the image or missing at finish().
class RowWriter {
 public:
  virtual ~RowWriter() = default;
  // Rows [y0, y0 + band.height) of the image (band.width == its width).
  virtual void radianceRows(int y0, const RadianceImage& band);
  virtual void byteRows(int y0, const Image& band);
  virtual void finish() = 0;
};

// One row of the table.
struct ImageFormat {
  std::string_view name;                     // "PPM": for messages and --help
  std::vector<std::string_view> extensions;  // lower case, without the dot; the first is the one texts show
  bool linearFloat = false;                  // radiance as it is; else 8-bit bytes, gamma-encoded
  std::string_view description;              // after "FILE.ppm writes" in --help: "binary PPM"
  // Whether the file at `path` starts as one (by its first bytes, whatever its name).
  bool (*isFile)(const std::string& path) = nullptr;
  // The writer of a width x height image with `records` into `sink` (`path` for messages).
  std::unique_ptr<RowWriter> (*openRows)(ByteSink& sink, int width, int height, const ImageRecords& records,
                                         const std::string& path) = nullptr;
  // The records of a file that isFile. Throws IoError for one that cannot be read or is cut short.
  ImageRecords (*readText)(const std::string& path) = nullptr;
  // Linear-float formats only (null for the others): the whole image (its records into
  // `text`; `samples` left at 1), and its size and records alone (`rgb` empty) after checking
  // that its pixels are all there. Throw IoError.
  RadianceImage (*read)(const std::string& path) = nullptr;
  RadianceImage (*readInfo)(const std::string& path) = nullptr;
};

// Every format, the default (what an unknown name gets) first.
const std::vector<ImageFormat>& imageFormats();

// The format written for `path`: the row whose extension ends its last component (any case),
// else the default.
const ImageFormat& imageFormatFor(const std::string& path);

// True when `path` ends in an extension of the table (any case): a name vkrt writes as its
// extension says. Any other name gets the default format, and a warning.
bool hasImageExtension(const std::string& path);

// Why vkrt would not write the file an output line's `name` says (ParseOptions::
// outputNameProblem): "is not named .png, ...: vkrt writes PNG, under that name" for a name
// of no format's extension; "" for one with an extension of the table, or named as a scene
// file (which is refused, alone, when the output is checked).
std::string outputNameProblem(const std::string& name);

// True when `path` ends in `.test` (any case), a scene file's name: never an output's
// (checkOutputWritable refuses it, and no warning about its format comes before that).
bool namedAsSceneFile(const std::string& path);

// "a PNG", "an EXR": a format's name (PNG, PPM, PFM, EXR, JPEG) after its article.
std::string withArticle(const std::string& formatName);

// The format vkrt reads `path` as, by its name alone (any case): the table's for one of its
// extensions, "JPEG" for .jpg or .jpeg (read, never written); nothing for any other name.
std::optional<std::string> imageKindByName(const std::string& path);

// Whether what imageFormatFor(path) writes is linear float (an 8-bit image cannot be).
bool holdsLinearFloat(const std::string& path);

// The formats a text lists.
enum class FormatsOf { All, Bytes, LinearFloat };

// ".png, .ppm or .pfm": the first extension of each format, in table order.
std::string imageExtensionsText(FormatsOf which = FormatsOf::All);
// "PNG, PPM or PFM", the same way; imageFormatNames the names alone.
std::string imageFormatNamesText(FormatsOf which = FormatsOf::All);
std::vector<std::string> imageFormatNames(FormatsOf which = FormatsOf::All);
// ".png": what a name that must be made gets.
std::string defaultImageExtension();
// For -o's help: "FILE.ppm writes binary PPM, FILE.pfm linear float (...), any other name
// PNG" with `stem` "FILE".
std::string imageNamesHelpText(const std::string& stem);
// "'PATH': a .pfm holds linear radiance, and this image is 8-bit; write .png or .ppm": why an
// 8-bit image cannot be written to `path` (holdsLinearFloat(path)).
std::string bytesAsFloatMessage(const std::string& path);

// Writes `image` in the format of imageFormatFor(path), atomically. Throws IoError, and
// UsageError (bytesAsFloatMessage) for a linear-float name, before anything is created.
void writeImageAtomic(const Image& image, const std::string& path);

// Writes a render: a linear-float format as it is (with its records), an 8-bit one encoded
// with `gamma` (image/encode.h) a band of rows at a time. Throws IoError.
void writeImageAtomic(const RadianceImage& image, const std::string& path, double gamma);

// Opens `format`'s writer on a temporary file beside `path`, hands it to `write`, finishes
// it and renames the file over `path` (writeFileAtomic): an existing file is replaced whole
// or not at all. Throws what `write` and the writer throw, and IoError.
void writeRowsAtomic(const std::string& path, const ImageFormat& format, int width, int height,
                     const ImageRecords& records, const std::function<void(RowWriter&)>& write);

// Linear-float image files, read by what gathers float tiles and sample batches (merge.cpp)
// and their records (crop.cpp). Whether the file at `path` is one (by its first bytes,
// whatever its name), and which; floatImageFormatOf gives nullptr for any other file.
bool isFloatImageFile(const std::string& path);
const ImageFormat* floatImageFormatOf(const std::string& path);
// Reads one whole (its records into `text`; `samples` left at 1), or only its size and
// records after checking that its pixels are all there. Throws IoError (also for a file that
// is no linear-float image).
RadianceImage readFloatImage(const std::string& path);
RadianceImage readFloatImageInfo(const std::string& path);
// Its records. Throws IoError.
ImageRecords readFloatImageText(const std::string& path);

// The records of an image file of any format in the table, known by its first bytes; none
// for a file of no format there. Throws IoError for a file that cannot be read, is empty, or
// is cut short.
ImageRecords readImageFileText(const std::string& path);

// Reads a PNG or a JPEG (stb_image), or a binary PPM (P6, or P5 grey) of any maxval
// (image/ppm.h), as 8-bit RGB. Throws IoError: a file that cannot be opened or read says the
// system's reason ("No such file or directory"), one that ends early says so, and an image
// with no pixels is refused.
Image readImage(const std::string& path);

// The width and height readImage would give, from the file's header, without decoding its
// pixels. Throws IoError for a file readImage cannot read.
void readImageSize(const std::string& path, int& width, int& height);

// The error of every image reader: "cannot read image 'PATH': WHY".
IoError imageReadError(const std::string& path, const std::string& why);

// An image file open for reading (binary), closed when it goes. openImageFile throws IoError
// ("cannot read image 'PATH': " and the system's reason) when it cannot be opened.
using ImageFileHandle = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;
ImageFileHandle openImageFile(const std::string& path);

// Every reader's check of a header's size, before anything is decoded or written: throws
// IoError ("cannot read image 'PATH': it is 0x3 pixels, and an image has at least one pixel")
// unless both are at least 1. An image of no pixels is no image: written as PNG it would be
// an invalid file, and compared it would pass anything of the same size.
void checkImageHasPixels(const std::string& path, std::int64_t width, std::int64_t height);

}  // namespace vkrt
