// Tetrahedral mesh readers and writers (io/mesh_io.cpp and the per-format files): round trips
// through every format, files written by gmsh 4.8 (tests/data/meshes), the .unv structure and
// .vtu's variants (bad input: test_mesh_io_errors.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "bisect/errors.hpp"
#include "bisect/io.hpp"
#include "input_error.hpp"
#include "io/mesh_formats.hpp"
#include "mesh_io_grid.hpp"

namespace bisect {
namespace {

const std::string kData = std::string(BISECT_TEST_DATA) + "/meshes/";

using test::grid_mesh;
using test::six_volume;

void expect_same(const TetMesh& a, const TetMesh& b, bool with_tris) {
  EXPECT_EQ(a.order, b.order);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(a.nodes[i][k], b.nodes[i][k]) << "node " << i;  // bit-exact
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.region, b.region);
  EXPECT_EQ(a.node_ids, b.node_ids);
  EXPECT_EQ(a.tet_ids, b.tet_ids);
  if (with_tris) {
    EXPECT_EQ(a.tris, b.tris);
    EXPECT_EQ(a.tri_tag, b.tri_tag);
  }
}

using Writer = void (*)(const TetMesh&, std::ostream&);
using Reader = TetMesh (*)(std::istream&, const std::string&);

TetMesh round_trip(const TetMesh& m, Writer w, Reader r) {
  std::stringstream s;
  w(m, s);
  return r(s, "memory");
}

TEST(MeshIoRoundTrip, GridMeshIsValid) {
  for (int order : {1, 2}) {
    const TetMesh m = grid_mesh(2, order);
    EXPECT_EQ(m.num_tets(), 48u);
    EXPECT_EQ(m.num_tris(), 6u * 8 + 8);
    for (std::size_t t = 0; t < m.num_tets(); ++t)
      EXPECT_GT(six_volume(m.nodes[m.tet_node(t, 0)], m.nodes[m.tet_node(t, 1)], m.nodes[m.tet_node(t, 2)],
                           m.nodes[m.tet_node(t, 3)]), 0);
  }
}

TEST(MeshIoRoundTrip, Vtu) {
  for (int order : {1, 2}) {
    const TetMesh m = grid_mesh(2, order);
    expect_same(m, round_trip(m, meshio::write_vtu, meshio::read_vtu), false);  // .vtu holds no triangles
  }
}

TEST(MeshIoRoundTrip, Msh) {
  for (int order : {1, 2}) {
    const TetMesh m = grid_mesh(2, order);
    expect_same(m, round_trip(m, meshio::write_msh, meshio::read_msh), true);
  }
}

TEST(MeshIoRoundTrip, Inp) {
  for (int order : {1, 2}) {
    const TetMesh m = grid_mesh(2, order);
    const TetMesh r = round_trip(m, meshio::write_inp, meshio::read_inp);
    expect_same(m, r, false);  // boundary tags become node sets, not triangles
    EXPECT_TRUE(r.tris.empty());
  }
}

TEST(MeshIoRoundTrip, FileNumbersAreKept) {
  TetMesh m = grid_mesh(2, 2);
  for (std::size_t i = 0; i < m.nodes.size(); ++i) m.node_ids.push_back(1000 - 7 * std::int64_t(i));
  for (std::size_t t = 0; t < m.num_tets(); ++t) m.tet_ids.push_back(50 + 3 * std::int64_t(t));
  expect_same(m, round_trip(m, meshio::write_msh, meshio::read_msh), true);
  expect_same(m, round_trip(m, meshio::write_inp, meshio::read_inp), false);
}

TEST(MeshIoRoundTrip, ThroughFilesWithAnyCaseExtension) {
  const TetMesh m = grid_mesh(1, 1);
  for (const char* ext : {".VTU", ".Msh", ".inp"}) {
    const std::string path = testing::TempDir() + "mesh_io_case" + ext;
    write_mesh(m, path);
    expect_same(m, read_mesh(path), std::string(ext) == ".Msh");
    std::remove(path.c_str());
  }
}

TEST(MeshIoRoundTrip, InpWritesSetsNotTriangles) {
  std::stringstream s;
  meshio::write_inp(grid_mesh(1, 1), s);
  const std::string t = s.str();
  EXPECT_NE(t.find("*ELEMENT, TYPE=C3D4, ELSET=Region1\n"), std::string::npos);
  EXPECT_NE(t.find("*ELSET, ELSET=Eall\n1, 2, 3, 4, 5, 6,\n"), std::string::npos);
  EXPECT_NE(t.find("*NSET, NSET=Face1\n"), std::string::npos);
  EXPECT_EQ(t.find("CPS3"), std::string::npos);
}

TEST(MeshIoRoundTrip, InpHasASurfaceAndAnElementSetPerFace) {
  // Read with the Abaqus manual's own face table (S1 = nodes 1-2-3, S2 = 1-4-2, S3 = 2-4-3,
  // S4 = 3-4-1), not the writer's: every "element, S<k>" line of Face<t+1>_Surface is a triangle
  // of tag t, every triangle is there (an interface's from both sides), and Face<t+1>_Elements
  // lists the surface's elements. The grid's numbers are not the indices, so a writer that
  // printed indices would fail too.
  const std::array<std::array<int, 3>, 4> abaqus{{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}}};
  for (int order : {1, 2}) {
    TetMesh m = grid_mesh(2, order);
    for (std::size_t t = 0; t < m.num_tets(); ++t) m.tet_ids.push_back(100 + 2 * std::int64_t(t));
    std::stringstream out;
    meshio::write_inp(m, out);
    std::map<std::string, std::vector<std::pair<std::int64_t, int>>> surfaces;
    std::map<std::string, std::vector<std::int64_t>> elsets;
    std::string line, surface, elset;
    while (std::getline(out, line)) {
      if (line[0] == '*') {
        surface = elset = "";
        if (line.rfind("*SURFACE, NAME=", 0) == 0) {
          EXPECT_NE(line.find(", TYPE=ELEMENT"), std::string::npos) << line;
          surface = line.substr(15, line.find(',', 15) - 15);
          surfaces[surface];
        } else if (line.rfind("*ELSET, ELSET=Face", 0) == 0) {
          elset = line.substr(14);
          elsets[elset];
        }
        continue;
      }
      if (!surface.empty()) {
        const std::size_t comma = line.find(", S");
        ASSERT_NE(comma, std::string::npos) << line;
        surfaces[surface].emplace_back(std::stoll(line.substr(0, comma)), std::stoi(line.substr(comma + 3)));
      } else if (!elset.empty()) {
        std::stringstream ids(line);
        for (std::string id; std::getline(ids, id, ',');)
          if (id.find_first_not_of(' ') != std::string::npos) elsets[elset].push_back(std::stoll(id));
      }
    }
    ASSERT_EQ(surfaces.size(), 7u);  // six sides and the interface
    ASSERT_EQ(elsets.size(), 7u);
    for (Index tag = 0; tag < 7; ++tag) {
      const std::string name = "Face" + std::to_string(tag + 1);
      std::multiset<std::array<Index, 3>> want, got;
      for (std::size_t f = 0; f < m.num_tris(); ++f)
        if (m.tri_tag[f] == tag) {
          const Index* v = &m.tris[f * m.nodes_per_tri()];
          std::array<Index, 3> k{v[0], v[1], v[2]};
          std::sort(k.begin(), k.end());
          want.insert(k);
          if (tag == 6) want.insert(k);  // an interface: a face of a tetrahedron on each side
        }
      std::set<std::int64_t> elements;
      for (const auto& [id, label] : surfaces[name + "_Surface"]) {
        ASSERT_GE(label, 1);
        ASSERT_LE(label, 4);
        ASSERT_EQ((id - 100) % 2, 0);
        const std::size_t t = static_cast<std::size_t>((id - 100) / 2);
        ASSERT_LT(t, m.num_tets());
        std::array<Index, 3> k;
        for (int i = 0; i < 3; ++i) k[i] = m.tet_node(t, abaqus[label - 1][i]);
        std::sort(k.begin(), k.end());
        got.insert(k);
        elements.insert(id);
      }
      EXPECT_FALSE(want.empty()) << name;
      EXPECT_EQ(got, want) << name << ", order " << order;
      EXPECT_EQ(std::vector<std::int64_t>(elements.begin(), elements.end()), elsets[name + "_Elements"]) << name;
    }
    // the reader still takes the file, sets and surfaces skipped
    std::stringstream in(out.str());
    expect_same(m, meshio::read_inp(in, "surfaces.inp"), false);
  }
}

