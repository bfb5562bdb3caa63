#include "gaze/gaze_recording.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "temp_file.h"

using gaze::GazeFormatError;
using gaze::GazePoint;
using gaze::GazeRecording;
using gaze_test::TempFile;

namespace {

// Expects reading `text` to throw GazeFormatError whose message names the file, the line and `what`.
void expectFormatError(const std::string& text, int line, const std::string& what) {
  TempFile file;
  file.write(text);
  try {
    gaze::readGazeRecording(file.path());
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const GazeFormatError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(file.path() + ":" + std::to_string(line) + ":"), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
}

const char* kHeader = "time_s,x,y,valid\n";

}  // namespace

TEST(GazeRecording, RoundTripIsExact) {
  GazeRecording original;
  // Numbers that need all 17 digits, a denormal-ish small value, and invalid samples off screen.
  original.samples = {{0.0, 0.5, 0.5, true},
                      {1.0 / 120.0, 0.1 + 0.2, 1.0 / 3.0, true},
                      {2.0 / 120.0, 0.0, 1.0, true},
                      {0.1 + 0.2, 1e-300, std::nextafter(1.0, 0.0), false},
                      {12345.678901234567, -3.25, 7.5, false},
                      {12345.678901234569, 0.7071067811865476, 0.2718281828459045, true}};
  TempFile file;
  gaze::writeGazeRecording(file.path(), original);
  const GazeRecording read = gaze::readGazeRecording(file.path());
  ASSERT_EQ(read.samples.size(), original.samples.size());
  for (std::size_t i = 0; i < read.samples.size(); ++i) {
    EXPECT_EQ(read.samples[i].time_s, original.samples[i].time_s) << i;
    EXPECT_EQ(read.samples[i].x, original.samples[i].x) << i;
    EXPECT_EQ(read.samples[i].y, original.samples[i].y) << i;
    EXPECT_EQ(read.samples[i].valid, original.samples[i].valid) << i;
  }
  EXPECT_EQ(file.read().rfind("time_s,x,y,valid\n", 0), 0u);
}

TEST(GazeRecording, ReadsCommentsBlankLinesCrLfAndSpaces) {
  TempFile file;
  file.write(
      "# recorded by a test\r\n\r\ntime_s,x,y,valid\r\n# a comment between samples\r\n"
      "0, 0.25 ,0.75,1\r\n0.5,+0.5,0.5,0\r\n\r\n1e-1,0,0,1\n");
  // 1e-1 < 0.5: that last line must fail, which also proves exponent notation parses.
  EXPECT_THROW(gaze::readGazeRecording(file.path()), GazeFormatError);
  file.write(
      "# recorded by a test\r\n\r\ntime_s,x,y,valid\r\n# a comment between samples\r\n"
      "0, 0.25 ,0.75,1\r\n0.5,+0.5,0.5,0\r\n\r\n1e0,0,0,1\n");
  const GazeRecording read = gaze::readGazeRecording(file.path());
  ASSERT_EQ(read.samples.size(), 3u);
  EXPECT_EQ(read.samples[0].x, 0.25);
  EXPECT_EQ(read.samples[0].y, 0.75);
  EXPECT_TRUE(read.samples[0].valid);
  EXPECT_FALSE(read.samples[1].valid);
  EXPECT_EQ(read.samples[2].time_s, 1.0);
  EXPECT_DOUBLE_EQ(read.duration(), 1.0);
}

TEST(GazeRecording, RejectsBadHeader) {
  expectFormatError("time,x,y,valid\n0,0.5,0.5,1\n", 1, "expected header");
  expectFormatError("# only a comment\n0,0.5,0.5,1\n", 2, "expected header");
}

TEST(GazeRecording, RejectsMissingHeaderAndEmptyFile) {
  expectFormatError("", 0, "no header");
  expectFormatError("# nothing\n\n", 2, "no header");
}

TEST(GazeRecording, RejectsRecordingWithoutSamples) {
  expectFormatError(std::string(kHeader) + "# no data\n", 2, "no samples");
}

TEST(GazeRecording, RejectsNonNumbers) {
  expectFormatError(std::string(kHeader) + "0,0.5,0.5,1\nabc,0.5,0.5,1\n", 3, "time_s is not a number");
  expectFormatError(std::string(kHeader) + "0,0.5x,0.5,1\n", 2, "x is not a number");
  expectFormatError(std::string(kHeader) + "0,0.5,,1\n", 2, "y is not a number");
  expectFormatError(std::string(kHeader) + "0,0.5,0.5,yes\n", 2, "valid must be 0 or 1");
  expectFormatError(std::string(kHeader) + "0,0.5,0.5,2\n", 2, "valid must be 0 or 1");
}

TEST(GazeRecording, RejectsWrongFieldCount) {
  expectFormatError(std::string(kHeader) + "0,0.5,0.5\n", 2, "4 comma-separated fields");
  expectFormatError(std::string(kHeader) + "0,0.5,0.5,1,7\n", 2, "4 comma-separated fields");
}

TEST(GazeRecording, RejectsNanAndInfinity) {
  expectFormatError(std::string(kHeader) + "0,nan,0.5,0\n", 2, "not a finite number");
  expectFormatError(std::string(kHeader) + "0,0.5,NaN,1\n", 2, "not a finite number");
  expectFormatError(std::string(kHeader) + "inf,0.5,0.5,1\n", 2, "not a finite number");
}

TEST(GazeRecording, RejectsValidPointOffScreenButAcceptsInvalidOne) {
  expectFormatError(std::string(kHeader) + "0,1.0001,0.5,1\n", 2, "outside [0, 1]");
  expectFormatError(std::string(kHeader) + "0,0.5,-0.01,1\n", 2, "outside [0, 1]");
  TempFile file;
  file.write(std::string(kHeader) + "0,1.5,-2,0\n");
  EXPECT_EQ(gaze::readGazeRecording(file.path()).samples.size(), 1u);
}

TEST(GazeRecording, RejectsTimeThatDoesNotIncrease) {
  expectFormatError(std::string(kHeader) + "0,0.5,0.5,1\n0.1,0.5,0.5,1\n0.1,0.5,0.5,1\n", 4, "does not increase");
  expectFormatError(std::string(kHeader) + "1,0.5,0.5,1\n# c\n0.5,0.5,0.5,1\n", 4, "does not increase");
}

TEST(GazeRecording, MissingFileNamesThePath) {
  const std::string path = ::testing::TempDir() + "gaze_no_such_file_here.csv";
  try {
    gaze::readGazeRecording(path);
    FAIL() << "no error";
  } catch (const GazeFormatError& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos);
  }
}

