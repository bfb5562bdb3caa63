// The vector pair sums (thesis_stages_avx2.cpp, thesis_stages_avx512.cpp) against the scalar
// reference on a cloud mixing L0 and L1 particles: every form the CPU has gives the same
// density, pressure, acceleration, |n| and surface-distance hop up to float rounding. Skipped where
// the CPU (or the build, SPH_FORCE_SCALAR) has no vector form. The public stages run the form
// simdLevel() names, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "sph/neighbor_grid.h"
#include "sph/params.h"
#include "sph/particles.h"
#include "sph/simd/simd_level.h"
#include "sph/solvers/thesis/thesis_stages.h"

namespace {

struct Cloud {
  sph::SimParams params = sph::thesisPreset();
  sph::ParticleSet particles{1500};
  sph::NeighborGrid grid;
};

// Where the cloud's particles go: a cube of side `extent` (0.3: a dense heap, lists of about 60;
// 1.2: a spray, lists of 0 to a few, so batches cross from one particle's list into the next's
// at every lane), and `coincident` pairs moved onto one point.
struct CloudShape {
  float extent = 0.3f;
  int coincident = 0;
};

// A loose heap of both classes with random velocities and surface distances (some still
// unreached), so every term of both stages, surface tension and mixed pairs included, is non-zero.
void makeCloud(Cloud& cloud, const CloudShape& shape) {
  const auto classes = cloud.params.levelProps();
  std::mt19937 rng(4242);
  std::uniform_real_distribution<float> pos(0.0f, 0.3f);
  std::uniform_real_distribution<float> vel(-0.5f, 0.5f);
  std::uniform_real_distribution<float> dist(0.0f, 0.1f);
  std::bernoulli_distribution large(0.5);
  std::bernoulli_distribution unreached(0.3);
  while (cloud.particles.size() < cloud.particles.capacity()) {
    const sph::Level c = large(rng) ? sph::Level{1} : sph::Level{0};
    const float e = shape.extent / 0.3f;
    const std::uint32_t k =
        cloud.particles.add(sph::Vec3(e * pos(rng), e * pos(rng) * 0.5f, e * pos(rng)),
                            sph::Vec3(vel(rng), vel(rng), vel(rng)), c, classes[sph::levelIndex(c)]);
    cloud.particles.surface_distance[k] = unreached(rng) ? std::numeric_limits<float>::infinity() : dist(rng);
  }
  for (int c = 0; c < shape.coincident; ++c) {
    cloud.particles.position[2 * static_cast<std::size_t>(c) + 1] =
        cloud.particles.position[2 * static_cast<std::size_t>(c)];
  }
  sph::Aabb bounds;
  bounds.min = Eigen::Vector3d::Zero();
  bounds.max = Eigen::Vector3d::Constant(shape.extent);
  cloud.grid.configure(bounds, static_cast<float>(std::max(classes[0].support, classes[1].support)),
                       cloud.particles.size());
  cloud.grid.build(cloud.particles);
}

// A vector form of the two stages.
struct StageForm {
  const char* name;
  sph::SimdLevel level;
  decltype(&sph::scalar::computeDensityPressure) density;
  decltype(&sph::scalar::computeAccelerations) accelerations;
};

const StageForm kVectorForms[] = {
    {"avx2", sph::SimdLevel::kAvx2, sph::avx2::computeDensityPressure, sph::avx2::computeAccelerations},
    {"avx512", sph::SimdLevel::kAvx512, sph::avx512::computeDensityPressure, sph::avx512::computeAccelerations},
};

// |a - b| within `rel` of `scale` (the mean magnitude of the quantity over the cloud).
void expectClose(float a, float b, double scale, double rel, const char* what, std::size_t i) {
  EXPECT_LE(std::abs(static_cast<double>(a) - b), rel * scale)
      << what << " of particle " << i << ": " << a << " vs " << b;
}

void expectFormMatchesScalar(const StageForm& form, const sph::SimParams& params, const CloudShape& shape) {
  SCOPED_TRACE(form.name);
  Cloud cloud;
  cloud.params = params;
  makeCloud(cloud, shape);
  const bool dense = shape.extent <= 0.3f;
  const sph::KernelTable kernels = sph::makeKernelTable(cloud.params);
  sph::ParticleSet scalar = cloud.particles;
  sph::ParticleSet vector = cloud.particles;

  sph::scalar::computeDensityPressure(cloud.params, kernels, cloud.grid, scalar);
  form.density(cloud.params, kernels, cloud.grid, vector);
  double mean_rho = 0.0;
  for (float rho : scalar.density) mean_rho += rho / static_cast<double>(scalar.size());
  for (std::size_t i = 0; i < scalar.size(); ++i) {
    expectClose(vector.density[i], scalar.density[i], scalar.density[i], 1e-5, "density", i);
    expectClose(vector.volume[i], scalar.volume[i], scalar.volume[i], 1e-5, "volume", i);
  }
  ASSERT_GT(mean_rho, 0.0);

  // Forces from the same densities, so only the force stage's own differences show.
  vector = scalar;
  sph::scalar::computeAccelerations(cloud.params, kernels, cloud.grid, scalar, true);
  form.accelerations(cloud.params, kernels, cloud.grid, vector, true);
  double mean_acc = 0.0, mean_normal = 0.0;
  std::size_t tension = 0, reached = 0;
  for (std::size_t i = 0; i < scalar.size(); ++i) {
    mean_acc += scalar.acceleration[i].norm() / static_cast<double>(scalar.size());
    mean_normal += scalar.normal_length[i] / static_cast<double>(scalar.size());
    tension += scalar.normal_length[i] >= cloud.params.surfaceThreshold();
    reached += std::isfinite(scalar.surface_hop[i]);
  }
  if (dense) {
    ASSERT_GT(tension, 10u);
    ASSERT_GT(reached, scalar.size() / 2);
  }
  for (std::size_t i = 0; i < scalar.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      expectClose(vector.acceleration[i][a], scalar.acceleration[i][a], mean_acc, 1e-4, "acceleration", i);
    }
    expectClose(vector.normal_length[i], scalar.normal_length[i], mean_normal, 1e-4, "|n|", i);
    if (std::isfinite(scalar.surface_hop[i])) {
      expectClose(vector.surface_hop[i], scalar.surface_hop[i], scalar.surface_hop[i], 1e-5, "surface hop", i);
    } else {
      EXPECT_EQ(vector.surface_hop[i], scalar.surface_hop[i]) << "particle " << i;
    }
  }
}

