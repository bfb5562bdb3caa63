#include "sph/adaptive/perceptual_budget.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sph/adaptive/display_geometry.h"

namespace sph {

namespace {

constexpr std::uint32_t kNoOwner = std::numeric_limits<std::uint32_t>::max();
constexpr double kArcminPerDegree = 60.0;

int cellOf(float u, int cells) {
  return std::clamp(static_cast<int>(std::floor(u * static_cast<float>(cells))), 0, cells - 1);
}

}  // namespace

PerceptualBudget PerceptualBudgetMeter::measure(const ParticleSet& p, const SimParams& params,
                                                const ScreenCamera& camera, double gaze_x, double gaze_y,
                                                const AdaptiveConfig& config) {
  PerceptualBudget out;
  const std::size_t n = p.size();
  const Projector projector(camera);
  const FastProjection& fast = projector.fast();
  const auto aspect = static_cast<float>(projector.aspect());
  const int columns = kDepthGridWidth;
  const int rows = std::max(1, static_cast<int>(std::lround(static_cast<double>(columns) / aspect)));
  const float inf = std::numeric_limits<float>::infinity();
  cell_depth_.assign(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), inf);
  cell_owner_.assign(cell_depth_.size(), kNoOwner);
  seen_.assign(n, 0);

  // Every particle in front of the eye with its centre on the display marks the cells its disc
  // covers with its distance; the nearest keeps each cell (ascending i: a tie keeps the lower index).
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = p.position[i];
    const FastScreenDisc disc = projector.projectFast(x, p.radius[i]);
    if (!onDisplay(disc)) continue;
    const float depth =
        fast.depth_row[0] * x.x() + fast.depth_row[1] * x.y() + fast.depth_row[2] * x.z() + fast.depth_row[3];
    const float radius_y = disc.radius * aspect;  // in viewport heights
    const int c0 = cellOf(disc.x - disc.radius, columns), c1 = cellOf(disc.x + disc.radius, columns);
    const int r0 = cellOf(disc.y - radius_y, rows), r1 = cellOf(disc.y + radius_y, rows);
    const int centre_column = cellOf(disc.x, columns), centre_row = cellOf(disc.y, rows);
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        // The cells whose centre the disc covers, and the cell of its own centre.
        const float dx = (static_cast<float>(c) + 0.5f) / static_cast<float>(columns) - disc.x;
        const float dy = ((static_cast<float>(r) + 0.5f) / static_cast<float>(rows) - disc.y) / aspect;
        const bool covered = dx * dx + dy * dy <= disc.radius * disc.radius || (c == centre_column && r == centre_row);
        const std::size_t cell =
            static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(c);
        if (covered && depth < cell_depth_[cell]) {
          cell_depth_[cell] = depth;
          cell_owner_[cell] = static_cast<std::uint32_t>(i);
        }
      }
    }
  }
  for (const std::uint32_t owner : cell_owner_) {
    if (owner != kNoOwner) seen_[owner] = 1;
  }

  // The particle under the gaze: of those on the display whose disc covers the gaze point (as the
  // user sees the display: discRadiusDeg), the nearest the eye (a tie keeps the lower index). It is
  // what the eye sees there, so it is visible even where no cell's centre samples it (a disc
  // narrower than a cell).
  const auto gx = static_cast<float>(gaze_x), gy = static_cast<float>(gaze_y);
  const float tan_half = displayTanHalf(config, camera);
  const Eigen::Vector3f gaze_dir = screenDirection(gx, gy, tan_half, aspect);
  std::size_t gazed = n;
  float gazed_depth = inf;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = p.position[i];
    const FastScreenDisc disc = projector.projectFast(x, p.radius[i]);
    if (!onDisplay(disc)) continue;
    const float e = angleDeg(gaze_dir, screenDirection(disc.x, disc.y, tan_half, aspect));
    const float depth =
        fast.depth_row[0] * x.x() + fast.depth_row[1] * x.y() + fast.depth_row[2] * x.z() + fast.depth_row[3];
    if (e <= discRadiusDeg(disc.radius, tan_half) && depth < gazed_depth) {
      gazed_depth = depth;
      gazed = i;
    }
  }
  if (gazed != n) seen_[gazed] = 1;
  // The reference distance: the water under the gaze point, or (where the gaze falls on none) the
  // nearest water to it on the display.
  float reference_depth = gazed_depth;
  if (gazed == n) {
    const int gaze_column = cellOf(gx, columns), gaze_row = cellOf(gy, rows);
    long best = std::numeric_limits<long>::max();
    for (std::size_t cell = 0; cell < cell_owner_.size(); ++cell) {
      if (cell_owner_[cell] == kNoOwner) continue;
      const long dc = static_cast<long>(cell % static_cast<std::size_t>(columns)) - gaze_column;
      const long dr = static_cast<long>(cell / static_cast<std::size_t>(columns)) - gaze_row;
      if (dc * dc + dr * dr < best) {
        best = dc * dc + dr * dr;
        reference_depth = cell_depth_[cell];
      }
    }
    if (!std::isfinite(reference_depth)) return out;  // no water on the display
  } else {
    out.gaze_level = levelIndex(p.level[gazed]);
  }

  const auto finest_radius = static_cast<float>(params.levelProps()[0].radius);
  const float finest_disc = finest_radius * fast.focal_over_width / reference_depth;
  const float reference_deg = discWidthDeg(gx, gy, finest_disc, tan_half, aspect);
  const auto mar_gain = static_cast<float>(config.foveated_mar_slope / config.foveated_mar_w0_deg);
  const auto q = static_cast<float>(config.foveated_quality);

  for (std::size_t i = 0; i < n; ++i) {
    if (seen_[i] == 0) continue;
    const FastScreenDisc disc = projector.projectFast(p.position[i], p.radius[i]);
    const float width = discWidthDeg(disc.x, disc.y, disc.radius, tan_half, aspect);
    const float e = angleDeg(gaze_dir, screenDirection(disc.x, disc.y, tan_half, aspect));
    ++out.visible;
    // The finest level cannot be refined: only a coarser particle can be over budget.
    if (levelIndex(p.level[i]) > 0 && width > q * (1.0f + mar_gain * e) * reference_deg) ++out.over_budget;
    if (i == gazed) {
      out.gaze_width_arcmin = kArcminPerDegree * width;
      out.gaze_mar_arcmin = kArcminPerDegree * (config.foveated_mar_w0_deg + config.foveated_mar_slope * e);
    }
  }
  return out;
}

}  // namespace sph
