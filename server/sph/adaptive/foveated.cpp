#include "sph/adaptive/foveated.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

#include "sph/adaptive/display_geometry.h"
#include "sph/adaptive/foveated_rules.h"
#include "sph/thread_share.h"

namespace sph {

namespace {

// The finest level below `level` (the finest a merged particle may border) among particle i's
// neighbours and theirs that lies within sqrt(reach2) of it, or `level` where none does.
// `finest_near[k]`: the finest level among k and its neighbours, so only the neighbours with a
// finer one are searched.
int finestWithin(const ParticleSet& p, const NeighborGrid& grid, const std::vector<std::int8_t>& finest_near,
                 std::size_t i, int level, float reach2) {
  const Vec3 xi = p.position[i];
  int finest = level;
  const auto consider = [&](std::uint32_t j) {
    const int l = levelIndex(p.level[j]);
    if (l < finest && (p.position[j] - xi).squaredNorm() < reach2) finest = l;
  };
  for (const std::uint32_t k : grid.neighbors(i)) {
    if (finest_near[k] >= level) continue;
    consider(k);
    for (const std::uint32_t j : grid.neighbors(k)) consider(j);
  }
  return finest;
}

// The finest level among particle i's neighbours (i of level `own`), `none` where it has none:
// read in list order from the levels the grid keeps for lists of mixed levels; a list of one level
// is all of i's (NeighborGrid::hasOtherSupport).
int finestNeighbourLevel(const NeighborGrid& grid, std::size_t i, int own, int none) {
  const std::uint32_t count = grid.neighborCount(i);
  if (count == 0) return none;
  if (!grid.hasOtherSupport(i)) return own;
  const std::uint8_t* levels = grid.neighborLevels(i);
  int finest = none;
  for (std::uint32_t k = 0; k < count; ++k) finest = std::min(finest, static_cast<int>(levels[k]));
  return finest;
}

// Where the eye sees particles on the display: their disc, eccentricity and distance.
struct EyeView {
  Projector projector;
  float aspect, tan_half;
  Eigen::Vector3f gaze_dir;
  Eigen::Vector4f depth_row;  // view-space distance
  EyeView(const ScreenCamera& camera, double gaze_x, double gaze_y, const AdaptiveConfig& config)
      : projector(camera),
        aspect(static_cast<float>(projector.aspect())),
        tan_half(displayTanHalf(config, camera)),
        gaze_dir(screenDirection(static_cast<float>(gaze_x), static_cast<float>(gaze_y), tan_half, aspect)),
        depth_row(-camera.view.row(2).cast<float>()) {}

