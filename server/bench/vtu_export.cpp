#include "bench/vtu_export.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace bench {
namespace {

// The appended section is one block per array: a UInt64 byte count, then the bytes (little endian,
// as x86-64 writes them; the header says so).
class AppendedData {
 public:
  // Returns the array's offset within the appended section, for its DataArray element.
  template <typename T>
  std::uint64_t add(const std::vector<T>& values) {
    return addBytes(values.data(), values.size() * sizeof(T));
  }
  std::uint64_t addBytes(const void* data, std::uint64_t size) {
    const std::uint64_t offset = bytes_.size();
    const auto* count = reinterpret_cast<const char*>(&size);
    bytes_.insert(bytes_.end(), count, count + sizeof size);
    const auto* begin = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), begin, begin + size);
    return offset;
  }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  std::vector<char> bytes_;
};

std::vector<float> flatten(const std::vector<sph::Vec3>& v) {
  std::vector<float> out(3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (int k = 0; k < 3; ++k) out[3 * i + k] = static_cast<float>(v[i][k]);
  }
  return out;
}

std::string dataArray(const char* type, const char* name, int components, std::uint64_t offset) {
  std::ostringstream s;
  s << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
    << "\" format=\"appended\" offset=\"" << offset << "\"/>\n";
  return s.str();
}

std::string xmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') {
      out += "&amp;";
    } else if (c == '"') {
      out += "&quot;";
    } else if (c == '<') {
      out += "&lt;";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

void writeVtu(const sph::ParticleSet& p, double time, const std::string& path) {
  const std::size_t n = p.size();
  AppendedData data;
  const std::vector<double> time_value{time};
  const std::uint64_t o_time = data.add(time_value);
  const std::uint64_t o_points = data.add(flatten(p.position));
  std::vector<std::int32_t> connectivity(n), offsets(n);  // Int32: half the bytes of Int64, ample for a particle set
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int32_t>(i);
    offsets[i] = static_cast<std::int32_t>(i + 1);
  }
  const std::vector<std::uint8_t> types(n, 1);  // VTK_VERTEX
  const std::uint64_t o_conn = data.add(connectivity);
  const std::uint64_t o_offsets = data.add(offsets);
  const std::uint64_t o_types = data.add(types);
  const std::uint64_t o_velocity = data.add(flatten(p.velocity));
  const std::uint64_t o_density = data.add(p.density);
  const std::uint64_t o_pressure = data.add(p.pressure);
  const std::uint64_t o_mass = data.add(p.mass);
  const std::uint64_t o_radius = data.add(p.radius);
  std::vector<std::uint8_t> level(n);
  for (std::size_t i = 0; i < n; ++i) level[i] = static_cast<std::uint8_t>(p.level[i]);
  const std::uint64_t o_level = data.add(level);
  const std::uint64_t o_id = data.add(p.id);

  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      << "<UnstructuredGrid>\n<FieldData>\n"
      << "<DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"appended\" offset=\"" << o_time
      << "\"/>\n</FieldData>\n"
      << "<Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n"
      << "<Points>\n"
      << dataArray("Float32", "position", 3, o_points) << "</Points>\n"
      << "<Cells>\n"
      << dataArray("Int32", "connectivity", 1, o_conn) << dataArray("Int32", "offsets", 1, o_offsets)
      << dataArray("UInt8", "types", 1, o_types) << "</Cells>\n"
      << "<PointData Scalars=\"density\" Vectors=\"velocity\">\n"
      << dataArray("Float32", "velocity", 3, o_velocity) << dataArray("Float32", "density", 1, o_density)
      << dataArray("Float32", "pressure", 1, o_pressure) << dataArray("Float32", "mass", 1, o_mass)
      << dataArray("Float32", "radius", 1, o_radius) << dataArray("UInt8", "level", 1, o_level)
      << dataArray("UInt32", "id", 1, o_id) << "</PointData>\n"
      << "</Piece>\n</UnstructuredGrid>\n"
      << "<AppendedData encoding=\"raw\">\n_";
  out.write(data.bytes().data(), static_cast<std::streamsize>(data.bytes().size()));
  out << "\n</AppendedData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("cannot write " + path);
}

void PvdIndex::add(double time, const std::string& file) { entries_.emplace_back(time, file); }

void PvdIndex::write() const {
  std::ofstream out(path_);
  if (!out) throw std::runtime_error("cannot write " + path_);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [time, file] : entries_) {
    out << "<DataSet timestep=\"" << std::setprecision(12) << time << "\" part=\"0\" file=\"" << xmlEscape(file)
        << "\"/>\n";
  }
  out << "</Collection>\n</VTKFile>\n";
}

}  // namespace bench
