// OFF (Object File Format): "OFF", then "nv nf ne", nv vertex lines "x y z", nf face lines
// "n i0 ... i(n-1)" with 0-based vertex indices, each optionally followed by a colour. `#` starts
// a comment. Messages number vertices and faces from 0 as the file does, and say so. Faces may be
// polygons; they are checked like .poly faces, and the surface must be closed as for STL.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "io/file_paths.hpp"
#include "io/face_checks.hpp"
#include "io/text_scan.hpp"

namespace bisect {
namespace {

io::Naming off_naming() {
  io::Naming n;
  n.node = "vertex", n.nodes = "vertices";
  n.base = 0;
  n.note = " (OFF numbers vertices and faces from 0)";
  return n;
}

std::int64_t count_field(const io::LineScanner& s, std::size_t i, const std::string& what) {
  const std::int64_t v = s.integer(i, what);
  if (v < 0 || v > std::numeric_limits<Index>::max())
    s.fail(what + " is " + std::to_string(v) + "; it must be between 0 and " +
           std::to_string(std::numeric_limits<Index>::max()));
  return v;
}

}  // namespace

PolyInput read_off(std::istream& stream, const std::string& name) {
  io::LineScanner s(stream, name, "#");
  const io::Naming naming = off_naming();
  PolyInput in;
  in.source = name;
  s.first("the header 'OFF'");
  // Variants (COFF, NOFF, STOFF, 4OFF, OFF BINARY) carry other per-vertex data: refuse them by
  // name rather than misread their columns.
  const std::string& head = s.token(0);
  if (head != "OFF") {
    if (head.size() > 3 && head.compare(head.size() - 3, 3, "OFF") == 0)
      s.fail("unsupported OFF variant '" + io::printable(head) + "'; only plain 'OFF' is read");
    s.fail("expected the header 'OFF', found '" + io::printable(head) + "'");
  }
  std::size_t first = 1;  // the counts may follow the keyword on the same line
  if (s.size() == 1) {
    s.expect("the counts line 'vertices faces edges'");
    first = 0;
  } else if (s.token(1) == "BINARY") {
    s.fail("binary OFF is not supported; write it as text");
  }
  const std::size_t ncounts = s.size() - first;
  if (ncounts != 3 && ncounts != 2)
    s.fail("expected the counts 'vertices faces edges', found '" + s.rest(first) + "'");
  const std::int64_t nv = count_field(s, first, "the vertex count");
  const std::int64_t nf = count_field(s, first + 1, "the face count");
  if (ncounts == 3) count_field(s, first + 2, "the edge count");  // unused, as in most readers
  if (nv < 3 || nf < 1) s.fail("an OFF surface needs at least 3 vertices and 1 face");
  const std::string hint = "; do the counts (" + io::count_of(nv, "vertex", "vertices") + ", " +
                           io::count_of(nf, "face", "faces") + ") match the file?";

  in.nodes.reserve(std::size_t(std::min<std::int64_t>(nv, 1 << 20)));
  for (std::int64_t i = 0; i < nv; ++i) {
    const std::string vertex = "vertex " + std::to_string(i);
    s.expect(vertex + " (the counts say " + io::count_of(nv, "vertex", "vertices") + ", numbered from 0)");
    if (s.size() != 3)
      s.fail(vertex + " has " + io::count_of(s.size(), "number", "numbers") + " ('" + s.rest(0) +
             "'); a vertex is 3 coordinates x y z" + hint + naming.note);
    in.nodes.emplace_back(s.real(0, "the x coordinate of " + vertex + naming.note),
                          s.real(1, "the y coordinate of " + vertex + naming.note),
                          s.real(2, "the z coordinate of " + vertex + naming.note));
  }

  std::vector<int> line_of;
  for (std::int64_t i = 0; i < nf; ++i) {
    const std::string face = "face " + std::to_string(i);
    const Index f = Index(i);
    s.expect(face + " (the counts say " + io::count_of(nf, "face", "faces") + ", numbered from 0)");
    const std::int64_t k = s.integer(0, "the vertex count of " + face);
    if (k < 3) s.fail(face + " has " + io::count_of(k, "vertex", "vertices") + "; a face needs at least 3" + naming.note);
    const std::int64_t extra = std::int64_t(s.size()) - 1 - k;
    if (extra < 0)
      s.fail(face + " says it has " + std::to_string(k) + " vertices but lists " + std::to_string(s.size() - 1) +
             naming.note);
    // What follows the indices is a colour: an index, RGB or RGBA.
    if (extra == 2 || extra > 4)
      s.fail(face + " has " + std::to_string(extra) + " numbers after its " + std::to_string(k) +
             " vertices; expected none or a colour (1, 3 or 4 numbers)" + hint + naming.note);
    PolyFace pf;
    for (std::int64_t t = 1; t <= k; ++t) {
      const std::int64_t v = s.integer(std::size_t(t), "a vertex index of " + face);
      if (v < 0 || v >= nv)
        s.fail(face + " refers to vertex " + std::to_string(v) + ", but there are " +
               io::count_of(nv, "vertex", "vertices") + naming.note);
      pf.nodes.push_back(Index(v));
    }
    io::check_distinct_nodes(pf.nodes, f, io::where(name, s.line()), naming);
    io::check_face_shape(in.nodes, pf.nodes, f, io::where(name, s.line()), naming, true);
    in.faces.push_back(std::move(pf));
    line_of.push_back(s.line());
  }
  if (s.next()) s.fail("extra data after the last face: '" + s.rest(0) + "'" + hint);

  if (auto e = io::first_odd_edge(in.faces, {}))
    io::fail(name, line_of[e->faces[0]], "not closed: " + io::describe(*e, in.nodes, naming) + naming.note);
  PolyRegion region;
  for (std::size_t i = 0; i < in.faces.size(); ++i) region.faces.push_back(Index(i));
  in.regions.push_back(std::move(region));
  return in;
}

PolyInput read_off(const std::string& path) {
  io::check_readable_file(path);
  std::ifstream f(path);
  if (!f) throw InputError(path + ": cannot open the file (" + std::strerror(errno) + ")");
  return read_off(f, path);
}

}  // namespace bisect
