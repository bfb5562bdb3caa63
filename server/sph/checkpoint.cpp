#include "sph/checkpoint.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <type_traits>
#include <vector>

#include "sph/simulation.h"

namespace sph {
namespace {

constexpr char kMagic[8] = {'G', 'S', 'P', 'H', 'C', 'K', 'P', 'T'};
// 2: without the attribute pbf_lambda (written, never read).
constexpr std::uint32_t kFormatVersion = 2;
// A name in the header longer than this is corruption, not a scene.
constexpr std::uint32_t kMaxNameBytes = 4096;

std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;
  }
  return h;
}

// Stored as raw bytes: plain values, and Eigen's fixed-size vectors (three floats, no padding, but
// with user-declared copy constructors, so not "trivially copyable" to the standard's trait).
template <typename T>
inline constexpr bool kRawBytes = std::is_trivially_copyable_v<T> || std::is_same_v<T, Vec3>;
static_assert(sizeof(Vec3) == 3 * sizeof(float));

class Writer {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void putString(const std::string& s) {
    put(static_cast<std::uint32_t>(s.size()));
    bytes_ += s;
  }
  template <typename T>
  void putValues(const std::vector<T>& v) {
    static_assert(kRawBytes<T>);
    bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

// Reads from a buffer; every read past its end is a truncated file.
class Reader {
 public:
  Reader(std::string_view bytes, const std::string& path) : bytes_(bytes), path_(path) {}
  template <typename T>
  T get() {
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  std::string getString() {
    const auto n = get<std::uint32_t>();
    if (n > kMaxNameBytes) fail("a name of " + std::to_string(n) + " bytes (corrupted?)");
    return std::string(take(n), n);
  }
  const char* take(std::size_t n) {
    if (n > bytes_.size() - at_) fail("truncated");
    const char* p = bytes_.data() + at_;
    at_ += n;
    return p;
  }
  bool atEnd() const { return at_ == bytes_.size(); }
  [[noreturn]] void fail(const std::string& why) const { throw CheckpointError(path_ + ": " + why); }

 private:
  std::string_view bytes_;
  const std::string& path_;
  std::size_t at_ = 0;
};

void requireSame(const Reader& in, const char* what, const std::string& file_value, const std::string& run_value) {
  if (file_value != run_value) {
    in.fail(std::string("saved with ") + what + " '" + file_value + "', this run uses '" + run_value + "'");
  }
}

// Vectors (position, velocity, acceleration) are finite in any state a step leaves; some scalars
// are infinite by design (surface_distance before the surface is reached).
template <typename T>
bool allFinite(const std::vector<T>& v) {
  if constexpr (std::is_same_v<T, Vec3>) {
    for (const Vec3& x : v) {
      if (!x.allFinite()) return false;
    }
  }
  return true;
}

}  // namespace

void saveCheckpoint(const Simulation& sim, const std::string& method, const std::string& path) {
  const ParticleSet& p = sim.particles();
  Writer out;
  out.bytes().append(kMagic, sizeof(kMagic));
  out.put(kFormatVersion);
  out.putString(sim.scene().name);
  out.putString(sim.params().preset);
  out.putString(method);
  out.put(sim.params().time_step);
  out.put(static_cast<std::int64_t>(sim.stepCount()));
  out.put(static_cast<std::uint8_t>(sim.surfaceDistanceTracking() ? 1 : 0));
  out.put(p.nextId());
  out.put(static_cast<std::uint64_t>(p.size()));
  out.put(static_cast<std::uint32_t>(std::tuple_size_v<std::decay_t<decltype(kParticleAttributes)>>));
  p.forEachAttributeSpec([&](const auto& values, const auto& spec) {
    out.putString(spec.name);
    out.put(static_cast<std::uint32_t>(sizeof(typename std::decay_t<decltype(spec)>::Value)));
    out.putValues(values);
  });
  out.put(fnv1a(out.bytes()));

  const std::string temporary = path + ".partial";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(out.bytes().data(), static_cast<std::streamsize>(out.bytes().size()));
    file.close();
    if (!file) throw CheckpointError(path + ": cannot write (" + std::strerror(errno) + ")");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw CheckpointError(path + ": cannot write (" + ec.message() + ")");
  }
}

CheckpointInfo loadCheckpoint(Simulation& sim, const std::string& method, const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw CheckpointError(path + ": cannot open (" + std::strerror(errno) + ")");
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (bytes.size() < sizeof(kMagic) + sizeof(std::uint64_t) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic))) {
    throw CheckpointError(path + ": not a checkpoint file");
  }
  const std::string_view body(bytes.data(), bytes.size() - sizeof(std::uint64_t));
  std::uint64_t stored_hash = 0;
  std::memcpy(&stored_hash, bytes.data() + body.size(), sizeof(stored_hash));
  if (fnv1a(body) != stored_hash) throw CheckpointError(path + ": checksum mismatch (corrupted or truncated)");

  Reader in(body, path);
  in.take(sizeof(kMagic));
  const auto version = in.get<std::uint32_t>();
  if (version != kFormatVersion) {
    in.fail("format version " + std::to_string(version) + ", this program reads " + std::to_string(kFormatVersion));
  }
  CheckpointInfo info;
  info.scene = in.getString();
  info.preset = in.getString();
  info.method = in.getString();
  requireSame(in, "scene", info.scene, sim.scene().name);
  requireSame(in, "preset", info.preset, sim.params().preset);
  requireSame(in, "method", info.method, method);
  if (in.get<double>() != sim.params().time_step) in.fail("saved with another time step");
  info.steps = in.get<std::int64_t>();
  if (info.steps < 0) in.fail("negative step count");
  const auto tracking = in.get<std::uint8_t>();
  if (tracking > 1) in.fail("corrupted surface-distance flag");
  const auto next_id = in.get<std::uint32_t>();
  info.particles = in.get<std::uint64_t>();
  ParticleSet& live = sim.particles();
  if (info.particles > live.capacity()) {
    in.fail(std::to_string(info.particles) + " particles, more than this run's capacity of " +
            std::to_string(live.capacity()));
  }
  const auto attribute_count = in.get<std::uint32_t>();
  if (attribute_count != std::tuple_size_v<std::decay_t<decltype(kParticleAttributes)>>) {
    in.fail("saved with " + std::to_string(attribute_count) + " particle attributes, this program has " +
            std::to_string(std::tuple_size_v<std::decay_t<decltype(kParticleAttributes)>>));
  }

  // Everything is read and checked into a copy first: a bad file leaves the simulation untouched.
  ParticleSet restored(live.capacity());
  restored.forEachAttributeSpec([&](auto& values, const auto& spec) {
    using T = typename std::decay_t<decltype(spec)>::Value;
    static_assert(kRawBytes<T>);
    const std::string name = in.getString();
    if (name != spec.name) in.fail("attribute '" + name + "' where '" + spec.name + "' belongs");
    if (in.get<std::uint32_t>() != sizeof(T)) in.fail(std::string("attribute '") + spec.name + "' has another size");
    values.resize(info.particles);
    std::memcpy(static_cast<void*>(values.data()), in.take(info.particles * sizeof(T)), info.particles * sizeof(T));
    if (!allFinite(values)) in.fail(std::string("attribute '") + spec.name + "' holds a non-finite value");
  });
  if (!in.atEnd()) in.fail("unexpected bytes after the last attribute");
  const auto classes = sim.params().levelProps();
  for (std::size_t i = 0; i < restored.size(); ++i) {
    if (levelIndex(restored.level[i]) >= sim.params().levels) {
      in.fail("particle " + std::to_string(i) + " has level " + std::to_string(levelIndex(restored.level[i])) +
              ", past this run's " + std::to_string(sim.params().levels) + " levels");
    }
    if (restored.id[i] >= next_id) in.fail("particle id " + std::to_string(restored.id[i]) + " beyond the id counter");
    // The solvers take a particle's mass and support from its class (pair_kernels.h): a file from a
    // scene of other particle counts (the same name, another mass) would not match them.
    const LevelProps& props = classes[levelIndex(restored.level[i])];
    if (restored.mass[i] != static_cast<float>(props.mass) ||
        restored.support[i] != static_cast<float>(props.support)) {
      in.fail("particle " + std::to_string(i) +
              " has another mass or support than its level has here (saved from "
              "a scene with other particle counts?)");
    }
  }
  restored.setNextId(next_id);
  sim.restore(std::move(restored), info.steps, tracking == 1);
  return info;
}

}  // namespace sph
