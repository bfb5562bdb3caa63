#include "open_gaze_parser.h"

#include <gtest/gtest.h>

#include <cmath>

#include <string>
#include <vector>

using namespace gaze_bridge;

namespace {

std::vector<std::string> drain(OpenGazeLineSplitter& splitter) {
  std::vector<std::string> lines;
  std::string line;
  while (splitter.nextLine(line)) lines.push_back(line);
  return lines;
}

}  // namespace

TEST(OpenGazeLineSplitter, ReassemblesRecordsSplitAtEveryByte) {
  const std::string stream =
      "<ACK ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />\r\n"
      "<REC TIME=\"1.000\" BPOGX=\"0.25\" BPOGY=\"0.75\" BPOGV=\"1\" />\r\n"
      "<REC TIME=\"1.016\" BPOGX=\"0.5\" BPOGY=\"0.5\" BPOGV=\"0\" />\r\n";
  const std::vector<std::string> expected = {"<ACK ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />",
                                             "<REC TIME=\"1.000\" BPOGX=\"0.25\" BPOGY=\"0.75\" BPOGV=\"1\" />",
                                             "<REC TIME=\"1.016\" BPOGX=\"0.5\" BPOGY=\"0.5\" BPOGV=\"0\" />"};
  // Every cut into two reads, and every cut into three, including between \r and \n.
  for (std::size_t a = 0; a <= stream.size(); ++a) {
    for (std::size_t b = a; b <= stream.size(); b += 7) {
      OpenGazeLineSplitter splitter;
      std::vector<std::string> lines;
      for (auto [from, to] : {std::pair{std::size_t{0}, a}, std::pair{a, b}, std::pair{b, stream.size()}}) {
        splitter.feed(stream.data() + from, to - from);
        for (auto& line : drain(splitter)) lines.push_back(line);
      }
      ASSERT_EQ(lines, expected) << "cuts at " << a << ", " << b;
    }
  }
}

TEST(OpenGazeLineSplitter, DiscardsAnEndlessLine) {
  OpenGazeLineSplitter splitter;
  const std::string junk(OpenGazeLineSplitter::kMaxLineBytes + 10, 'x');
  splitter.feed(junk.data(), junk.size());
  EXPECT_EQ(splitter.discarded(), 1u);
  const std::string good = "<REC BPOGX=\"0.1\" BPOGY=\"0.2\" BPOGV=\"1\" />\n";
  splitter.feed(good.data(), good.size());
  EXPECT_EQ(drain(splitter), std::vector<std::string>{good.substr(0, good.size() - 1)});
}

TEST(OpenGazeParser, ParsesRecord) {
  OpenGazeTag tag;
  ASSERT_TRUE(parseOpenGazeTag("<REC TIME=\"12.345\" BPOGX=\"0.512\" BPOGY=\"0.430\" BPOGV=\"1\" />", tag));
  EXPECT_EQ(tag.name, "REC");
  OpenGazeRecord record;
  ASSERT_TRUE(parseOpenGazeRecord(tag, record));
  EXPECT_DOUBLE_EQ(record.time_s, 12.345);
  EXPECT_DOUBLE_EQ(record.x, 0.512);
  EXPECT_DOUBLE_EQ(record.y, 0.430);
  EXPECT_TRUE(record.valid);
  ASSERT_TRUE(parseOpenGazeTag("<REC BPOGX=\"0.5\" BPOGY=\"0.5\" BPOGV=\"0\"/>", tag));
  ASSERT_TRUE(parseOpenGazeRecord(tag, record));
  EXPECT_FALSE(record.valid);
  EXPECT_TRUE(std::isnan(record.time_s));
}

TEST(OpenGazeParser, RejectsMalformedTagsAndRecords) {
  OpenGazeTag tag;
  OpenGazeRecord record;
  EXPECT_FALSE(parseOpenGazeTag("REC BPOGX=\"0.5\"", tag));
  EXPECT_FALSE(parseOpenGazeTag("<REC BPOGX=\"0.5 />", tag));
  EXPECT_FALSE(parseOpenGazeTag("<REC BPOGX=0.5 />", tag));
  EXPECT_FALSE(parseOpenGazeTag("<>", tag));
  ASSERT_TRUE(parseOpenGazeTag("<REC BPOGX=\"abc\" BPOGY=\"0.5\" BPOGV=\"1\" />", tag));
  EXPECT_FALSE(parseOpenGazeRecord(tag, record));
  ASSERT_TRUE(parseOpenGazeTag("<REC BPOGX=\"0.5\" BPOGV=\"1\" />", tag));
  EXPECT_FALSE(parseOpenGazeRecord(tag, record));
  ASSERT_TRUE(parseOpenGazeTag("<ACK ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />", tag));
  EXPECT_EQ(tag.name, "ACK");
  ASSERT_NE(tag.find("ID"), nullptr);
  EXPECT_EQ(*tag.find("ID"), "ENABLE_SEND_DATA");
  EXPECT_FALSE(parseOpenGazeRecord(tag, record));
}

TEST(OpenGazeParser, StartCommandsEnableBestPogTimeAndData) {
  const auto& commands = openGazeStartCommands();
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_EQ(commands[0], "<SET ID=\"ENABLE_SEND_POG_BEST\" STATE=\"1\" />\r\n");
  EXPECT_EQ(commands[1], "<SET ID=\"ENABLE_SEND_TIME\" STATE=\"1\" />\r\n");
  EXPECT_EQ(commands[2], "<SET ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />\r\n");
}