  struct Seen {
    FastScreenDisc disc;
    bool on_screen;  // in front of the eye, its centre on the display
    float e;         // eccentricity, degrees (180 behind the eye)
    float disc_deg;  // the disc's angular radius
    float depth;
  };
  Seen see(const Vec3& x, float radius) const {
    Seen s;
    s.disc = projector.projectFast(x, radius);
    s.on_screen = onDisplay(s.disc);
    s.e = s.disc.in_front ? angleDeg(gaze_dir, screenDirection(s.disc.x, s.disc.y, tan_half, aspect)) : 180.0f;
    s.disc_deg = discRadiusDeg(s.disc.radius, tan_half);
    s.depth = depth_row.head<3>().dot(x) + depth_row.w();
    return s;
  }
};

}  // namespace

FoveaWater::FoveaWater()
    : under(std::numeric_limits<float>::infinity()),
      least_e(std::numeric_limits<float>::infinity()),
      least_e_depth(std::numeric_limits<float>::infinity()) {}

void FoveaWater::consider(float e_deg, float disc_deg, float depth) {
  if (e_deg <= disc_deg) under = std::min(under, depth);
  takeIfLessEccentric(e_deg, depth);
}

void FoveaWater::combine(const FoveaWater& other) {
  under = std::min(under, other.under);
  takeIfLessEccentric(other.least_e, other.least_e_depth);
}

void FoveaWater::takeIfLessEccentric(float e_deg, float depth) {
  if (e_deg < least_e || (e_deg == least_e && depth < least_e_depth)) {
    least_e = e_deg;
    least_e_depth = depth;
  }
}

float FoveaWater::depth() const { return std::isfinite(under) ? under : least_e_depth; }

float foveaWaterDepth(const ParticleSet& p, const ScreenCamera& camera, double gaze_x, double gaze_y,
                      const AdaptiveConfig& config) {
  const EyeView eye(camera, gaze_x, gaze_y, config);
  const std::size_t n = p.size();
  FoveaWater water;
#pragma omp parallel
  {
    FoveaWater mine;
    const ThreadShare share = threadShare(n);
    for (std::size_t i = share.begin; i < share.end; ++i) {
      const EyeView::Seen seen = eye.see(p.position[i], p.radius[i]);
      if (seen.on_screen) mine.consider(seen.e, seen.disc_deg, seen.depth);
    }
#pragma omp critical(sph_fovea_water)
    water.combine(mine);
  }
  return water.depth();
}

int settleSurfaceDistance(Simulation& sim, const AdaptiveConfig& config, FoveatedScratch& scratch) {
  ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  const NeighborGrid& grid = sim.grid();
  const auto surface_threshold = static_cast<float>(config.surface_normal_scale * sim.params().surfaceThreshold());
  const auto large_support = static_cast<float>(sim.params().levelProps()[1].support);
  const float far = std::numeric_limits<float>::infinity();
  std::vector<float>& next = scratch.settled;
  next.resize(n);
  // The least d_j + |r_ij| over i's neighbours, from the current field.
  const auto nearest = [&](std::size_t i) {
    float hop = far;
    for (const std::uint32_t j : grid.neighbors(i)) {
      hop = std::min(hop, p.surface_distance[j] + (p.position[j] - p.position[i]).norm());
    }
    return hop;
  };
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const bool surface = p.normal_length[i] * p.support[i] / large_support >= surface_threshold;
    p.surface_distance[i] = surface ? 0.0f : far;
  }
  // Each sweep carries the distance one neighbour further; the field settles within as many
  // sweeps as the deepest particle is hops from the surface.
  int sweeps = 0;
  bool changed = true;
  while (changed && sweeps < static_cast<int>(n) + 1) {
    changed = false;
#pragma omp parallel for schedule(static) reduction(|| : changed)
    for (std::size_t i = 0; i < n; ++i) {
      next[i] = p.surface_distance[i] == 0.0f ? 0.0f : std::min(p.surface_distance[i], nearest(i));
      changed = changed || next[i] != p.surface_distance[i];
    }
    std::copy_n(next.begin(), n, p.surface_distance.begin());
    ++sweeps;
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) p.surface_hop[i] = nearest(i);
  return sweeps;
}

double acuityRatio(const AdaptiveConfig& config, double e_deg) {
  return 1.0 + config.foveated_mar_slope * std::max(e_deg, 0.0) / config.foveated_mar_w0_deg;
}

