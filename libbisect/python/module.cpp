// bisectmesh._core: the C++ library as FreeCAD's Python sees it. Arrays cross as NumPy arrays
// (nodes #N by 3 float64, tets #T by 4|10 integer, 0-based node indices); dicts carry the rest.
// The GIL is released while C++ works so that a FreeCAD GUI thread stays responsive.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cctype>
#include <cmath>
#include <exception>
#include <functional>
#include <optional>
#include <string>

#include "bisect/errors.hpp"
#include "bisect/generate.hpp"
#include "bisect/io.hpp"
#include "bisect/poly_input.hpp"
#include "bisect/quality.hpp"
#include "bisect/validate.hpp"
#include "io/face_checks.hpp"
#include "util/progress_poll.hpp"
#include "bisect/occ.hpp"
#include "options.hpp"

namespace py = pybind11;
using namespace bisect;

namespace {

using NodeArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

// Builds a TetMesh from NumPy arrays, checking shapes and index ranges so that a wrong argument
// is a Python exception, not a read out of bounds.
TetMesh mesh_from_arrays(const NodeArray& nodes, const IndexArray& tets, const py::object& region,
                         const py::object& node_ids, const py::object& tet_ids) {
  if (nodes.ndim() != 2 || nodes.shape(1) != 3)
    throw InputError("nodes must be an array of shape (N, 3)");
  if (tets.ndim() != 2 || (tets.shape(1) != 4 && tets.shape(1) != 10))
    throw InputError("tets must be an array of shape (M, 4) or (M, 10)");
  TetMesh m;
  m.order = tets.shape(1) == 10 ? 2 : 1;
  const auto n = nodes.unchecked<2>();
  m.nodes.resize(n.shape(0));
  for (py::ssize_t i = 0; i < n.shape(0); ++i) m.nodes[i] = Vec3(n(i, 0), n(i, 1), n(i, 2));
  const auto t = tets.unchecked<2>();
  m.tets.resize(t.shape(0) * t.shape(1));
  for (py::ssize_t i = 0; i < t.shape(0); ++i)
    for (py::ssize_t j = 0; j < t.shape(1); ++j) {
      const std::int64_t v = t(i, j);
      if (v < 0 || v >= n.shape(0))
        throw InputError("tets[" + std::to_string(i) + "] refers to node index " + std::to_string(v) +
                         ", but there are " + std::to_string(n.shape(0)) + " nodes");
      m.tets[i * t.shape(1) + j] = Index(v);
    }
  // through the buffer: a cast to std::vector makes a Python int of every entry (0.5 s per 10^6,
  // with the GIL held: the window froze while the panel's check started)
  const auto flat = [](const py::object& values) {
    const IndexArray a = values.cast<IndexArray>();
    return std::vector<std::int64_t>(a.data(), a.data() + a.size());
  };
  if (!region.is_none()) {
    const std::vector<std::int64_t> r = flat(region);
    m.region.assign(r.begin(), r.end());
  } else {
    m.region.assign(t.shape(0), 0);
  }
  if (m.region.size() != std::size_t(t.shape(0))) throw InputError("region must have one entry per tetrahedron");
  if (!node_ids.is_none()) m.node_ids = flat(node_ids);
  if (!tet_ids.is_none()) m.tet_ids = flat(tet_ids);
  if (!m.node_ids.empty() && m.node_ids.size() != m.nodes.size())
    throw InputError("node_ids must have one entry per node");
  if (!m.tet_ids.empty() && m.tet_ids.size() != m.num_tets())
    throw InputError("tet_ids must have one entry per tetrahedron");
  return m;
}

template <class T>
py::array_t<T> to_array(const std::vector<T>& v, py::ssize_t cols = 1) {
  if (cols == 1) return py::array_t<T>(py::ssize_t(v.size()), v.data());
  return py::array_t<T>({py::ssize_t(v.size()) / cols, cols}, v.data());
}

py::dict mesh_to_dict(const TetMesh& m) {
  std::vector<double> xyz;
  xyz.reserve(m.nodes.size() * 3);
  for (const Vec3& p : m.nodes) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  py::dict d;
  d["order"] = m.order;
  d["nodes"] = to_array(xyz, 3);
  d["tets"] = to_array(m.tets, m.nodes_per_tet());
  d["region"] = to_array(m.region);
  d["tris"] = to_array(m.tris, m.nodes_per_tri());
  d["tri_tag"] = to_array(m.tri_tag);
  d["node_ids"] = to_array(m.node_ids);
  d["tet_ids"] = to_array(m.tet_ids);
  return d;
}

// One JSON writer (quality_json) serves the CLI and Python alike, so both report the same keys.
// Its numbers are written with operator<<, which spells a non-finite value nan or inf (a stage
// that timed nothing, the quality of an empty mesh); Python's json reads NaN and Infinity, so
// those tokens (outside strings) are respelled: a report never fails to load.
py::object json_loads(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  bool in_string = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < s.size()) out += s[++i];
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    const bool word_start = i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1]));
    if (word_start && s.compare(i, 3, "nan") == 0) {
      if (!out.empty() && out.back() == '-') out.pop_back();  // -nan: JSON has no negative NaN
      out += "NaN";
      i += 2;
    } else if (word_start && s.compare(i, 3, "inf") == 0) {
      out += "Infinity";
      i += 2;
    } else {
      out += c;
    }
  }
  return py::module_::import("json").attr("loads")(out);
}

