// Internal interface of the tetrahedral mesh readers and writers (read_mesh / write_mesh in
// io.hpp dispatch to these). Stream overloads take the name used in error messages, so that the
// tests can read and write in memory and every message still says `NAME:LINE: what`.
#pragma once
#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bisect/errors.hpp"
#include "bisect/tet_mesh.hpp"

namespace bisect::meshio {

// Writers. Coordinates are written with the shortest decimal form that reads back to the same
// double (std::to_chars), so every format round-trips bit-exactly; .unv uses its fixed D25.16.
void write_vtu(const TetMesh& mesh, std::ostream& out);
void write_msh(const TetMesh& mesh, std::ostream& out);
void write_inp(const TetMesh& mesh, std::ostream& out);
void write_unv(const TetMesh& mesh, std::ostream& out);

// A face of a tetrahedron: `face` is opposite corner `face` (kTetFace's numbering).
struct ElementFace {
  std::size_t tet;
  int face;
};
// Abaqus / CalculiX face label S<k> of our face f: S1 = corners 1-2-3, S2 = 1-4-2, S3 = 2-4-3,
// S4 = 3-4-1 in the element's 1-based numbering, i.e. opposite our corners 3, 2, 0 and 1.
constexpr std::array<int, 4> kAbaqusTetFace{3, 4, 2, 1};
// Per triangle tag, the tetrahedron faces that are its triangles (corners matched, any order),
// in tetrahedron order then face order: one per boundary triangle, two per interface triangle.
std::map<Index, std::vector<ElementFace>> element_faces(const TetMesh& mesh);

// Readers. `name` only labels error messages.
TetMesh read_vtu(std::istream& in, const std::string& name);
TetMesh read_msh(std::istream& in, const std::string& name);
TetMesh read_inp(std::istream& in, const std::string& name);

// ---- helpers shared by the readers and writers (mesh_io.cpp) ----

std::string slurp(std::istream& in);

[[noreturn]] void fail(const std::string& name, long line, const std::string& what);

// Appends the shortest round-trip form of v.
void put_real(std::string& out, double v);
// Appends "x y z" the same way.
void put_point(std::string& out, const Vec3& p);
void put_int(std::string& out, std::int64_t v);
// Writers build text in a string and hand it to the stream in large pieces (formatted stream
// insertion is several times slower for millions of numbers): spill() when the buffer is large
// or `force`.
void spill(std::string& buf, std::ostream& out, bool force = false);

// Checks that a mesh about to be written is consistent (array sizes, node indices in range,
// non-negative regions and tags); throws InputError naming the element otherwise.
void check_writable(const TetMesh& mesh, const std::string& format);

// Per-element bookkeeping the readers collect before node ids are resolved.
struct RawElements {
  std::vector<std::int64_t> ids;    // element number in the file
  std::vector<long> lines;          // line of its record, for messages
  std::vector<std::int64_t> nodes;  // node ids, npe per element, already in tet_mesh.hpp order
  std::vector<Index> group;         // region (tets) or tag (triangles)
};

// Resolves node ids against `node_ids` (file numbers of mesh.nodes, in order), fills mesh.tets /
// tets_ids / region and mesh.tris / tri_tag, puts elements in increasing id order when the file
// had them otherwise (writers group elements by region, so sorting restores the original order),
// and drops ids that are just 1..n. Throws naming the element and the undefined node.
void finish_mesh(TetMesh& mesh, const std::string& name, std::vector<std::int64_t> node_ids,
                 const RawElements& tets, const RawElements& tris, const char* elem_word);

// Region numbering by first appearance: returns the 0-based index of key, numbering it if new.
template <class Key>
Index first_appearance(std::map<Key, Index>& seen, const Key& key) {
  const Index next = Index(seen.size());
  return seen.emplace(key, next).first->second;
}

// Whitespace-separated tokens over a whole file held in memory, with the line number of the
// last token for messages. A token asked for at the end of the file means a truncated file.
class TokenCursor {
public:
  TokenCursor(std::string text, std::string name) : text_(std::move(text)), name_(std::move(name)) {}

  const std::string& name() const { return name_; }
  long line() const { return line_; }
  [[noreturn]] void fail(const std::string& what) const { meshio::fail(name_, line_, what); }

  // Skips blanks and newlines; true at the end of the text.
  bool at_end() {
    skip_space(true);
    return pos_ >= text_.size();
  }
  // True when only blanks remain on the current line.
  bool at_eol() {
    skip_space(false);
    return pos_ >= text_.size() || text_[pos_] == '\n' || text_[pos_] == '\r';
  }
  std::string_view token(const char* what) {
    if (at_end()) fail(std::string("unexpected end of file while reading ") + what);
    std::size_t b = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    return std::string_view(text_).substr(b, pos_ - b);
  }
  std::int64_t integer(const char* what) {
    std::string_view t = token(what);
    std::int64_t v = 0;
    auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(std::string("expected an integer (") + what + "), found '" + std::string(t) + "'");
    return v;
  }
  double real(const char* what) {
    std::string_view t = token(what);
    double v = 0;
    if (!parse_real(t, v))
      fail(std::string("expected a number (") + what + "), found '" + std::string(t) + "'");
    return v;
  }
  // Rest of the current line (without the newline), and moves past it.
  std::string_view rest_of_line() {
    std::size_t b = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    std::string_view r = std::string_view(text_).substr(b, pos_ - b);
    if (pos_ < text_.size()) {
      ++pos_;
      ++line_;
    }
    if (!r.empty() && r.back() == '\r') r.remove_suffix(1);
    return r;
  }

  static bool parse_real(std::string_view t, double& v) {
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);  // from_chars rejects a leading '+'
    auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    return r.ec == std::errc() && r.ptr == t.data() + t.size() && !t.empty();
  }

private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
  void skip_space(bool newlines) {
    while (pos_ < text_.size()) {
      char c = text_[pos_];
      if (c == '\n') {
        if (!newlines) return;
        ++line_;
      } else if (!is_space(c)) {
        return;
      }
      ++pos_;
    }
  }

  std::string text_;
  std::string name_;
  std::size_t pos_ = 0;
  long line_ = 1;
};

}  // namespace bisect::meshio
