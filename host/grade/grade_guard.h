// What a submitted file must be before grading reads it, told from its kind, its length and its
// header alone: a regular file (not a FIFO, whose read would wait for ever, nor a device, nor a
// link that leads nowhere), no longer than a file of its kind can be, and for an image, one of
// the reference's size (a header that claims 100000x100000 pixels is never decoded: the image
// could not pass, and its pixels would not fit in memory).
#pragma once

#include <cstdint>
#include <string>

namespace vkrt {

// The longest scene file a submission may hand in (the course's largest, the dragon of hw2-4,
// is 3.6 MB); a longer one is not parsed.
inline constexpr std::uint64_t kMaxSubmittedSceneBytes = std::uint64_t{32} << 20;

// The longest image file of a width x height image: 64 MB and 16 bytes a pixel (an
// uncompressed EXR of 32-bit RGBA, the widest image a format vkrt reads holds).
std::uint64_t maxSubmittedImageBytes(int width, int height);

// What a submitted image is before it is decoded: why it is not read (`problem`), or its size
// from its header.
struct SubmittedImage {
  std::string problem;
  int width = 0, height = 0;
};
SubmittedImage checkSubmittedImage(const std::string& path, int referenceWidth, int referenceHeight);

// Why a submitted scene file is not parsed (not a regular file, longer than
// kMaxSubmittedSceneBytes), or "".
std::string submittedSceneProblem(const std::string& path);

}  // namespace vkrt
