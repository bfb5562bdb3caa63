#include "scene/scene_loader.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <type_traits>

#include <spdlog/spdlog.h>

#include "sph/adaptive/method.h"
#include "sph/param_table.h"

namespace scene {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// Carries the file name and the key path into every message.
struct Context {
  std::string source;

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw SceneError(source + ": key '" + key + "': " + what);
  }

  void allowOnly(const json& object, const std::string& key, const std::set<std::string>& allowed) const {
    if (!object.is_object()) fail(key.empty() ? "(top level)" : key, "must be an object");
    for (const auto& [name, value] : object.items()) {
      (void)value;
      if (!allowed.contains(name)) {
        const std::string full = key.empty() ? name : key + "." + name;
        fail(full, "unknown key");
      }
    }
  }

  const json& required(const json& object, const std::string& parent, const std::string& name) const {
    if (!object.contains(name)) fail(parent.empty() ? name : parent + "." + name, "missing");
    return object.at(name);
  }

  double number(const json& value, const std::string& key) const {
    if (!value.is_number()) fail(key, "must be a number");
    const double v = value.get<double>();
    if (!std::isfinite(v)) fail(key, "must be finite");
    return v;
  }

  double positive(const json& value, const std::string& key) const {
    const double v = number(value, key);
    if (v <= 0.0) fail(key, "must be > 0");
    return v;
  }

  double nonNegative(const json& value, const std::string& key) const {
    const double v = number(value, key);
    if (v < 0.0) fail(key, "must be >= 0");
    return v;
  }

  int positiveInt(const json& value, const std::string& key) const {
    if (!value.is_number_integer() || value.get<long long>() <= 0 || value.get<long long>() > 100000000) {
      fail(key, "must be a positive integer");
    }
    return static_cast<int>(value.get<long long>());
  }

  Eigen::Vector3d vec3(const json& value, const std::string& key) const {
    if (!value.is_array() || value.size() != 3) fail(key, "must be an array of 3 numbers");
    Eigen::Vector3d v;
    for (int a = 0; a < 3; ++a) v[a] = number(value[a], key + "[" + std::to_string(a) + "]");
    return v;
  }

  sph::Aabb box(const json& value, const std::string& key) const {
    allowOnly(value, key, {"min", "max"});
    sph::Aabb b;
    b.min = vec3(required(value, key, "min"), key + ".min");
    b.max = vec3(required(value, key, "max"), key + ".max");
    if ((b.max.array() <= b.min.array()).any()) fail(key, "max must exceed min on every axis");
    return b;
  }
};

// Every key of `section` ("params" or "adaptive") by the settings table (sph/param_table.h): its
// type, then its range, onto `holder` (SimParams or AdaptiveConfig).
template <class Holder>
void readSettings(const Context& ctx, const std::string& section, const json& values, Holder& holder) {
  constexpr bool adaptive = std::is_same_v<Holder, sph::AdaptiveConfig>;
  if (!values.is_object()) ctx.fail(section, "must be an object");
  for (const auto& [name, value] : values.items()) {
    const std::string key = section + "." + name;
    const sph::ParamSpec* spec = sph::findParameter(name);
    if (spec == nullptr) ctx.fail(key, "unknown parameter");
    if (spec->isAdaptive() != adaptive) {
      ctx.fail(key, adaptive ? "unknown parameter (a simulation parameter: it belongs in 'params')"
                             : "unknown parameter (an adaptive setting: it belongs in 'adaptive')");
    }
    if (name != spec->key) {
      spdlog::warn("{}: key '{}' is now called '{}.{}' (the old name still works)", ctx.source, key, section,
                   spec->key);
    }
    double number = 0.0;
    if (spec->isFlag()) {
      if (!value.is_boolean()) ctx.fail(key, "must be true or false");
      number = value.template get<bool>() ? 1.0 : 0.0;
    } else if (spec->isInteger()) {
      if (!value.is_number_integer()) ctx.fail(key, "must be " + spec->accepts());
      number = static_cast<double>(value.template get<long long>());
    } else {
      number = ctx.number(value, key);
    }
    if (const std::string why = spec->check(number); !why.empty()) ctx.fail(key, why);
    spec->set(holder, number);
  }
}

int axisIndex(const Context& ctx, const json& value, const std::string& key) {
  if (value == "x") return 0;
  if (value == "y") return 1;
  if (value == "z") return 2;
  ctx.fail(key, "must be \"x\", \"y\" or \"z\"");
}

