#include "sph/solvers/floor_contact.h"

namespace sph {

namespace {

// How far above the guard a particle's predicted position may end and still count as on the
// floor, in spacings: one resting on the guard predicts below it (gravity), one a hair above it
// counts too.
constexpr float kBand = 0.01f;

// The share of a held particle's slip along the floor taken away each solver step (a few a frame,
// CFL-bounded). With none, the floor layer slid and the validation tank kept moving; with all of it
// (the slip stopped each step) the tests' tanks' wall layers read compressed. 0.1 and 0.5 also
// brought them to rest; 0.3 is the value the tanks were checked with throughout (docs/fluids.md,
// "dfsph: divergence-free SPH", the floor held by the solve).
constexpr float kSlipLoss = 0.3f;

constexpr int kFloorAxis = 1;

}  // namespace

void FloorContact::find(ParticleSet& p, const BoxState& box, const std::array<WallReach, kMaxLevels>& reach,
                        const std::array<float, kMaxLevels>& spacing, float dt) {
  const std::size_t n = p.size();
  held_.reserve(p.capacity());
  held_.assign(n, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<std::size_t>(levelIndex(p.level[i]));
    const float band = kBand * spacing[c];
    Vec3& u = p.velocity[i];
    const Vec3 predicted = p.position[i] + dt * u;
    if (predicted[kFloorAxis] > guardLow(box, reach[c], kFloorAxis) + band) continue;
    std::uint8_t axes = 1u << kFloorAxis;
    removeVelocityIntoFace(box, kFloorAxis, true, u);
    for (const int a : {0, 2}) {
      const bool at_min = predicted[a] <= guardLow(box, reach[c], a) + band;
      const bool at_max = predicted[a] >= guardHigh(box, reach[c], a) - band;
      if (!at_min && !at_max) continue;
      axes |= static_cast<std::uint8_t>(1u << a);
      removeVelocityIntoFace(box, a, at_min, u);
    }
    held_[i] = axes;
  }
}

void FloorContact::hold(std::vector<Vec3>& acceleration) const { scaleHeld(acceleration, 0.0f, 1.0f); }

// The walls move only along their normals: along the floor they stand still.
void FloorContact::relaxSlip(ParticleSet& p) const { scaleHeld(p.velocity, 1.0f, 1.0f - kSlipLoss); }

void FloorContact::scaleHeld(std::vector<Vec3>& v, float along_held, float along_free) const {
  const std::size_t n = held_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t axes = held_[i];
    if (axes == 0) continue;
    for (int a = 0; a < 3; ++a) v[i][a] *= (axes & (1u << a)) ? along_held : along_free;
  }
}

}  // namespace sph
