// Abaqus / CalculiX .inp: writer and reader of C3D4 and C3D10 meshes.
//
// Writer: *NODE (NSET=Nall), one *ELEMENT block per region with ELSET=Region<k> (k = region+1),
// an *ELSET Eall of every tetrahedron, and per boundary-triangle tag t an *NSET Face<t+1> with
// the nodes of its triangles (supports, nodal loads), an *ELSET Face<t+1>_Elements of the
// tetrahedra with a face on them, and a *SURFACE Face<t+1>_Surface (TYPE=ELEMENT) of those
// tetrahedra's faces as "element, S<i>" (pressure by *DSLOAD, *TIE, *CONTACT PAIR, *FILM). An
// interface triangle is a face of a tetrahedron on each side: its surface holds both, in element
// order (a tie takes one side: the lines of one region's elements). Triangles are not written as
// elements: a CalculiX deck with 2D elements beside the solid would mesh them.
// C3D10 orders its mid-edge nodes 01 12 02 03 13 23 like tet_mesh.hpp, and C3D4/C3D10 are
// positively oriented like ours (checked on gmsh's .inp output), so no reordering is needed.
//
// Reader: *NODE and *ELEMENT with TYPE=C3D4 or C3D10 and their variants (C3D4H, C3D10T, C3D10M,
// ...); every other element type and keyword is skipped. Data lines continue on the next line
// until an element has all its nodes. Regions are the ELSET= names of the *ELEMENT blocks
// (case-insensitive) in order of first appearance; a block without ELSET= is a region of its
// own. Node and element numbers go to node_ids / tet_ids; elements come back sorted by number.
// Triangles are not read (the .inp we write has none; boundary node sets are not triangles).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cctype>
#include <map>
#include <ostream>
#include <set>

#include "bisect/io.hpp"
#include "io/mesh_formats.hpp"

namespace bisect::meshio {

void write_inp(const TetMesh& mesh, std::ostream& out) {
  check_writable(mesh, ".inp");
  const int npt = mesh.nodes_per_tet(), npf = mesh.nodes_per_tri();
  const std::size_t nt = mesh.num_tets(), nf = mesh.num_tris();
  std::string s;
  s += "** Written by BisectMesh: " + std::to_string(mesh.nodes.size()) + " nodes, " + std::to_string(nt) +
       (npt == 4 ? " C3D4" : " C3D10") + " elements\n";
  s += "*NODE, NSET=Nall\n";
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    put_int(s, mesh.node_id(n));
    for (int k = 0; k < 3; ++k) {
      s += ", ";
      put_real(s, mesh.nodes[n][k]);
    }
    s += '\n';
    spill(s, out);
  }
  std::map<Index, std::vector<std::size_t>> by_region;
  for (std::size_t t = 0; t < nt; ++t) by_region[mesh.region[t]].push_back(t);
  for (auto& [r, ts] : by_region) {
    s += std::string("*ELEMENT, TYPE=") + (npt == 4 ? "C3D4" : "C3D10") + ", ELSET=Region" + std::to_string(r + 1) + "\n";
    for (std::size_t t : ts) {
      put_int(s, mesh.tet_id(t));
      for (int i = 0; i < npt; ++i) {
        s += ", ";
        put_int(s, mesh.node_id(mesh.tet_node(t, i)));
      }
      s += '\n';
      spill(s, out);
    }
  }
  // Set data lines: at most 16 entries per line (the Abaqus limit).
  auto put_list = [&](const std::vector<std::int64_t>& ids) {
    for (std::size_t i = 0; i < ids.size(); ++i) {
      put_int(s, ids[i]);
      s += (i + 1 == ids.size() || i % 16 == 15) ? ",\n" : ", ";
      spill(s, out);
    }
  };
  s += "*ELSET, ELSET=Eall\n";
  std::vector<std::int64_t> ids;
  for (auto& [r, ts] : by_region)
    for (std::size_t t : ts) ids.push_back(mesh.tet_id(t));
  put_list(ids);
  std::map<Index, std::set<std::int64_t>> face_nodes;
  for (std::size_t f = 0; f < nf; ++f)
    for (int i = 0; i < npf; ++i) face_nodes[mesh.tri_tag[f]].insert(mesh.node_id(mesh.tris[f * npf + i]));
  const std::map<Index, std::vector<ElementFace>> on_face = element_faces(mesh);
  for (auto& [g, nodes] : face_nodes) {
    const std::string name = "Face" + std::to_string(g + 1);
    s += "*NSET, NSET=" + name + "\n";
    put_list(std::vector<std::int64_t>(nodes.begin(), nodes.end()));
    const auto it = on_face.find(g);
    if (it == on_face.end()) continue;  // no tetrahedron has these triangles: the validator says so
    std::set<std::int64_t> elements;
    for (const ElementFace& e : it->second) elements.insert(mesh.tet_id(e.tet));
    s += "*ELSET, ELSET=" + name + "_Elements\n";
    put_list(std::vector<std::int64_t>(elements.begin(), elements.end()));
    s += "*SURFACE, NAME=" + name + "_Surface, TYPE=ELEMENT\n";
    for (const ElementFace& e : it->second) {
      put_int(s, mesh.tet_id(e.tet));
      s += ", S";
      s += char('0' + kAbaqusTetFace[static_cast<std::size_t>(e.face)]);
      s += '\n';
      spill(s, out);
    }
  }
  spill(s, out, true);
}

