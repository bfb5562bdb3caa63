// Particle snapshots for ParaView: VTK XML UnstructuredGrid files (.vtu) with the arrays appended as
// raw binary (a tenth of the ASCII legacy file, and read without parsing), plus a .pvd index that
// gives each file its simulation time so ParaView plays the run as a time series.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sph/particles.h"

namespace bench {

// One .vtu: points = positions, one vertex cell per particle, point data velocity, density,
// pressure, mass, radius, level (0 for L0, the finest), id; `time` in the file's field data.
void writeVtu(const sph::ParticleSet& particles, double time, const std::string& path);

// The .pvd index of a run's snapshots. write() rewrites the whole file each time, so the index is
// complete whenever a run stops (an interrupted run included).
class PvdIndex {
 public:
  explicit PvdIndex(std::string path) : path_(std::move(path)) {}
  // `file` relative to the index's folder.
  void add(double time, const std::string& file);
  void write() const;

 private:
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace bench
