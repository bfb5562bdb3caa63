#include "sph/adaptive/decide.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/adaptive/decision_passes.h"
#include "sph/simd/simd_level.h"
#include "sph/thread_share.h"

namespace sph {

DecisionCounts decideBySurface(Simulation& sim, const AdaptiveConfig& config, std::span<std::int8_t> out) {
  ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  const float surface_threshold =
      static_cast<float>(config.surface_normal_scale * sim.params().surfaceThreshold());  // (3.44)
  const BoxState box = sim.boxNow();
  const Boundary& boundary = sim.scene().boundary;
  const SurfaceArrays arrays{p.position.data()->data(),
                             p.surface_hop.data(),
                             p.normal_length.data(),
                             p.pressure.data(),
                             p.level.data(),
                             sim.grid().neighborCounts().data(),
                             p.surface_distance.data(),
                             out.data()};
  const DecisionPassForms forms = decisionPassForms();

  // Character field, eq. (3.45), and the decision, eq. (3.46). N_max is taken per size class: the
  // classes have different neighbour counts by design (x_SMALL 50, x_LARGE 20, table 3.2), and one
  // global maximum would make every L1 particle look "isolated" next to L0 ones, so splitting
  // would creep inwards step after step. Particles the distance field has not reached yet are
  // deeper than every reached one: they take d = dmax.
  const auto inverse = [](float v) { return v > 0.0f ? 1.0f / v : 0.0f; };
  CharacterField field{};
  field.alpha = static_cast<float>(config.alpha);
  field.beta = static_cast<float>(config.beta);
  field.gamma = static_cast<float>(config.gamma);
  field.inv_weights = 1.0f / (field.alpha + field.beta + field.gamma);
  field.split_below = static_cast<float>(config.threshold);
  field.merge_from = 2.0f * field.split_below;

  FieldMaxima all;
  int split_wanted = 0;
  int merge_wanted = 0;
  // One parallel region, two passes: the maxima (combined in any order, max is exact) between.
#pragma omp parallel reduction(+ : split_wanted, merge_wanted)
  {
    const ThreadShare share = threadShare(n);
    const FieldMaxima mine = forms.surfaceDistances(arrays, share.begin, share.end, surface_threshold,
                                                    config.surface_includes_walls, box, boundary);
#pragma omp critical(sph_surface_maxima)
    {
      all.pressure = std::max(all.pressure, mine.pressure);
      all.distance = std::max(all.distance, mine.distance);
      for (int c = 0; c < kMaxLevels; ++c) all.neighbors[c] = std::max(all.neighbors[c], mine.neighbors[c]);
    }
#pragma omp barrier
    CharacterField local = field;
    local.max_distance = all.distance;
    local.inv_dmax = inverse(all.distance);
    local.inv_fmax = inverse(all.pressure);
    for (int c = 0; c < kMaxLevels; ++c) local.inv_nmax[c] = inverse(static_cast<float>(all.neighbors[c]));
    const DecisionCounts counts = forms.characterDecisions(arrays, share.begin, share.end, local);
    split_wanted += counts.split_wanted;
    merge_wanted += counts.merge_wanted;
  }
  return {split_wanted, merge_wanted};
}

DecisionCounts decideByGaze(const ParticleSet& particles, const ScreenCamera& camera, double gaze_x, double gaze_y,
                            const AdaptiveConfig& config, bool hybrid, std::span<std::int8_t> out) {
  const Projector projector(camera);
  const GazeCircle gaze{projector.fast(),
                        static_cast<float>(gaze_x),
                        static_cast<float>(gaze_y),
                        static_cast<float>(1.0 / projector.aspect()),
                        static_cast<float>(config.gaze_radius),
                        static_cast<float>(config.gaze_ring_radius)};
  const float* xyz = particles.position.data()->data();  // packed x, y, z
  const float* radius = particles.radius.data();
  const std::size_t n = particles.size();
  const DecisionPassForms forms = decisionPassForms();
  int split_wanted = 0;
  int merge_wanted = 0;
#pragma omp parallel reduction(+ : split_wanted, merge_wanted)
  {
    const ThreadShare share = threadShare(n);
    const DecisionCounts mine =
        forms.gazeDecisions(gaze, xyz, radius, particles.level.data(), out.data(), share.begin, share.end, hybrid);
    split_wanted += mine.split_wanted;
    merge_wanted += mine.merge_wanted;
  }
  return {split_wanted, merge_wanted};
}

}  // namespace sph