void readCamera(const Context& ctx, const json& cam, sph::CameraSpec& c) {
  ctx.allowOnly(cam, "camera", {"eye", "target", "up", "fov_y_degrees", "viewport", "near", "far"});
  c.eye = ctx.vec3(ctx.required(cam, "camera", "eye"), "camera.eye");
  c.target = ctx.vec3(ctx.required(cam, "camera", "target"), "camera.target");
  if (cam.contains("up")) c.up = ctx.vec3(cam["up"], "camera.up");
  if (cam.contains("fov_y_degrees")) {
    c.fov_y_degrees = ctx.positive(cam["fov_y_degrees"], "camera.fov_y_degrees");
    if (c.fov_y_degrees >= 180.0) ctx.fail("camera.fov_y_degrees", "must be < 180");
  }
  if (cam.contains("viewport")) {
    const json& vp = cam["viewport"];
    if (!vp.is_array() || vp.size() != 2) ctx.fail("camera.viewport", "must be [width, height]");
    c.viewport_width = ctx.positiveInt(vp[0], "camera.viewport[0]");
    c.viewport_height = ctx.positiveInt(vp[1], "camera.viewport[1]");
  }
  if (cam.contains("near")) c.near_plane = ctx.positive(cam["near"], "camera.near");
  if (cam.contains("far")) c.far_plane = ctx.positive(cam["far"], "camera.far");
  if (c.far_plane <= c.near_plane) ctx.fail("camera.far", "must exceed camera.near");
  if ((c.eye - c.target).norm() <= 0.0) ctx.fail("camera.target", "must differ from camera.eye");
  if (c.up.norm() <= 0.0 || c.up.cross(c.target - c.eye).norm() <= 1e-9) {
    ctx.fail("camera.up", "must be non-zero and not parallel to the view direction");
  }
}

// The "adaptive" object by the settings table, then what holds between its settings.
void readAdaptive(const Context& ctx, const json& a, sph::AdaptiveConfig& c) {
  readSettings(ctx, "adaptive", a, c);
  try {
    c.validate();
  } catch (const std::invalid_argument& e) {
    ctx.fail("adaptive", e.what());
  }
}

}  // namespace

std::string defaultSceneDir() {
  if (const char* env = std::getenv("SPH_SCENE_DIR"); env && *env) return env;
  // An installed program finds the scenes installed beside it (PREFIX/bin -> PREFIX/share/...), so
  // a package works wherever it is unpacked; a program in a build tree has none there and falls back
  // to the source tree it was built from.
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / SPH_INSTALLED_SCENE_DIR;
    if (fs::is_directory(installed, ec)) return installed.lexically_normal().string();
  }
  return SPH_SOURCE_SCENE_DIR;
}

