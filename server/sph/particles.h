// Particle state as a structure of arrays. Every per-particle attribute is listed once, in
// forEachAttribute(), so that permute() and compact() move all of them and none can be forgotten.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "sph/params.h"

namespace sph {

using Vec3 = Eigen::Vector3f;

class ParticleSet {
 public:
  // The thesis's ceiling: 10,000 LARGE particles that may all split into 20,000 SMALL.
  static constexpr std::size_t kDefaultCapacity = 20000;

  explicit ParticleSet(std::size_t capacity = kDefaultCapacity);

  std::size_t size() const { return id.size(); }
  std::size_t capacity() const { return capacity_; }
  bool empty() const { return id.empty(); }

  // Appends one particle at rest; class-derived attributes (mass, radius, support) come from `props`.
  // Throws std::length_error past the capacity (the step never grows the arrays).
  std::uint32_t add(const Vec3& position, const Vec3& velocity, SizeClass size_class, const SizeClassProps& props);
  void clear();
  // Appends `n` particles with fresh ids and every other attribute zeroed, for the caller to fill
  // (the adaptive step's split children). Returns the index of the first. Throws std::length_error
  // past the capacity.
  std::size_t appendZeroed(std::size_t n);

  // Reorders every attribute so that new index k holds old index order[k].
  void permute(std::span<const std::uint32_t> order);
  // Keeps the particles with keep[i] != 0, in order; returns the new size.
  std::size_t compact(std::span<const std::uint8_t> keep);
  // Removes the particles with keep[i] == 0 by moving the last particle into each hole, from the
  // highest index down: attributes move O(removed) times instead of O(size), order not kept (the
  // periodic re-sort restores locality). Deterministic for a given input.
  void swapRemove(std::span<const std::uint8_t> keep);

  // Sum of masses in double precision (exact for the two-class masses of the presets up to rounding
  // of the float attributes themselves; tests compare against class counts).
  double totalMass() const;
  std::size_t countOf(SizeClass c) const;

  // Attributes (structure of arrays). Public so that stages read them directly; size is the same.
  std::vector<std::uint32_t> id;  // stable id, survives reordering
  std::vector<SizeClass> size_class;
  std::vector<float> mass;
  std::vector<float> radius;   // particle radius, eq. (3.7)
  std::vector<float> support;  // support radius h, eq. (3.8)
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;
  std::vector<Vec3> acceleration;
  std::vector<float> density;        // eq. (3.11)
  std::vector<float> pressure;       // eq. (3.12)
  std::vector<float> normal_length;  // |n| of the colour field gradient, eq. (3.17)
  // Per-particle factors of the pair sums, set with the density so the force loop divides less:
  std::vector<float> pressure_term;  // p / rho^2, eq. (3.13)
  std::vector<float> volume;         // m / rho, eqs. (3.14), (3.16)
  // Adaptive step, surface criterion: distance to the surface or a boundary, d in (3.45), kept
  // from step to step (infinity until reached), and this step's one-hop update of it.
  std::vector<float> surface_distance;
  std::vector<float> surface_hop;

  template <typename F>
  void forEachAttribute(F&& f) {
    f(id);
    f(size_class);
    f(mass);
    f(radius);
    f(support);
    f(position);
    f(velocity);
    f(acceleration);
    f(density);
    f(pressure);
    f(normal_length);
    f(pressure_term);
    f(volume);
    f(surface_distance);
    f(surface_hop);
  }

 private:
  struct RemovalMove {
    std::uint32_t hole, from;
  };
  std::vector<RemovalMove> removal_moves_;  // swapRemove's scratch
  std::size_t capacity_;
  std::uint32_t next_id_ = 0;
};

}  // namespace sph
