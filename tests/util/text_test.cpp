// How messages show text they did not write (util/text.h): a path's control characters
// escaped and its other bytes, UTF-8 included, kept; a token's every non-ASCII byte escaped;
// both cut short past their limits.
#include <gtest/gtest.h>

#include "util/text.h"

using namespace vkrt;

TEST(MessageText, APathKeepsItsLettersAndEscapesWhatWouldSteerTheTerminal) {
  EXPECT_EQ(abbreviated("class/Zo\xC3\xAB/scene5.png"), "class/Zo\xC3\xAB/scene5.png");
  EXPECT_EQ(abbreviated("class/\x1b]0;pwned\x07/a\nb\x7f.png"), "class/\\x1B]0;pwned\\x07/a\\x0Ab\\x7F.png");
  EXPECT_EQ(abbreviated("abcdef", 3), "abc... (6 bytes)");
  EXPECT_EQ(abbreviated("\x1b\x1b\x1b\x1b", 2), "\\x1B\\x1B... (4 bytes)");
}

TEST(MessageText, ATokenEscapesEveryByteOutsidePrintableAscii) {
  EXPECT_EQ(echoed("Zo\xC3\xAB\t"), "Zo\\xC3\\xAB\\x09");
  EXPECT_EQ(quoted("a b"), "'a b'");
  EXPECT_EQ(echoed(std::string(300, 'x')), std::string(200, 'x') + "... (300 bytes)");
}
