// Peer text in logs and replies: short printable text as sent, anything else capped, cut on a UTF-8
// character boundary, control characters and broken UTF-8 replaced.
#include "net/peer_text.h"

#include <gtest/gtest.h>

namespace {

using net::echoText;

TEST(PeerText, ShortPrintableTextIsUnchanged) {
  EXPECT_EQ(echoText("dambreak"), "dambreak");
  EXPECT_EQ(echoText("gaze_rädius"), "gaze_rädius");
  EXPECT_EQ(echoText(""), "");
}

TEST(PeerText, LongTextIsCutAndItsLengthSaid) {
  const std::string long_name(60000, 'a');
  const std::string echoed = echoText(long_name);
  EXPECT_EQ(echoed, std::string(net::kMaxEchoBytes - 17, 'a') + "... (60000 bytes)");
  EXPECT_EQ(echoed.size(), net::kMaxEchoBytes);
  EXPECT_EQ(echoText(std::string(1 << 20, 'x'), net::kMaxErrorBytes).size(), net::kMaxErrorBytes);
  EXPECT_EQ(echoText(std::string(64, 'y')), std::string(64, 'y')) << "exactly the limit is not cut";
}

TEST(PeerText, ControlCharactersCannotForgeALogLine) { EXPECT_EQ(echoText("a\nb\rc\x1b[31m\x7f"), "a?b?c?[31m?"); }

TEST(PeerText, CutsOnACharacterBoundaryAndReplacesBrokenUtf8) {
  // 37 bytes cut to 20: "... (37 bytes)" leaves room for 6, and the 2-byte character at 5..6
  // would end past it, so it is left out whole.
  EXPECT_EQ(echoText("aaaaa\xc3\xa4" + std::string(30, 'b'), 20), "aaaaa... (37 bytes)");
  EXPECT_EQ(echoText("a\xc3"), "a?") << "a truncated sequence";
  EXPECT_EQ(echoText("\xed\xa0\x80"), "???") << "a surrogate";
  EXPECT_EQ(echoText("\xe0\x80\xaf"), "???") << "an overlong form";
  EXPECT_EQ(echoText("\xff\xfe"), "??");
}

}  // namespace