// ---- files written by gmsh ----

struct Counts {
  std::size_t nodes = 0, tets = 0, tris = 0;
};

// Counts straight from the file's own headers, independently of the reader under test.
Counts header_counts(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  Counts c;
  const bool inp = path.size() > 4 && path.substr(path.size() - 4) == ".inp";
  if (inp) {
    int mode = 0;  // 1 nodes, 2 tetrahedra
    while (std::getline(in, line)) {
      if (line.rfind("**", 0) == 0) continue;
      if (line[0] == '*') {
        mode = line.rfind("*NODE", 0) == 0 ? 1 : line.find("C3D") != std::string::npos ? 2 : 0;
        continue;
      }
      if (mode == 1) ++c.nodes;
      if (mode == 2) ++c.tets;
    }
    return c;
  }
  std::getline(in, line);
  std::string version;
  in >> version;
  while (std::getline(in, line)) {
    if (line == "$Nodes") {
      std::size_t a, b;
      in >> a;
      if (version == "4.1") in >> b;
      c.nodes = version == "4.1" ? b : a;
    } else if (line == "$Elements") {
      std::size_t blocks;
      in >> blocks;
      if (version == "4.1") {
        std::size_t total, lo, hi;
        in >> total >> lo >> hi;
        for (std::size_t b = 0; b < blocks; ++b) {
          int dim, tag, type;
          std::size_t count;
          in >> dim >> tag >> type >> count;
          std::getline(in, line);
          for (std::size_t e = 0; e < count; ++e) std::getline(in, line);
          if (type == 4 || type == 11) c.tets += count;
          if (type == 2 || type == 9) c.tris += count;
        }
      } else {
        std::getline(in, line);
        for (std::size_t e = 0; e < blocks; ++e) {
          std::getline(in, line);
          std::istringstream ls(line);
          int id, type;
          ls >> id >> type;
          if (type == 4 || type == 11) ++c.tets;
          if (type == 2 || type == 9) ++c.tris;
        }
      }
    }
  }
  return c;
}

