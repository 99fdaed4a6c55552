// VTK XML UnstructuredGrid (.vtu): ASCII writer; reader of ASCII and of inline base64 binary
// data arrays (uncompressed, header UInt32 or UInt64 as header_type says, either byte order).
//
// The writer stores the tetrahedra only (VTK_TETRA 10 or VTK_QUADRATIC_TETRA 24) and the cell
// array "region" (Int32): a .vtu holding the boundary triangles too would mix volume and surface
// cells, which ParaView's volume filters and the "region" array then have to tell apart. VTK's
// tetrahedron is positive when (p0, p1, p2) seen from p3 turns counter-clockwise, the same sign as
// tet_mesh.hpp's orient3d > 0, and its quadratic tetrahedron orders the mid-edge nodes
// 01 12 02 03 13 23 like ours: no reordering. Checked on gmsh's legacy .vtk output, and with VTK
// 9.1 itself: it reads our files with positive vtkMeshQuality volumes and every quadratic edge's
// mid node halfway, and the files it writes (tests/data/meshes/*_vtk_*.vtu) read back here.
//
// The reader keeps cells of types 10 and 24 and skips the others; "region" cell data when present
// (else every tetrahedron is region 0); pieces are concatenated. Appended data and compressed
// arrays are refused with a message saying so.
#include <algorithm>
#include <array>
#include <cstring>
#include <ostream>

#include "bisect/io.hpp"
#include "io/mesh_formats.hpp"

namespace bisect::meshio {

void write_vtu(const TetMesh& mesh, std::ostream& out) {
  check_writable(mesh, ".vtu");
  const int npt = mesh.nodes_per_tet();
  const std::size_t nt = mesh.num_tets();
  std::string s;
  s += "<?xml version=\"1.0\"?>\n";
  s += "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  s += "  <UnstructuredGrid>\n";
  s += "    <Piece NumberOfPoints=\"" + std::to_string(mesh.nodes.size()) + "\" NumberOfCells=\"" + std::to_string(nt) + "\">\n";
  s += "      <Points>\n        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& p : mesh.nodes) {
    put_point(s, p);
    s += '\n';
    spill(s, out);
  }
  s += "        </DataArray>\n      </Points>\n      <Cells>\n";
  s += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t t = 0; t < nt; ++t) {
    for (int i = 0; i < npt; ++i) {
      put_int(s, mesh.tet_node(t, i));
      s += i + 1 < npt ? ' ' : '\n';
    }
    spill(s, out);
  }
  s += "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t t = 0; t < nt; ++t) {
    put_int(s, std::int64_t(t + 1) * npt);
    s += (t % 16 == 15 || t + 1 == nt) ? '\n' : ' ';
    spill(s, out);
  }
  s += "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t t = 0; t < nt; ++t) {
    s += npt == 4 ? "10" : "24";
    s += (t % 32 == 31 || t + 1 == nt) ? '\n' : ' ';
    spill(s, out);
  }
  s += "        </DataArray>\n      </Cells>\n";
  s += "      <CellData Scalars=\"region\">\n        <DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n";
  for (std::size_t t = 0; t < nt; ++t) {
    put_int(s, mesh.region[t]);
    s += (t % 32 == 31 || t + 1 == nt) ? '\n' : ' ';
    spill(s, out);
  }
  s += "        </DataArray>\n      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  spill(s, out, true);
}

namespace {

struct Tag {
  std::string name;  // without '<'; "/Piece" for an end tag
  std::vector<std::pair<std::string, std::string>> attrs;
  bool self_closing = false;
  std::size_t begin = 0, end = 0;  // offsets of '<' and one past '>'

  const std::string* attr(const char* key) const {
    for (auto& [k, v] : attrs)
      if (k == key) return &v;
    return nullptr;
  }
};

// A data array decoded to int64 (integer types) or double (Float32/Float64).
struct Array {
  bool is_float = false;
  std::vector<std::int64_t> ints;
  std::vector<double> reals;
  int components = 1;
  std::size_t size() const { return is_float ? reals.size() : ints.size(); }
};

struct VtuReader {
  std::string text;
  std::string name;
  std::size_t pos = 0;
  bool header64 = false, big_endian = false, compressed = false;

  long line_at(std::size_t p) const { return 1 + long(std::count(text.begin(), text.begin() + std::min(p, text.size()), '\n')); }
  [[noreturn]] void fail_at(std::size_t p, const std::string& what) const { fail(name, line_at(p), what); }