std::vector<std::string> listScenes(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") {
      names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

sph::Scene loadScene(const std::string& name_or_path, const std::string& dir, const std::string& preset) {
  fs::path path(name_or_path);
  const bool looks_like_path = path.has_extension() || name_or_path.find('/') != std::string::npos;
  if (!looks_like_path) path = fs::path(dir) / (name_or_path + ".json");
  std::ifstream in(path);
  if (!in) {
    std::string msg = "cannot open scene file '" + path.string() + "'";
    if (!looks_like_path) {
      msg = "unknown scene '" + name_or_path + "' (no " + path.string() + "); known scenes:";
      for (const auto& n : listScenes(dir)) msg += " " + n;
    }
    throw SceneError(msg);
  }
  std::stringstream text;
  text << in.rdbuf();
  sph::Scene s = parseScene(text.str(), path.string(), preset);
  if (s.name.empty()) s.name = path.stem().string();
  if (!s.gaze_recording.empty() && fs::path(s.gaze_recording).is_relative()) {
    s.gaze_recording = (path.parent_path() / s.gaze_recording).string();
  }
  return s;
}

std::string knownPresetList() {
  std::string known;
  for (const auto& name : sph::presetNames()) known += (known.empty() ? "" : ", ") + name;
  return known;
}

sph::Scene parseScene(const std::string& json_text, const std::string& source, const std::string& preset) {
  const Context ctx{source};
  sph::SimParams preset_params;
  if (!preset.empty() && !sph::presetByName(preset, preset_params)) {
    throw SceneError("unknown preset '" + preset + "' (known: " + knownPresetList() + ")");
  }
  json doc;
  try {
    doc = json::parse(json_text);
  } catch (const json::exception& e) {
    // parse_error, and also out_of_range for a number too large for a double (e.g. 1e999): found by
    // tests/fuzz/fuzz_scene_loader, since it escaped as a non-SceneError.
    throw SceneError(source + ": not valid JSON: " + e.what());
  }
  ctx.allowOnly(doc, "",
                {"name", "description", "preset", "params", "box", "box_changes", "moving_walls", "spheres",
                 "cylinders", "water", "large_particles", "frames", "camera", "method", "adaptive", "gaze_recording"});
  sph::Scene s;
  s.source = source;
  if (doc.contains("name")) {
    if (!doc["name"].is_string()) ctx.fail("name", "must be a string");
    s.name = doc["name"].get<std::string>();
  }
  if (doc.contains("description")) {
    if (!doc["description"].is_string()) ctx.fail("description", "must be a string");
    s.description = doc["description"].get<std::string>();
  }
  if (doc.contains("preset")) {
    if (!doc["preset"].is_string() || !sph::presetByName(doc["preset"].get<std::string>(), s.params)) {
      ctx.fail("preset", "unknown preset (known: " + knownPresetList() + ")");
    }
  }
  // The caller's preset replaces the file's; the file's own "params" still apply on top of it.
  if (!preset.empty()) s.params = preset_params;
  if (doc.contains("params")) readSettings(ctx, "params", doc["params"], s.params);
  try {
    s.params.validate();
  } catch (const std::invalid_argument& e) {
    throw SceneError(source + ": " + e.what());
  }

  s.boundary.box = ctx.box(ctx.required(doc, "", "box"), "box");
  if (doc.contains("box_changes")) {
    const json& changes = doc["box_changes"];
    if (!changes.is_array()) ctx.fail("box_changes", "must be an array");
    double last_time = -1.0;
    for (std::size_t i = 0; i < changes.size(); ++i) {
      const std::string key = "box_changes[" + std::to_string(i) + "]";
      ctx.allowOnly(changes[i], key, {"time", "min", "max"});
      sph::BoxChange c;
      c.time = ctx.nonNegative(ctx.required(changes[i], key, "time"), key + ".time");
      if (c.time <= last_time) ctx.fail(key + ".time", "times must increase");
      last_time = c.time;
      json bounds = {{"min", ctx.required(changes[i], key, "min")}, {"max", ctx.required(changes[i], key, "max")}};
      c.box = ctx.box(bounds, key);
      s.boundary.changes.push_back(c);
    }
  }
  if (doc.contains("moving_walls")) {
    const json& walls = doc["moving_walls"];
    if (!walls.is_array()) ctx.fail("moving_walls", "must be an array");
    for (std::size_t i = 0; i < walls.size(); ++i) {
      const std::string key = "moving_walls[" + std::to_string(i) + "]";
      ctx.allowOnly(walls[i], key, {"axis", "side", "amplitude", "period", "start_time"});
      sph::MovingWall w;
      w.axis = axisIndex(ctx, ctx.required(walls[i], key, "axis"), key + ".axis");
      const json& side = ctx.required(walls[i], key, "side");
      if (side != "min" && side != "max") ctx.fail(key + ".side", "must be \"min\" or \"max\"");
      w.max_side = side == "max";
      w.amplitude = ctx.number(ctx.required(walls[i], key, "amplitude"), key + ".amplitude");
      w.period = ctx.positive(ctx.required(walls[i], key, "period"), key + ".period");
      if (walls[i].contains("start_time")) w.start_time = ctx.nonNegative(walls[i]["start_time"], key + ".start_time");
      s.boundary.moving_walls.push_back(w);
    }
  }
  if (doc.contains("spheres")) {
    const json& spheres = doc["spheres"];
    if (!spheres.is_array()) ctx.fail("spheres", "must be an array");
    for (std::size_t i = 0; i < spheres.size(); ++i) {
      const std::string key = "spheres[" + std::to_string(i) + "]";
      ctx.allowOnly(spheres[i], key, {"centre", "radius"});
      sph::Sphere sp;
      sp.centre = ctx.vec3(ctx.required(spheres[i], key, "centre"), key + ".centre");
      sp.radius = ctx.positive(ctx.required(spheres[i], key, "radius"), key + ".radius");
      s.boundary.spheres.push_back(sp);
    }
  }
  if (doc.contains("cylinders")) {
    const json& cylinders = doc["cylinders"];
    if (!cylinders.is_array()) ctx.fail("cylinders", "must be an array");
    for (std::size_t i = 0; i < cylinders.size(); ++i) {
      const std::string key = "cylinders[" + std::to_string(i) + "]";
      ctx.allowOnly(cylinders[i], key, {"x", "z", "radius"});
      sph::Cylinder c;
      c.x = ctx.number(ctx.required(cylinders[i], key, "x"), key + ".x");
      c.z = ctx.number(ctx.required(cylinders[i], key, "z"), key + ".z");
      c.radius = ctx.positive(ctx.required(cylinders[i], key, "radius"), key + ".radius");
      s.boundary.cylinders.push_back(c);
    }
  }

  s.water = ctx.box(ctx.required(doc, "", "water"), "water");
  if (!s.boundary.box.contains(s.water.min) || !s.boundary.box.contains(s.water.max)) {
    ctx.fail("water", "region lies outside 'box'");
  }
  if (doc.contains("large_particles")) s.large_particles = ctx.positiveInt(doc["large_particles"], "large_particles");
  if (doc.contains("frames")) s.frames = ctx.positiveInt(doc["frames"], "frames");
  if (doc.contains("camera")) readCamera(ctx, doc["camera"], s.camera);
  if (doc.contains("method")) {
    sph::Method m;
    if (!doc["method"].is_string() || !sph::methodByName(doc["method"].get<std::string>(), m)) {
      std::string known;
      for (const std::string& name : sph::methodNames()) known += (known.empty() ? "" : ", ") + name;
      ctx.fail("method", "unknown method (known: " + known + ")");
    }
    s.method = doc["method"].get<std::string>();
  }
  if (doc.contains("adaptive")) readAdaptive(ctx, doc["adaptive"], s.adaptive);
  if (doc.contains("gaze_recording")) {
    if (!doc["gaze_recording"].is_string() || doc["gaze_recording"].get<std::string>().empty()) {
      ctx.fail("gaze_recording", "must be a file name");
    }
    s.gaze_recording = doc["gaze_recording"].get<std::string>();
  }
  return s;
}

}  // namespace scene
