#include "test_frames.h"

#include <cmath>
#include <cstring>
#include <random>

namespace viewer_test {

namespace {
void setVec(gsph::v1::Vec3* v, float x, float y, float z) {
  v->set_x(x);
  v->set_y(y);
  v->set_z(z);
}
std::uint16_t quantize(float v, float lo, float hi) {
  const float t = (v - lo) / (hi - lo);
  return static_cast<std::uint16_t>(std::lround(std::fmin(std::fmax(t, 0.0f), 1.0f) * 65535.0f));
}
}  // namespace

gsph::v1::Frame makeFrame(const FrameSpec& spec, std::uint64_t sequence) {
  gsph::v1::Frame f;
  f.set_protocol_version(gsph::v1::PROTOCOL_VERSION_CURRENT);
  f.set_sequence(sequence);
  f.set_step(static_cast<std::int64_t>(sequence) * 2);
  f.set_sim_time(0.01 * static_cast<double>(sequence));
  f.set_scene("viewer_test");
  f.set_method(gsph::v1::METHOD_GAZE);
  const auto n = static_cast<std::uint32_t>(spec.particles.size());
  f.set_particle_count(n);
  std::string classes;
  for (const auto& p : spec.particles) classes.push_back(static_cast<char>(p.level));
  f.set_size_classes(classes);
  f.set_radius_small(spec.radius_small);
  f.set_radius_large(spec.radius_large);
  for (float r : spec.level_radii) f.add_level_radii(r);
  std::string bytes;
  if (spec.quantized) {
    f.set_encoding(gsph::v1::POSITION_ENCODING_QUANTIZED16);
    setVec(f.mutable_quantization_box()->mutable_min(), spec.box_lo, spec.box_lo, spec.box_lo);
    setVec(f.mutable_quantization_box()->mutable_max(), spec.box_hi, spec.box_hi, spec.box_hi);
    for (const auto& p : spec.particles) {
      const std::uint16_t q[3] = {quantize(p.x, spec.box_lo, spec.box_hi), quantize(p.y, spec.box_lo, spec.box_hi),
                                  quantize(p.z, spec.box_lo, spec.box_hi)};
      bytes.append(reinterpret_cast<const char*>(q), sizeof(q));
    }
  } else {
    f.set_encoding(gsph::v1::POSITION_ENCODING_FLOAT32);
    for (const auto& p : spec.particles) {
      const float xyz[3] = {p.x, p.y, p.z};
      bytes.append(reinterpret_cast<const char*>(xyz), sizeof(xyz));
    }
  }
  f.set_positions(bytes);
  if (spec.with_velocities) {
    std::string v;
    for (std::size_t i = 0; i < spec.particles.size(); ++i) {
      const float xyz[3] = {0.1f * static_cast<float>(i % 7), 0.0f, 0.0f};
      v.append(reinterpret_cast<const char*>(xyz), sizeof(xyz));
    }
    f.set_velocities(v);
  }
  if (!spec.neighbor_counts.empty()) {
    f.set_neighbor_counts(std::string(spec.neighbor_counts.begin(), spec.neighbor_counts.end()));
  }
  if (spec.with_box) {
    setVec(f.mutable_geometry()->mutable_box()->mutable_min(), spec.box_lo, spec.box_lo, spec.box_lo);
    setVec(f.mutable_geometry()->mutable_box()->mutable_max(), spec.box_hi, spec.box_hi, spec.box_hi);
  }
  if (spec.with_gaze) {
    auto* g = f.mutable_gaze();
    g->set_mode(gsph::v1::GAZE_MODE_TRACKING);
    g->set_x(spec.gaze_x);
    g->set_y(spec.gaze_y);
    g->set_radius(spec.gaze_radius);
    g->set_ring_radius(spec.gaze_ring);
  }
  auto* t = f.mutable_timings();
  t->set_neighbor_ms(1.0f);
  t->set_density_pressure_ms(2.0f);
  t->set_accel_integrate_collide_ms(3.0f);
  t->set_adaptive_ms(0.5f);
  t->set_total_ms(6.5f);
  f.set_steps_per_second(60.0f);
  return f;
}

std::vector<TestParticle> particleCloud(std::size_t n, float lo, float hi) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> u(lo, hi);
  std::vector<TestParticle> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = {u(rng), u(rng), u(rng), static_cast<std::uint8_t>(i % 2)};
  }
  return out;
}

}  // namespace viewer_test
