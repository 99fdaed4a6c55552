#include "mesh2d/planar_mesher.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "bisect/errors.hpp"
#include "geom/recentre.hpp"
#include "mesh2d/fill_region.hpp"
#include "mesh2d/prep_regions.hpp"
#include "mesh2d/quads.hpp"
#include "mesh2d/spacing.hpp"
#include "mesh2d/tri_quality.hpp"

namespace bisect::mesh2d {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// One meshing at spacing h: the boundary grid, then each region filled.
TriMesh2 mesh_once(const PlanarDomain& d, double h, double element_area, PlanarStats& st) {
  const auto t0 = Clock::now();
  BoundaryGrid g = discretise_boundaries(d, h);
  st.seconds_nodes += since(t0);
  TriMesh2 m;
  m.nodes = g.nodes;
  const std::size_t boundary_nodes = g.nodes.size();
  st.convex_pieces = 0;
  FillTimes times;
  for (std::size_t r = 0; r < d.regions.size(); ++r)
    st.convex_pieces += fill_region(m, g.loops[r], h, element_area, static_cast<Index>(r), &times);
  m.fixed.assign(m.nodes.size(), 0);
  for (std::size_t v = 0; v < boundary_nodes; ++v) m.fixed[v] = 1;  // input boundaries and interfaces
  st.seconds_nodes += times.nodes;
  st.seconds_triangulate += times.triangulate;
  return m;
}

}  // namespace

TriMesh2 mesh_planar(const Poly2Input& in, const PlanarOptions& opt, PlanarStats* stats) {
  const Vec2 shift = geom::recentring_shift(in.nodes);  // a part far from the origin: near it
  if (shift != Vec2::Zero()) {
    Poly2Input near = in;
    for (Vec2& p : near.nodes) p -= shift;
    TriMesh2 m = mesh_planar(near, opt, stats);
    for (Vec2& p : m.nodes) p += shift;
    return m;
  }
  const auto t0 = Clock::now();
  PlanarStats st;
  const PlanarDomain d = prepare_planar(in);
  const std::int64_t want = opt.elements > 0 ? opt.elements : d.required_elements;
  if (want <= 0) throw InputError(in.source + ": no required number of elements (give -n or the file's first line)");
  double element_area = d.area / static_cast<double>(want);
  double h = element_spacing(d.area, want);
  TriMesh2 m = mesh_once(d, h, element_area, st);
  // calibrate: the count goes with 1 / h^2; a few corrections, keeping the closest count
  for (int round = 0; round < 3; ++round) {
    const double ratio = static_cast<double>(m.tris.size()) / static_cast<double>(want);
    if (std::abs(ratio - 1) <= 0.05) break;
    h *= std::sqrt(ratio);
    element_area *= ratio;
    TriMesh2 again = mesh_once(d, h, element_area, st);
    const auto miss = [&](const TriMesh2& x) { return std::abs(static_cast<double>(x.tris.size()) - static_cast<double>(want)); };
    if (miss(again) < miss(m)) m = std::move(again);
  }
  const auto t2 = Clock::now();
  if (opt.optimize) optimize_planar(m);
  if (opt.quads) make_quads(m);
  st.seconds_optimize = since(t2);
  st.nodes = static_cast<std::int64_t>(m.nodes.size());
  st.triangles = static_cast<std::int64_t>(m.tris.size());
  st.quads = static_cast<std::int64_t>(m.quads.size());
  st.min_angle_deg = min_angle_deg(m);
  st.max_angle_deg = max_angle_deg(m);
  st.seconds_total = since(t0);
  if (stats) *stats = st;
  return m;
}

void write_tri_vtu(const TriMesh2& m, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot write");
  out.precision(17);
  const std::size_t cells = m.tris.size() + m.quads.size();
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << m.nodes.size() << "\" NumberOfCells=\"" << cells << "\">\n"
      << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec2& p : m.nodes) out << p.x() << ' ' << p.y() << " 0\n";
  out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& t : m.tris) out << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  for (const auto& q : m.quads) out << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << '\n';
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t off = 0;
  for (std::size_t i = 0; i < m.tris.size(); ++i) out << (off += 3) << '\n';
  for (std::size_t i = 0; i < m.quads.size(); ++i) out << (off += 4) << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < m.tris.size(); ++i) out << "5\n";
  for (std::size_t i = 0; i < m.quads.size(); ++i) out << "9\n";
  out << "</DataArray>\n</Cells>\n<CellData Scalars=\"region\">\n<DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n";
  for (Index r : m.tri_region) out << r + 1 << '\n';
  for (Index r : m.quad_region) out << r + 1 << '\n';
  out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  if (!out) throw InputError(path + ": write failed");
}

std::string planar_stats_json(const PlanarStats& s) {
  std::ostringstream o;
  o << "{\"nodes\": " << s.nodes << ", \"triangles\": " << s.triangles << ", \"quads\": " << s.quads
    << ", \"convex_pieces\": " << s.convex_pieces << ", \"min_angle\": " << s.min_angle_deg << ", \"max_angle\": " << s.max_angle_deg
    << ", \"times\": {\"nodes\": " << s.seconds_nodes << ", \"triangulate\": " << s.seconds_triangulate
    << ", \"optimize\": " << s.seconds_optimize << ", \"total\": " << s.seconds_total << "}}";
  return o.str();
}

}  // namespace bisect::mesh2d
