#include "open_gaze_parser.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace gaze_bridge {

void OpenGazeLineSplitter::feed(const char* data, std::size_t size) {
  if (start_ > 0 && start_ >= buffer_.size() / 2) {  // drop the consumed prefix now and then
    buffer_.erase(0, start_);
    start_ = 0;
  }
  buffer_.append(data, size);
  if (buffer_.size() - start_ > kMaxLineBytes && buffer_.find('\n', start_) == std::string::npos) {
    buffer_.clear();
    start_ = 0;
    ++discarded_;
  }
}

bool OpenGazeLineSplitter::nextLine(std::string& line) {
  const std::size_t end = buffer_.find('\n', start_);
  if (end == std::string::npos) return false;
  std::size_t stop = end;
  if (stop > start_ && buffer_[stop - 1] == '\r') --stop;
  line.assign(buffer_, start_, stop - start_);
  start_ = end + 1;
  if (start_ == buffer_.size()) clear();
  return true;
}

const std::string* OpenGazeTag::find(std::string_view key) const {
  for (const auto& [k, v] : attributes) {
    if (k == key) return &v;
  }
  return nullptr;
}

bool parseOpenGazeTag(std::string_view line, OpenGazeTag& tag) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  auto skip = [&](std::size_t i) {
    while (i < line.size() && is_space(line[i])) ++i;
    return i;
  };
  tag.name.clear();
  tag.attributes.clear();
  std::size_t i = skip(0);
  if (i >= line.size() || line[i] != '<') return false;
  ++i;
  const std::size_t name_start = i;
  while (i < line.size() && !is_space(line[i]) && line[i] != '/' && line[i] != '>') ++i;
  if (i == name_start) return false;
  tag.name.assign(line.substr(name_start, i - name_start));
  while (true) {
    i = skip(i);
    if (i >= line.size()) return false;
    if (line[i] == '/' || line[i] == '>') break;
    const std::size_t key_start = i;
    while (i < line.size() && line[i] != '=' && !is_space(line[i])) ++i;
    if (i >= line.size() || line[i] != '=' || i == key_start) return false;
    std::string key(line.substr(key_start, i - key_start));
    ++i;
    if (i >= line.size() || line[i] != '"') return false;
    const std::size_t value_end = line.find('"', i + 1);
    if (value_end == std::string_view::npos) return false;
    tag.attributes.emplace_back(std::move(key), std::string(line.substr(i + 1, value_end - i - 1)));
    i = value_end + 1;
  }
  return true;
}

namespace {

bool toDouble(const std::string* text, double& value) {
  if (text == nullptr || text->empty()) return false;
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  return error == std::errc() && end == text->data() + text->size() && std::isfinite(value);
}

}  // namespace

bool parseOpenGazeRecord(const OpenGazeTag& tag, OpenGazeRecord& record) {
  if (tag.name != "REC") return false;
  double valid = 0.0;
  if (!toDouble(tag.find("BPOGX"), record.x) || !toDouble(tag.find("BPOGY"), record.y) ||
      !toDouble(tag.find("BPOGV"), valid)) {
    return false;
  }
  record.valid = valid != 0.0;
  if (!toDouble(tag.find("TIME"), record.time_s)) record.time_s = std::numeric_limits<double>::quiet_NaN();
  return true;
}

const std::vector<std::string>& openGazeStartCommands() {
  static const std::vector<std::string> commands = {
      "<SET ID=\"ENABLE_SEND_POG_BEST\" STATE=\"1\" />\r\n",
      "<SET ID=\"ENABLE_SEND_TIME\" STATE=\"1\" />\r\n",
      "<SET ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />\r\n",
  };
  return commands;
}

}  // namespace gaze_bridge