// Checks a gmsh mesh of the two boxes [0,1]x[0,.5]x[0,.25] and [1,2]x[0,.5]x[0,.25].
TetMesh check_gmsh_box(const std::string& file, int order) {
  SCOPED_TRACE(file);
  const std::string path = kData + file;
  const TetMesh m = read_mesh(path);
  const Counts c = header_counts(path);
  EXPECT_EQ(m.order, order);
  EXPECT_EQ(m.nodes.size(), c.nodes);
  EXPECT_EQ(m.num_tets(), c.tets);
  EXPECT_EQ(m.num_tris(), c.tris);
  EXPECT_GT(c.tets, 50u);
  long double volume = 0;
  std::size_t positive = 0;
  double vol_left = 0, vol_right = 0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const long double v = six_volume(m.nodes[m.tet_node(t, 0)], m.nodes[m.tet_node(t, 1)], m.nodes[m.tet_node(t, 2)],
                                      m.nodes[m.tet_node(t, 3)]) / 6;
    positive += v > 0;
    volume += v;
    (m.region[t] == 0 ? vol_left : vol_right) += double(v);
    if (order == 2)
      for (int e = 0; e < 6; ++e) {  // straight-sided: each mid node halfway along its edge
        const Vec3 p = 0.5 * (m.nodes[m.tet_node(t, kTetEdge[e][0])] + m.nodes[m.tet_node(t, kTetEdge[e][1])]);
        EXPECT_LT((m.nodes[m.tet_node(t, 4 + e)] - p).norm(), 1e-12) << "tet " << t << " edge " << e;
      }
  }
  EXPECT_EQ(positive, m.num_tets());
  EXPECT_NEAR(double(volume), 0.25, 0.25 * 1e-12);
  // Regions: 0 = the left box (first to appear), 1 = the right one.
  EXPECT_NEAR(vol_left, 0.125, 1e-12);
  EXPECT_NEAR(vol_right, 0.125, 1e-12);
  for (std::size_t f = 0; f < m.num_tris() && order == 2; ++f)
    for (int e = 0; e < 3; ++e) {
      const Vec3 p = 0.5 * (m.nodes[m.tris[6 * f + kTriEdge[e][0]]] + m.nodes[m.tris[6 * f + kTriEdge[e][1]]]);
      EXPECT_LT((m.nodes[m.tris[6 * f + 3 + e]] - p).norm(), 1e-12);
    }
  return m;
}

