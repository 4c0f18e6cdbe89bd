#include "driver/snapshot_writer.hpp"

#include "driver/outputs.hpp"

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace epac {
namespace driver {

namespace {

template <class V>
void data_array(std::ostringstream& o, const char* type, const std::string& name, int components, const V& values) {
  o << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\"";
  if (components > 1) o << " NumberOfComponents=\"" << components << "\"";
  o << " format=\"ascii\">\n          ";
  for (std::size_t k = 0; k < values.size(); ++k) o << (k ? " " : "") << values[k];
  o << "\n        </DataArray>\n";
}

}  // namespace

std::string vtp_text(const ParticleSnapshot& s) {
  const std::size_t n = s.radius.size();
  std::ostringstream o;
  o << std::setprecision(10);
  o << "<?xml version=\"1.0\"?>\n"
    << "<!-- epac-run particle snapshot: step " << s.step << ", time " << s.time << " s; SI units -->\n"
    << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
    << "  <PolyData>\n"
    << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
    << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
    << "      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
  data_array(o, "Float64", "radius", 1, s.radius);    // m
  data_array(o, "Float64", "radius0", 1, s.radius0);  // m
  data_array(o, "Int64", "id", 1, s.id);
  data_array(o, "Int32", "material", 1, s.material);
  data_array(o, "Float64", "velocity", 3, s.v);              // m/s
  data_array(o, "Float64", "angular_velocity", 3, s.omega);  // rad/s
  data_array(o, "Float64", "contact_force", 3, s.force);     // N
  for (const auto& e : s.extras) data_array(o, "Float64", e.first, 1, e.second);
  o << "      </PointData>\n"
    << "      <Points>\n";
  // absolute positions round-trip (see ParticlesWriter)
  o << std::setprecision(std::numeric_limits<double>::max_digits10);
  data_array(o, "Float64", "position", 3, s.x);  // m
  o << std::setprecision(10);
  o << "      </Points>\n"
    << "      <Verts>\n";
  std::vector<std::int64_t> conn(n), offs(n);
  for (std::size_t k = 0; k < n; ++k) {
    conn[k] = static_cast<std::int64_t>(k);
    offs[k] = static_cast<std::int64_t>(k + 1);
  }
  data_array(o, "Int64", "connectivity", 1, conn);
  data_array(o, "Int64", "offsets", 1, offs);
  o << "      </Verts>\n"
    << "    </Piece>\n"
    << "  </PolyData>\n"
    << "</VTKFile>\n";
  return o.str();
}

SnapshotWriter::SnapshotWriter(const std::string& out_dir) : dir_(out_dir), pvd_path_(out_dir + "/particles.pvd") {
  std::error_code ec;
  std::filesystem::create_directories(out_dir + "/snapshots", ec);
  if (ec) throw std::runtime_error("cannot create '" + out_dir + "/snapshots': " + ec.message());
}

void SnapshotWriter::write(const ParticleSnapshot& s) {
  char name[64];
  std::snprintf(name, sizeof name, "snapshots/particles_%012lld.vtp", static_cast<long long>(s.step));
  write_file_atomic(dir_ + "/" + name, vtp_text(s));  // whole or absent
  series_.emplace_back(s.time, name);
  std::ostringstream o;
  o << std::setprecision(17);
  o << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <Collection>\n";
  for (const auto& e : series_)
    o << "    <DataSet timestep=\"" << e.first << "\" group=\"\" part=\"0\" file=\"" << e.second << "\"/>\n";
  o << "  </Collection>\n"
    << "</VTKFile>\n";
  write_file_atomic(pvd_path_, o.str());  // rewritten each time: valid after every snapshot
}

}  // namespace driver
}  // namespace epac
