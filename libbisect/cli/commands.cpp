#include "commands.hpp"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <sstream>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "bisect/json_text.hpp"
#include "bisect/poly_input.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"
#include "io/file_paths.hpp"

namespace bisect::cli {
namespace {

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Shortest text that reads back to the same double, for JSON; %g for people.
std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
std::string fmt(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
int info_3d(const std::string& path, const CommonOptions& opt, std::ostream& out) {
  const PolyInput in = read_polyhedral(path);
  const PolySummary s = summarize(in);
  if (opt.quiet) return 0;
  if (opt.json) {
    out << "{\"file\":" << json_string(path) << ",\"dimension\":3,\"regions\":[";
    for (std::size_t i = 0; i < s.regions.size(); ++i) {
      const RegionSummary& r = s.regions[i];
      out << (i ? "," : "") << "{\"region\":" << i + 1 << ",\"faces\":" << r.faces << ",\"nodes\":" << r.nodes
          << ",\"shells\":" << r.shells << ",\"face_holes\":" << r.holes
          << ",\"cavity\":" << (r.cavity ? "true" : "false")
          << ",\"inside\":" << (r.inside < 0 ? std::string("null") : std::to_string(r.inside + 1))
          << ",\"volume\":" << num(r.volume) << "}";
    }
    out << "],\"faces\":" << s.faces << ",\"nodes\":" << s.nodes << ",\"required_elements\":" << in.required_elements
        << ",\"bbox\":[[" << num(s.bbox_min.x()) << "," << num(s.bbox_min.y()) << "," << num(s.bbox_min.z())
        << "],[" << num(s.bbox_max.x()) << "," << num(s.bbox_max.y()) << "," << num(s.bbox_max.z())
        << "]],\"volume\":" << num(s.volume) << "}\n";
    return 0;
  }
  out << path << ": " << s.regions.size() << (s.regions.size() == 1 ? " region, " : " regions, ") << s.faces
      << " faces, " << s.nodes << " nodes";
  if (in.required_elements > 0) out << ", " << in.required_elements << " elements required";
  out << "\n";
  out << "bounding box: (" << fmt(s.bbox_min.x()) << ", " << fmt(s.bbox_min.y()) << ", " << fmt(s.bbox_min.z())
      << ") to (" << fmt(s.bbox_max.x()) << ", " << fmt(s.bbox_max.y()) << ", " << fmt(s.bbox_max.z()) << ")\n";
  for (std::size_t i = 0; i < s.regions.size(); ++i) {
    const RegionSummary& r = s.regions[i];
    out << "region " << i + 1 << ": " << (r.cavity ? "cavity, " : "") << r.faces << " faces, " << r.nodes << " nodes, "
        << r.shells << (r.shells == 1 ? " shell" : " shells");
    if (r.holes) out << ", " << r.holes << " face holes";
    if (r.inside >= 0) out << ", inside region " << r.inside + 1;
    out << ", volume " << fmt(r.volume) << "\n";
  }
  out << "volume: " << fmt(s.volume) << "\n";
  return 0;
}

int info_2d(const std::string& path, const CommonOptions& opt, std::ostream& out) {
  const Poly2Input in = read_poly2(path);
  const Poly2Summary s = summarize(in);
  if (opt.quiet) return 0;
  if (opt.json) {
    out << "{\"file\":" << json_string(path) << ",\"dimension\":2,\"polygons\":[";
    for (std::size_t i = 0; i < s.polygons.size(); ++i) {
      const auto& p = s.polygons[i];
      out << (i ? "," : "") << "{\"polygon\":" << i + 1 << ",\"nodes\":" << p.nodes
          << ",\"hole\":" << (p.hole ? "true" : "false")
          << ",\"inside\":" << (p.inside < 0 ? std::string("null") : std::to_string(p.inside + 1))
          << ",\"area\":" << num(p.area) << ",\"net_area\":" << num(p.net_area) << "}";
    }
    out << "],\"nodes\":" << s.nodes << ",\"required_elements\":" << in.required_elements << ",\"bbox\":[["
        << num(s.bbox_min.x()) << "," << num(s.bbox_min.y()) << "],[" << num(s.bbox_max.x()) << ","
        << num(s.bbox_max.y()) << "]],\"area\":" << num(s.area) << "}\n";
    return 0;
  }
  out << path << ": 2D, " << s.polygons.size() << " polygons, " << s.nodes << " nodes";
  if (in.required_elements > 0) out << ", " << in.required_elements << " elements required";
  out << "\n";
  out << "bounding box: (" << fmt(s.bbox_min.x()) << ", " << fmt(s.bbox_min.y()) << ") to (" << fmt(s.bbox_max.x())
      << ", " << fmt(s.bbox_max.y()) << ")\n";
  for (std::size_t i = 0; i < s.polygons.size(); ++i) {
    const auto& p = s.polygons[i];
    out << "polygon " << i + 1 << ": " << (p.hole ? "hole, " : "region, ") << p.nodes << " nodes";
    if (p.inside >= 0) out << ", inside polygon " << p.inside + 1;
    out << ", area " << fmt(p.area);
    if (!p.hole) out << ", net area " << fmt(p.net_area);
    out << "\n";
  }
  out << "area: " << fmt(s.area) << "\n";
  return 0;
}

void print_measure(std::ostream& out, const char* name, const MeasureStats& m, const char* unit) {
  out << "  " << name << ": min " << fmt(m.min) << unit << ", mean " << fmt(m.mean) << unit << ", max " << fmt(m.max)
      << unit << "\n";
}

void print_histogram(std::ostream& out, const char* name, const MeasureStats& m, std::size_t total) {
  out << name << " histogram:\n";
  const std::size_t bins = m.histogram.size();
  const std::size_t peak = bins ? *std::max_element(m.histogram.begin(), m.histogram.end()) : 0;
  for (std::size_t b = 0; b < bins; ++b) {
    const double lo = m.lo + (m.hi - m.lo) * double(b) / double(bins);
    const double hi = m.lo + (m.hi - m.lo) * double(b + 1) / double(bins);
    char label[64];
    std::snprintf(label, sizeof label, "  [%7.4g, %7.4g) %9zu ", lo, hi, m.histogram[b]);
    const int bar = peak ? int(40.0 * double(m.histogram[b]) / double(peak) + 0.5) : 0;
    out << label << std::string(std::size_t(bar), '#');
    if (total && m.histogram[b]) {
      char pct[16];
      std::snprintf(pct, sizeof pct, " %.3g%%", 100.0 * double(m.histogram[b]) / double(total));
      out << pct;
    }
    out << "\n";
  }
}

}  // namespace

int run_info(const std::string& input, const CommonOptions& opt, std::ostream& out, std::ostream&) {
  io::check_readable_file(input);
  const std::string ext = lower_extension(input);
  if (ext == ".poly2") return info_2d(input, opt, out);
  if (ext == ".poly" || ext == ".stl" || ext == ".off") return info_3d(input, opt, out);
  throw InputError(input + ": unknown input type '" + ext + "'; info reads .poly, .poly2, .stl and .off");
}

int run_quality(const std::string& path, const CommonOptions& opt, std::ostream& out, std::ostream& err) {
  io::check_readable_file(path);
  const TetMesh mesh = read_mesh(path);
  const std::vector<Violation> violations = validate(mesh);
  const QualitySummary q = summarize_quality(element_quality(mesh));
  const bool valid = violations.empty();
  if (opt.json && !opt.quiet) {
    out << "{\"file\":" << json_string(path) << ",\"nodes\":" << mesh.nodes.size() << ",\"tets\":" << mesh.num_tets()
        << ",\"order\":" << mesh.order << ",\"valid\":" << (valid ? "true" : "false") << ",\"violations\":[";
    for (std::size_t i = 0; i < violations.size(); ++i) {
      const Violation& v = violations[i];
      out << (i ? "," : "") << "{\"kind\":" << json_string(to_string(v.kind)) << ",\"ids\":[";
      for (std::size_t k = 0; k < v.ids.size(); ++k) out << (k ? "," : "") << v.ids[k];
      out << "],\"message\":" << json_string(v.message) << "}";
    }
    out << "],\"quality\":" << quality_json(q) << "}\n";
  } else if (!opt.quiet) {
    out << path << ": " << mesh.nodes.size() << " nodes, " << mesh.num_tets() << " tetrahedra ("
        << mesh.nodes_per_tet() << "-node)\n";
    if (valid) {
      out << "valid: yes\n";
    } else {
      out << "valid: no, " << violations.size() << (violations.size() == 1 ? " violation" : " violations") << "\n";
      const std::size_t shown = std::min<std::size_t>(violations.size(), 20);
      for (std::size_t i = 0; i < shown; ++i) out << "  " << violations[i].message << "\n";
      if (shown < violations.size()) out << "  ... and " << violations.size() - shown << " more (--json lists all)\n";
    }
    out << "quality of " << q.tets << " tetrahedra:\n";
    print_measure(out, "min dihedral angle", q.dihedral_min, " deg");
    print_measure(out, "max dihedral angle", q.dihedral_max, " deg");
    print_measure(out, "min solid angle   ", q.solid_angle_min, " sr");
    print_measure(out, "gamma             ", q.gamma, "");
    print_measure(out, "alpha (r/R)       ", q.alpha, "");
    out << "  tetrahedra with a dihedral angle under 10 deg: " << fmt(q.pct_dihedral_below_10) << "%\n";
    print_histogram(out, "min dihedral angle (deg)", q.dihedral_min, q.tets);
    print_histogram(out, "gamma", q.gamma, q.tets);
  }
  if (!valid) {
    err << "bisect-mesh: " << path << ": invalid mesh: " << violations.front().message;
    if (violations.size() > 1) err << " (and " << violations.size() - 1 << " more)";
    err << "\n";
    return 2;
  }
  return 0;
}

}  // namespace bisect::cli
