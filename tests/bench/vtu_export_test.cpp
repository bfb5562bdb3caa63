// The ParaView export: a .vtu whose appended binary arrays read back to the particles written, and a
// .pvd index that lists every snapshot with its time. Reads the files the way a VTK reader does
// (offsets into the appended section, a UInt64 byte count before each array).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "bench/bench_output.h"
#include "bench/vtu_export.h"

namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The bytes of the array `name` (its DataArray element's offset into the appended section).
std::string arrayBytes(const std::string& file, const std::string& name) {
  const auto element = file.find("Name=\"" + name + "\"");
  if (element == std::string::npos) return "missing";
  const auto offset_at = file.find("offset=\"", element) + 8;
  const std::uint64_t offset = std::stoull(file.substr(offset_at, file.find('"', offset_at) - offset_at));
  const auto data = file.find("<AppendedData encoding=\"raw\">\n_") + std::strlen("<AppendedData encoding=\"raw\">\n_");
  std::uint64_t size = 0;
  std::memcpy(&size, file.data() + data + offset, sizeof size);
  return file.substr(data + offset + sizeof size, size);
}

template <typename T>
std::vector<T> values(const std::string& bytes) {
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

sph::ParticleSet threeParticles() {
  sph::ParticleSet p;
  p.id = {7, 8, 9};
  p.level = {sph::Level{0}, sph::Level{1}, sph::Level{0}};
  p.mass = {0.5f, 1.0f, 0.5f};
  p.radius = {0.01f, 0.0126f, 0.01f};
  p.position = {{0.1f, 0.2f, 0.3f}, {0.4f, 0.5f, 0.6f}, {0.7f, 0.8f, 0.9f}};
  p.velocity = {{1.0f, 0.0f, 0.0f}, {0.0f, -2.0f, 0.0f}, {0.0f, 0.0f, 3.0f}};
  p.density = {1000.0f, 1010.0f, 990.0f};
  p.pressure = {10.0f, 110.0f, -5.0f};
  return p;
}

std::string scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("sph_vtu_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

TEST(VtuExport, ArraysReadBackAsWritten) {
  const sph::ParticleSet p = threeParticles();
  const std::string path = scratch("p.vtu");
  bench::writeVtu(p, 1.25, path);
  const std::string file = readAll(path);
  EXPECT_NE(file.find("NumberOfPoints=\"3\" NumberOfCells=\"3\""), std::string::npos);
  EXPECT_EQ(values<double>(arrayBytes(file, "TimeValue")), std::vector<double>{1.25});
  const auto position = values<float>(arrayBytes(file, "position"));
  ASSERT_EQ(position.size(), 9u);
  EXPECT_FLOAT_EQ(position[3], 0.4f);
  EXPECT_FLOAT_EQ(position[8], 0.9f);
  const auto velocity = values<float>(arrayBytes(file, "velocity"));
  ASSERT_EQ(velocity.size(), 9u);
  EXPECT_FLOAT_EQ(velocity[4], -2.0f);
  EXPECT_EQ(values<float>(arrayBytes(file, "density")), p.density);
  EXPECT_EQ(values<float>(arrayBytes(file, "pressure")), p.pressure);
  EXPECT_EQ(values<float>(arrayBytes(file, "mass")), p.mass);
  EXPECT_EQ(values<float>(arrayBytes(file, "radius")), p.radius);
  EXPECT_EQ(values<std::uint8_t>(arrayBytes(file, "level")), (std::vector<std::uint8_t>{0, 1, 0}));
  EXPECT_EQ(values<std::uint32_t>(arrayBytes(file, "id")), p.id);
  // One vertex cell per particle, so ParaView shows the points without a Glyph filter.
  EXPECT_EQ(values<std::int32_t>(arrayBytes(file, "connectivity")), (std::vector<std::int32_t>{0, 1, 2}));
  EXPECT_EQ(values<std::int32_t>(arrayBytes(file, "offsets")), (std::vector<std::int32_t>{1, 2, 3}));
  EXPECT_EQ(values<std::uint8_t>(arrayBytes(file, "types")), (std::vector<std::uint8_t>{1, 1, 1}));
  EXPECT_NE(file.rfind("</VTKFile>\n"), std::string::npos);
}

TEST(VtuExport, PvdListsEverySnapshotWithItsTime) {
  const std::string path = scratch("run.pvd");
  bench::PvdIndex index(path);
  index.add(0.0, "particles_00000.vtu");
  index.write();
  index.add(0.5, "particles_00050.vtu");
  index.write();  // rewritten whole: complete after every snapshot
  const std::string file = readAll(path);
  const auto first = file.find("timestep=\"0\" part=\"0\" file=\"particles_00000.vtu\"");
  const auto second = file.find("timestep=\"0.5\" part=\"0\" file=\"particles_00050.vtu\"");
  ASSERT_NE(first, std::string::npos) << file;
  ASSERT_NE(second, std::string::npos) << file;
  EXPECT_LT(first, second);
  EXPECT_NE(file.find("type=\"Collection\""), std::string::npos);
}

}  // namespace

namespace {

// The fields a snapshot file carries, by name: the VTU's DataArray names, the legacy VTK's POINTS
// (position) and VECTORS / SCALARS, the CSV's header (x, y, z as position; vx, vy, vz as velocity).
std::set<std::string> fieldsOf(const std::string& file, bench::SnapshotFormat format) {
  std::set<std::string> fields;
  const std::string text = readAll(file);
  std::istringstream lines(text);
  std::string line;
  if (format == bench::SnapshotFormat::Csv) {
    std::getline(lines, line);
    std::istringstream header(line);
    for (std::string name; std::getline(header, name, ',');) {
      if (name == "x" || name == "y" || name == "z") name = "position";
      if (name == "vx" || name == "vy" || name == "vz") name = "velocity";
      fields.insert(name);
    }
    return fields;
  }
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string first, name;
    words >> first >> name;
    if (first == "POINTS") fields.insert("position");
    if (first == "VECTORS" || first == "SCALARS") fields.insert(name);
    for (std::size_t at = line.find("Name=\""); at != std::string::npos; at = line.find("Name=\"", at + 1)) {
      const std::size_t from = at + 6;
      const std::string array = line.substr(from, line.find('"', from) - from);
      // The cells' arrays and the time are the file's structure, not particle fields.
      if (array != "TimeValue" && array != "connectivity" && array != "offsets" && array != "types") {
        fields.insert(array);
      }
    }
  }
  return fields;
}

}  // namespace

TEST(SnapshotFormats, AllThreeCarryTheSameFieldsAndTheClassAsANumber) {
  const sph::ParticleSet p = threeParticles();
  const std::string vtu = scratch("fields.vtu"), vtk = scratch("fields.vtk"), csv = scratch("fields.csv");
  bench::writeVtu(p, 0.0, vtu);
  bench::writeSnapshot(p, bench::SnapshotFormat::Vtk, vtk);
  bench::writeSnapshot(p, bench::SnapshotFormat::Csv, csv);
  const std::set<std::string> expected = {"position", "velocity", "density", "pressure",
                                          "mass",     "radius",   "level",   "id"};
  EXPECT_EQ(fieldsOf(vtu, bench::SnapshotFormat::Vtu), expected);
  EXPECT_EQ(fieldsOf(vtk, bench::SnapshotFormat::Vtk), expected);
  EXPECT_EQ(fieldsOf(csv, bench::SnapshotFormat::Csv), expected);
  std::istringstream rows(readAll(csv));
  std::string header, second_row;
  std::getline(rows, header);
  std::getline(rows, second_row);
  std::getline(rows, second_row);  // the L1 particle
  EXPECT_EQ(second_row.substr(second_row.rfind(',') + 1), "1") << second_row;
}