TEST(MeshIoGmsh, Order1AllFormatsAgree) {
  const TetMesh a = check_gmsh_box("box2_o1.msh", 1);
  const TetMesh b = check_gmsh_box("box2_o1_v22.msh", 1);
  const TetMesh c = check_gmsh_box("box2_o1.inp", 1);
  expect_same(a, b, true);
  expect_same(a, c, false);
  // Triangle tags are surface entity tags - 1: xmin is surface 1, the interface surface 2;
  // surface 7 (xmax) has no physical group, so gmsh did not save it.
  std::map<Index, int> tags;
  for (Index g : a.tri_tag) ++tags[g];
  EXPECT_EQ(tags.size(), 10u);
  EXPECT_EQ(tags.count(6), 0u);
  EXPECT_GT(tags[0], 0);
  for (std::size_t f = 0; f < a.num_tris(); ++f) {
    if (a.tri_tag[f] != 0) continue;
    for (int i = 0; i < 3; ++i) EXPECT_EQ(a.nodes[a.tris[3 * f + i]].x(), 0.0);
  }
}

TEST(MeshIoGmsh, Order2AllFormatsAgree) {
  const TetMesh a = check_gmsh_box("box2_o2.msh", 2);
  const TetMesh b = check_gmsh_box("box2_o2_v22.msh", 2);
  const TetMesh c = check_gmsh_box("box2_o2.inp", 2);
  expect_same(a, b, true);
  expect_same(a, c, false);
}

TEST(MeshIoGmsh, WithoutPhysicalGroupsRegionsComeFromEntities) {
  // gmsh saved points, lines, triangles and tetrahedra: only the last two are kept.
  const TetMesh a = check_gmsh_box("box2_nophys_o1.msh", 1);
  const TetMesh b = check_gmsh_box("box2_nophys_o2_v22.msh", 2);
  std::map<Index, int> tags;
  for (Index g : a.tri_tag) ++tags[g];
  EXPECT_EQ(tags.size(), 11u);  // all 11 surfaces, 0..10
  EXPECT_EQ(tags.begin()->first, 0);
  EXPECT_EQ(tags.rbegin()->first, 10);
  EXPECT_EQ(b.num_tris(), header_counts(kData + "box2_nophys_o2_v22.msh").tris);
}

