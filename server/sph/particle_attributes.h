// The per-particle attributes, each declared once with what becomes of it when particles are
// reordered, removed, split and merged. ParticleSet (particles.h) walks kParticleAttributes for
// every one of those operations, so an attribute added here is moved, split and merged with the
// others, and one left out of the table fails to compile (the static_assert below). A solver's own
// state is declared in its folder (solvers/<name>/<name>_attributes.h) the same way, and gathered
// here: ParticleAttributes inherits its struct and kParticleAttributes takes in its table.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

#include "sph/attribute_spec.h"
#include "sph/params.h"
#include "sph/solvers/dfsph/dfsph_attributes.h"
#include "sph/solvers/pbf/pbf_attributes.h"

namespace sph {

using Vec3 = Eigen::Vector3f;

// The attributes themselves (structure of arrays), public so that stages read them directly;
// every vector has the same size. Declare a new one here AND in kParticleAttributes below; one
// only a solver reads, in its folder's struct and table (read as the others are: `p.kappa`).
struct ParticleAttributes : DfsphAttributes, PbfAttributes {
  std::vector<std::uint32_t> id;  // stable id, survives reordering
  std::vector<Level> level;       // L0 the finest (params.h)
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
  // Non-zero for a particle the adaptive step placed (a split's children, a merged particle), one of
  // the PlacedMark values below. Where a split or a merge puts a particle is a choice of the method,
  // not a motion of the water: pbf lets the density constraint move a placed particle without making
  // it faster, until the constraint holds it, and iterates longer in the frame after a placement
  // (pbf_solver.cpp); dfsph moves fresh placements apart by position before that frame's first step
  // (local_placement.h). After each frame the solver says what becomes of the marks
  // (FluidSolver::releasePlaced).
  std::vector<std::uint8_t> placed;
  // foveated: frames in a row the eye has allowed this particle a coarser level; a merge waits for
  // `foveated_merge_hold_s` of them (adaptive/foveated.h). A split's children and a merged
  // particle start again from 0.
  std::vector<std::uint16_t> coarsen_wait;
};

// The values of ParticleAttributes::placed.
enum PlacedMark : std::uint8_t {
  kNotPlaced = 0,
  kPlacedThisFrame = 1,  // placed by the adaptive step after the last frame (SplitRule::kMark, MergeRule::kMark)
  kPlacedEarlier = 2,    // pbf: placed, a frame run on it, its constraint not yet holding it
  kNearPlacement = 3,    // pbf: a neighbour of this frame's fresh placements
};

namespace detail {
inline constexpr float kFar = std::numeric_limits<float>::infinity();
}  // namespace detail

// Attributes the next step recomputes before reading them (density to volume, acceleration,
// normal length) still get the rule that describes them, so a frame sent between steps shows
// sensible values. The order is the one checkpoints (checkpoint.h) write and read attributes in,
// which is why the solvers' tables sit between the shared ones.
inline const auto kParticleAttributes = std::tuple_cat(
    std::make_tuple(
        AttributeSpec<std::uint32_t>{&ParticleAttributes::id, "id", 0u, SplitRule::kFreshId, MergeRule::kKeep},
        AttributeSpec<Level>{&ParticleAttributes::level, "level", Level{0}, SplitRule::kLevel, MergeRule::kLevel},
        AttributeSpec<float>{&ParticleAttributes::mass, "mass", 0.0f, SplitRule::kHalve, MergeRule::kSum},
        AttributeSpec<float>{&ParticleAttributes::radius, "radius", 0.0f, SplitRule::kLevel, MergeRule::kLevel},
        AttributeSpec<float>{&ParticleAttributes::support, "support", 0.0f, SplitRule::kLevel, MergeRule::kLevel},
        AttributeSpec<Vec3>{&ParticleAttributes::position, "position", Vec3::Zero(), SplitRule::kCopy,
                            MergeRule::kAverage},
        AttributeSpec<Vec3>{&ParticleAttributes::velocity, "velocity", Vec3::Zero(), SplitRule::kCopy,
                            MergeRule::kAverage},
        AttributeSpec<Vec3>{&ParticleAttributes::acceleration, "acceleration", Vec3::Zero(), SplitRule::kCopy,
                            MergeRule::kAverage},
        AttributeSpec<float>{&ParticleAttributes::density, "density", 0.0f, SplitRule::kCopy, MergeRule::kAverage},
        AttributeSpec<float>{&ParticleAttributes::pressure, "pressure", 0.0f, SplitRule::kCopy, MergeRule::kAverage},
        // The surface criterion (3.44) asks |n| >= l of either: the merged particle is at the
        // surface if one of the two was.
        AttributeSpec<float>{&ParticleAttributes::normal_length, "normal_length", 0.0f, SplitRule::kCopy,
                             MergeRule::kMax},
        AttributeSpec<float>{&ParticleAttributes::pressure_term, "pressure_term", 0.0f, SplitRule::kCopy,
                             MergeRule::kAverage},
        AttributeSpec<float>{&ParticleAttributes::volume, "volume", 0.0f, SplitRule::kHalve, MergeRule::kSum},
        AttributeSpec<float>{&ParticleAttributes::surface_distance, "surface_distance", detail::kFar, SplitRule::kCopy,
                             MergeRule::kMin},
        AttributeSpec<float>{&ParticleAttributes::surface_hop, "surface_hop", detail::kFar, SplitRule::kCopy,
                             MergeRule::kMin}),
    kDfsphAttributes,
    std::make_tuple(AttributeSpec<std::uint8_t>{&ParticleAttributes::placed, "placed", std::uint8_t{0},
                                                SplitRule::kMark, MergeRule::kMark},
                    AttributeSpec<std::uint16_t>{&ParticleAttributes::coarsen_wait, "coarsen_wait", std::uint16_t{0},
                                                 SplitRule::kReset, MergeRule::kReset}),
    kPbfAttributes);

// Every vector is the same size, whatever its element type: a member of ParticleAttributes (or of
// a solver's struct it inherits) that is missing from the table, or listed twice, changes one side
// of this and stops the build.
static_assert(sizeof(ParticleAttributes) ==
                  std::tuple_size_v<std::remove_cv_t<decltype(kParticleAttributes)>> * sizeof(std::vector<float>),
              "every member of ParticleAttributes needs its entry (and rules) in kParticleAttributes");

}  // namespace sph