std::map<Index, std::vector<ElementFace>> element_faces(const TetMesh& mesh) {
  const int npf = mesh.nodes_per_tri();
  const std::size_t nt = mesh.num_tets(), nf = mesh.num_tris(), nn = mesh.nodes.size();
  // the triangles filed under their smallest corner (a counting sort: boundary nodes only hold any)
  std::vector<std::uint32_t> first(nn + 1, 0);
  std::vector<std::array<Index, 3>> sorted(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    std::array<Index, 3> k{mesh.tris[f * npf], mesh.tris[f * npf + 1], mesh.tris[f * npf + 2]};
    std::sort(k.begin(), k.end());
    sorted[f] = k;
    if (k[0] >= 0 && static_cast<std::size_t>(k[2]) < nn) ++first[static_cast<std::size_t>(k[0]) + 1];
  }
  for (std::size_t v = 0; v < nn; ++v) first[v + 1] += first[v];
  std::vector<std::uint32_t> at(first.begin(), first.end() - 1), filed(first[nn]);
  for (std::size_t f = 0; f < nf; ++f)
    if (sorted[f][0] >= 0 && static_cast<std::size_t>(sorted[f][2]) < nn) filed[at[static_cast<std::size_t>(sorted[f][0])]++] = static_cast<std::uint32_t>(f);
  std::map<Index, std::vector<ElementFace>> r;
  for (std::size_t t = 0; t < nt; ++t)
    for (int face = 0; face < 4; ++face) {
      const auto& c = kTetFace[static_cast<std::size_t>(face)];
      std::array<Index, 3> k{mesh.tet_node(t, c[0]), mesh.tet_node(t, c[1]), mesh.tet_node(t, c[2])};
      std::sort(k.begin(), k.end());
      if (k[0] < 0 || static_cast<std::size_t>(k[2]) >= nn) continue;
      const std::size_t v = static_cast<std::size_t>(k[0]);
      for (std::uint32_t i = first[v]; i < first[v + 1]; ++i)
        if (sorted[filed[i]] == k) r[mesh.tri_tag[filed[i]]].push_back({t, face});
    }
  return r;
}

namespace {

std::string upper(std::string_view v) {
  std::string r(v);
  for (char& c : r) c = char(std::toupper(static_cast<unsigned char>(c)));
  return r;
}

std::string_view trim(std::string_view v) {
  while (!v.empty() && std::isspace(static_cast<unsigned char>(v.front()))) v.remove_prefix(1);
  while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back()))) v.remove_suffix(1);
  return v;
}

// Splits a data line at commas; an empty last field (a trailing comma) is dropped.
std::vector<std::string_view> fields(std::string_view line) {
  std::vector<std::string_view> r;
  std::size_t b = 0;
  while (true) {
    std::size_t c = line.find(',', b);
    std::string_view f = trim(line.substr(b, c == std::string_view::npos ? std::string_view::npos : c - b));
    if (c == std::string_view::npos) {
      if (!f.empty()) r.push_back(f);
      return r;
    }
    r.push_back(f);
    b = c + 1;
  }
}

// Tetrahedron node count of an element type name, 0 for types we skip.
int tet_nodes_of(const std::string& type) {
  auto variant_of = [&](const char* base) {
    const std::size_t n = std::char_traits<char>::length(base);
    if (type.compare(0, n, base) != 0) return false;
    for (std::size_t i = n; i < type.size(); ++i)
      if (!std::isalpha(static_cast<unsigned char>(type[i]))) return false;  // C3D4H, C3D10MT, ...
    return true;
  };
  if (variant_of("C3D10")) return 10;
  if (variant_of("C3D4")) return 4;
  return 0;
}

}  // namespace

