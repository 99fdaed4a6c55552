// STL, ASCII or binary. Corners with identical coordinates become one node; each triangle is a
// face; all faces form one region (which shells are outer boundaries and which bound cavities is
// for the domain stage to find). The surface must be closed: every edge shared by an even number
// of triangles. Triangles and nodes are numbered from 1 in messages, nodes in order of first use.
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "io/file_paths.hpp"
#include "io/face_checks.hpp"
#include "io/text_scan.hpp"

namespace bisect {
namespace {

io::Naming stl_naming() {
  io::Naming n;
  n.face = "triangle", n.faces = "triangles";
  return n;
}

// Welds corners into nodes by exact coordinates (the STL has no other notion of sharing) and
// checks each triangle as it arrives, so that the message can still name its line.
class SoupBuilder {
public:
  explicit SoupBuilder(std::string name) { in_.source = std::move(name); }

  // `where` is "file:line" for ASCII, "file" for binary.
  void add(const std::array<Vec3, 3>& corner, const std::string& where, int line) {
    const Index t = Index(in_.faces.size());
    PolyFace face;
    for (const Vec3& p : corner) face.nodes.push_back(node(p));
    for (int i = 0; i < 3; ++i)
      for (int j = i + 1; j < 3; ++j)
        if (face.nodes[i] == face.nodes[j])
          throw InputError(where + ": " + naming_.face_name(t) + " is degenerate: its corners " +
                           std::to_string(i + 1) + " and " + std::to_string(j + 1) + " are the same point " +
                           io::fmt_point(corner[i]));
    io::check_face_shape(in_.nodes, face.nodes, t, where, naming_, false);
    in_.faces.push_back(std::move(face));
    lines_.push_back(line);
  }

  std::size_t triangles() const { return in_.faces.size(); }

  PolyInput finish() {
    if (in_.faces.empty()) throw InputError(in_.source + ": the STL holds no triangles");
    if (auto e = io::first_odd_edge(in_.faces, {})) {
      throw InputError(io::where(in_.source, lines_[e->faces[0]]) +
                       ": not closed: " + io::describe(*e, in_.nodes, naming_));
    }
    PolyRegion region;
    region.faces.resize(in_.faces.size());
    for (std::size_t i = 0; i < in_.faces.size(); ++i) region.faces[i] = Index(i);
    in_.regions.push_back(std::move(region));
    return std::move(in_);
  }

private:
  struct KeyHash {
    std::size_t operator()(const std::array<double, 3>& k) const {
      std::size_t h = 0;
      for (double d : k) {
        std::uint64_t b;
        std::memcpy(&b, &d, sizeof b);
        h = (h ^ (b + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)));
      }
      // Floats widened to doubles have zero low bits: mix the high ones down (murmur3 finalizer).
      std::uint64_t x = h;
      x = (x ^ (x >> 33)) * 0xff51afd7ed558ccdULL;
      x = (x ^ (x >> 33)) * 0xc4ceb9fe1a85ec53ULL;
      return std::size_t(x ^ (x >> 33));
    }
  };

  Index node(const Vec3& p) {
    // +0.0 for -0.0, so that the two spellings of zero weld (== already treats them as equal).
    const std::array<double, 3> key{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};
    auto [it, inserted] = ids_.try_emplace(key, Index(in_.nodes.size()));
    if (inserted) in_.nodes.push_back(p);
    return it->second;
  }

