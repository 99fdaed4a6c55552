// I-DEAS universal file (.unv) writer: dataset 2411 (nodes, double precision), dataset 2412
// (elements: 111 linear tetrahedron, 118 parabolic tetrahedron, 91 linear triangle, 92 parabolic
// triangle) and dataset 2477 (element groups per region and per triangle tag). This is the mesh
// format FreeCAD's Fem.read / SMESH read most directly.
//
// Node order. UNV lists quadratic elements corner, mid, corner, mid ... around the faces: the
// tetrahedron as c1 m12 c2 m23 c3 m31 m14 m24 m34 c4, the triangle as c1 m12 c2 m23 c3 m31.
// UNV tetrahedra are positively oriented like ours (gmsh writes its tetrahedra unchanged), but
// SMESH's reader and FreeCAD's .inp importer turn the same positive tetrahedron into different
// SMDS node orders: checked with FreeCAD 0.20.2 on gmsh's own files, UNV (a b c d) becomes
// SMDS (a c b d) and C3D4 (a b c d) becomes SMDS (b a c d). Starting the UNV tetrahedron at our
// corner 1, i.e. writing corners (p1 p2 p0 p3) — an even permutation, still positive — makes
// Fem.read of our .unv and of our .inp of the same mesh agree node for node, mid-edge nodes
// included. Triangles are written as they are (SMESH keeps a 91's order).
#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <ostream>

#include "bisect/io.hpp"
#include "io/mesh_formats.hpp"

namespace bisect::meshio {
namespace {

// UNV slot i holds our slot kUnv...[i].
constexpr std::array<int, 4> kUnvTet4{1, 2, 0, 3};
// corners (p1 p2 p0 p3); mids: p1p2 = edge 12 (slot 5), p2p0 = 02 (6), p0p1 = 01 (4),
// p1p3 = 13 (8), p2p3 = 23 (9), p0p3 = 03 (7).
constexpr std::array<int, 10> kUnvTet10{1, 5, 2, 6, 0, 4, 8, 9, 7, 3};
constexpr std::array<int, 3> kUnvTri3{0, 1, 2};
constexpr std::array<int, 6> kUnvTri6{0, 3, 1, 4, 2, 5};

void put_i10(std::string& s, std::int64_t v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%10lld", static_cast<long long>(v));
  s += buf;
}

// FORMAT 1P3D25.16: 17 significant digits, enough to read every double back exactly.
void put_d25(std::string& s, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%25.16E", v);
  for (char* c = buf; *c; ++c)
    if (*c == 'E') *c = 'D';
  s += buf;
}

void put_element(std::string& s, std::int64_t label, int fe, const int* slots, int n, const Index* nodes,
                 const TetMesh& mesh) {
  put_i10(s, label);
  put_i10(s, fe);
  put_i10(s, 1);  // physical property table
  put_i10(s, 1);  // material property table
  put_i10(s, 7);  // colour
  put_i10(s, n);
  s += '\n';
  for (int i = 0; i < n; ++i) {  // FORMAT 8I10
    put_i10(s, mesh.node_id(nodes[slots[i]]));
    if (i % 8 == 7 || i + 1 == n) s += '\n';
  }
}

}  // namespace

void write_unv(const TetMesh& mesh, std::ostream& out) {
  check_writable(mesh, ".unv");
  const int npt = mesh.nodes_per_tet(), npf = mesh.nodes_per_tri();
  const std::size_t nt = mesh.num_tets(), nf = mesh.num_tris();
  std::string s;
  s += "    -1\n  2411\n";
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    // label, export coordinate system, displacement coordinate system, colour
    put_i10(s, mesh.node_id(n));
    s += "         1         1        11\n";
    put_d25(s, mesh.nodes[n].x());
    put_d25(s, mesh.nodes[n].y());
    put_d25(s, mesh.nodes[n].z());
    s += '\n';
    spill(s, out);
  }
  s += "    -1\n    -1\n  2412\n";
  std::int64_t max_id = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    put_element(s, mesh.tet_id(t), npt == 4 ? 111 : 118, npt == 4 ? kUnvTet4.data() : kUnvTet10.data(), npt,
                &mesh.tets[t * npt], mesh);
    max_id = std::max(max_id, mesh.tet_id(t));
    spill(s, out);
  }
  for (std::size_t f = 0; f < nf; ++f) {  // numbered after the tetrahedra
    put_element(s, max_id + 1 + std::int64_t(f), npf == 3 ? 91 : 92, npf == 3 ? kUnvTri3.data() : kUnvTri6.data(), npf,
                &mesh.tris[f * npf], mesh);
    spill(s, out);
  }
  s += "    -1\n";

  // Dataset 2477 (permanent groups): a group of elements per region ("Region<k>", k = region+1)
  // and per triangle tag ("Face<t+1>"), the names our .msh and .inp use. FreeCAD's Fem.read
  // turns them into mesh groups (checked: Fem.read(...).Groups).
  std::map<Index, std::vector<std::int64_t>> regions, faces;
  for (std::size_t t = 0; t < nt; ++t) regions[mesh.region[t]].push_back(mesh.tet_id(t));
  for (std::size_t f = 0; f < nf; ++f) faces[mesh.tri_tag[f]].push_back(max_id + 1 + std::int64_t(f));
  if (!regions.empty() || !faces.empty()) {
    s += "    -1\n  2477\n";
    int group = 0;
    auto put_group = [&](const std::string& name, const std::vector<std::int64_t>& elems) {
      // group number, six active set numbers (none), number of entities; the name; then
      // two entities per line: type 8 (finite element), label, 0, 0.
      put_i10(s, ++group);
      for (int k = 0; k < 6; ++k) put_i10(s, 0);
      put_i10(s, std::int64_t(elems.size()));
      s += '\n' + name + '\n';
      for (std::size_t i = 0; i < elems.size(); ++i) {
        put_i10(s, 8);
        put_i10(s, elems[i]);
        put_i10(s, 0);
        put_i10(s, 0);
        if (i % 2 == 1 || i + 1 == elems.size()) s += '\n';
        spill(s, out);
      }
    };
    for (auto& [r, e] : regions) put_group("Region" + std::to_string(r + 1), e);
    for (auto& [g, e] : faces) put_group("Face" + std::to_string(g + 1), e);
    s += "    -1\n";
  }
  spill(s, out, true);
}

}  // namespace bisect::meshio
