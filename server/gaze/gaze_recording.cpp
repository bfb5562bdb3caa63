#include "gaze/gaze_recording.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <system_error>

namespace gaze {

namespace {

std::string_view trim(std::string_view text) {
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& what) {
  throw GazeFormatError(path + ":" + std::to_string(line) + ": " + what);
}

// std::from_chars: locale-independent and exact (the writer's to_chars output reads back bit for bit).
bool parseDouble(std::string_view text, double& value) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

// Splits "a,b,c,d" into exactly four fields; false for any other count.
bool splitFields(std::string_view line, std::array<std::string_view, 4>& fields) {
  std::size_t count = 0;
  while (true) {
    const std::size_t comma = line.find(',');
    if (count == fields.size()) return false;
    fields[count++] = line.substr(0, comma);
    if (comma == std::string_view::npos) break;
    line.remove_prefix(comma + 1);
  }
  return count == fields.size();
}

std::string formatDouble(double value) {
  std::array<char, 64> buffer{};
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  (void)error;  // 64 chars always suffice for the shortest form of a double
  return std::string(buffer.data(), end);
}

}  // namespace

double GazeRecording::duration() const {
  if (samples.size() < 2) return 0.0;
  return samples.back().time_s - samples.front().time_s;
}

bool GazeRecording::latestAt(double t, GazePoint& out) const {
  // First sample strictly after t; the one before it is the newest at or before t.
  const auto after = std::upper_bound(samples.begin(), samples.end(), t,
                                      [](double time, const GazePoint& p) { return time < p.time_s; });
  if (after == samples.begin()) return false;
  out = *(after - 1);
  return true;
}

std::string checkGazePoint(const GazePoint& point, const GazePoint* previous) {
  if (!std::isfinite(point.time_s)) return "time_s is not a finite number";
  if (!std::isfinite(point.x) || !std::isfinite(point.y)) return "x or y is not a finite number";
  if (point.valid && (point.x < 0.0 || point.x > 1.0 || point.y < 0.0 || point.y > 1.0)) {
    return "valid sample outside [0, 1]: x=" + formatDouble(point.x) + " y=" + formatDouble(point.y);
  }
  if (previous != nullptr && !(point.time_s > previous->time_s)) {
    return "time_s " + formatDouble(point.time_s) + " does not increase (previous " + formatDouble(previous->time_s) +
           ")";
  }
  return {};
}

std::string formatGazePoint(const GazePoint& point) {
  return formatDouble(point.time_s) + "," + formatDouble(point.x) + "," + formatDouble(point.y) + "," +
         (point.valid ? "1" : "0");
}

GazeRecording readGazeRecording(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw GazeFormatError(path + ": cannot open gaze recording");

  GazeRecording recording;
  bool have_header = false;
  std::string raw;
  std::size_t line_number = 0;
  while (std::getline(in, raw)) {
    ++line_number;
    const std::string_view line = trim(raw);
    if (line.empty() || line.front() == '#') continue;
    if (!have_header) {
      if (line != kGazeRecordingHeader) {
        fail(path, line_number,
             "expected header '" + std::string(kGazeRecordingHeader) + "', got '" + std::string(line) + "'");
      }
      have_header = true;
      continue;
    }
    std::array<std::string_view, 4> fields;
    if (!splitFields(line, fields)) fail(path, line_number, "expected 4 comma-separated fields");
    GazePoint point;
    if (!parseDouble(fields[0], point.time_s)) fail(path, line_number, "time_s is not a number");
    if (!parseDouble(fields[1], point.x)) fail(path, line_number, "x is not a number");
    if (!parseDouble(fields[2], point.y)) fail(path, line_number, "y is not a number");
    const std::string_view valid = trim(fields[3]);
    if (valid == "1") {
      point.valid = true;
    } else if (valid == "0") {
      point.valid = false;
    } else {
      fail(path, line_number, "valid must be 0 or 1, got '" + std::string(valid) + "'");
    }
    const std::string problem = checkGazePoint(point, recording.samples.empty() ? nullptr : &recording.samples.back());
    if (!problem.empty()) fail(path, line_number, problem);
    recording.samples.push_back(point);
  }
  if (in.bad()) throw GazeFormatError(path + ": read error");
  if (!have_header) fail(path, line_number, "no header line '" + std::string(kGazeRecordingHeader) + "'");
  if (recording.samples.empty()) fail(path, line_number, "recording has no samples");
  return recording;
}

void writeGazeRecording(const std::string& path, const GazeRecording& recording) {
  // Validate everything first so a bad recording leaves no file behind.
  if (recording.samples.empty()) throw GazeFormatError(path + ": recording has no samples");
  for (std::size_t i = 0; i < recording.samples.size(); ++i) {
    const std::string problem = checkGazePoint(recording.samples[i], i == 0 ? nullptr : &recording.samples[i - 1]);
    if (!problem.empty()) throw GazeFormatError(path + ": sample " + std::to_string(i) + ": " + problem);
  }
  std::ostringstream text;
  text << kGazeRecordingHeader << '\n';
  for (const GazePoint& point : recording.samples) text << formatGazePoint(point) << '\n';

  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
  out << text.str();
  out.flush();
  if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace gaze
