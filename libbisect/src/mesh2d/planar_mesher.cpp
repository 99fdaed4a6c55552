#include "mesh2d/planar_mesher.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "bisect/errors.hpp"
#include "geom/recentre.hpp"
#include "io/file_paths.hpp"
#include "mesh2d/fill_region.hpp"
#include "mesh2d/planar_failure.hpp"
#include "mesh2d/prep_regions.hpp"
#include "mesh2d/quads.hpp"
#include "mesh2d/spacing.hpp"
#include "mesh2d/tri_quality.hpp"

namespace bisect::mesh2d {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// One meshing at spacing h: the boundary grid, then each region filled.
TriMesh2 mesh_once(const Poly2Input& in, const PlanarDomain& d, double h, double element_area, PlanarStats& st, const Vec2& shift) {
  const auto t0 = Clock::now();
  BoundaryGrid g = discretise_boundaries(d, h);
  st.seconds_nodes += since(t0);
  TriMesh2 m;
  m.nodes = g.nodes;
  const std::size_t boundary_nodes = g.nodes.size();
  st.convex_pieces = 0;
  FillTimes times;
  for (std::size_t r = 0; r < d.regions.size(); ++r) {
    try {
      st.convex_pieces += fill_region(m, g.loops[r], h, element_area, static_cast<Index>(r), &times);
    } catch (const PlanarFailure& e) {
      throw placed_failure(in, r, e, shift);
    }
  }
  m.fixed.assign(m.nodes.size(), 0);
  for (std::size_t v = 0; v < boundary_nodes; ++v) m.fixed[v] = 1;  // input boundaries and interfaces
  st.seconds_nodes += times.nodes;
  st.seconds_triangulate += times.triangulate;
  return m;
}

// The planar mesher on an input already near the origin; the input was moved by -shift (messages
// give the input's own coordinates).
TriMesh2 mesh_near_origin(const Poly2Input& in, const PlanarOptions& opt, PlanarStats* stats, const Vec2& shift) {
  const auto t0 = Clock::now();
  PlanarStats st;
  const PlanarDomain d = prepare_planar(in);
  const std::int64_t want = opt.elements > 0 ? opt.elements : d.required_elements;
  if (want <= 0) throw InputError(in.source + ": no required number of elements (give -n or the file's first line)");
  double element_area = d.area / static_cast<double>(want);
  double h = element_spacing(d.area, want);
  TriMesh2 m = mesh_once(in, d, h, element_area, st, shift);
  // calibrate: the count goes with 1 / h^2; a few corrections, keeping the closest count
  for (int round = 0; round < 3; ++round) {
    const double ratio = static_cast<double>(m.tris.size()) / static_cast<double>(want);
    if (std::abs(ratio - 1) <= 0.05) break;
    h *= std::sqrt(ratio);
    element_area *= ratio;
    TriMesh2 again = mesh_once(in, d, h, element_area, st, shift);
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

}  // namespace

MeshingError placed_failure(const Poly2Input& in, std::size_t r, const PlanarFailure& e, const Vec2& shift) {
  const PlanarDomain d = prepare_planar(in);
  const PlanarRegion& reg = d.regions.at(r);
  std::ostringstream msg;
  msg.precision(9);
  msg << in.source << ": polygon " << reg.polygon + 1;
  if (e.loop > 0 && static_cast<std::size_t>(e.loop) < reg.loop_polygon.size())
    msg << " around polygon " << reg.loop_polygon[e.loop] + 1 << (in.polygons[reg.loop_polygon[e.loop]].hole ? " (a hole)" : " (a sub-domain)");
  const Vec2 at = e.where + shift;
  // nine digits of the part's own size, however far from the origin it lies
  const double scale = std::sqrt(std::max(d.area, 1e-300)), far = at.lpNorm<Eigen::Infinity>();
  msg.precision(9 + static_cast<int>(std::clamp(std::ceil(std::log10(std::max(far / scale, 1.0))), 0.0, 8.0)));
  msg << ": " << e.what() << ", near (" << at.x() << ", " << at.y() << ")";
  return MeshingError(msg.str());
}

TriMesh2 mesh_planar(const Poly2Input& in, const PlanarOptions& opt, PlanarStats* stats) {
  const Vec2 shift = geom::recentring_shift(in.nodes);  // a part far from the origin: near it
  if (shift == Vec2::Zero()) return mesh_near_origin(in, opt, stats, shift);
  Poly2Input near = in;
  for (Vec2& p : near.nodes) p -= shift;
  TriMesh2 m = mesh_near_origin(near, opt, stats, shift);
  for (Vec2& p : m.nodes) p += shift;
  return m;
}


void write_tri_vtu(const TriMesh2& m, const std::string& path) {
  io::write_output_file(path, [&](std::ostream& out) {
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
  });
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