TEST(MeshIoGmsh, OurMshReadsLikeGmshs) {
  // Our 4.1 writer's output of a gmsh mesh reads back identically (entity blocks, tet10 order).
  for (const char* f : {"box2_o1.msh", "box2_o2.msh"}) {
    TetMesh m = read_mesh(kData + f);
    expect_same(m, round_trip(m, meshio::write_msh, meshio::read_msh), true);
  }
}

// ---- .unv ----

struct UnvRecord {
  std::int64_t label;
  int fe;
  std::vector<std::int64_t> nodes;
};

// Parses our .unv strictly: dataset markers, record counts, fixed-width fields.
void parse_unv(const std::string& text, std::map<std::int64_t, Vec3>& nodes, std::vector<UnvRecord>& elems,
               std::map<std::string, std::vector<std::int64_t>>& groups) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> datasets;
  while (std::getline(in, line)) {
    ASSERT_EQ(line, "    -1");
    std::getline(in, line);
    datasets.push_back(line);
    while (std::getline(in, line) && line != "    -1") {
      ASSERT_EQ(line.size() % 10, 0u) << line;
      if (datasets.back() == "  2477") {  // group number, 6 set numbers, entity count; name; entities
        ASSERT_EQ(line.size(), 80u);
        std::istringstream h(line);
        std::int64_t v, count = 0;
        for (int k = 0; k < 8; ++k) h >> (k < 7 ? v : count);
        std::string name;
        ASSERT_TRUE(std::getline(in, name));
        auto& g = groups[name];
        for (std::int64_t i = 0; i < count; i += 2) {
          ASSERT_TRUE(std::getline(in, line));
          ASSERT_EQ(line.size(), i + 1 < count ? 80u : 40u);
          std::istringstream es(line);
          std::int64_t type, label, z1, z2;
          while (es >> type >> label >> z1 >> z2) {
            EXPECT_EQ(type, 8);
            g.push_back(label);
          }
        }
        continue;
      }
      std::istringstream h(line);
      std::int64_t label;
      h >> label;
      if (datasets.back() == "  2411") {
        ASSERT_EQ(line.size(), 40u);
        std::string c;
        ASSERT_TRUE(std::getline(in, c));
        ASSERT_EQ(c.size(), 75u);  // 3D25.16
        for (char& ch : c) ch = ch == 'D' ? 'E' : ch;
        Vec3 p;
        std::istringstream cs(c);
        cs >> p.x() >> p.y() >> p.z();
        nodes[label] = p;
      } else {
        ASSERT_EQ(datasets.back(), "  2412");
        ASSERT_EQ(line.size(), 60u);
        UnvRecord r{label, 0, {}};
        int phys, mat, color, nn;
        h >> r.fe >> phys >> mat >> color >> nn;
        while (int(r.nodes.size()) < nn) {
          ASSERT_TRUE(std::getline(in, line));
          ASSERT_LE(line.size(), 80u);
          std::istringstream ns(line);
          std::int64_t v;
          while (ns >> v) r.nodes.push_back(v);
        }
        ASSERT_EQ(int(r.nodes.size()), nn);
        elems.push_back(r);
      }
    }
  }
  EXPECT_EQ(datasets, (std::vector<std::string>{"  2411", "  2412", "  2477"}));
}

