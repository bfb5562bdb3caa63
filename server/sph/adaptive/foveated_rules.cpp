#include "sph/adaptive/foveated_rules.h"

#include <cmath>

#include <Eigen/Eigenvalues>

namespace sph {

float neighbourSpread(const Eigen::Matrix3f& moment, float enough) {
  const float mean = moment.trace() / 3.0f;
  if (!(mean > 0.0f)) return 0.0f;  // no neighbours: a drop
  // The smallest eigenvalue is at least det / ((trace - smallest) / 2)^2 >= det / (1.5 mean)^2:
  // above `enough`, the eigenvalues are not needed.
  const float lower_bound = moment.determinant() / (2.25f * mean * mean);
  if (lower_bound >= enough * enough * mean) return std::sqrt(lower_bound / mean);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> eigen;
  eigen.computeDirect(moment, Eigen::EigenvaluesOnly);
  return std::sqrt(std::max(eigen.eigenvalues()(0), 0.0f) / mean);
}

}  // namespace sph