  // Next tag after pos, skipping text, comments and <?...?>; false at the end of the text.
  bool next_tag(Tag& tag) {
    while (true) {
      const std::size_t lt = text.find('<', pos);
      if (lt == std::string::npos) return false;
      if (text.compare(lt, 4, "<!--") == 0) {
        const std::size_t e = text.find("-->", lt);
        if (e == std::string::npos) fail_at(lt, "unterminated comment");
        pos = e + 3;
        continue;
      }
      const std::size_t gt = text.find('>', lt);
      if (gt == std::string::npos) fail_at(lt, "unterminated tag (truncated file?)");
      pos = gt + 1;
      if (text[lt + 1] == '?' || text[lt + 1] == '!') continue;
      tag = Tag();
      tag.begin = lt;
      tag.end = gt + 1;
      std::size_t i = lt + 1, stop = gt;
      if (text[stop - 1] == '/') {
        tag.self_closing = true;
        --stop;
      }
      auto space = [&](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
      while (i < stop && !space(text[i])) tag.name += text[i++];
      while (true) {
        while (i < stop && space(text[i])) ++i;
        if (i >= stop) break;
        std::string key;
        while (i < stop && text[i] != '=' && !space(text[i])) key += text[i++];
        while (i < stop && space(text[i])) ++i;
        if (i >= stop || text[i] != '=') fail_at(lt, "attribute '" + key + "' of <" + tag.name + "> has no value");
        ++i;
        while (i < stop && space(text[i])) ++i;
        if (i >= stop || (text[i] != '"' && text[i] != '\'')) fail_at(lt, "attribute '" + key + "' is not quoted");
        const char q = text[i++];
        const std::size_t e = text.find(q, i);
        if (e == std::string::npos || e > stop) fail_at(lt, "attribute '" + key + "' is not terminated");
        tag.attrs.emplace_back(key, text.substr(i, e - i));
        i = e + 1;
      }
      return true;
    }
  }

  std::vector<unsigned char> base64(std::size_t b, std::size_t e) const {
    std::vector<unsigned char> out;
    out.reserve((e - b) * 3 / 4);
    unsigned acc = 0;
    int bits = 0;
    for (std::size_t i = b; i < e; ++i) {
      const char c = text[i];
      int v;
      if (c >= 'A' && c <= 'Z') v = c - 'A';
      else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
      else if (c >= '0' && c <= '9') v = c - '0' + 52;
      else if (c == '+') v = 62;
      else if (c == '/') v = 63;
      else if (c == '=') {
        // Padding ends one encoded block; VTK may encode the header and the data separately,
        // so decoding goes on with a fresh block after it.
        bits = 0;
        acc = 0;
        continue;
      } else if (c == ' ' || c == '\n' || c == '\r' || c == '\t') {
        continue;
      } else {
        fail_at(i, std::string("invalid character '") + c + "' in base64 data");
      }
      acc = (acc << 6) | unsigned(v);
      bits += 6;
      if (bits >= 8) {
        bits -= 8;
        out.push_back(static_cast<unsigned char>((acc >> bits) & 0xFF));
        acc &= (1u << bits) - 1;
      }
    }
    return out;
  }

  // Decodes one <DataArray> whose start tag is `tag`; moves pos past its end tag.
  Array data_array(const Tag& tag) {
    Array a;
    const std::string* type = tag.attr("type");
    const std::string* format = tag.attr("format");
    const std::string* nc = tag.attr("NumberOfComponents");
    if (nc) a.components = std::atoi(nc->c_str());
    const std::string fmt = format ? *format : "ascii";
    if (!type) fail_at(tag.begin, "<DataArray> without a type");
    static const std::array<std::pair<const char*, int>, 10> kTypes{{{"Int8", 1}, {"UInt8", 1}, {"Int16", 2}, {"UInt16", 2},
      {"Int32", 4}, {"UInt32", 4}, {"Int64", 8}, {"UInt64", 8}, {"Float32", 4}, {"Float64", 8}}};
    int width = 0;
    for (auto& [n, w] : kTypes)
      if (*type == n) width = w;
    if (!width) fail_at(tag.begin, "unsupported DataArray type '" + *type + "'");
    a.is_float = type->compare(0, 5, "Float") == 0;
    const bool is_signed = (*type)[0] == 'I';
    if (fmt == "appended")
      fail_at(tag.begin, "appended data is not supported; write the .vtu with ascii or inline binary data arrays");
    std::size_t b = tag.end, e = tag.end;
    if (!tag.self_closing) {
      const std::size_t close = text.find("</DataArray>", b);
      if (close == std::string::npos) fail_at(tag.begin, "<DataArray> is not closed (truncated file?)");
      // The values end at the first child element: VTK 9 puts <InformationKey> elements (the
      // array's L2 norm range) after them.
      e = std::min(close, text.find('<', b));
      pos = close + 12;
    }
    if (fmt == "ascii") {
      TokenCursor cur(text.substr(b, e - b), name);
      const long base = line_at(b) - 1;
      while (!cur.at_end()) {
        if (a.is_float) {
          std::string_view t = cur.token("value");
          double v;
          if (!TokenCursor::parse_real(t, v))
            fail(name, base + cur.line(), "bad number '" + std::string(t) + "' in data array");
          a.reals.push_back(v);
        } else {
          std::string_view t = cur.token("value");
          std::int64_t v;
          auto r = std::from_chars(t.data(), t.data() + t.size(), v);
          if (r.ec != std::errc() || r.ptr != t.data() + t.size())
            fail(name, base + cur.line(), "bad integer '" + std::string(t) + "' in data array");
          a.ints.push_back(v);
        }
      }
    } else if (fmt == "binary") {
      if (compressed) fail_at(tag.begin, "compressed binary data is not supported; write the .vtu uncompressed or ascii");
      const std::vector<unsigned char> raw = base64(b, e);
      const std::size_t hs = header64 ? 8 : 4;
      if (raw.size() < hs) fail_at(tag.begin, "binary data array without its size header");
      std::uint64_t nbytes = 0;
      for (std::size_t k = 0; k < hs; ++k)
        nbytes |= std::uint64_t(raw[big_endian ? hs - 1 - k : k]) << (8 * k);
      if (nbytes > raw.size() - hs || nbytes % width)
        fail_at(tag.begin, "binary data array announces " + std::to_string(nbytes) + " bytes, holds " + std::to_string(raw.size() - hs));
      const std::size_t count = nbytes / width;
      for (std::size_t k = 0; k < count; ++k) {
        unsigned char v[8];
        for (int j = 0; j < width; ++j) v[j] = raw[hs + k * width + (big_endian ? width - 1 - j : j)];
        if (a.is_float) {
          if (width == 4) {
            float f;
            std::memcpy(&f, v, 4);
            a.reals.push_back(f);
          } else {
            double d;
            std::memcpy(&d, v, 8);
            a.reals.push_back(d);
          }
        } else {
          std::uint64_t u = 0;
          for (int j = 0; j < width; ++j) u |= std::uint64_t(v[j]) << (8 * j);
          if (is_signed && width < 8 && (u >> (8 * width - 1)))
            u |= ~std::uint64_t(0) << (8 * width);  // sign-extend
          a.ints.push_back(std::int64_t(u));
        }
      }
    } else {
      fail_at(tag.begin, "DataArray format '" + fmt + "' is not supported (ascii or binary)");
    }
    return a;
  }

  TetMesh read() {
    TetMesh mesh;
    Tag tag;
    bool seen_file = false, closed = false;
    int order = 0;
    std::size_t order_pos = 0;
    while (next_tag(tag)) {
      if (tag.name == "VTKFile") {
        seen_file = true;
        const std::string* type = tag.attr("type");
        if (!type || *type != "UnstructuredGrid")
          fail_at(tag.begin, "not a VTK UnstructuredGrid file (type=\"" + (type ? *type : std::string()) + "\")");
        const std::string* ht = tag.attr("header_type");
        header64 = ht && *ht == "UInt64";
        const std::string* bo = tag.attr("byte_order");
        big_endian = bo && *bo == "BigEndian";
        compressed = tag.attr("compressor") && !tag.attr("compressor")->empty();
      } else if (tag.name == "Piece") {
        if (!seen_file) fail_at(tag.begin, "<Piece> outside <VTKFile>");
        piece(tag, mesh, order, order_pos);
      } else if (tag.name == "/VTKFile") {
        closed = true;
      }
    }
    if (!seen_file) fail(name, 1, "not a VTK XML file (no <VTKFile>)");
    if (!closed) fail_at(text.size(), "no </VTKFile> (truncated file?)");
    mesh.order = order == 0 ? 1 : order;
    return mesh;
  }

  void piece(const Tag& ptag, TetMesh& mesh, int& order, std::size_t& order_pos) {
    const std::string* np = ptag.attr("NumberOfPoints");
    const std::string* nc = ptag.attr("NumberOfCells");
    if (!np || !nc) fail_at(ptag.begin, "<Piece> without NumberOfPoints / NumberOfCells");
    const std::size_t npts = std::strtoull(np->c_str(), nullptr, 10), ncells = std::strtoull(nc->c_str(), nullptr, 10);
    Array points, conn, offsets, types, region;
    std::size_t points_at = 0, conn_at = 0, region_at = 0;
    bool have_points = false, have_conn = false, have_off = false, have_types = false, have_region = false;
    std::string section;
    Tag tag;
    while (true) {
      if (!next_tag(tag)) fail_at(ptag.begin, "<Piece> is not closed (truncated file?)");
      if (tag.name == "/Piece") break;
      if (tag.name == "Points" || tag.name == "Cells" || tag.name == "CellData" || tag.name == "PointData") {
        section = tag.self_closing ? "" : tag.name;
      } else if (!tag.name.empty() && tag.name[0] == '/') {
        section.clear();
      } else if (tag.name == "DataArray") {
        const std::string* an = tag.attr("Name");
        const std::string arr = an ? *an : "";
        if (section == "Points" && !have_points) {
          points_at = tag.begin;
          points = data_array(tag);
          have_points = true;
        } else if (section == "Cells" && arr == "connectivity") {
          conn_at = tag.begin;
          conn = data_array(tag);
          have_conn = true;
        } else if (section == "Cells" && arr == "offsets") {
          offsets = data_array(tag);
          have_off = true;
        } else if (section == "Cells" && arr == "types") {
          types = data_array(tag);
          have_types = true;
        } else if (section == "CellData" && arr == "region") {
          region_at = tag.begin;
          region = data_array(tag);
          have_region = true;
        } else if (!tag.self_closing) {
          const std::size_t e = text.find("</DataArray>", tag.end);
          if (e == std::string::npos) fail_at(tag.begin, "<DataArray> is not closed (truncated file?)");
          pos = e + 12;
        }
      }
    }
    if (npts && !have_points) fail_at(ptag.begin, "piece has no <Points> data array");
    if (have_points && (points.components != 3 || points.size() != 3 * npts))
      fail_at(points_at, "<Points> holds " + std::to_string(points.size()) + " values, expected 3 x " + std::to_string(npts));
    if (ncells && !(have_conn && have_off && have_types))
      fail_at(ptag.begin, "piece lacks the connectivity, offsets or types array of its cells");
    if (ncells && (offsets.size() != ncells || types.size() != ncells))
      fail_at(ptag.begin, "offsets/types hold " + std::to_string(offsets.size()) + "/" + std::to_string(types.size()) +
                              " values for " + std::to_string(ncells) + " cells");
    if (have_region && region.size() != ncells)
      fail_at(region_at, "\"region\" holds " + std::to_string(region.size()) + " values for " + std::to_string(ncells) + " cells");
    const Index base = Index(mesh.nodes.size());
    for (std::size_t i = 0; i < npts; ++i) {
      const double* p = points.is_float ? &points.reals[3 * i] : nullptr;
      mesh.nodes.emplace_back(p ? p[0] : double(points.ints[3 * i]), p ? p[1] : double(points.ints[3 * i + 1]),
                              p ? p[2] : double(points.ints[3 * i + 2]));
    }
    if (ncells && (conn.is_float || offsets.is_float || types.is_float)) fail_at(conn_at, "cell arrays must hold integers");
    std::int64_t prev = 0;
    for (std::size_t c = 0; c < ncells; ++c) {
      const std::int64_t end = offsets.ints[c];
      if (end < prev || std::size_t(end) > conn.size())
        fail_at(conn_at, "cell " + std::to_string(c) + ": offset " + std::to_string(end) + " out of order or past the " +
                             std::to_string(conn.size()) + " connectivity entries");
      const std::int64_t type = types.ints[c], n = end - prev;
      if (type == 10 || type == 24) {
        const int want = type == 10 ? 4 : 10;
        if (n != want)
          fail_at(conn_at, "cell " + std::to_string(c) + " of type " + std::to_string(type) + " has " + std::to_string(n) +
                               " points, expected " + std::to_string(want));
        const int o = type == 10 ? 1 : 2;
        if (order && order != o)
          fail_at(std::max(order_pos, conn_at), "4-node and 10-node tetrahedra in one mesh (cell " + std::to_string(c) + ")");
        order = o;
        order_pos = conn_at;
        for (std::int64_t k = prev; k < end; ++k) {
          const std::int64_t v = conn.ints[k];
          if (v < 0 || std::size_t(v) >= npts)
            fail_at(conn_at, "cell " + std::to_string(c) + " refers to point " + std::to_string(v) + ", the piece has " +
                                 std::to_string(npts) + " points");
          mesh.tets.push_back(base + Index(v));
        }
        std::int64_t r = 0;
        if (have_region) r = region.is_float ? std::int64_t(region.reals[c]) : region.ints[c];
        mesh.region.push_back(Index(r));
      }
      prev = end;
    }
  }
};

}  // namespace

TetMesh read_vtu(std::istream& in, const std::string& name) {
  VtuReader r;
  r.text = slurp(in);
  r.name = name;
  return r.read();
}

}  // namespace bisect::meshio