TEST(MeshIoUnv, Structure) {
  for (int order : {1, 2}) {
    const TetMesh m = grid_mesh(2, order);
    std::stringstream s;
    meshio::write_unv(m, s);
    std::map<std::int64_t, Vec3> nodes;
    std::vector<UnvRecord> elems;
    std::map<std::string, std::vector<std::int64_t>> groups;
    parse_unv(s.str(), nodes, elems, groups);
    // Element groups per region and per triangle tag, named as in our .msh and .inp.
    ASSERT_EQ(groups.size(), 2u + 7u);
    for (std::size_t t = 0; t < m.num_tets(); ++t) {
      const auto& g = groups["Region" + std::to_string(m.region[t] + 1)];
      EXPECT_NE(std::find(g.begin(), g.end(), std::int64_t(t) + 1), g.end());
    }
    EXPECT_EQ(groups["Region1"].size() + groups["Region2"].size(), m.num_tets());
    for (std::size_t f = 0; f < m.num_tris(); ++f) {
      const auto& g = groups["Face" + std::to_string(m.tri_tag[f] + 1)];
      EXPECT_NE(std::find(g.begin(), g.end(), std::int64_t(m.num_tets() + f) + 1), g.end());
    }
    ASSERT_EQ(nodes.size(), m.nodes.size());
    for (std::size_t i = 0; i < m.nodes.size(); ++i) EXPECT_EQ(nodes[std::int64_t(i) + 1], m.nodes[i]);  // D25.16 is exact
    ASSERT_EQ(elems.size(), m.num_tets() + m.num_tris());
    for (std::size_t e = 0; e < elems.size(); ++e) {
      const UnvRecord& r = elems[e];
      EXPECT_EQ(r.label, std::int64_t(e) + 1);
      const bool tet = e < m.num_tets();
      EXPECT_EQ(r.fe, tet ? (order == 1 ? 111 : 118) : (order == 1 ? 91 : 92));
      std::vector<Vec3> p;
      for (auto v : r.nodes) p.push_back(nodes.at(v));
      if (tet) {
        // Corners (c1 c2 c3 c4) = our (p1 p2 p0 p3): the rotation FreeCAD reads as our .inp.
        const std::size_t t = e;
        const std::array<int, 4> corner_slot = order == 1 ? std::array<int, 4>{0, 1, 2, 3} : std::array<int, 4>{0, 2, 4, 9};
        const int ours[4] = {1, 2, 0, 3};
        for (int i = 0; i < 4; ++i) EXPECT_EQ(p[corner_slot[i]], m.nodes[m.tet_node(t, ours[i])]);
        if (order == 2) {
          // c1 m12 c2 m23 c3 m31 m14 m24 m34 c4: each mid halfway between its corners
          const int mids[6][3] = {{1, 0, 2}, {3, 2, 4}, {5, 4, 0}, {6, 0, 9}, {7, 2, 9}, {8, 4, 9}};
          for (auto& md : mids) EXPECT_EQ(p[md[0]], 0.5 * (p[md[1]] + p[md[2]]));
        }
        EXPECT_GT(six_volume(p[corner_slot[0]], p[corner_slot[1]], p[corner_slot[2]], p[corner_slot[3]]), 0);
      } else {
        const std::size_t f = e - m.num_tets();
        const int slots[6] = {0, 3, 1, 4, 2, 5};
        for (int i = 0; i < (order == 1 ? 3 : 6); ++i)
          EXPECT_EQ(p[i], m.nodes[m.tris[f * m.nodes_per_tri() + (order == 1 ? i : slots[i])]]);
      }
    }
  }
}

// ---- .vtu specifics ----

std::string base64(const std::string& in) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < in.size(); i += 3) {
    unsigned v = 0;
    for (std::size_t j = 0; j < 3; ++j) v = v << 8 | (i + j < in.size() ? (unsigned char)in[i + j] : 0u);
    for (std::size_t j = 0; j < 4; ++j) out += j <= in.size() - i ? k[(v >> (18 - 6 * j)) & 63] : '=';
  }
  return out;
}

