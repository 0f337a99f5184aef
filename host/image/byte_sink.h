// Where a file format's bytes go: an open file (writeFileAtomic's temporary file) or memory
// (pngBytes, for `vkrt view`'s page). Every image writer writes through one, so a format is
// written the same way into either. Depends on errors.h, text.h and the platform layer's
// file functions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

namespace vkrt {

// Bytes written in order (write: PNG, PPM, the PFM header), or at a place (writeAt: PFM puts
// its rows bottom first and its trailer after them, OpenEXR seeks back to fill in its line
// offsets), as into a file: write() goes at the sink's position and moves it on; writeAt()
// leaves it alone; a place past the end leaves the bytes between as zeros.
class ByteSink {
 public:
  virtual ~ByteSink() = default;
  // All of `data` at the position, which then moves past it. Throws IoError.
  virtual void write(const std::uint8_t* data, std::size_t size) = 0;
  // All of `data` at `offset`, the position left alone. Throws IoError.
  virtual void writeAt(const std::uint8_t* data, std::size_t size, std::uint64_t offset) = 0;
};

// An open file (write and pwrite through the platform layer). Its errors name `path`:
// write()'s abbreviated as messages abbreviate paths, writeAt()'s as given. Does not close
// the file.
class FileSink : public ByteSink {
 public:
  FileSink(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  void write(const std::uint8_t* data, std::size_t size) override;
  void writeAt(const std::uint8_t* data, std::size_t size, std::uint64_t offset) override;

 private:
  int fd_;
  std::string path_;
};

// A string that grows as bytes come (writeAt past the end grows it with zeros). Throws
// std::bad_alloc when memory runs out, nothing else.
class MemorySink : public ByteSink {
 public:
  void write(const std::uint8_t* data, std::size_t size) override;
  void writeAt(const std::uint8_t* data, std::size_t size, std::uint64_t offset) override;
  const std::string& bytes() const { return bytes_; }
  // The bytes, moved out: the sink is left empty, its position where it was.
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
  std::uint64_t position_ = 0;
};

}  // namespace vkrt
