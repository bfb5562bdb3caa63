// Particle state as a structure of arrays. The attributes and their split and merge rules are
// declared once, in particle_attributes.h (a solver's own in its folder, gathered there); every
// operation here walks that declaration, so none can be forgotten.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

#include "sph/params.h"
#include "sph/particle_attributes.h"

namespace sph {

class ParticleSet : public ParticleAttributes {
 public:
  // The thesis's ceiling: 10,000 L1 particles that may all split into 20,000 L0.
  static constexpr std::size_t kDefaultCapacity = 20000;

  explicit ParticleSet(std::size_t capacity = kDefaultCapacity);

  std::size_t size() const { return id.size(); }
  std::size_t capacity() const { return capacity_; }
  // The id the next added particle gets; a checkpoint restores it with the particles.
  std::uint32_t nextId() const { return next_id_; }
  void setNextId(std::uint32_t next) { next_id_ = next; }
  bool empty() const { return id.empty(); }

  // Appends one particle; class-derived attributes (mass, radius, support) come from `props`, the
  // others take their reset values. Throws std::length_error past the capacity (the step never
  // grows the arrays).
  std::uint32_t add(const Vec3& position, const Vec3& velocity, Level level, const LevelProps& props);
  void clear();
  // Appends `n` particles with fresh ids and every other attribute at its reset value, for the
  // caller to fill (the adaptive step's split children). Returns the index of the first. Throws
  // std::length_error past the capacity.
  std::size_t appendReset(std::size_t n);

  // Split: `parent` and `child` (appended by appendReset) become the two children, every
  // attribute by its SplitRule; then both take the level below the parent's, `child_level` with
  // `child_props` (setLevel; L0 for the thesis's L1). The caller places them (positions
  // start as the parent's).
  void splitInto(std::size_t parent, std::size_t child, Level child_level, const LevelProps& child_props);
  // Merge: `survivor` becomes the merged particle, every attribute by its MergeRule from the
  // two, and takes the level above theirs, `merged_level` with `merged_props` (L1 for two of the
  // thesis's L0). The caller removes `absorbed` afterwards.
  void mergeInto(std::size_t survivor, std::size_t absorbed, Level merged_level, const LevelProps& merged_props);
  // The class-derived attributes (SplitRule::kLevel / MergeRule::kLevel): size class, radius, support.
  void setLevel(std::size_t i, Level c, const LevelProps& props);

  // Reorders every attribute so that new index k holds old index order[k].
  void permute(std::span<const std::uint32_t> order);
  // Keeps the particles with keep[i] != 0, in order; returns the new size.
  std::size_t compact(std::span<const std::uint8_t> keep);
  // Removes the particles with keep[i] == 0 by moving the last particle into each hole, from the
  // highest index down: attributes move O(removed) times instead of O(size), order not kept (the
  // periodic re-sort restores locality). Deterministic for a given input.
  void swapRemove(std::span<const std::uint8_t> keep);

  // Sum of masses in double precision (exact for the levels' masses of the presets up to rounding
  // of the float attributes themselves; tests compare against level counts).
  double totalMass() const;
  std::size_t countOf(Level c) const;
  // The particles of each level, L0 first, in one pass.
  std::array<std::size_t, kMaxLevels> countByLevel() const;
  // The particles the adaptive step placed since the last frame (`placed` kPlacedThisFrame: split
  // children, merged particles), ascending, into `out`.
  void freshPlacements(std::vector<std::uint32_t>& out) const;

  // f(vector) for every attribute, in declaration order.
  template <typename F>
  void forEachAttribute(F&& f) {
    std::apply([&](const auto&... spec) { (f(this->*spec.member), ...); }, kParticleAttributes);
  }
  template <typename F>
  void forEachAttribute(F&& f) const {
    std::apply([&](const auto&... spec) { (f(this->*spec.member), ...); }, kParticleAttributes);
  }
  // f(vector, spec) for every attribute, spec an AttributeSpec<T> (name, reset value, rules).
  template <typename F>
  void forEachAttributeSpec(F&& f) {
    std::apply([&](const auto&... spec) { (f(this->*spec.member, spec), ...); }, kParticleAttributes);
  }
  template <typename F>
  void forEachAttributeSpec(F&& f) const {
    std::apply([&](const auto&... spec) { (f(this->*spec.member, spec), ...); }, kParticleAttributes);
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
