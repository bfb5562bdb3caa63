#include "sph/fill_water.h"

#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace sph {

namespace {

// The lattice a level fills the scene's water region with: its spacing, its inset from the
// region's faces, and its sites along each axis.
struct Lattice {
  double spacing = 0.0;
  double inset = 0.0;
  std::array<int, 3> cells{};
  long sites() const { return static_cast<long>(cells[0]) * cells[1] * cells[2]; }
};

Lattice latticeOf(const Scene& scene, const LevelProps& props, const FluidSolver& solver) {
  Lattice l;
  l.spacing = std::cbrt(props.mass / scene.params.rest_density);
  l.inset = solver.fillInset(l.spacing, props.radius);
  for (int a = 0; a < 3; ++a) {
    const double room = scene.water.max[a] - scene.water.min[a] - 2.0 * l.inset;
    l.cells[static_cast<std::size_t>(a)] = room < 0.0 ? 0 : static_cast<int>(std::floor(room / l.spacing)) + 1;
  }
  return l;
}

}  // namespace

Level fillingLevel(const Scene& scene, Level wanted, const FluidSolver& solver) {
  const auto levels = scene.params.levelProps();
  for (int k = levelIndex(wanted); k >= 0; --k) {
    const Level level = asLevel(k);
    if (latticeOf(scene, levels[static_cast<std::size_t>(k)], solver).sites() >= initialParticleCount(scene, level)) {
      return level;
    }
  }
  return wanted;
}

void fillWater(const Scene& scene, Level start_class, const FluidSolver& solver, ParticleSet& out) {
  const auto levels = scene.params.levelProps();
  const LevelProps props = levels[levelIndex(start_class)];
  const std::array<int, kMaxLevels> fill = initialFill(scene, start_class);
  const int count = std::accumulate(fill.begin(), fill.end(), 0);
  // Every particle may refine to L0: the finest count must fit as well as the start's.
  const int finest = initialParticleCount(scene, Level{0});
  if (static_cast<std::size_t>(finest) > out.capacity()) {
    throw std::invalid_argument(scene.source + ": key 'large_particles' (" + std::to_string(scene.large_particles) +
                                ") makes " + std::to_string(finest) +
                                " L0 particles when refined, more than the capacity of " +
                                std::to_string(out.capacity()));
  }
  const Lattice lattice = latticeOf(scene, props, solver);
  const double spacing = lattice.spacing;
  const double inset = lattice.inset;
  const std::array<int, 3>& cells = lattice.cells;
  const long capacity = lattice.sites();
  if (capacity < count) {
    throw std::invalid_argument(scene.source + ": water region holds " + std::to_string(capacity) + " " +
                                levelName(start_class) + " particles at spacing " + std::to_string(spacing) +
                                ", the scene needs " + std::to_string(count));
  }
  out.clear();
  // The fill's rest, one particle each of some finer levels, takes the last sites filled.
  std::vector<Level> rest;
  for (int j = 0; j < levelIndex(start_class); ++j) {
    if (fill[static_cast<std::size_t>(j)] != 0) rest.push_back(asLevel(j));
  }
  const long first_rest = count - static_cast<long>(rest.size());
  long site = 0;
  // The lowest layers full, and the particles left over for the top layer spread evenly over its
  // cells (every cell whose share of them, in row order, reaches a new whole): filled row by row
  // they would cover one side of the footprint, a step in the surface a spacing high that sets the
  // water sloshing towards the bare side as soon as it moves (docs/fluids.md, "Water starts at
  // rest").
  const long per_layer = static_cast<long>(cells[0]) * cells[2];
  const long full_layers = per_layer > 0 ? count / per_layer : 0;
  const long top = count - full_layers * per_layer;
  for (long y = 0; y <= full_layers && y < cells[1]; ++y) {
    for (long c = 0; c < per_layer; ++c) {
      if (y == full_layers && (c + 1) * top / per_layer == c * top / per_layer) continue;
      const long z = c / cells[0];
      const long x = c % cells[0];
      const Eigen::Vector3d p = scene.water.min + Eigen::Vector3d(inset + static_cast<double>(x) * spacing,
                                                                  inset + static_cast<double>(y) * spacing,
                                                                  inset + static_cast<double>(z) * spacing);
      const Level level = site < first_rest ? start_class : rest[static_cast<std::size_t>(site - first_rest)];
      ++site;
      out.add(p.cast<float>(), Vec3::Zero(), level, level == start_class ? props : levels[levelIndex(level)]);
    }
  }
  const BoxState box = scene.boundary.stateAt(0.0);
  const auto margin = static_cast<float>(inset);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Vec3& p = out.position[i];
    for (int a = 0; a < 3; ++a) {
      if (p[a] - margin < box.min[a] - 1e-6f || p[a] + margin > box.max[a] + 1e-6f) {
        throw std::invalid_argument(scene.source + ": key 'water' places particles outside 'box'");
      }
    }
  }
}

}  // namespace sph