TetMesh read_inp(std::istream& in, const std::string& name) {
  const std::string text = slurp(in);
  std::vector<std::int64_t> node_ids;
  std::vector<Vec3> nodes;
  RawElements tets[2];  // [0] C3D4, [1] C3D10
  long first_line[2] = {0, 0};
  std::map<std::string, Index> regions;

  enum class Mode { Skip, Node, Element } mode = Mode::Skip;
  int npe = 0;
  std::string elset;  // ELSET= of the current *ELEMENT block
  Index region = -1;  // its region, numbered when its first element is complete
  std::vector<std::int64_t> pending;  // values of an element record spread over lines
  long pending_line = 0;

  auto parse_int = [&](std::string_view f, long line, const char* what) {
    std::int64_t v = 0;
    auto r = std::from_chars(f.data(), f.data() + f.size(), v);
    if (r.ec != std::errc() || r.ptr != f.data() + f.size() || f.empty())
      fail(name, line, std::string("expected ") + what + ", found '" + std::string(f) + "'");
    return v;
  };
  auto unfinished = [&]() {
    if (!pending.empty())
      fail(name, pending_line, "element " + std::to_string(pending[0]) + " has " + std::to_string(pending.size() - 1) +
                                   " nodes, expected " + std::to_string(npe) + " (truncated record?)");
  };

  std::size_t pos = 0;
  long line_no = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line = trim(std::string_view(text).substr(pos, end - pos));
    pos = end + 1;
    ++line_no;
    if (line.empty() || line.substr(0, 2) == "**") continue;

    if (line.front() == '*') {
      unfinished();
      const std::vector<std::string_view> kw = fields(line);
      const std::string key = upper(kw.empty() ? line : kw[0]);
      std::map<std::string, std::string> param;
      for (std::size_t i = 1; i < kw.size(); ++i) {
        const std::size_t eq = kw[i].find('=');
        if (eq == std::string_view::npos) param[upper(kw[i])] = "";
        else param[upper(trim(kw[i].substr(0, eq)))] = std::string(trim(kw[i].substr(eq + 1)));
      }
      mode = Mode::Skip;
      if (key == "*NODE") {
        mode = Mode::Node;
      } else if (key == "*ELEMENT") {
        npe = tet_nodes_of(upper(param["TYPE"]));
        if (npe) {
          mode = Mode::Element;
          const int k = npe == 10;
          if (!first_line[k]) first_line[k] = line_no;
          elset = upper(param["ELSET"]);
          region = -1;
        }
      } else if (key == "*INCLUDE") {
        fail(name, line_no, "*INCLUDE is not supported; merge the included file into this one");
      }
      continue;
    }

    if (mode == Mode::Node) {
      const std::vector<std::string_view> f = fields(line);
      if (f.size() < 2 || f.size() > 4)
        fail(name, line_no, "expected 'number, x, y, z' in *NODE, found '" + std::string(line) + "'");
      node_ids.push_back(parse_int(f[0], line_no, "a node number"));
      Vec3 p = Vec3::Zero();  // Abaqus: omitted coordinates are zero
      for (std::size_t k = 1; k < f.size(); ++k)
        if (!f[k].empty() && !TokenCursor::parse_real(f[k], p[k - 1]))
          fail(name, line_no, "node " + std::to_string(node_ids.back()) + ": bad coordinate '" + std::string(f[k]) + "'");
      nodes.push_back(p);
    } else if (mode == Mode::Element) {
      if (pending.empty()) pending_line = line_no;
      for (std::string_view f : fields(line)) pending.push_back(parse_int(f, line_no, "an element or node number"));
      if (pending.size() > std::size_t(npe) + 1)
        fail(name, line_no, "element " + std::to_string(pending[0]) + " has more than " + std::to_string(npe) + " nodes");
      if (pending.size() == std::size_t(npe) + 1) {
        RawElements& raw = tets[npe == 10];
        raw.ids.push_back(pending[0]);
        raw.lines.push_back(pending_line);
        raw.nodes.insert(raw.nodes.end(), pending.begin() + 1, pending.end());
        if (region < 0) region = first_appearance(regions, elset);
        raw.group.push_back(region);
        pending.clear();
      }
    }
  }
  unfinished();
  if (!tets[0].ids.empty() && !tets[1].ids.empty())
    fail(name, std::max(first_line[0], first_line[1]), "C3D4 and C3D10 elements in one mesh");
  TetMesh mesh;
  mesh.order = tets[1].ids.empty() ? 1 : 2;
  mesh.nodes = std::move(nodes);
  finish_mesh(mesh, name, std::move(node_ids), tets[mesh.order - 1], RawElements(), "element");
  return mesh;
}

}  // namespace bisect::meshio
