#include "options.hpp"

#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>

#include "bisect/errors.hpp"

namespace py = pybind11;

namespace bisect::python {
namespace {

std::string show(const py::handle& v) { return py::repr(v).cast<std::string>(); }

// Python's promise (README): a wrong type raises TypeError, a bad value ValueError (InputError),
// each naming the argument.
// An integer argument (a bool is not one) within [lo, hi].
std::int64_t integer(const py::handle& v, const char* name, std::int64_t lo, std::int64_t hi) {
  if (py::isinstance<py::bool_>(v) || !py::isinstance<py::int_>(v))
    throw py::type_error(std::string(name) + " must be a whole number (got " + show(v) + ")");
  long long x = 0;
  try {
    x = v.cast<long long>();
  } catch (const py::cast_error&) {
    throw InputError(std::string(name) + " is out of range (got " + show(v) + ")");
  }
  if (x < lo || x > hi)
    throw InputError(std::string(name) + " must lie between " + std::to_string(lo) + " and " + std::to_string(hi) + " (got " + std::to_string(x) + ")");
  return x;
}

// A finite number >= 0 (0 meaning "not set" where the option says so).
double number(const py::handle& v, const char* name) {
  if (py::isinstance<py::bool_>(v) || !(py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)))
    throw py::type_error(std::string(name) + " must be a number (got " + show(v) + ")");
  const double x = v.cast<double>();
  if (!std::isfinite(x) || x < 0) throw InputError(std::string(name) + " must be a finite number, 0 or more (got " + show(v) + ")");
  return x;
}

bool flag(const py::handle& v, const char* name) {
  if (!py::isinstance<py::bool_>(v)) throw py::type_error(std::string(name) + " must be True or False (got " + show(v) + ")");
  return v.cast<bool>();
}

// FreeCAD's sub-element numbers (from 1) or names ("Face3") of one kind, 0-based.
std::vector<Index> entities(const py::handle& v, const std::string& prefix, const std::string& where) {
  std::vector<Index> out;
  if (v.is_none()) return out;
  if (py::isinstance<py::str>(v) || !py::isinstance<py::sequence>(v)) throw py::type_error(where + ": " + prefix + "s must be a list (got " + show(v) + ")");
  for (const py::handle item : v.cast<py::sequence>()) {
    std::int64_t k = 0;
    if (py::isinstance<py::str>(item)) {
      const std::string s = item.cast<std::string>();
      if (s.rfind(prefix, 0) != 0 || s.size() == prefix.size())
        throw InputError(where + ": " + show(item) + " is not a " + prefix + " name (" + prefix + "1, " + prefix + "2, ...)");
      try {
        k = std::stoll(s.substr(prefix.size()));
      } catch (const std::exception&) {
        throw InputError(where + ": " + show(item) + " is not a " + prefix + " name");
      }
    } else {
      k = integer(item, (where + " " + prefix).c_str(), 1, std::numeric_limits<Index>::max());
    }
    if (k < 1) throw InputError(where + ": " + prefix + " numbers start at 1 (got " + std::to_string(k) + ")");
    out.push_back(static_cast<Index>(k - 1));
  }
  return out;
}

}  // namespace

py::dict default_options() {
  const GenerateOptions o;
  py::dict d;
  d["elements"] = o.sizing.elements;
  d["size"] = o.sizing.size;
  d["order"] = o.order;
  d["optimize"] = o.optimize.passes;
  d["smooth"] = o.optimize.smooth_passes;
  d["slivers"] = o.optimize.sliver_rounds;
  d["mean_shape"] = o.optimize.mean_rounds;
  d["grading"] = o.sizing.grading;
  d["boundary_flips"] = o.optimize.boundary_flips;
  d["face_moves"] = o.optimize.face_moves;
  d["threads"] = o.threads;
  d["merge_coplanar"] = o.merge_coplanar;
  d["quality_floor"] = o.quality_floor;
  d["insertion"] = o.delaunay_insertion ? "delaunay" : "minmax";
  d["min_size"] = o.sizing.min_size;
  d["max_size"] = o.sizing.max_size;
  d["curvature_elements"] = o.sizing.curvature_elements;
  d["chord_deviation"] = o.sizing.chord_deviation;
  d["size_grading"] = o.sizing.size_grading;
  d["regions"] = py::list();
  d["max_elements"] = o.max_elements;
  return d;
}

