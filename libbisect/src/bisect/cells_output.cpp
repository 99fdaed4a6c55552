// The convex cells as a thesis .poly file (6.13) and the decomposition's statistics as JSON.
#include <fstream>
#include <iomanip>
#include <sstream>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "bisect/polyhedral_model.hpp"
#include "io/file_paths.hpp"

namespace bisect {

void write_cells_poly(const Decomposition& d, const std::string& path) {
  const PolyhedralModel& m = d.model;
  std::unordered_map<Index, Index> node_id, face_id;  // model -> 1-based file numbers
  std::vector<Index> node_order;
  std::vector<std::vector<Index>> file_faces;          // loops as separate faces (holes inside)
  std::vector<std::vector<Index>> cell_faces(d.cells.size());
  for (std::size_t c = 0; c < d.cells.size(); ++c)
    for (Index f : d.cells[c].faces) {
      auto it = face_id.find(f);
      if (it == face_id.end()) {
        it = face_id.emplace(f, static_cast<Index>(file_faces.size())).first;
        for (const auto& loop : m.faces[f].loops) {
          file_faces.push_back(loop);
          for (Index v : loop)
            if (node_id.emplace(v, static_cast<Index>(node_order.size()) + 1).second) node_order.push_back(v);
        }
      }
      const std::size_t loops = m.faces[f].loops.size();
      for (std::size_t l = 0; l < loops; ++l) cell_faces[c].push_back(it->second + static_cast<Index>(l) + 1);
    }
  io::write_output_file(path, [&](std::ostream& out) {
    out << std::setprecision(17);
    out << "-- convex cells of " << m.source << " by BisectMesh: one region per cell; a face with a\n"
        << "-- hole is followed by the hole as a face lying inside it (thesis 6.13)\n";
    out << file_faces.size() << ' ' << node_order.size() << ' ' << d.cells.size() << " 0\n";
    for (Index v : node_order) out << m.nodes[v].x() << ' ' << m.nodes[v].y() << ' ' << m.nodes[v].z() << '\n';
    for (const auto& loop : file_faces) {
      out << loop.size();
      for (Index v : loop) out << ' ' << node_id[v];
      out << '\n';
    }
    out << "-- regions: cell k, then the input region it comes from as a comment\n";
    for (std::size_t c = 0; c < d.cells.size(); ++c) {
      out << "-- cell " << c + 1 << " of input region " << d.cells[c].source_region + 1 << '\n';
      out << cell_faces[c].size();
      for (Index f : cell_faces[c]) out << ' ' << f;
      out << '\n';
    }
  });
}

std::string decompose_stats_json(const DecomposeStats& s) {
  std::ostringstream o;
  auto dict = [&](const std::map<std::string, std::size_t>& m) {
    o << '{';
    bool first = true;
    for (const auto& [k, v] : m) o << (first ? "" : ", ") << '"' << k << "\": " << v, first = false;
    o << '}';
  };
  o << "{\"convex_cells\": " << s.convex_cells << ", \"bisections\": ";
  dict(s.bisections);
  o << ", \"rejected_planes\": ";
  dict(s.rejected);
  o << ", \"deferred_edges\": " << s.deferred << ", \"narrow_margin_retry\": " << (s.narrow_margin_retry ? "true" : "false")
    << ", \"face_corner_retry\": " << (s.face_corner_retry ? "true" : "false")
    << ", \"times\": {\"init_geom\": " << s.prepare_seconds
    << ", \"bisect\": " << s.bisect_seconds << "}}";
  return o.str();
}

}  // namespace bisect