std::string violation_kind_name(ViolationKind k) { return to_string(k); }

// The indices an input item holds: the item itself (a sequence), or its entry `key` when it is a
// dict (whose other entries the caller reads).
std::vector<Index> index_list(const py::object& item, const char* key) {
  if (py::isinstance<py::dict>(item)) return item.cast<py::dict>()[key].cast<std::vector<Index>>();
  return item.cast<std::vector<Index>>();
}

// A polyhedral input from Python: nodes (N, 3); faces, each a sequence of node indices (a
// planar polygon) or a dict {"nodes": [...], "hole_of": k}; regions, each a sequence of face
// indices or a dict {"faces": [...], "cavity": bool}. Checked as the file readers check theirs,
// with faces, nodes and regions numbered from 0 in the messages.
PolyInput poly_from_python(const NodeArray& nodes, const py::sequence& faces, const py::sequence& regions, const std::string& source) {
  if (nodes.ndim() != 2 || nodes.shape(1) != 3) throw InputError("nodes must be an array of shape (N, 3)");
  PolyInput in;
  in.source = source.empty() ? std::string("input") : source;
  const auto n = nodes.unchecked<2>();
  for (py::ssize_t i = 0; i < n.shape(0); ++i) {
    in.nodes.emplace_back(n(i, 0), n(i, 1), n(i, 2));
    if (!std::isfinite(n(i, 0)) || !std::isfinite(n(i, 1)) || !std::isfinite(n(i, 2)))
      throw InputError(in.source + ": node " + std::to_string(i) + " has a coordinate that is not a finite number");
  }
  io::Naming naming;
  naming.base = 0;
  naming.note = " (numbered from 0)";
  for (py::ssize_t f = 0; f < py::ssize_t(faces.size()); ++f) {
    PolyFace face;
    const py::object item = faces[f];
    face.nodes = index_list(item, "nodes");
    if (py::isinstance<py::dict>(item)) {
      const py::dict d = item.cast<py::dict>();
      if (d.contains("hole_of") && !d["hole_of"].is_none()) face.hole_of = d["hole_of"].cast<Index>();
    }
    for (Index v : face.nodes)
      if (v < 0 || v >= Index(in.nodes.size()))
        throw InputError(in.source + ": face " + std::to_string(f) + " refers to node " + std::to_string(v) + ", but there are " +
                         std::to_string(in.nodes.size()) + " nodes (numbered from 0)");
    if (face.hole_of >= py::ssize_t(faces.size()) || face.hole_of == Index(f))
      throw InputError(in.source + ": face " + std::to_string(f) + " is a hole of face " + std::to_string(face.hole_of) + ", which is not another face");
    io::check_face_size(face.nodes, Index(f), in.source, naming);
    io::check_distinct_nodes(face.nodes, Index(f), in.source, naming);
    io::check_face_shape(in.nodes, face.nodes, Index(f), in.source, naming, true);
    in.faces.push_back(std::move(face));
  }
  for (py::ssize_t r = 0; r < py::ssize_t(regions.size()); ++r) {
    PolyRegion region;
    const py::object item = regions[r];
    region.faces = index_list(item, "faces");
    if (py::isinstance<py::dict>(item) && item.cast<py::dict>().contains("cavity")) region.cavity = item.cast<py::dict>()["cavity"].cast<bool>();
    if (region.faces.empty()) throw InputError(in.source + ": region " + std::to_string(r) + " has no faces");
    for (Index f : region.faces)
      if (f < 0 || f >= Index(in.faces.size()))
        throw InputError(in.source + ": region " + std::to_string(r) + " refers to face " + std::to_string(f) + ", but there are " +
                         std::to_string(in.faces.size()) + " faces (numbered from 0)");
    std::vector<bool> excused(in.faces.size(), false);
    for (std::size_t f = 0; f < in.faces.size(); ++f) excused[f] = in.faces[f].hole_of >= 0;
    if (const auto odd = io::first_odd_edge(in.faces, region.faces, &excused))
      throw InputError(in.source + ": region " + std::to_string(r) + " is not closed: " + io::describe(*odd, in.nodes, naming));
    in.regions.push_back(std::move(region));
  }
  if (in.regions.empty()) throw InputError(in.source + ": no regions");
  return in;
}

