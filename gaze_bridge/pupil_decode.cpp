#include "pupil_decode.h"

#include <cmath>
#include <msgpack.hpp>
#include <string_view>

namespace gaze_bridge {

namespace {

bool keyIs(const msgpack::object& key, std::string_view name) {
  if (key.type == msgpack::type::STR) return std::string_view(key.via.str.ptr, key.via.str.size) == name;
  if (key.type == msgpack::type::BIN) return std::string_view(key.via.bin.ptr, key.via.bin.size) == name;
  return false;
}

const msgpack::object* lookup(const msgpack::object& map, std::string_view name) {
  if (map.type != msgpack::type::MAP) return nullptr;
  for (std::uint32_t i = 0; i < map.via.map.size; ++i) {
    if (keyIs(map.via.map.ptr[i].key, name)) return &map.via.map.ptr[i].val;
  }
  return nullptr;
}

bool asNumber(const msgpack::object* object, double& value) {
  if (object == nullptr) return false;
  switch (object->type) {
    case msgpack::type::FLOAT32:
    case msgpack::type::FLOAT64:
      value = object->via.f64;
      break;
    case msgpack::type::POSITIVE_INTEGER:
      value = static_cast<double>(object->via.u64);
      break;
    case msgpack::type::NEGATIVE_INTEGER:
      value = static_cast<double>(object->via.i64);
      break;
    default:
      return false;
  }
  return std::isfinite(value);
}

bool decodeEntry(const msgpack::object& entry, std::int64_t arrival_ns, TrackerSample& sample) {
  const msgpack::object* norm_pos = lookup(entry, "norm_pos");
  if (norm_pos == nullptr || norm_pos->type != msgpack::type::ARRAY || norm_pos->via.array.size != 2) return false;
  double nx = 0.0, ny = 0.0, confidence = 0.0, timestamp = 0.0;
  if (!asNumber(&norm_pos->via.array.ptr[0], nx) || !asNumber(&norm_pos->via.array.ptr[1], ny)) return false;
  // Pupil's confidence lies in [0, 1]; outside it the entry is malformed, and a value beyond float's
  // range would make the cast below undefined behaviour (found by tests/fuzz/fuzz_pupil_decode).
  if (!asNumber(lookup(entry, "confidence"), confidence) || confidence < 0.0 || confidence > 1.0) return false;
  if (!asNumber(lookup(entry, "timestamp"), timestamp)) return false;
  const msgpack::object* on_surf = lookup(entry, "on_surf");
  // on_surf may be missing in old Capture versions: then the position decides.
  const bool on_surface = on_surf == nullptr || (on_surf->type == msgpack::type::BOOLEAN && on_surf->via.boolean);
  sample.tracker_time_s = timestamp;
  sample.x = nx;
  sample.y = 1.0 - ny;  // bottom-left origin -> top-left
  sample.valid = on_surface;
  sample.confidence = static_cast<float>(confidence);
  sample.arrival_ns = arrival_ns;
  return true;
}

}  // namespace

std::string decodePupilSurfaceMessage(const void* data, std::size_t size, std::int64_t arrival_ns,
                                      std::vector<TrackerSample>& out, std::size_t& skipped) {
  msgpack::object_handle handle;
  try {
    // Limits bound what a hostile or corrupt payload can make the decoder allocate.
    const msgpack::unpack_limit limits(/*array=*/100000, /*map=*/10000, /*str=*/1 << 20, /*bin=*/1 << 22,
                                       /*ext=*/1 << 20, /*depth=*/32);
    handle = msgpack::unpack(static_cast<const char*>(data), size, nullptr, nullptr, limits);
  } catch (const std::exception& error) {
    return std::string("msgpack: ") + error.what();
  }
  const msgpack::object& root = handle.get();
  if (root.type != msgpack::type::MAP) return "payload is not a msgpack map";
  const msgpack::object* gaze = lookup(root, "gaze_on_surfaces");
  if (gaze == nullptr) return "no gaze_on_surfaces";
  if (gaze->type != msgpack::type::ARRAY) return "gaze_on_surfaces is not an array";
  for (std::uint32_t i = 0; i < gaze->via.array.size; ++i) {
    TrackerSample sample;
    if (decodeEntry(gaze->via.array.ptr[i], arrival_ns, sample)) {
      out.push_back(sample);
    } else {
      ++skipped;
    }
  }
  return {};
}

}  // namespace gaze_bridge
