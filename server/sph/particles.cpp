#include "sph/particles.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace sph {

namespace {

void requireRoom(std::size_t wanted, std::size_t capacity) {
  if (wanted > capacity) throw std::length_error("particle capacity " + std::to_string(capacity) + " exceeded");
}

template <typename T>
T mergedValue(MergeRule rule, const T& a, const T& b, const T& reset) {
  switch (rule) {
    case MergeRule::kKeep:
    case MergeRule::kLevel:  // set by setLevel afterwards
      return a;
    case MergeRule::kReset:
      return reset;
    case MergeRule::kAverage:
      if constexpr (std::is_arithmetic_v<T> || std::is_same_v<T, Vec3>) return T(0.5f * (a + b));
      break;
    case MergeRule::kSum:
      if constexpr (std::is_arithmetic_v<T> || std::is_same_v<T, Vec3>) return T(a + b);
      break;
    case MergeRule::kMin:
      if constexpr (std::is_arithmetic_v<T>) return std::min(a, b);
      break;
    case MergeRule::kMax:
      if constexpr (std::is_arithmetic_v<T>) return std::max(a, b);
      break;
    case MergeRule::kMark:
      if constexpr (std::is_arithmetic_v<T>) return T(kPlacedThisFrame);
      break;
  }
  throw std::logic_error("merge rule does not apply to this attribute's type");
}

}  // namespace

ParticleSet::ParticleSet(std::size_t capacity) : capacity_(capacity) {
  forEachAttribute([&](auto& v) { v.reserve(capacity_); });
  removal_moves_.reserve(capacity_ / 2);  // a merge removes one of two particles
}

std::uint32_t ParticleSet::add(const Vec3& p, const Vec3& v, Level c, const LevelProps& props) {
  requireRoom(size() + 1, capacity_);
  forEachAttributeSpec([](auto& values, const auto& spec) { values.push_back(spec.reset_value); });
  const std::size_t i = size() - 1;
  const std::uint32_t new_id = next_id_++;
  id[i] = new_id;
  mass[i] = static_cast<float>(props.mass);
  setLevel(i, c, props);
  position[i] = p;
  velocity[i] = v;
  return new_id;
}

std::size_t ParticleSet::appendReset(std::size_t n) {
  const std::size_t first = size();
  requireRoom(first + n, capacity_);
  forEachAttributeSpec([&](auto& values, const auto& spec) { values.resize(first + n, spec.reset_value); });
  for (std::size_t k = first; k < first + n; ++k) id[k] = next_id_++;
  return first;
}

void ParticleSet::setLevel(std::size_t i, Level c, const LevelProps& props) {
  level[i] = c;
  radius[i] = static_cast<float>(props.radius);
  support[i] = static_cast<float>(props.support);
}

void ParticleSet::splitInto(std::size_t parent, std::size_t child, Level child_level, const LevelProps& child_props) {
  forEachAttributeSpec([&](auto& v, const auto& spec) {
    using T = typename std::remove_cvref_t<decltype(spec)>::Value;
    switch (spec.split) {
      case SplitRule::kCopy:
        v[child] = v[parent];
        break;
      case SplitRule::kHalve:
        if constexpr (std::is_arithmetic_v<T> || std::is_same_v<T, Vec3>) {
          v[parent] = T(0.5f * v[parent]);
          v[child] = v[parent];
          break;
        }
        throw std::logic_error(std::string("split rule kHalve does not apply to ") + spec.name);
      case SplitRule::kReset:
        v[parent] = spec.reset_value;
        v[child] = spec.reset_value;
        break;
      case SplitRule::kMark:
        if constexpr (std::is_arithmetic_v<T>) {
          v[parent] = T(kPlacedThisFrame);
          v[child] = T(kPlacedThisFrame);
          break;
        }
        throw std::logic_error(std::string("split rule kMark does not apply to ") + spec.name);
      case SplitRule::kFreshId:  // the child keeps the id appendReset gave it
      case SplitRule::kLevel:    // setLevel below
        break;
    }
  });
  setLevel(parent, child_level, child_props);
  setLevel(child, child_level, child_props);
}

void ParticleSet::mergeInto(std::size_t survivor, std::size_t absorbed, Level merged_level,
                            const LevelProps& merged_props) {
  forEachAttributeSpec([&](auto& v, const auto& spec) {
    v[survivor] = mergedValue(spec.merge, v[survivor], v[absorbed], spec.reset_value);
  });
  setLevel(survivor, merged_level, merged_props);
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

std::array<std::size_t, kMaxLevels> ParticleSet::countByLevel() const {
  std::array<std::size_t, kMaxLevels> n{};
  for (const Level s : level) n[static_cast<std::size_t>(levelIndex(s)) % kMaxLevels] += 1;
  return n;
}

void ParticleSet::freshPlacements(std::vector<std::uint32_t>& out) const {
  out.clear();
  for (std::size_t i = 0; i < size(); ++i) {
    if (placed[i] == kPlacedThisFrame) out.push_back(static_cast<std::uint32_t>(i));
  }
}

std::size_t ParticleSet::countOf(Level c) const {
  std::size_t n = 0;
  for (Level s : level) n += (s == c);
  return n;
}

}  // namespace sph
