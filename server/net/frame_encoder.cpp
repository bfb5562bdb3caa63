#include "net/frame_encoder.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <span>

namespace net {
namespace {

// The wire format is little-endian; on such hosts the particle arrays are copied as they are.
static_assert(std::endian::native == std::endian::little, "frame encoding assumes a little-endian host");
static_assert(sizeof(sph::Vec3) == 3 * sizeof(float), "positions must be packed x, y, z floats");
static_assert(sizeof(sph::Level) == 1 && static_cast<int>(sph::Level{0}) == 0 && static_cast<int>(sph::Level{1}) == 1,
              "size_classes bytes are the Level values");
static_assert(sph::kMaxLevels <= 16, "level_radii holds at most 16 levels (client_viewer/decoded_frame.h)");

constexpr double kQuantLevels = 65535.0;

void setVec3(gsph::v1::Vec3* out, float x, float y, float z) {
  out->set_x(x);
  out->set_y(y);
  out->set_z(z);
}

std::int64_t systemTimeUs() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

void encodeGeometry(const sph::Simulation& sim, gsph::v1::Geometry* g) {
  const sph::BoxState box = sim.boxNow();
  setVec3(g->mutable_box()->mutable_min(), box.min.x(), box.min.y(), box.min.z());
  setVec3(g->mutable_box()->mutable_max(), box.max.x(), box.max.y(), box.max.z());
  const sph::Boundary& b = sim.scene().boundary;
  // Cleared repeated message fields keep their element objects, so refilling allocates nothing.
  g->clear_spheres();
  g->clear_cylinders();
  for (const sph::Sphere& s : b.spheres) {
    gsph::v1::Sphere* out = g->add_spheres();
    setVec3(out->mutable_center(), static_cast<float>(s.centre.x()), static_cast<float>(s.centre.y()),
            static_cast<float>(s.centre.z()));
    out->set_radius(static_cast<float>(s.radius));
  }
  for (const sph::Cylinder& c : b.cylinders) {
    gsph::v1::Cylinder* out = g->add_cylinders();
    out->set_x(static_cast<float>(c.x));
    out->set_z(static_cast<float>(c.z));
    out->set_radius(static_cast<float>(c.radius));
  }
}

// The radius of every level of the run, present or not, so a client can size any level byte it meets.
void encodeLevelRadii(const sph::SimParams& params, gsph::v1::Frame& f) {
  const auto classes = params.levelProps();
  f.set_radius_small(static_cast<float>(classes[sph::levelIndex(sph::Level{0})].radius));
  f.set_radius_large(static_cast<float>(classes[sph::levelIndex(sph::Level{1})].radius));
  f.clear_level_radii();
  for (int k = 0; k < params.levels; ++k)
    f.add_level_radii(static_cast<float>(classes[static_cast<std::size_t>(k)].radius));
}

}  // namespace

gsph::v1::Method toProtoMethod(sph::Method m) {
  switch (m) {
    case sph::Method::Regular:
      return gsph::v1::METHOD_REGULAR;
    case sph::Method::Surface:
      return gsph::v1::METHOD_SURFACE;
    case sph::Method::Gaze:
      return gsph::v1::METHOD_GAZE;
    case sph::Method::Hybrid:
      return gsph::v1::METHOD_HYBRID;
    case sph::Method::Foveated:
      return gsph::v1::METHOD_FOVEATED;
  }
  return gsph::v1::METHOD_UNSPECIFIED;
}

bool fromProtoMethod(int value, sph::Method& out) {
  switch (value) {
    case gsph::v1::METHOD_REGULAR:
      out = sph::Method::Regular;
      return true;
    case gsph::v1::METHOD_SURFACE:
      out = sph::Method::Surface;
      return true;
    case gsph::v1::METHOD_GAZE:
      out = sph::Method::Gaze;
      return true;
    case gsph::v1::METHOD_HYBRID:
      out = sph::Method::Hybrid;
      return true;
    case gsph::v1::METHOD_FOVEATED:
      out = sph::Method::Foveated;
      return true;
    default:
      return false;
  }
}

gsph::v1::GazeMode toProtoGazeMode(sph::GazeMode m) {
  switch (m) {
    case sph::GazeMode::None:
      return gsph::v1::GAZE_MODE_NONE;
    case sph::GazeMode::Tracking:
      return gsph::v1::GAZE_MODE_TRACKING;
    case sph::GazeMode::Holding:
      return gsph::v1::GAZE_MODE_HOLDING;
    case sph::GazeMode::Fallback:
      return gsph::v1::GAZE_MODE_FALLBACK;
  }
  return gsph::v1::GAZE_MODE_UNSPECIFIED;
}

const gsph::v1::Frame& FrameEncoder::encode(const sph::Simulation& sim, const FrameInfo& info) {
  const sph::ParticleSet& p = sim.particles();
  gsph::v1::Frame& f = frame_;
  f.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
  f.set_sequence(info.sequence);
  f.set_step(sim.stepCount());
  f.set_sim_time(sim.time());
  f.set_scene(info.scene);
  f.set_method(toProtoMethod(info.method));
  f.set_paused(info.paused);
  f.set_quality(info.quality);
  f.set_periphery_gain(info.periphery_gain);
  f.set_realtime_ratio(info.realtime_ratio);
  const FoveationEcho& fov = info.foveation;
  f.set_periphery_gain_ceiling(fov.periphery_gain_ceiling);
  f.set_visible_count(fov.visible);
  f.set_over_budget_count(fov.over_budget);
  f.set_fovea_width_arcmin(fov.fovea_width_arcmin);
  f.set_fovea_mar_arcmin(fov.fovea_mar_arcmin);
  f.mutable_fovea_ring_radii()->Assign(fov.ring_radii.begin(), fov.ring_radii.end());
  f.set_particle_count(static_cast<std::uint32_t>(p.size()));
  setLevelCounts(sim, f);

  const sph::PhaseTimings& t = sim.lastTimings();
  gsph::v1::PhaseTimings* pt = f.mutable_timings();
  pt->set_neighbor_ms(static_cast<float>(t.neighbor_ms));
  pt->set_density_pressure_ms(static_cast<float>(t.density_pressure_ms));
  pt->set_accel_integrate_collide_ms(static_cast<float>(t.accel_integrate_collide_ms));
  pt->set_adaptive_ms(static_cast<float>(t.adaptive_ms));
  pt->set_total_ms(static_cast<float>(t.total_ms));
  f.set_steps_per_second(static_cast<float>(info.steps_per_second));

  gsph::v1::GazeUsed* g = f.mutable_gaze();
  g->set_mode(info.gaze.mode);
  g->set_x(static_cast<float>(info.gaze.x));
  g->set_y(static_cast<float>(info.gaze.y));
  g->set_radius(static_cast<float>(info.gaze.radius));
  g->set_ring_radius(static_cast<float>(info.gaze.ring_radius));
  g->set_age_ms(info.gaze.has_sample ? static_cast<float>(info.gaze.age_s * 1e3) : -1.0f);
  g->set_sample_sequence(info.gaze.sample_sequence);
  g->set_sample_bridge_time_us(info.gaze.sample_bridge_time_us);
  g->set_source_id(info.gaze.source_id);

  if (info.camera != nullptr) {
    f.mutable_camera()->CopyFrom(*info.camera);
  } else {
    f.clear_camera();
  }
  encodeGeometry(sim, f.mutable_geometry());
  encodeLevelRadii(sim.params(), f);

  encodePositions(sim);
  std::string* sizes = f.mutable_size_classes();
  sizes->resize(p.size());
  if (!p.empty()) std::memcpy(sizes->data(), p.level.data(), p.size());
  if (velocities_) {
    std::string* v = f.mutable_velocities();
    v->resize(p.size() * sizeof(sph::Vec3));
    if (!p.empty()) std::memcpy(v->data(), p.velocity.data(), v->size());
  } else {
    f.clear_velocities();
  }
  if (neighbor_counts_) {
    encodeNeighborCounts(sim);
  } else {
    f.clear_neighbor_counts();
  }
  f.set_send_time_us(systemTimeUs());
  return f;
}

void FrameEncoder::encodePositions(const sph::Simulation& sim) {
  const sph::ParticleSet& p = sim.particles();
  std::string* out = frame_.mutable_positions();
  if (encoding_ == PositionEncoding::Float32) {
    frame_.set_encoding(gsph::v1::POSITION_ENCODING_FLOAT32);
    frame_.clear_quantization_box();
    out->resize(p.size() * sizeof(sph::Vec3));
    if (!p.empty()) std::memcpy(out->data(), p.position.data(), out->size());
    return;
  }
  frame_.set_encoding(gsph::v1::POSITION_ENCODING_QUANTIZED16);
  // Relative to the box at this instant: particles stay inside it up to the collision slack, which
  // the clamp absorbs.
  const sph::BoxState box = sim.boxNow();
  gsph::v1::Box* qbox = frame_.mutable_quantization_box();
  setVec3(qbox->mutable_min(), box.min.x(), box.min.y(), box.min.z());
  setVec3(qbox->mutable_max(), box.max.x(), box.max.y(), box.max.z());
  float scale[3];
  for (int a = 0; a < 3; ++a) {
    const float extent = box.max[a] - box.min[a];
    scale[a] = extent > 0.0f ? static_cast<float>(kQuantLevels / extent) : 0.0f;
  }
  out->resize(p.size() * 3 * sizeof(std::uint16_t));
  auto* q = reinterpret_cast<std::uint16_t*>(out->data());
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      const float v = std::nearbyint((p.position[i][a] - box.min[a]) * scale[a]);
      // NaN compares false both ways and lands on 0, as does anything below the box.
      q[3 * i + a] = static_cast<std::uint16_t>(v > 0.0f ? std::min(v, static_cast<float>(kQuantLevels)) : 0.0f);
    }
  }
}