  PolyInput in_;
  io::Naming naming_ = stl_naming();
  std::unordered_map<std::array<double, 3>, Index, KeyHash> ids_;
  std::vector<int> lines_;
};

bool keyword(const std::string* tok, const char* word) {
  if (!tok || tok->size() != std::strlen(word)) return false;
  for (std::size_t i = 0; i < tok->size(); ++i)
    if (std::tolower(static_cast<unsigned char>((*tok)[i])) != word[i]) return false;
  return true;
}

PolyInput read_ascii(const std::string& data, const std::string& name) {
  std::istringstream stream(data);
  io::LineScanner lines(stream, name, "");
  io::TokenCursor cur(lines);
  SoupBuilder soup(name);
  auto expect = [&](const char* word, const std::string& context) {
    const std::string* tok = cur.next();
    if (!tok) lines.fail("the file ends inside " + context + " (expected '" + word + "')");
    if (!keyword(tok, word)) lines.fail("expected '" + std::string(word) + "' in " + context + ", found '" + io::printable(*tok) + "'");
  };
  auto number = [&](const std::string& what, bool finite) {
    const std::string* tok = cur.next();
    if (!tok) lines.fail("the file ends before " + what);
    double v = 0;
    if (!io::parse_real(*tok, v)) lines.fail("expected a number for " + what + ", found '" + io::printable(*tok) + "'");
    if (finite && !std::isfinite(v)) lines.fail(what + " is not a finite number ('" + io::printable(*tok) + "')");
    return v;
  };

  const std::string* tok = cur.next();
  if (!keyword(tok, "solid")) lines.fail("an ASCII STL starts with 'solid'");
  cur.skip_rest_of_line();  // the solid's name is free text
  for (;;) {
    tok = cur.next();
    if (!tok) lines.fail("the file ends before 'endsolid'");
    if (keyword(tok, "endsolid")) {
      cur.skip_rest_of_line();
      tok = cur.next();
      if (!tok) break;
      // Some exporters write one solid per part into a single file: read them all.
      if (!keyword(tok, "solid")) lines.fail("expected 'solid' or the end of the file after 'endsolid', found '" + io::printable(*tok) + "'");
      cur.skip_rest_of_line();
      continue;
    }
    const std::string tri = "triangle " + std::to_string(soup.triangles() + 1);
    if (!keyword(tok, "facet")) lines.fail("expected 'facet' or 'endsolid', found '" + io::printable(*tok) + "'");
    const int line = cur.line();
    expect("normal", tri);
    for (const char* c : {"x", "y", "z"}) number(std::string("the normal's ") + c + " of " + tri, false);
    expect("outer", tri);
    expect("loop", tri);
    std::array<Vec3, 3> corner;
    for (int v = 0; v < 3; ++v) {
      expect("vertex", tri + " (it needs 3 vertices)");
      for (int c = 0; c < 3; ++c)
        corner[v][c] = number(std::string("the ") + "xyz"[c] + " coordinate of vertex " + std::to_string(v + 1) +
                                  " of " + tri, true);
    }
    expect("endloop", tri + " (a facet has exactly 3 vertices)");
    expect("endfacet", tri);
    soup.add(corner, io::where(name, line), line);
  }
  return soup.finish();
}

std::uint32_t le32(const unsigned char* p) {
  return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

float le_float(const unsigned char* p) {
  const std::uint32_t bits = le32(p);  // byte order of the file, whatever the host's
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

PolyInput read_binary(const std::string& data, const std::string& name) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  const std::uint64_t n = le32(bytes + 80);
  if (n > std::uint64_t(std::numeric_limits<Index>::max()))
    throw InputError(name + ": " + std::to_string(n) + " triangles are more than a 32-bit index can number");
  SoupBuilder soup(name);
  for (std::uint64_t t = 0; t < n; ++t) {
    const unsigned char* rec = bytes + 84 + 50 * t + 12;  // skip the normal: we compute our own
    std::array<Vec3, 3> corner;
    for (int v = 0; v < 3; ++v) {
      for (int c = 0; c < 3; ++c) corner[v][c] = le_float(rec + 12 * v + 4 * c);
      if (!corner[v].allFinite())
        throw InputError(name + ": triangle " + std::to_string(t + 1) + ": corner " + std::to_string(v + 1) +
                         " has a coordinate that is not a finite number " + io::fmt_point(corner[v]));
    }
    soup.add(corner, name, 0);
  }
  return soup.finish();
}

bool starts_with_solid(const std::string& data) {
  std::size_t i = 0;
  while (i < data.size() && std::isspace(static_cast<unsigned char>(data[i]))) ++i;
  if (data.compare(i, 5, "solid") != 0) return false;
  return i + 5 == data.size() || std::isspace(static_cast<unsigned char>(data[i + 5]));
}

}  // namespace

PolyInput read_stl(std::istream& in, const std::string& name) {
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (data.empty()) throw InputError(name + ": the file is empty");
  // Binary when the size equation of the binary layout holds, even if the 80-byte header
  // happens to start with "solid" (many exporters write exactly that); ASCII when the file
  // starts with "solid" and is text (binary records almost always hold zero bytes).
  const std::uint64_t size = data.size();
  const std::uint64_t n = size >= 84 ? le32(reinterpret_cast<const unsigned char*>(data.data()) + 80) : 0;
  if (size >= 84 && 84 + 50 * n == size) return read_binary(data, name);
  if (starts_with_solid(data) && data.find('\0') == std::string::npos) return read_ascii(data, name);
  if (size < 84)
    throw InputError(name + ": not an STL: " + std::to_string(size) +
                     " bytes, too short for a binary STL (at least 84), and it does not start with 'solid'");
  const std::uint64_t expected = 84 + 50 * n;
  throw InputError(name + ": " + (size < expected ? "truncated binary STL" : "binary STL with trailing data") +
                   ": its header announces " + std::to_string(n) + " triangles, which take 84 + 50 x " +
                   std::to_string(n) + " = " + std::to_string(expected) + " bytes, but the file has " +
                   std::to_string(size) + " bytes");
}

PolyInput read_stl(const std::string& path) {
  io::check_readable_file(path);
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(path + ": cannot open the file (" + std::strerror(errno) + ")");
  return read_stl(f, path);
}

}  // namespace bisect