// Every vector form this CPU has against the scalar one, to the same tolerance.
void expectVectorMatchesScalar(const sph::SimParams& params, const CloudShape& shape = {}) {
  for (const StageForm& form : kVectorForms) {
    if (sph::simdAvailable(form.level)) expectFormMatchesScalar(form, params, shape);
  }
}

bool anyVectorForm() {
  return sph::simdAvailable(sph::SimdLevel::kAvx2) || sph::simdAvailable(sph::SimdLevel::kAvx512);
}

TEST(VectorStages, MatchTheScalarReference) {
  if (!anyVectorForm()) GTEST_SKIP() << "no vector form here: one form only";
  expectVectorMatchesScalar(sph::thesisPreset());
}

// A spray: many empty lists and lists shorter than a batch, so batches hold the ends of one list
// and the start of the next (and stop where a list is shorter than the rest of the batch), with
// pairs of particles on one point among them.
TEST(VectorStages, MatchTheScalarReferenceOnShortAndEmptyLists) {
  if (!anyVectorForm()) GTEST_SKIP() << "no vector form here: one form only";
  Cloud probe;
  makeCloud(probe, {1.2f, 0});
  std::size_t empty = 0, short_lists = 0;
  for (std::size_t i = 0; i < probe.particles.size(); ++i) {
    empty += probe.grid.neighborCount(i) == 0;
    short_lists += probe.grid.neighborCount(i) > 0 && probe.grid.neighborCount(i) < 8;
  }
  ASSERT_GT(empty, 50u);
  ASSERT_GT(short_lists, 200u);
  expectVectorMatchesScalar(sph::thesisPreset(), {1.2f, 40});
  expectVectorMatchesScalar(sph::thesisPreset(), {0.3f, 40});
}