void FrameEncoder::encodeNeighborCounts(const sph::Simulation& sim) {
  const std::size_t n = sim.particles().size();
  const std::span<const std::uint32_t> counts = sim.grid().neighborCounts();
  std::string* out = frame_.mutable_neighbor_counts();
  out->resize(n);
  // The counts are those of the step's neighbour search, indexed as the particles were then. The
  // adaptive step runs after it: a split appends children past the counted range and a merge moves
  // the last particles into the holes, so those few particles carry another particle's count, and
  // the appended ones (and all before the first step) 255, which a viewer takes as "not spray".
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t c = i < counts.size() ? counts[i] : 255u;
    (*out)[i] = static_cast<char>(std::min<std::uint32_t>(c, 255u));
  }
}

zmq::message_t FrameEncoder::serialize() {
  const std::size_t size = frame_.ByteSizeLong();
  zmq::message_t msg(size);
  frame_.SerializeWithCachedSizesToArray(static_cast<std::uint8_t*>(msg.data()));
  return msg;
}

std::vector<float> decodePositions(const gsph::v1::Frame& frame) {
  std::vector<float> xyz;
  const std::string& bytes = frame.positions();
  if (frame.encoding() == gsph::v1::POSITION_ENCODING_QUANTIZED16) {
    const std::size_t n = bytes.size() / (3 * sizeof(std::uint16_t));
    xyz.resize(3 * n);
    const gsph::v1::Box& b = frame.quantization_box();
    const float lo[3] = {b.min().x(), b.min().y(), b.min().z()};
    const float hi[3] = {b.max().x(), b.max().y(), b.max().z()};
    for (std::size_t k = 0; k < 3 * n; ++k) {
      std::uint16_t v;
      std::memcpy(&v, bytes.data() + 2 * k, sizeof v);
      const int a = static_cast<int>(k % 3);
      xyz[k] = lo[a] + static_cast<float>(v / kQuantLevels) * (hi[a] - lo[a]);
    }
  } else {
    xyz.resize(bytes.size() / sizeof(float));
    if (!xyz.empty()) std::memcpy(xyz.data(), bytes.data(), xyz.size() * sizeof(float));
  }
  return xyz;
}

}  // namespace net
