// The tokenizer: scene text -> its lines' words, each line numbered for the messages
// (doc/scene-format.md, "File structure"). Words are split at blanks, `#` starts a comment
// that runs to the end of the line, and a UTF-8 byte-order mark before the first line is
// skipped. A control byte that is not a blank means the file is not text: the tokenizer stops
// there and says where.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>

namespace vkrt {

// The most arguments a command takes (quadLight's 12).
inline constexpr int kMaxArgs = 12;

// What each byte is to the tokenizer: one table lookup per byte. NUL, the other C0 control
// bytes but the blanks, and DEL never occur in text.
enum ByteClass : unsigned char { kToken, kBlank, kComment, kBinary };
constexpr std::array<ByteClass, 256> makeByteClasses() {
  std::array<ByteClass, 256> t{};
  for (int c = 0; c < 0x20; ++c) t[c] = kBinary;
  for (int c : {' ', '\t', '\r', '\v', '\f'}) t[c] = kBlank;
  t['#'] = kComment;
  t[0x7F] = kBinary;
  return t;
}
inline constexpr std::array<ByteClass, 256> kByteClass = makeByteClasses();
inline ByteClass byteClass(char c) { return kByteClass[static_cast<unsigned char>(c)]; }

// Whether byte `c` may stand in a scene file's line.
inline bool isTextByte(char c) { return byteClass(c) != kBinary; }

// Whether a and b are the same word but for the case of ASCII letters (`maxDepth`, `MIS`).
bool equalIgnoringCase(std::string_view a, std::string_view b);

// One line that holds words: the command, then its arguments. A line keeps its first
// kMaxWords words, more than any command takes; `count` is how many it has, so that a message
// can say how many arguments it got.
struct TokenLine {
  static constexpr int kMaxWords = kMaxArgs + 2;
  int number = 0;   // from 1
  std::string_view words[kMaxWords];
  int count = 0;

  std::string_view command() const { return words[0]; }
};

class Tokenizer {
 public:
  enum class Status { Line, End, NotText };

  explicit Tokenizer(std::string_view text);

  // The next line that holds a word into `line` (lines of blanks and comments are passed
  // over, and counted): Line; End when the text is read; NotText at a byte that is not text,
  // which notTextMessage() then names. Its words before that byte are not given.
  Status next(TokenLine& line);

  // The number of the line read last (0 before the first; at End, how many lines the text has).
  int lineNumber() const { return lineNumber_; }

  // "file is not text (byte 0x00 in column 7); expected a CSE167 scene file".
  std::string notTextMessage() const;

 private:
  bool split(std::string_view text, TokenLine& line);

  std::string_view text_;
  std::size_t pos_ = 0;
  int lineNumber_ = 0;
  std::size_t notTextColumn_ = 0;   // from 1
  unsigned char notTextByte_ = 0;
};

}  // namespace vkrt