GenerateOptions generate_options(const py::dict& kwargs) {
  GenerateOptions o;
  const py::dict known = default_options();
  for (const auto& [key, value] : kwargs) {
    const std::string k = key.cast<std::string>();
    if (!known.contains(key)) throw py::type_error("unknown option " + k);
    if (value.is_none()) continue;  // None: the default
    if (k == "elements") o.sizing.elements = integer(value, "elements", 0, std::int64_t(1) << 40);
    else if (k == "size") o.sizing.size = number(value, "size");
    else if (k == "order") o.order = static_cast<int>(integer(value, "order", 1, 2));
    else if (k == "optimize") o.optimize.passes = static_cast<int>(integer(value, "optimize", 0, 100));
    else if (k == "smooth") o.optimize.smooth_passes = static_cast<int>(integer(value, "smooth", 0, 100));
    else if (k == "slivers") o.optimize.sliver_rounds = static_cast<int>(integer(value, "slivers", 0, 100));
    else if (k == "mean_shape") o.optimize.mean_rounds = static_cast<int>(integer(value, "mean_shape", 0, 100));
    else if (k == "grading") o.sizing.grading = number(value, "grading");
    else if (k == "boundary_flips") o.optimize.boundary_flips = flag(value, "boundary_flips");
    else if (k == "face_moves") o.optimize.face_moves = flag(value, "face_moves");
    else if (k == "threads") o.threads = static_cast<int>(integer(value, "threads", 0, 1024));
    else if (k == "merge_coplanar") o.merge_coplanar = flag(value, "merge_coplanar");
    else if (k == "quality_floor") o.quality_floor = flag(value, "quality_floor");
    else if (k == "insertion") {
      const std::string s = py::isinstance<py::str>(value) ? value.cast<std::string>() : "";
      if (s != "delaunay" && s != "minmax") throw InputError("insertion must be 'delaunay' or 'minmax' (got " + show(value) + ")");
      o.delaunay_insertion = s == "delaunay";
    } else if (k == "min_size") o.sizing.min_size = number(value, "min_size");
    else if (k == "max_size") o.sizing.max_size = number(value, "max_size");
    else if (k == "curvature_elements") o.sizing.curvature_elements = number(value, "curvature_elements");
    else if (k == "chord_deviation") o.sizing.chord_deviation = number(value, "chord_deviation");
    else if (k == "size_grading") o.sizing.size_grading = number(value, "size_grading");
    else if (k == "max_elements") {  // thin walls and small features past this many: refused before the fill
      o.max_elements = number(value, "max_elements");
      o.limit_cause = "max_elements (mesh_shape's default: what half of this machine's memory holds)";
    }
    else if (k == "regions") {
      if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value))
        throw py::type_error("regions must be a list of dicts {size, faces, edges, vertices, solids} (got " + show(value) + ")");
      int r = 0;
      for (const py::handle item : value.cast<py::sequence>()) {
        const std::string where = "regions[" + std::to_string(r++) + "]";
        if (!py::isinstance<py::dict>(item)) throw py::type_error(where + " must be a dict {size, faces, edges, vertices, solids}");
        const py::dict d = item.cast<py::dict>();
        for (const auto& [rk, rv] : d) {
          const std::string name = rk.cast<std::string>();
          if (name != "size" && name != "faces" && name != "edges" && name != "vertices" && name != "solids")
            throw InputError(where + ": unknown key " + name + " (size, faces, edges, vertices, solids)");
        }
        SizeRegion g;
        if (!d.contains("size")) throw InputError(where + " has no size");
        g.size = number(d["size"], (where + " size").c_str());
        if (!(g.size > 0)) throw InputError(where + ": its size must be positive");
        if (d.contains("faces")) g.faces = entities(d["faces"], "Face", where);
        if (d.contains("edges")) g.edges = entities(d["edges"], "Edge", where);
        if (d.contains("vertices")) g.vertices = entities(d["vertices"], "Vertex", where);
        if (d.contains("solids")) g.solids = entities(d["solids"], "Solid", where);
        o.sizing.regions.push_back(std::move(g));
      }
    }
  }
  // Python names its arguments: not the CLI's -n or -s, which the pipeline's own message names
  if (o.sizing.elements <= 0 && o.sizing.size <= 0)
    throw InputError("give elements (a positive number of tetrahedra) or size (a positive element size)");
  if (o.sizing.curvature_elements > 0 && o.sizing.curvature_elements < 3)
    throw InputError("curvature_elements must be 0 (no bound) or at least 3 (got " + std::to_string(o.sizing.curvature_elements) + ")");
  if (!(o.sizing.size_grading > 0)) throw InputError("size_grading must be positive");
  if (o.sizing.max_size > 0 && o.sizing.min_size > o.sizing.max_size)
    throw InputError("min_size " + std::to_string(o.sizing.min_size) + " exceeds max_size " + std::to_string(o.sizing.max_size));
  return o;
}

}  // namespace bisect::python