// A Python progress callback for the C++ pipeline: called on this thread (the pipeline promises
// it) with the GIL taken back; an exception it raises cancels the run and reaches the caller
// unchanged. run() releases the GIL while the work goes on.
class ProgressBridge {
 public:
  explicit ProgressBridge(const py::object& progress) : progress_(progress) {}
  std::function<bool(double)> callback() {
    if (progress_.is_none()) return {};
    return [this](double x) {
      py::gil_scoped_acquire gil;
      try {
        const py::object r = progress_(x);
        return r.is_none() || r.cast<bool>();
      } catch (py::error_already_set& e) {
        raised_.emplace(std::move(e));
        return false;
      }
    };
  }
  template <class F>
  void run(F&& work) {
    try {
      py::gil_scoped_release release;
      work();
    } catch (const Cancelled&) {
      if (raised_) throw std::move(*raised_);
      throw;
    }
  }

 private:
  py::object progress_;
  std::optional<py::error_already_set> raised_;
};

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "BisectMesh C++ core: the tetrahedral generator, quality measures, mesh validation, mesh and polyhedral I/O.";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<MeshingError>(m, "MeshingError", PyExc_RuntimeError);
  static py::exception<Cancelled> cancelled(m, "Cancelled", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Cancelled& e) {
      cancelled(e.what());
    }
  });

  m.def(
      "generate",
      [](const NodeArray& nodes, const py::sequence& faces, const py::sequence& regions, const py::object& node_spacing,
         const py::object& progress, const std::string& source, const py::kwargs& options) {
        PolyInput in = poly_from_python(nodes, faces, regions, source);
        if (!node_spacing.is_none()) {
          const auto hint = node_spacing.cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
          if (hint.ndim() != 1 || std::size_t(hint.shape(0)) != in.nodes.size())
            throw InputError(in.source + ": node_spacing needs one value per node (" + std::to_string(in.nodes.size()) + ")");
          const double* h = hint.data();
          for (std::size_t i = 0; i < in.nodes.size(); ++i)
            if (!(std::isfinite(h[i]) && h[i] >= 0))
              throw InputError(in.source + ": node " + std::to_string(i) + " asks for spacing " + std::to_string(h[i]) +
                               "; give a positive number, or 0 for no hint");
          in.node_spacing.assign(h, h + in.nodes.size());
        }
        GenerateOptions opt = python::generate_options(options);
        ProgressBridge bridge(progress);
        opt.progress = bridge.callback();
        TetMesh mesh;
        GenerateStats st;
        std::string stats;
        bridge.run([&] {
          mesh = generate_mesh(in, opt, &st);
          util::ProgressPoll poll(opt.progress);
          poll.at(1.0);
          stats = generate_stats_json(st, summarize_quality(element_quality(mesh, [&poll] { return poll.cancelled(); }, opt.threads)));
        });
        py::dict d = mesh_to_dict(mesh);
        d["stats"] = json_loads(stats);
        return d;
      },
      py::arg("nodes"), py::arg("faces"), py::arg("regions"), py::kw_only(), py::arg("node_spacing") = py::none(),
      py::arg("progress") = py::none(), py::arg("source") = "",
      "Tetrahedral mesh of a polyhedral input, in-process (the pipeline of `bisect-mesh INPUT -o OUT`).\n\n"
      "nodes (N, 3); faces: node index lists (planar polygons) or {'nodes': [...], 'hole_of': k}; regions: face "
      "index lists or {'faces': [...], 'cavity': bool}; all numbered from 0. Options as keywords (default_options() "
      "lists them with their defaults): elements (R) or size, order, optimize, smooth, slivers, grading, "
      "boundary_flips, face_moves, threads, merge_coplanar, quality_floor, insertion. node_spacing (N,): the element size each node asks "
      "for (a density hint; 0: none). progress(fraction) is called on this thread; returning False cancels (raises "
      "Cancelled). Returns the mesh dict of read_mesh (tri_tag: the input face of each boundary triangle; region: "
      "the input region of each tetrahedron) with 'stats', the --stats JSON as a dict. Raises InputError (a "
      "ValueError) for bad input or options, MeshingError when a stage cannot finish.");

  m.def("default_options", &python::default_options, "The generators' keyword options with their defaults.");

  m.def(
      "mesh_brep",
      [](const std::string& brep, const std::string& name, const py::object& write, bool arrays, const py::object& progress,
         const py::kwargs& options) {
        GenerateOptions opt = python::generate_options(options);
        ProgressBridge bridge(progress);
        opt.progress = bridge.callback();
        TetMesh mesh;
        GenerateStats st;
        std::string stats;
        const std::string path = write.is_none() ? std::string() : write.cast<std::string>();
        bridge.run([&] {
          const BrepInput in = load_brep_string(brep, name.empty() ? std::string("the shape") : name);
          mesh = generate_brep_mesh(in, opt, &st);
          util::ProgressPoll poll(opt.progress);  // Stop within the summary too (0.4 s at 10^6)
          poll.at(1.0);
          stats = generate_stats_json(st, summarize_quality(element_quality(mesh, [&poll] { return poll.cancelled(); }, opt.threads)));
          if (!path.empty()) write_mesh(mesh, path);
        });
        py::dict d = arrays ? mesh_to_dict(mesh) : py::dict();
        d["stats"] = json_loads(stats);
        return d;
      },
      py::arg("brep"), py::kw_only(), py::arg("name") = "", py::arg("write") = py::none(), py::arg("arrays") = true,
      py::arg("progress") = py::none(),
      "Tetrahedral mesh of a B-rep shape handed over as a BREP string (FreeCAD: Part.Shape.exportBrepToString()), "
      "in-process: the true-surface route (faces meshed on their surfaces, then the 3D pipeline; order 2 curved "
      "on the surfaces with every Jacobian positive). Options as keywords (default_options()): elements or size, "
      "order, min_size, max_size, curvature_elements, chord_deviation, size_grading, regions ([{size, faces, "
      "edges, vertices, solids}] with FreeCAD's numbers from 1 or names like 'Face3'), optimize, smooth, slivers, "
      "threads, insertion. write: a path to write the mesh to as well: .vtu, .msh, .inp (ELSET Region<k> per "
      "solid, NSET Face<k> per B-rep face) or .unv (groups Region<k> and Face<k>, which FreeCAD's FemMesh.read "
      "loads). arrays=False: return only 'stats'. Raises "
      "InputError (a ValueError) naming FreeCAD's Face<k>, Edge<k> or Solid<k>, MeshingError, Cancelled.");

  m.def(
      "element_quality",
      [](const NodeArray& nodes, const IndexArray& tets) {
        const TetMesh mesh = mesh_from_arrays(nodes, tets, py::none(), py::none(), py::none());
        std::vector<TetQuality> q;
        {
          py::gil_scoped_release release;
          q = element_quality(mesh);
        }
        const py::ssize_t n = py::ssize_t(q.size());
        py::array_t<double> vol(n), dmin(n), dmax(n), solid(n), gamma(n), alpha(n);
        auto v = vol.mutable_unchecked<1>(), a = dmin.mutable_unchecked<1>(), b = dmax.mutable_unchecked<1>(),
             s = solid.mutable_unchecked<1>(), g = gamma.mutable_unchecked<1>(), al = alpha.mutable_unchecked<1>();
        for (py::ssize_t i = 0; i < n; ++i) {
          v(i) = q[i].volume;
          a(i) = q[i].dihedral_min;
          b(i) = q[i].dihedral_max;
          s(i) = q[i].solid_angle_min;
          g(i) = q[i].gamma;
          al(i) = q[i].alpha;
        }
        py::dict d;
        d["volume"] = vol;
        d["dihedral_min"] = dmin;
        d["dihedral_max"] = dmax;
        d["solid_angle_min"] = solid;
        d["gamma"] = gamma;
        d["alpha"] = alpha;
        return d;
      },
      py::arg("nodes"), py::arg("tets"),
      "Per-tetrahedron measures: volume (signed), dihedral_min/max (degrees), solid_angle_min (sr), "
      "gamma, alpha.");

  m.def(
      "quality_summary",
      [](const NodeArray& nodes, const IndexArray& tets, const py::object& progress) {
        const TetMesh mesh = mesh_from_arrays(nodes, tets, py::none(), py::none(), py::none());
        std::string json;
        ProgressBridge bridge(progress);
        const std::function<bool(double)> callback = bridge.callback();
        util::ProgressPoll poll(callback);
        bridge.run([&] { json = quality_json(summarize_quality(element_quality(mesh, [&poll] { return poll.cancelled(); }, 0))); });
        return json_loads(json);
      },
      py::arg("nodes"), py::arg("tets"), py::arg("progress") = py::none(),
      "The quality summary (min, mean, max, histograms) as a dict. progress(0.0) -> bool|None is "
      "called on this thread at most every 50 ms; False raises Cancelled.");

  m.def(
      "validate",
      [](const NodeArray& nodes, const IndexArray& tets, const py::object& node_ids, const py::object& tet_ids,
         const py::object& progress) {
        const TetMesh mesh = mesh_from_arrays(nodes, tets, py::none(), node_ids, tet_ids);
        std::vector<Violation> found;
        ProgressBridge bridge(progress);
        const std::function<bool(double)> callback = bridge.callback();
        bridge.run([&] { found = validate(mesh, callback); });
        py::list out;
        for (const Violation& v : found) {
          py::dict d;
          d["kind"] = violation_kind_name(v.kind);
          d["ids"] = v.ids;
          d["message"] = v.message;
          out.append(d);
        }
        return out;
      },
      py::arg("nodes"), py::arg("tets"), py::arg("node_ids") = py::none(), py::arg("tet_ids") = py::none(),
      py::arg("progress") = py::none(),
      "Every violation of the mesh invariants as dicts {kind, ids, message}; empty when valid. "
      "progress(fraction) -> bool|None is called on this thread at most every 50 ms; False raises Cancelled.");

  m.def(
      "read_mesh",
      [](const std::string& path) {
        TetMesh mesh;
        {
          py::gil_scoped_release release;
          mesh = read_mesh(path);
        }
        return mesh_to_dict(mesh);
      },
      py::arg("path"), "Reads a .vtu, .msh or .inp tetrahedral mesh.");

  m.def(
      "write_mesh",
      [](const std::string& path, const NodeArray& nodes, const IndexArray& tets, const py::object& region,
         const py::object& tris, const py::object& tri_tag) {
        TetMesh mesh = mesh_from_arrays(nodes, tets, region, py::none(), py::none());
        if (!tris.is_none()) {
          const IndexArray t = tris.cast<IndexArray>();
          if (t.ndim() != 2 || t.shape(1) != mesh.nodes_per_tri())
            throw InputError("tris must be an array of shape (B, " + std::to_string(mesh.nodes_per_tri()) + ")");
          const auto u = t.unchecked<2>();
          for (py::ssize_t i = 0; i < u.shape(0); ++i)
            for (py::ssize_t j = 0; j < u.shape(1); ++j) {
              if (u(i, j) < 0 || u(i, j) >= py::ssize_t(mesh.nodes.size()))
                throw InputError("tris[" + std::to_string(i) + "] refers to a node that does not exist");
              mesh.tris.push_back(Index(u(i, j)));
            }
          mesh.tri_tag = tri_tag.is_none() ? std::vector<Index>(u.shape(0), 0) : tri_tag.cast<std::vector<Index>>();
          if (mesh.tri_tag.size() != mesh.num_tris()) throw InputError("tri_tag must have one entry per triangle");
        }
        py::gil_scoped_release release;
        write_mesh(mesh, path);
      },
      py::arg("path"), py::arg("nodes"), py::arg("tets"), py::arg("region") = py::none(), py::arg("tris") = py::none(),
      py::arg("tri_tag") = py::none(), "Writes .vtu, .msh (4.1 ASCII), .inp or .unv by the path's extension.");

  m.def(
      "summarize_input",
      [](const std::string& path) {
        PolySummary s;
        {
          py::gil_scoped_release release;
          s = summarize(read_polyhedral(path));
        }
        py::list regions;
        for (const RegionSummary& r : s.regions) {
          py::dict d;
          d["faces"] = r.faces;
          d["nodes"] = r.nodes;
          d["shells"] = r.shells;
          d["holes"] = r.holes;
          d["cavity"] = r.cavity;
          d["inside"] = r.inside < 0 ? py::object(py::none()) : py::object(py::int_(r.inside));
          d["volume"] = r.volume;
          regions.append(d);
        }
        py::dict d;
        d["regions"] = regions;
        d["faces"] = s.faces;
        d["nodes"] = s.nodes;
        d["bbox_min"] = py::make_tuple(s.bbox_min.x(), s.bbox_min.y(), s.bbox_min.z());
        d["bbox_max"] = py::make_tuple(s.bbox_max.x(), s.bbox_max.y(), s.bbox_max.z());
        d["volume"] = s.volume;
        return d;
      },
      py::arg("path"), "Reads and checks a .poly, .stl or .off input; returns what `bisect-mesh info` prints.");
}
