// The Gazepoint Open Gaze API's wire format: XML-like tags, one per line terminated by "\r\n", e.g.
//   <ACK ID="ENABLE_SEND_DATA" STATE="1" />
//   <REC TIME="12.345" BPOGX="0.512" BPOGY="0.430" BPOGV="1" />
// BPOGX/BPOGY are fractions of the screen with the origin top-left; BPOGV 0 means invalid. TCP may split
// a line across reads or merge several into one: OpenGazeLineSplitter reassembles them.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace gaze_bridge {

class OpenGazeLineSplitter {
 public:
  // A line longer than this without a terminator is garbage: it is discarded (and counted).
  static constexpr std::size_t kMaxLineBytes = 64 * 1024;

  void feed(const char* data, std::size_t size);
  // The next complete line without its "\r\n" (a bare "\n" also ends a line); false when none.
  bool nextLine(std::string& line);
  std::size_t discarded() const { return discarded_; }
  void clear() {
    buffer_.clear();
    start_ = 0;
  }

 private:
  std::string buffer_;
  std::size_t start_ = 0;  // consumed prefix, erased lazily
  std::size_t discarded_ = 0;
};

struct OpenGazeTag {
  std::string name;  // "REC", "ACK", "NACK", "CAL", ...
  std::vector<std::pair<std::string, std::string>> attributes;
  // Value of an attribute, or nullptr.
  const std::string* find(std::string_view key) const;
};

// Parses `<NAME KEY="value" ... />`; false when the line is not such a tag.
bool parseOpenGazeTag(std::string_view line, OpenGazeTag& tag);

struct OpenGazeRecord {
  double time_s = 0.0;  // TIME, seconds since the tracker started (NaN when the record has none)
  double x = 0.0, y = 0.0;
  bool valid = false;
};

// A REC tag with numeric BPOGX, BPOGY and BPOGV; false otherwise (not a REC, or fields missing/bad).
bool parseOpenGazeRecord(const OpenGazeTag& tag, OpenGazeRecord& record);

// The commands the bridge sends after connecting, in order, each terminated by "\r\n".
const std::vector<std::string>& openGazeStartCommands();

}  // namespace gaze_bridge
