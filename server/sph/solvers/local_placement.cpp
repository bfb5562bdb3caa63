#include "sph/solvers/local_placement.h"

#include <algorithm>
#include <iterator>

#include "sph/simd/simd_level.h"

namespace sph {

namespace {

// The compression particle i's placement added, as the last constraint pass computed its density:
// rho_i - max(rho_i at the frame's start, rho0) (a child starts with its parent's density).
float placementExcess(const ParticleSet& p, std::span<const float> at_start, float rest_density, std::size_t i) {
  return p.density[i] - std::max(at_start[i], rest_density);
}

}  // namespace

PbfConstants pbfConstantsOf(const SimParams& params, const IncompressibleSetup& setup) {
  PbfConstants c;
  c.kernels = setup.kernels;
  c.rest_density = static_cast<float>(params.rest_density);
  for (std::size_t k = 0; k < kMaxLevels; ++k) {
    // A full resting neighbourhood's constraint denominator (pbf_passes.h): sum_j m_j |grad W|^2 / rho0^2.
    const double full = setup.lattice_grad_sq[k] / (params.rest_density * params.rest_density);
    c.relaxation[k] = static_cast<float>(params.pbf_relaxation * full);
    c.lambda_scale[k] = static_cast<float>(-1.0 / (full * (1.0 + params.pbf_relaxation)));
    c.tensile_reference[k] = cubicW(setup.kernels[k], static_cast<float>(params.pbf_tensile_dq) * setup.kernels[k].h);
    c.contact[k] = setup.contact[k];
  }
  c.tensile_k = static_cast<float>(params.pbf_tensile_k);
  c.omega = static_cast<float>(params.pbf_omega);
  c.tensile_n = params.pbf_tensile_n;
  c.boundary = setup.boundary.get();
  return c;
}

PbfArrays pbfArraysOf(ParticleSet& p, std::vector<float>& lambda, std::vector<float>& lambda_step,
                      std::vector<Vec3>& wall_grad) {
  PbfArrays a;
  a.n = p.size();
  a.mass = p.mass.data();
  a.support = p.support.data();
  a.class_index = reinterpret_cast<const std::uint8_t*>(p.level.data());
  a.density = p.density.data();
  a.lambda = lambda.data();
  a.lambda_step = lambda_step.data();
  a.wall_grad = wall_grad.data()->data();
  return a;
}

int LocalPlacement::placeFresh(ParticleSet& p, NeighborGrid& grid, Grid state, const PbfConstants& c, float limit,
                               int max_iterations, std::span<Vec3> carried) {
  fresh_.reserve(p.capacity());
  p.freshPlacements(fresh_);
  if (fresh_.empty()) return 0;
  const std::size_t n = p.size();
  for (auto* v : {&lambda_, &lambda_step_, &density_at_start_}) v->reserve(p.capacity());
  for (auto* v : {&next_position_, &wall_grad_}) v->reserve(p.capacity());
  lambda_.assign(n, 0.0f);
  lambda_step_.assign(n, 0.0f);
  density_at_start_.assign(p.density.begin(), p.density.end());
  next_position_.resize(n);
  wall_grad_.resize(n);
  if (state == Grid::kBuild) grid.build(p);
  PbfArrays a = pbfArraysOf(p, lambda_, lambda_step_, wall_grad_);
  const PbfPassForms forms = pbfPassForms();
  watched_.reserve(p.capacity());
  collectNeighbourhoods(grid, fresh_, mark_, watched_);
  const std::span<const std::uint32_t> candidates = watched_;
  // The candidates' densities where they stand, and the multipliers the first iteration's pass
  // would give them from zero: place() keeps those of the particles it updates.
  a.position = p.position.data()->data();
  a.only = candidates.data();
  a.only_count = candidates.size();
  forms.lambda(a, c, grid);
  a.only = nullptr;
  a.only_count = 0;
  return place(p, grid, candidates, a, c, forms, limit, max_iterations, carried);
}

void LocalPlacement::surround(const NeighborGrid& grid, PbfArrays& a) {
  // The last sets' multipliers stay as they are: only the new sets' change from here on.
  for (std::uint32_t i : updated_) a.lambda_step[i] = 0.0f;
  collectNeighbourhoods(grid, placed_, mark_, updated_);
  collectNeighbourhoods(grid, updated_, mark_, moved_);
}

int LocalPlacement::place(ParticleSet& p, const NeighborGrid& grid, std::span<const std::uint32_t> candidates,
                          PbfArrays& a, const PbfConstants& c, const PbfPassForms& forms, float limit,
                          int max_iterations, std::span<Vec3> carried) {
  const float rho0 = c.rest_density;
  const std::size_t room = p.capacity();
  for (auto* v : {&placed_, &updated_, &moved_, &unmeasured_}) v->reserve(room);
  const auto overLimit = [&](std::uint32_t i) { return placementExcess(p, density_at_start_, rho0, i) > limit; };
  // The candidates compressed beyond the limit.
  placed_.clear();
  for (std::uint32_t i : candidates) {
    if (overLimit(i)) placed_.push_back(i);
  }
  if (placed_.empty()) return 0;
  updated_.clear();
  surround(grid, a);
  // The measuring pass's multipliers stand for the first iteration's where it updates the
  // particle (the same pass from zero at the same positions); elsewhere they are zero, and only
  // the updated particles it did not measure take the first iteration's pass.
  for (std::uint32_t i : candidates) {
    if (!std::binary_search(updated_.begin(), updated_.end(), i)) a.lambda[i] = a.lambda_step[i] = 0.0f;
  }
  unmeasured_.clear();
  std::set_difference(updated_.begin(), updated_.end(), candidates.begin(), candidates.end(),
                      std::back_inserter(unmeasured_));
  int iteration = 0;
  while (iteration < max_iterations && !placed_.empty()) {
    a.position = p.position.data()->data();
    const std::vector<std::uint32_t>& pass = iteration == 0 ? unmeasured_ : updated_;
    a.only = pass.data();
    a.only_count = pass.size();
    if (!pass.empty()) forms.lambda(a, c, grid);
    a.position_next = next_position_.data()->data();
    a.only = moved_.data();
    a.only_count = moved_.size();
    forms.correct(a, c, grid, false);
    for (std::uint32_t i : moved_) {
      if (!carried.empty()) carried[i] += next_position_[i] - p.position[i];
      p.position[i] = next_position_[i];
    }
    ++iteration;
    // On while any particle the iteration updated is still compressed beyond the limit (the lambda
    // pass measured them all), around those alone: the placement's pushes can press a neighbour
    // beyond it, and a placement already within it needs no more.
    placed_.clear();
    for (std::uint32_t i : updated_) {
      if (overLimit(i)) placed_.push_back(i);
    }
    if (!placed_.empty()) surround(grid, a);
  }
  a.only = nullptr;
  a.only_count = 0;
  return iteration;
}

}  // namespace sph