template <class T>
std::string raw_bytes(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// A binary data array as VTK writes it: size header, then the data (encoded together, or the
// header on its own as VTK does for some writers).
template <class H, class T>
std::string binary_array(const std::vector<T>& v, bool separate) {
  const std::string data = raw_bytes(v);
  const std::string header = raw_bytes(std::vector<H>{H(data.size())});
  return separate ? base64(header) + base64(data) : base64(header + data);
}

template <class H>
std::string binary_vtu(bool separate) {
  // Two tetrahedra sharing a face, and a triangle cell (type 5) that must be skipped.
  const std::vector<float> pts{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  const std::vector<std::int32_t> conn{0, 1, 2, 3, 1, 2, 3, 1, 3, 2, 4};
  const std::vector<std::int32_t> off{4, 7, 11};
  const std::vector<std::uint8_t> types{10, 5, 10};
  const std::vector<std::int64_t> region{3, 9, -2};
  const std::string ht = sizeof(H) == 8 ? "UInt64" : "UInt32";
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"" +
         ht + "\">\n<UnstructuredGrid><Piece NumberOfPoints=\"5\" NumberOfCells=\"3\">\n<PointData></PointData>\n"
         "<CellData><DataArray type=\"Int64\" Name=\"other\" format=\"binary\">" + binary_array<H>(region, separate) +
         "</DataArray>\n<DataArray type=\"Int64\" Name=\"region\" format=\"binary\">\n  " + binary_array<H>(region, separate) +
         "\n</DataArray></CellData>\n<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">" +
         binary_array<H>(pts, separate) + "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"binary\">" +
         binary_array<H>(conn, separate) + "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"binary\">" +
         binary_array<H>(off, separate) + "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">" +
         binary_array<H>(types, separate) + "</DataArray>\n</Cells></Piece></UnstructuredGrid></VTKFile>\n";
}

TEST(MeshIoVtu, ReadsInlineBinary) {
  for (const std::string& text : {binary_vtu<std::uint32_t>(false), binary_vtu<std::uint64_t>(false),
                                  binary_vtu<std::uint32_t>(true), binary_vtu<std::uint64_t>(true)}) {
    std::istringstream in(text);
    const TetMesh m = meshio::read_vtu(in, "binary.vtu");
    ASSERT_EQ(m.nodes.size(), 5u);
    EXPECT_EQ(m.nodes[4], Vec3(1, 1, 1));
    EXPECT_EQ(m.tets, (std::vector<Index>{0, 1, 2, 3, 1, 3, 2, 4}));
    EXPECT_EQ(m.region, (std::vector<Index>{3, -2}));
  }
}

TEST(MeshIoVtu, ReadsFilesWrittenByVtk) {
  // VTK 9.1's vtkXMLUnstructuredGridWriter re-wrote our .vtu of grid_mesh(1, 2) and
  // grid_mesh(2, 1): inline binary without compression (UInt32 and UInt64 headers) and ascii.
  for (const char* f : {"grid1_o2_vtk_bin32.vtu", "grid2_o1_vtk_bin64.vtu", "grid1_o2_vtk_ascii.vtu", "grid2_o1_vtk_ascii.vtu"}) {
    SCOPED_TRACE(f);
    const TetMesh m = read_mesh(kData + f);
    const TetMesh g = f[4] == '1' ? grid_mesh(1, 2) : grid_mesh(2, 1);
    if (std::string(f).find("bin") != std::string::npos) {
      expect_same(g, m, false);  // binary Float64: bit-exact
    } else {
      ASSERT_EQ(m.nodes.size(), g.nodes.size());
      for (std::size_t i = 0; i < m.nodes.size(); ++i) EXPECT_LT((m.nodes[i] - g.nodes[i]).norm(), 1e-14);
      EXPECT_EQ(m.tets, g.tets);
      EXPECT_EQ(m.region, g.region);
    }
  }
}

TEST(MeshIoVtu, MissingRegionIsZero) {
  std::stringstream s;
  meshio::write_vtu(grid_mesh(1, 1), s);
  std::string t = s.str();
  const std::size_t b = t.find("<CellData"), e = t.find("</CellData>");
  t.erase(b, e + 11 - b);
  std::istringstream in(t);
  const TetMesh m = meshio::read_vtu(in, "noregion.vtu");
  EXPECT_EQ(m.num_tets(), 6u);
  EXPECT_EQ(m.region, std::vector<Index>(6, 0));
}

}  // namespace
}  // namespace bisect
