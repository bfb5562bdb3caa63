// Checkpoint and restart: the whole state a step reads (every particle attribute of
// kParticleAttributes, the id counter, the step count, whether the surface distance field
// advances) in one binary file, so that a run restarted from it continues exactly as the
// uninterrupted run would have, bit for bit. What a step recomputes from scratch (the neighbour
// grid, the solvers' scratch) is not stored.
//
// File layout (host byte order, x86-64 little-endian): the magic "GSPHCKPT", u32 format version,
// the scene name, preset and method (u32 length + bytes each), f64 frame time step, i64 steps,
// u8 surface-distance tracking, u32 next id, u64 particle count, u32 attribute count, then per
// attribute its name, u32 element size and the raw values; last a u64 FNV-1a hash of everything
// before it.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace sph {

class Simulation;

class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What a checkpoint says about the run it came from.
struct CheckpointInfo {
  std::string scene;
  std::string preset;
  std::string method;
  std::int64_t steps = 0;
  std::uint64_t particles = 0;
};

// Writes `sim`'s state to `path` (through a temporary file renamed into place, so a crash never
// leaves half a checkpoint under that name). Throws CheckpointError when it cannot.
void saveCheckpoint(const Simulation& sim, const std::string& method, const std::string& path);

// Replaces `sim`'s state with the checkpoint's. The file must come from the same scene, preset,
// method and time step as `sim` (the particles alone do not say how to step them); any mismatch,
// a truncated or corrupted file, or values no simulation could hold (an unknown size class, a
// non-finite position) throw CheckpointError naming the file and the reason, and `sim` is left
// exactly as it was.
CheckpointInfo loadCheckpoint(Simulation& sim, const std::string& method, const std::string& path);

}  // namespace sph
