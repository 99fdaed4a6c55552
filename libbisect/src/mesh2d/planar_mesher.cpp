#include "mesh2d/planar_mesher.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "bisect/errors.hpp"
#include "mesh2d/bisect2d.hpp"
#include "mesh2d/convex_decompose.hpp"
#include "mesh2d/prep_regions.hpp"
#include "mesh2d/quads.hpp"
#include "mesh2d/shrink_nodes.hpp"
#include "mesh2d/smooth.hpp"
#include "mesh2d/spacing.hpp"
#include "mesh2d/swap.hpp"
#include "mesh2d/tri_quality.hpp"

namespace bisect::mesh2d {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

TriMesh2 mesh_once(const PlanarDomain& d, double h, double element_area, PlanarStats& st) {
  const auto t0 = Clock::now();
  BoundaryGrid g = discretise_boundaries(d, h);
  TriMesh2 m;
  m.nodes = g.nodes;
  const std::size_t boundary_nodes = g.nodes.size();
  std::vector<std::pair<std::vector<Index>, std::vector<Index>>> pieces;  // loop, inside
  std::vector<Index> piece_region;
  for (std::size_t r = 0; r < d.regions.size(); ++r)
    for (auto& loop : convex_pieces(m.nodes, g.loops[r], h)) {
      std::vector<Vec2> poly;
      for (Index v : loop) poly.push_back(m.nodes[v]);
      std::vector<Index> inside;
      for (const Vec2& p : shrink_nodes(poly, h, element_area)) {
        m.nodes.push_back(p);
        inside.push_back(static_cast<Index>(m.nodes.size() - 1));
      }
      pieces.push_back({std::move(loop), std::move(inside)});
      piece_region.push_back(static_cast<Index>(r));
    }
  st.convex_pieces = static_cast<std::int64_t>(pieces.size());
  st.seconds_nodes += since(t0);
  const auto t1 = Clock::now();
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    bisection_triangulate(m.nodes, pieces[p].first, pieces[p].second, m.tris);
    m.tri_region.resize(m.tris.size(), piece_region[p]);
  }
  m.fixed.assign(m.nodes.size(), 0);
  for (std::size_t v = 0; v < boundary_nodes; ++v) m.fixed[v] = 1;  // input boundaries and interfaces
  st.seconds_triangulate += since(t1);
  return m;
}

}  // namespace

TriMesh2 mesh_planar(const Poly2Input& in, const PlanarOptions& opt, PlanarStats* stats) {
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
  if (opt.optimize) {  // swaps and smoothing in turn (4.4): each opens moves for the other
    for (int round = 0; round < 3; ++round) {
      swap_edges(m);
      smooth_laplace(m, {3});
    }
    swap_edges(m);
  }
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
