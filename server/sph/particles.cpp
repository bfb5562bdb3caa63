#include "sph/particles.h"

#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace sph {

ParticleSet::ParticleSet(std::size_t capacity) : capacity_(capacity) {
  forEachAttribute([&](auto& v) { v.reserve(capacity_); });
  removal_moves_.reserve(capacity_ / 2);  // a merge removes one of two particles
}

std::uint32_t ParticleSet::add(const Vec3& p, const Vec3& v, SizeClass c, const SizeClassProps& props) {
  if (size() >= capacity_) {
    throw std::length_error("particle capacity " + std::to_string(capacity_) + " exceeded");
  }
  const std::uint32_t new_id = next_id_++;
  id.push_back(new_id);
  size_class.push_back(c);
  mass.push_back(static_cast<float>(props.mass));
  radius.push_back(static_cast<float>(props.radius));
  support.push_back(static_cast<float>(props.support));
  position.push_back(p);
  velocity.push_back(v);
  acceleration.push_back(Vec3::Zero());
  density.push_back(0.0f);
  pressure.push_back(0.0f);
  normal_length.push_back(0.0f);
  pressure_term.push_back(0.0f);
  volume.push_back(0.0f);
  surface_distance.push_back(std::numeric_limits<float>::infinity());
  surface_hop.push_back(std::numeric_limits<float>::infinity());
  return new_id;
}

std::size_t ParticleSet::appendZeroed(std::size_t n) {
  const std::size_t first = size();
  if (first + n > capacity_) {
    throw std::length_error("particle capacity " + std::to_string(capacity_) + " exceeded");
  }
  forEachAttribute([&](auto& v) {
    using Value = typename std::remove_reference_t<decltype(v)>::value_type;
    // Eigen's default constructor leaves vectors uninitialised: say zero explicitly.
    if constexpr (std::is_same_v<Value, Vec3>) {
      v.resize(first + n, Vec3::Zero());
    } else {
      v.resize(first + n, Value{});
    }
  });
  for (std::size_t k = first; k < first + n; ++k) id[k] = next_id_++;
  return first;
}

void ParticleSet::clear() {
  forEachAttribute([](auto& v) { v.clear(); });
  next_id_ = 0;
}

void ParticleSet::permute(std::span<const std::uint32_t> order) {
  if (order.size() != size()) throw std::invalid_argument("permute: order size mismatch");
  forEachAttribute([&](auto& v) {
    // One scratch copy per attribute type, grown once to the ceiling and reused; `v` keeps its own
    // buffer (and so its reserved capacity).
    using Vec = std::remove_reference_t<decltype(v)>;
    static thread_local Vec scratch;
    scratch.assign(v.begin(), v.end());
    for (std::size_t k = 0; k < order.size(); ++k) v[k] = scratch[order[k]];
  });
}

std::size_t ParticleSet::compact(std::span<const std::uint8_t> keep) {
  if (keep.size() != size()) throw std::invalid_argument("compact: keep size mismatch");
  std::size_t n = 0;
  forEachAttribute([&](auto& v) {
    std::size_t w = 0;
    for (std::size_t r = 0; r < v.size(); ++r) {
      if (keep[r]) v[w++] = v[r];
    }
    v.resize(w);
    n = w;
  });
  return n;
}

void ParticleSet::swapRemove(std::span<const std::uint8_t> keep) {
  if (keep.size() != size()) throw std::invalid_argument("swapRemove: keep size mismatch");
  // First the moves, from the highest hole down: every index above `hole` has been handled when
  // we get there, so the last particle is a kept one. Then each attribute makes all the moves in
  // that order: one attribute at a time, the loads of different moves are independent, so the
  // CPU overlaps their cache misses (moving every attribute of one particle at a time did not).
  removal_moves_.clear();
  std::size_t last = keep.size();
  for (std::size_t hole = keep.size(); hole-- > 0;) {
    if (keep[hole]) continue;
    --last;
    if (hole != last) removal_moves_.push_back({static_cast<std::uint32_t>(hole), static_cast<std::uint32_t>(last)});
  }
  const std::size_t new_size = last;
  forEachAttribute([&](auto& v) {
    for (const RemovalMove& m : removal_moves_) v[m.hole] = v[m.from];
    v.erase(v.begin() + static_cast<std::ptrdiff_t>(new_size), v.end());
  });
}

double ParticleSet::totalMass() const {
  double m = 0.0;
  for (float mi : mass) m += mi;
  return m;
}

std::size_t ParticleSet::countOf(SizeClass c) const {
  std::size_t n = 0;
  for (SizeClass s : size_class) n += (s == c);
  return n;
}

}  // namespace sph