TEST(GazeRecording, WriterRefusesWhatCouldNotReadBackAndWritesNothing) {
  TempFile file;
  GazeRecording bad;
  bad.samples = {{0.0, 0.5, 0.5, true}, {0.0, 0.5, 0.5, true}};
  EXPECT_THROW(gaze::writeGazeRecording(file.path(), bad), GazeFormatError);
  bad.samples = {{0.0, std::numeric_limits<double>::quiet_NaN(), 0.5, false}};
  EXPECT_THROW(gaze::writeGazeRecording(file.path(), bad), GazeFormatError);
  bad.samples = {{0.0, 1.5, 0.5, true}};
  EXPECT_THROW(gaze::writeGazeRecording(file.path(), bad), GazeFormatError);
  EXPECT_THROW(gaze::writeGazeRecording(file.path(), GazeRecording{}), GazeFormatError);
  EXPECT_EQ(file.read(), "");
}

TEST(GazeRecording, LatestAtFindsNewestSampleAtOrBeforeTime) {
  GazeRecording recording;
  recording.samples = {{1.0, 0.1, 0.1, true}, {2.0, 0.2, 0.2, false}, {3.0, 0.3, 0.3, true}};
  GazePoint out;
  EXPECT_FALSE(recording.latestAt(0.999, out));
  ASSERT_TRUE(recording.latestAt(1.0, out));
  EXPECT_EQ(out.x, 0.1);
  ASSERT_TRUE(recording.latestAt(1.999, out));
  EXPECT_EQ(out.x, 0.1);
  ASSERT_TRUE(recording.latestAt(2.0, out));  // invalid samples are returned too
  EXPECT_EQ(out.x, 0.2);
  EXPECT_FALSE(out.valid);
  ASSERT_TRUE(recording.latestAt(2.5, out));
  EXPECT_EQ(out.x, 0.2);
  ASSERT_TRUE(recording.latestAt(1e9, out));
  EXPECT_EQ(out.x, 0.3);
  EXPECT_FALSE(GazeRecording{}.latestAt(5.0, out));
  EXPECT_DOUBLE_EQ(recording.duration(), 2.0);
  EXPECT_EQ(GazeRecording{}.duration(), 0.0);
}

TEST(GazeRecording, LatestAtMatchesLinearScanOnLongRecording) {
  GazeRecording recording;
  for (int i = 0; i < 1000; ++i) recording.samples.push_back({i * 0.01 + (i % 7) * 1e-4, i / 1000.0, 0.5, i % 3 != 0});
  for (int k = -5; k < 1100; ++k) {
    const double t = k * 0.00973;
    const GazePoint* expected = nullptr;
    for (const GazePoint& p : recording.samples) {
      if (p.time_s <= t) expected = &p;
    }
    GazePoint out;
    ASSERT_EQ(recording.latestAt(t, out), expected != nullptr) << t;
    if (expected != nullptr) {
      EXPECT_EQ(out.time_s, expected->time_s) << t;
    }
  }
}