// The vector stages tell the classes apart by mass where the masses differ, else by support.
TEST(VectorStages, MatchTheScalarReferenceWithEqualClassMasses) {
  if (!anyVectorForm()) GTEST_SKIP() << "no vector form here: one form only";
  sph::SimParams params = sph::thesisPreset();
  params.mass_large = params.mass_small;
  ASSERT_NE(params.levelProps()[0].support, params.levelProps()[1].support);
  expectVectorMatchesScalar(params);
}

}  // namespace

// The public stages are the dispatch point: they give exactly what the form simdLevel() names gives.
TEST(VectorStages, PublicStagesRunTheChosenForm) {
  Cloud cloud;
  makeCloud(cloud, {});
  const sph::KernelTable kernels = sph::makeKernelTable(cloud.params);
  sph::ParticleSet chosen = cloud.particles;
  sph::ParticleSet direct = cloud.particles;
  StageForm form{"scalar", sph::SimdLevel::kScalar, sph::scalar::computeDensityPressure,
                 sph::scalar::computeAccelerations};
  for (const StageForm& f : kVectorForms) {
    if (f.level == sph::simdLevel()) form = f;
  }
  sph::computeDensityPressure(cloud.params, kernels, cloud.grid, chosen);
  form.density(cloud.params, kernels, cloud.grid, direct);
  EXPECT_EQ(chosen.density, direct.density);
  sph::computeAccelerations(cloud.params, kernels, cloud.grid, chosen, true);
  form.accelerations(cloud.params, kernels, cloud.grid, direct, true);
  EXPECT_EQ(chosen.acceleration, direct.acceleration);
  EXPECT_EQ(chosen.surface_hop, direct.surface_hop);
}

TEST(SimdLevel, TheEnvironmentCanForceALowerFormButNotAMissingInstructionSet) {
  using sph::SimdLevel;
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kAvx512, nullptr), SimdLevel::kAvx512);
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kAvx512, ""), SimdLevel::kAvx512);
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kAvx512, "auto"), SimdLevel::kAvx512);
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kAvx512, "avx2"), SimdLevel::kAvx2);
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kAvx512, "scalar"), SimdLevel::kScalar);
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kAvx2, nullptr), SimdLevel::kAvx2);
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kAvx2, "avx512"), SimdLevel::kAvx2);
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kScalar, nullptr), SimdLevel::kScalar);
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kScalar, "avx512"), SimdLevel::kScalar);
  EXPECT_EQ(sph::chooseSimdLevel(SimdLevel::kScalar, "avx2"), SimdLevel::kScalar);
  EXPECT_THROW(sph::chooseSimdLevel(SimdLevel::kAvx512, "sse9"), std::invalid_argument);
  try {
    sph::chooseSimdLevel(SimdLevel::kAvx512, "AVX2");
    ADD_FAILURE() << "names are lower case";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("auto, avx512, avx2 or scalar"), std::string::npos) << e.what();
  }
  EXPECT_STREQ(sph::simdLevelName(SimdLevel::kAvx2), "avx2");
  EXPECT_TRUE(sph::simdAvailable(SimdLevel::kScalar));
  EXPECT_TRUE(sph::simdAvailable(sph::simdLevel()));
  // An AVX-512 CPU has AVX2 as well: the dispatch's order is the CPUs'.
  if (sph::simdAvailable(SimdLevel::kAvx512)) {
    EXPECT_TRUE(sph::simdAvailable(SimdLevel::kAvx2));
  }
}