DecisionCounts decideFoveated(Simulation& sim, const ScreenCamera& camera, double gaze_x, double gaze_y,
                              const AdaptiveConfig& config, bool splits_only, std::span<std::int8_t> out,
                              FoveatedScratch& scratch, FoveatedView& view, const SplitPassScope* scope) {
  if (scope != nullptr && !splits_only) throw std::invalid_argument("decideFoveated: a scope is for a split pass");
  ParticleSet& p = sim.particles();
  const std::size_t n = p.size();
  const NeighborGrid& grid = sim.grid();
  const auto levels = sim.params().levelProps();
  const int coarsest = std::clamp(sim.params().levels, kMinLevels, kMaxLevels) - 1;
  // Each level's width in finest particles.
  float width[kMaxLevels];
  for (int k = 0; k < kMaxLevels; ++k) width[k] = static_cast<float>(levels[k].radius / levels[0].radius);
  const auto rest_density = static_cast<float>(sim.params().rest_density);
  const EyeView eye(camera, gaze_x, gaze_y, config);
  const float aspect = eye.aspect;
  const float tan_half = eye.tan_half;
  // How wide a small disc looks at the gaze point, degrees per viewport width: a particle's width
  // is weighed as the user sees it, against a finest particle's at the gaze point (the perceptual
  // budget's measure), not on the screen.
  constexpr float kSmallDisc = 1e-3f;  // viewport widths
  const float gaze_scale =
      discWidthDeg(static_cast<float>(gaze_x), static_cast<float>(gaze_y), kSmallDisc, tan_half, aspect) /
      (2.0f * kSmallDisc);
  const auto q = static_cast<float>(config.foveated_quality);
  const auto mar_gain = static_cast<float>(config.foveated_mar_slope / config.foveated_mar_w0_deg);
  const auto periphery_gain = static_cast<float>(config.foveated_periphery_gain);
  const auto finest_spacing = static_cast<float>(std::cbrt(levels[0].mass / sim.params().rest_density));
  const float hidden_depth = static_cast<float>(config.foveated_hidden_depth) * finest_spacing;
  float support[kMaxLevels];
  for (int k = 0; k < kMaxLevels; ++k) support[k] = static_cast<float>(levels[k].support);
  const auto least_spread = static_cast<float>(config.foveated_shallow_spread);
  const auto hold_frames =
      static_cast<int>(std::min(std::ceil(config.foveated_merge_hold_s / sim.params().time_step - 1e-9), 65535.0));
  // The free surface, as the surface method finds it (3.44), |n| scaled to L1's support: the
  // colour field's gradient falls as 1 / h with the particle's own kernel.
  const auto surface_threshold = static_cast<float>(config.surface_normal_scale * sim.params().surfaceThreshold());
  const auto large_support = static_cast<float>(levels[1].support);
  const auto margin = static_cast<float>(config.foveated_coarsen_margin);
  const auto thin_fill = static_cast<float>(config.foveated_thin_fill);
  const int thin_level = std::clamp(config.foveated_thin_level, 0, coarsest);
  const int step = std::clamp(config.foveated_grading_step, 1, kMaxLevels - 1);
  // How far a particle of level k merged with a partner reaches: it lands half the pair's
  // distance away (the partner is a neighbour: within h_k), and reaches a particle of level
  // k - step, the coarsest the grading forbids it, within (h_k+1 + h_k-step) / 2, eq. (3.34).
  float merged_reach2[kMaxLevels] = {};
  for (int k = step; k < coarsest; ++k) {
    const double reach = 0.5 * levels[k].support + 0.5 * (levels[k + 1].support + levels[k - step].support);
    merged_reach2[k] = static_cast<float>(reach * reach);
  }

  scratch.allowed.resize(n);
  scratch.depth.resize(n);
  scratch.finest_near.resize(n);
  const float last_fovea = scratch.fovea_depth;
  // The particles decided: all, or the scope's (the others remain).
  const std::size_t visits = scope != nullptr ? scope->particles.size() : n;
  const auto visited = [&](std::size_t visit) -> std::size_t {
    return scope != nullptr ? scope->particles[visit] : visit;
  };
  if (scope != nullptr) std::fill(out.begin(), out.end(), kRemain);
  // The gaze point's water (FoveaWater), the threads' combined.
  const float inf = std::numeric_limits<float>::infinity();
  FoveaWater fovea_water;
  int split_wanted = 0, merge_wanted = 0, still_coarse = 0;
  int held_by_eye = 0, held_by_grading = 0, held_by_thin = 0, held_waiting = 0;
#pragma omp parallel reduction(+ : split_wanted, merge_wanted, still_coarse, held_by_eye, held_by_grading, \
                                   held_by_thin, held_waiting)
  {
    FoveaWater my_fovea_water;
    const ThreadShare share = threadShare(visits);
    // Pass 1: where each particle is seen (eccentricity, distance), the depth field, and the
    // nearest water at the gaze point.
    for (std::size_t visit = share.begin; visit < share.end; ++visit) {
      const std::size_t i = visited(visit);
      const EyeView::Seen seen = eye.see(p.position[i], p.radius[i]);
      const FastScreenDisc& disc = seen.disc;
      const float depth = seen.depth;
      const bool on_screen = seen.on_screen;
      const float e = seen.e;
      const float scaled_n = p.normal_length[i] * p.support[i] / large_support;
      const float d = scaled_n >= surface_threshold ? 0.0f : p.surface_hop[i];
      p.surface_distance[i] = d;
      scratch.depth[i] = depth;
      // The particle the gaze falls on (its disc covers the gaze point) is seen at the gaze point,
      // where the eye resolves MAR(0), however far off its centre lies: a particle wide on the
      // display would otherwise cover it at the next level. The periphery gain spares it and
      // those whose merge could cover it: a merged particle lands between its pair, at most half
      // a support from either, and is 2^(1/3) as wide. The governor coarsens the periphery,
      // never the gaze point.
      const float merge_reach = std::cbrt(2.0f) + 0.5f * p.support[i] / p.radius[i];
      const float disc_deg = seen.disc_deg;
      const bool gazed_on = e <= disc_deg * merge_reach;
      const float seen_e = e <= disc_deg ? 0.0f : e;
      // Water behind the eye or off the display is not seen: any level (inf, which pass 2 keeps
      // apart from the distance ratio, 0 behind the eye). Seen water's allowance is divided by how
      // many times as wide its disc looks as it would at the gaze point.
      float allowed = inf;
      if (on_screen) {
        const float seen_scale = disc.radius > 0.0f ? discWidthDeg(disc.x, disc.y, disc.radius, tan_half, aspect) /
                                                          (2.0f * disc.radius * gaze_scale)
                                                    : 1.0f;
        allowed = q * (1.0f + (gazed_on ? 1.0f : periphery_gain) * mar_gain * seen_e) / seen_scale;
      }
      scratch.allowed[i] = allowed;
      if (on_screen) my_fovea_water.consider(e, disc_deg, depth);
    }
#pragma omp critical(sph_fovea_depth)
    fovea_water.combine(my_fovea_water);
#pragma omp barrier
    const float fovea = scope != nullptr ? scope->fovea_depth : fovea_water.depth();
    // The water at the gaze point: this step's where any water is on the display, else the last
    // step's, else this particle's own distance (every particle then as at the gaze).
    const float fovea_depth = std::isfinite(fovea) ? fovea : last_fovea;
    // The finest level within one neighbour hop (the particle itself included): for the merges'
    // grading alone.
    if (!splits_only) {
      for (std::size_t i = share.begin; i < share.end; ++i) {
        const int own = levelIndex(p.level[i]);
        scratch.finest_near[i] = static_cast<std::int8_t>(std::min(own, finestNeighbourLevel(grid, i, own, own)));
      }
    }
#pragma omp barrier
    // Pass 2: the targets and the decisions.
    for (std::size_t visit = share.begin; visit < share.end; ++visit) {
      const std::size_t i = visited(visit);
      const int level = levelIndex(p.level[i]);
      const float depth = scratch.depth[i];
      const float distance_ratio = fovea_depth > 0.0f ? std::max(depth, 0.0f) / fovea_depth : 1.0f;
      // In finest widths at the gaze; unseen water (inf) stays inf whatever its distance.
      const bool seen = std::isfinite(scratch.allowed[i]);
      const float allowed = seen ? scratch.allowed[i] * distance_ratio : scratch.allowed[i];
      // The finest level among the neighbours, and within two hops (grading), and the second
      // moment of the neighbours' offsets about i (hidden and shallow water).
      const int finest_neighbour = finestNeighbourLevel(grid, i, levelIndex(p.level[i]), coarsest);
      int finest_two_hops = splits_only ? level : scratch.finest_near[i];  // for the merges' grading
      // The moment's six distinct entries, each summed in neighbour order as r r^T would.
      const Vec3 xi = p.position[i];
      float mxx = 0.0f, mxy = 0.0f, mxz = 0.0f, myy = 0.0f, myz = 0.0f, mzz = 0.0f;
      for (const std::uint32_t j : grid.neighbors(i)) {
        if (!splits_only) finest_two_hops = std::min(finest_two_hops, static_cast<int>(scratch.finest_near[j]));
        const Vec3 r = p.position[j] - xi;
        mxx += r.x() * r.x();
        mxy += r.x() * r.y();
        mxz += r.x() * r.z();
        myy += r.y() * r.y();
        myz += r.y() * r.z();
        mzz += r.z() * r.z();
      }
      Eigen::Matrix3f moment;
      moment << mxx, mxy, mxz, mxy, myy, myz, mxz, myz, mzz;
      // The neighbours' spread, measured once and only where a rule reads it (an eigenvalue
      // solve where the determinant's bound does not settle it).
      float spread = -1.0f;
      const auto spreadOfNeighbours = [&] {
        if (spread < 0.0f) spread = neighbourSpread(moment, least_spread * margin);
        return spread;
      };
      LevelBounds bounds = acuityBounds(allowed, width, coarsest, margin);
      if (p.surface_distance[i] >= hidden_depth) {
        hiddenRule(bounds, p.surface_distance[i], hidden_depth, support, spreadOfNeighbours(), least_spread, margin,
                   coarsest);
      }
      const int eye_level = bounds.target;  // what the eye needs, for the further split passes
      const int merge_by_eye = bounds.merge_upto;
      // Within two hops is where a level the merged particle may not border (finer than
      // `allowed_below`) may lie within its reach; where one does and the eye would let the
      // particle merge, measure whether it is within it.
      const int allowed_below = level + 1 - step;
      const bool measure_reach =
          finest_two_hops < allowed_below && finest_neighbour >= allowed_below && merge_by_eye > level;
      const int finest_in_reach =
          measure_reach ? finestWithin(p, grid, scratch.finest_near, i, allowed_below, merged_reach2[level])
                        : finest_two_hops;
      gradedRule(bounds, finest_neighbour, finest_in_reach, step);
      const int merge_by_grading = bounds.merge_upto;
      // How full the particle's support is: its density, which every level estimates alike. A
      // flat free surface fills about half of it; a sheet thinner than the support, a jet or a
      // drop less.
      thinRule(bounds, p.density[i] / rest_density, thin_fill, margin, thin_level);
      if (shallowCounts(bounds, thin_level)) {
        shallowRule(bounds, spreadOfNeighbours(), least_spread, margin, thin_level);
      }
      // A merge needs the eye to have allowed the coarser level for the hold without a break
      // (counted once a step, by the step's first decision).
      if (!splits_only) {
        const bool eye_allows = bounds.eye_margin > level;
        p.coarsen_wait[i] = eye_allows ? static_cast<std::uint16_t>(std::min(p.coarsen_wait[i] + 1, 65535)) : 0;
      }
      std::int8_t decision = kRemain;
      if (level > bounds.target) {
        decision = kSplit;
      } else if (!splits_only && level < bounds.merge_upto && level < coarsest && p.placed[i] == kNotPlaced &&
                 p.coarsen_wait[i] >= hold_frames) {
        decision = kMerge;
      }
      out[i] = decision;
      if (!splits_only && level < coarsest) {
        const bool by_eye = merge_by_eye <= level;
        const bool by_grading = !by_eye && merge_by_grading <= level;
        const bool by_thin = !by_eye && !by_grading && bounds.merge_upto <= level;
        held_by_eye += by_eye;
        held_by_grading += by_grading;
        held_by_thin += by_thin;
        held_waiting += !by_eye && !by_grading && !by_thin && decision != kMerge;
      }
      // Seen water still coarser than the eye allows once this split is made (the frame after
      // this step shows level - 1).
      if (seen && p.surface_distance[i] < hidden_depth) still_coarse += level - (decision == kSplit) > eye_level;
      split_wanted += decision == kSplit;
      merge_wanted += decision == kMerge;
    }
  }
  const float fovea = scope != nullptr ? scope->fovea_depth : fovea_water.depth();
  if (std::isfinite(fovea)) scratch.fovea_depth = fovea;
  view.still_coarse = still_coarse;
  if (!splits_only) view.held = {held_by_eye, held_by_grading, held_by_thin, held_waiting};
  view.fovea_depth = scratch.fovea_depth;
  return {split_wanted, merge_wanted};
}

}  // namespace sph
