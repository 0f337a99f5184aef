#include "scene/tokenizer.h"

#include <algorithm>
#include <cstdio>

namespace vkrt {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

char lowerAscii(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

}  // namespace

bool equalIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                            [](char x, char y) { return lowerAscii(x) == lowerAscii(y); });
}

// A UTF-8 byte-order mark (some Windows editors write one) is not part of the first line.
Tokenizer::Tokenizer(std::string_view text)
    : text_(text), pos_(text.substr(0, kByteOrderMark.size()) == kByteOrderMark ? kByteOrderMark.size() : 0) {}

Tokenizer::Status Tokenizer::next(TokenLine& line) {
  while (pos_ < text_.size()) {
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    ++lineNumber_;
    const std::string_view text = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    if (!split(text, line)) return Status::NotText;
    if (line.count > 0) {
      line.number = lineNumber_;
      return Status::Line;
    }
  }
  return Status::End;
}

// The words of one line into `line`; false at a byte that is not text.
bool Tokenizer::split(std::string_view text, TokenLine& line) {
  line.count = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    const ByteClass k = byteClass(text[i]);
    if (k == kBinary) {
      notTextColumn_ = i + 1;
      notTextByte_ = static_cast<unsigned char>(text[i]);
      return false;
    }
    if (k == kBlank) {
      ++i;
    } else if (k == kComment) {   // the whole line, or the rest of it; still text
      while (i < text.size() && isTextByte(text[i])) ++i;
    } else {
      const std::size_t start = i;
      while (i < text.size() && byteClass(text[i]) == kToken) ++i;
      if (line.count < TokenLine::kMaxWords) line.words[line.count] = text.substr(start, i - start);
      ++line.count;
    }
  }
  return true;
}

std::string Tokenizer::notTextMessage() const {
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X", notTextByte_);
  return std::string("file is not text (byte ") + hex + " in column " + std::to_string(notTextColumn_) +
         "); expected a CSE167 scene file";
}

}  // namespace vkrt
