// Reading JPEG with libjpeg-turbo: jpeg.h.
#include "image/jpeg.h"

#include <csetjmp>
#include <cstring>
#include <vector>

#include <jpeglib.h>
#include <jerror.h>

#include "image/image_file.h"   // imageReadError, checkImageHasPixels
#include "util/interrupt.h"

namespace vkrt {
namespace {

// libjpeg's errors end in a longjmp back to readInto's frame, which turns them into IoError:
// no C++ frame lies between (the library's are C), and readInto's objects outlive the jump.
struct ErrorManager {
  jpeg_error_mgr pub;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void onError(j_common_ptr cinfo) {
  auto* err = reinterpret_cast<ErrorManager*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, err->message);
  std::longjmp(err->jump, 1);
}

void onMessage(j_common_ptr, int) {}   // warnings (a file that ends early) are not printed

// The source: the head already read, then the file; at its end a fake end-of-image marker, as
// libjpeg's own stdio source does (the image's rest then decodes grey).
struct Source {
  jpeg_source_mgr pub;
  std::FILE* file;
  const unsigned char* head;
  std::size_t headSize;
  bool headGiven = false, ended = false;
  unsigned char buffer[16384];
};

void initSource(j_decompress_ptr) {}
void termSource(j_decompress_ptr) {}

boolean fillInput(j_decompress_ptr cinfo) {
  auto* s = reinterpret_cast<Source*>(cinfo->src);
  std::size_t got = 0;
  if (!s->headGiven) {
    s->headGiven = true;
    std::memcpy(s->buffer, s->head, s->headSize);
    got = s->headSize;
  } else if (!s->ended) {
    got = std::fread(s->buffer, 1, sizeof s->buffer, s->file);
  }
  if (got == 0) {
    s->ended = true;
    s->buffer[0] = 0xFF;
    s->buffer[1] = JPEG_EOI;
    got = 2;
  }
  s->pub.next_input_byte = s->buffer;
  s->pub.bytes_in_buffer = got;
  return TRUE;
}

void skipInput(j_decompress_ptr cinfo, long count) {
  auto* s = reinterpret_cast<Source*>(cinfo->src);
  while (count > 0) {
    if (s->pub.bytes_in_buffer == 0) fillInput(cinfo);
    const std::size_t step = std::min(static_cast<std::size_t>(count), s->pub.bytes_in_buffer);
    s->pub.next_input_byte += step;
    s->pub.bytes_in_buffer -= step;
    count -= static_cast<long>(step);
    if (s->ended) return;
  }
}

// Reads the header, and unless `sizeOnly` the pixels into `image`.
void readInto(std::FILE* file, const unsigned char* head, std::size_t headSize, const std::string& path,
              bool sizeOnly, Image& image, int& width, int& height) {
  jpeg_decompress_struct cinfo{};
  ErrorManager err{};
  Source source{};
  source.file = file, source.head = head, source.headSize = headSize;
  struct Destroy {
    jpeg_decompress_struct* cinfo;
    bool made = false;
    ~Destroy() {
      if (made) jpeg_destroy_decompress(cinfo);
    }
  } destroy{&cinfo};
  cinfo.err = jpeg_std_error(&err.pub);
  err.pub.error_exit = onError;
  err.pub.emit_message = onMessage;
  if (setjmp(err.jump)) {
    const std::string why = std::ferror(file) ? std::string(std::strerror(errno))
                            : err.pub.msg_code == JERR_EMPTY_IMAGE
                                ? "the JPEG is 0 pixels wide, and an image has at least one pixel"
                            : source.ended ? "the file ends early (it is truncated)"
                                           : "a damaged or unsupported JPEG (libjpeg: " + std::string(err.message) + ")";
    throw imageReadError(path, why);
  }
  jpeg_create_decompress(&cinfo);
  destroy.made = true;
  source.pub.init_source = initSource;
  source.pub.fill_input_buffer = fillInput;
  source.pub.skip_input_data = skipInput;
  source.pub.resync_to_restart = jpeg_resync_to_restart;
  source.pub.term_source = termSource;
  cinfo.src = &source.pub;
  jpeg_read_header(&cinfo, TRUE);
  width = static_cast<int>(cinfo.image_width), height = static_cast<int>(cinfo.image_height);
  checkImageHasPixels(path, width, height);
  if (sizeOnly) return;
  cinfo.out_color_space = JCS_RGB;
  jpeg_start_decompress(&cinfo);
  image = Image(width, height);
  while (cinfo.output_scanline < cinfo.output_height) {
    throwIfInterrupted();
    JSAMPROW row = image.pixel(0, static_cast<int>(cinfo.output_scanline));
    jpeg_read_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_decompress(&cinfo);
}

}  // namespace

bool isJpegHead(const unsigned char* head, std::size_t size) {
  return size >= 3 && head[0] == 0xFF && head[1] == 0xD8 && head[2] == 0xFF;
}

Image readJpeg(std::FILE* file, const unsigned char* head, std::size_t headSize, const std::string& path) {
  Image image;
  int width = 0, height = 0;
  readInto(file, head, headSize, path, false, image, width, height);
  return image;
}

void readJpegSize(std::FILE* file, const unsigned char* head, std::size_t headSize, const std::string& path,
                  int& width, int& height) {
  Image unused;
  readInto(file, head, headSize, path, true, unused, width, height);
}

}  // namespace vkrt
