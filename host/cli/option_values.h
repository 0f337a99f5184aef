// The values of command-line options, read and checked (cli/options.cpp's setters call
// these): numbers in their ranges, sizes, and outputs that vkrt cannot write. Each throws
// UsageError with the option's name and the value given.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image_file.h"   // FormatsOf

namespace vkrt {

// The first linear-float format's extension (".pfm"): a float file's name in examples.
std::string floatExtension();

// An integer option value in [lo, hi].
int integerValue(const std::string& option, const std::string& v, int lo, int hi);

// --size WxH, each side from 1 to kMaxImageEdge.
void sizeValue(const std::string& v, int& width, int& height);

// --scale F: a finite number greater than 0.
double scaleValue(const std::string& v);

// --seed N: a whole number from 0 to 2^32 - 1.
std::uint32_t seedValue(const std::string& v);

// --time SECONDS: a finite number greater than 0, at most a year.
double timeValue(const std::string& v);

// An output named '-': vkrt writes images into files only (its reports go to stdout).
void refuseStandardOutput(const std::string& option, const std::string& path);

// Whether an output path names a folder by its spelling: it ends in a separator ('/', and on
// Windows '\\' too), as -o DIR/ does.
bool endsInSeparator(const std::string& path);

// "output file 'x.bmp' is not named .png, .ppm or .pfm: vkrt writes PNG, under that name":
// `what` at `path`, which may be named as any of `which`.
std::string unnamedWarning(const std::string& what, const std::string& path, FormatsOf which);

// Whether an output path gets unnamedWarning: named as no image format, and not a folder
// (ends in '/', or is one) or a scene file, whose refusal by the write says so alone.
bool warnsOfItsName(const std::string& path);

// The warning of unnamedWarning for main() to print, or with `strict` a usage error.
void warnOfItsName(const std::string& what, const std::string& path, FormatsOf which, bool strict,
                   std::vector<std::string>& warnings);

}  // namespace vkrt
