// Gmsh .msh: writer of format 4.1 ASCII, reader of 4.1 and 2.2 ASCII.
//
// What the file's numbers become:
//   region   regions are numbered 0, 1, ... in the order their volumes first appear among the
//            tetrahedra of $Elements, a volume being known by its first physical tag when it has
//            one, else by its entity (elementary) tag. Our writer lists the volumes in increasing
//            region order with physical tag region+1, so its files read back unchanged.
//   tri_tag  the surface entity (elementary) tag minus one; our writer puts the triangles of tag
//            t on surface entity t+1.
//   ids      node tags go to TetMesh::node_ids and tetrahedron tags to tet_ids (left empty when
//            they are 1..n); elements come back in increasing tag order.
// Gmsh orders the mid-edge nodes of its 10-node tetrahedron 01 12 02 03 23 13: its last two
// slots are swapped against tet_mesh.hpp (checked on gmsh 4.8 output). Its tetrahedra are
// positively oriented like ours, and the 6-node triangle matches (01 12 20).
#include <algorithm>
#include <array>
#include <map>
#include <ostream>

#include "bisect/io.hpp"
#include "io/mesh_formats.hpp"

namespace bisect::meshio {
namespace {

// Gmsh slot i holds our slot kGmshTet10[i] (the swap is its own inverse).
constexpr std::array<int, 10> kGmshTet10{0, 1, 2, 3, 4, 5, 6, 7, 9, 8};

struct Box {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
};

void put_box(std::string& s, const Box& b) {
  const bool empty = b.lo.x() > b.hi.x();
  for (int k = 0; k < 6; ++k) {
    s += ' ';
    put_real(s, empty ? 0.0 : (k < 3 ? b.lo[k] : b.hi[k - 3]));
  }
}

}  // namespace

void write_msh(const TetMesh& mesh, std::ostream& out) {
  check_writable(mesh, ".msh");
  const int npt = mesh.nodes_per_tet(), npf = mesh.nodes_per_tri();
  const std::size_t nt = mesh.num_tets(), nf = mesh.num_tris(), nn = mesh.nodes.size();

  // One volume entity per region (tag region+1), one surface entity per triangle tag (tag+1).
  std::map<Index, std::vector<std::size_t>> vols, surfs;
  for (std::size_t t = 0; t < nt; ++t) vols[mesh.region[t]].push_back(t);
  for (std::size_t f = 0; f < nf; ++f) surfs[mesh.tri_tag[f]].push_back(f);
  // Nodes must sit on some entity: all go on the first volume, or on an empty volume 1.
  const Index node_vol = vols.empty() ? 1 : vols.begin()->first + 1;
  std::map<Index, Box> vbox, sbox;
  for (auto& [r, ts] : vols)
    for (std::size_t t : ts)
      for (int i = 0; i < npt; ++i) vbox[r].add(mesh.nodes[mesh.tet_node(t, i)]);
  for (auto& [g, fs] : surfs)
    for (std::size_t f : fs)
      for (int i = 0; i < npf; ++i) sbox[g].add(mesh.nodes[mesh.tris[f * npf + i]]);

  std::string s;
  s += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  s += "$PhysicalNames\n" + std::to_string(vols.size() + surfs.size()) + "\n";
  for (auto& [g, fs] : surfs) s += "2 " + std::to_string(g + 1) + " \"Face" + std::to_string(g + 1) + "\"\n";
  for (auto& [r, ts] : vols) s += "3 " + std::to_string(r + 1) + " \"Region" + std::to_string(r + 1) + "\"\n";
  s += "$EndPhysicalNames\n";

  const bool extra_vol = vols.empty() && nn > 0;
  s += "$Entities\n0 0 " + std::to_string(surfs.size()) + " " + std::to_string(vols.size() + (extra_vol ? 1 : 0)) + "\n";
  for (auto& [g, fs] : surfs) {
    s += std::to_string(g + 1);
    put_box(s, sbox[g]);
    s += " 1 " + std::to_string(g + 1) + " 0\n";
  }
  for (auto& [r, ts] : vols) {
    s += std::to_string(r + 1);
    put_box(s, vbox[r]);
    s += " 1 " + std::to_string(r + 1) + " 0\n";
  }
  if (extra_vol) {
    s += "1";
    put_box(s, Box());
    s += " 0 0\n";
  }
  s += "$EndEntities\n";

  std::int64_t nmin = 0, nmax = 0;
  for (std::size_t n = 0; n < nn; ++n) {
    nmin = n ? std::min(nmin, mesh.node_id(n)) : mesh.node_id(n);
    nmax = n ? std::max(nmax, mesh.node_id(n)) : mesh.node_id(n);
  }
  s += "$Nodes\n" + std::to_string(nn ? 1 : 0) + " " + std::to_string(nn) + " " + std::to_string(nmin) + " " +
       std::to_string(nmax) + "\n";
  if (nn) {
    s += "3 " + std::to_string(node_vol) + " 0 " + std::to_string(nn) + "\n";
    for (std::size_t n = 0; n < nn; ++n) {
      put_int(s, mesh.node_id(n));
      s += '\n';
      spill(s, out);
    }
    for (const Vec3& p : mesh.nodes) {
      put_point(s, p);
      s += '\n';
      spill(s, out);
    }
  }
  s += "$EndNodes\n";

  // Triangles are numbered after the largest tetrahedron number.
  std::int64_t emin = 1, emax = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    emin = t ? std::min(emin, mesh.tet_id(t)) : mesh.tet_id(t);
    emax = std::max(emax, mesh.tet_id(t));
  }
  const std::int64_t tri_base = emax + 1;
  if (nf) {
    if (!nt) emin = tri_base;
    emax = tri_base + std::int64_t(nf) - 1;
  }
  s += "$Elements\n" + std::to_string(vols.size() + surfs.size()) + " " + std::to_string(nt + nf) + " " +
       std::to_string(nt + nf ? emin : 0) + " " + std::to_string(nt + nf ? emax : 0) + "\n";
  for (auto& [r, ts] : vols) {
    s += "3 " + std::to_string(r + 1) + (npt == 4 ? " 4 " : " 11 ") + std::to_string(ts.size()) + "\n";
    for (std::size_t t : ts) {
      put_int(s, mesh.tet_id(t));
      for (int i = 0; i < npt; ++i) {
        s += ' ';
        put_int(s, mesh.node_id(mesh.tet_node(t, npt == 10 ? kGmshTet10[i] : i)));
      }
      s += '\n';
      spill(s, out);
    }
  }
  for (auto& [g, fs] : surfs) {
    s += "2 " + std::to_string(g + 1) + (npf == 3 ? " 2 " : " 9 ") + std::to_string(fs.size()) + "\n";
    for (std::size_t f : fs) {
      put_int(s, tri_base + std::int64_t(f));
      for (int i = 0; i < npf; ++i) {
        s += ' ';
        put_int(s, mesh.node_id(mesh.tris[f * npf + i]));
      }
      s += '\n';
      spill(s, out);
    }
  }
  s += "$EndElements\n";
  spill(s, out, true);
}

namespace {

// Elements of the four kinds we keep, collected before the file's order is known.
struct Collected {
  RawElements tet[2], tri[2];  // [0]: linear, [1]: quadratic
  long first_line[4] = {0, 0, 0, 0};
};

struct MshReader {
  TokenCursor cur;
  std::vector<std::int64_t> node_ids;
  std::vector<Vec3> nodes;
  std::map<std::int64_t, std::int64_t> vol_phys;  // volume entity -> its first physical tag
  std::map<std::pair<int, std::int64_t>, Index> region_keys;
  Collected c;

  void expect_end(const std::string& section) {
    std::string_view t = cur.token(("$End" + section).c_str());
    if (t != "$End" + section)
      cur.fail("expected $End" + section + ", found '" + std::string(t) + "' (counts in the section header do not match its contents?)");
  }
  void skip_section(const std::string& section) {
    while (cur.token(("$End" + section).c_str()) != "$End" + section) {
    }
  }

  // Reads the nodes of one element (its tag already read), which must fill the rest of its line.
  void element(int kind, std::int64_t type, Index group, std::int64_t id, long line) {
    RawElements& raw = kind < 2 ? c.tet[kind] : c.tri[kind - 2];
    const int npe = npe_of(kind);
    if (!c.first_line[kind]) c.first_line[kind] = line;
    raw.ids.push_back(id);
    raw.lines.push_back(line);
    const std::size_t base = raw.nodes.size();
    raw.nodes.resize(base + npe);
    for (int i = 0; i < npe; ++i) {
      if (cur.at_eol())
        cur.fail("element " + std::to_string(id) + " of type " + std::to_string(type) + " has " + std::to_string(i) +
                 " nodes, expected " + std::to_string(npe));
      raw.nodes[base + (npe == 10 ? kGmshTet10[i] : i)] = cur.integer("node tag");
    }
    if (!cur.at_eol())
      cur.fail("element " + std::to_string(id) + " of type " + std::to_string(type) + " has more than " +
               std::to_string(npe) + " nodes");
    raw.group.push_back(group);
  }

  // kind: 0 tet4, 1 tet10, 2 tri3, 3 tri6, -1 skipped.
  static int kind_of(std::int64_t type) {
    switch (type) {
      case 4: return 0;
      case 11: return 1;
      case 2: return 2;
      case 9: return 3;
      default: return -1;
    }
  }
  static int npe_of(int kind) { return kind == 0 ? 4 : kind == 1 ? 10 : kind == 2 ? 3 : 6; }

  void entities41() {
    std::int64_t count[4];
    for (auto& n : count) n = cur.integer("entity count");
    for (int dim = 0; dim < 4; ++dim) {
      for (std::int64_t e = 0; e < count[dim]; ++e) {
        const std::int64_t tag = cur.integer("entity tag");
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) cur.real("entity bounding box");
        const std::int64_t nphys = cur.integer("number of physical tags");
        for (std::int64_t k = 0; k < nphys; ++k) {
          const std::int64_t p = cur.integer("physical tag");
          if (dim == 3 && k == 0) vol_phys[tag] = p;
        }
        if (dim > 0) {
          const std::int64_t nb = cur.integer("number of bounding entities");
          for (std::int64_t k = 0; k < nb; ++k) cur.integer("bounding entity tag");
        }
      }
    }
    expect_end("Entities");
  }

  void nodes41() {
    const std::int64_t blocks = cur.integer("number of node blocks");
    const std::int64_t total = cur.integer("number of nodes");
    cur.integer("minimum node tag");
    cur.integer("maximum node tag");
    for (std::int64_t b = 0; b < blocks; ++b) {
      const std::int64_t dim = cur.integer("entity dimension");
      cur.integer("entity tag");
      const std::int64_t param = cur.integer("parametric flag");
      const std::int64_t n = cur.integer("number of nodes in block");
      for (std::int64_t i = 0; i < n; ++i) node_ids.push_back(cur.integer("node tag"));
      for (std::int64_t i = 0; i < n; ++i) {
        Vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = cur.real("node coordinate");
        if (param)
          for (std::int64_t k = 0; k < dim; ++k) cur.real("node parametric coordinate");
        nodes.push_back(p);
      }
    }
    if (std::int64_t(nodes.size()) != total)
      cur.fail("$Nodes announces " + std::to_string(total) + " nodes, its blocks hold " + std::to_string(nodes.size()));
    expect_end("Nodes");
  }

  void elements41() {
    const std::int64_t blocks = cur.integer("number of element blocks");
    cur.integer("number of elements");
    cur.integer("minimum element tag");
    cur.integer("maximum element tag");
    for (std::int64_t b = 0; b < blocks; ++b) {
      const std::int64_t dim = cur.integer("entity dimension");
      const std::int64_t etag = cur.integer("entity tag");
      const std::int64_t type = cur.integer("element type");
      const std::int64_t n = cur.integer("number of elements in block");
      const int kind = kind_of(type);
      Index group = 0;
      if (kind == 0 || kind == 1) {
        auto it = vol_phys.find(etag);
        group = first_appearance(region_keys, it != vol_phys.end() ? std::make_pair(0, it->second) : std::make_pair(1, etag));
      } else if (kind >= 2) {
        group = Index(etag - 1);
      }
      (void)dim;
      cur.rest_of_line();
      for (std::int64_t i = 0; i < n; ++i) {
        if (kind < 0) {
          if (cur.at_end()) cur.fail("unexpected end of file while reading element block");
          cur.rest_of_line();  // an element we do not keep: one line each in ASCII files
        } else {
          const std::int64_t id = cur.integer("element tag");
          element(kind, type, group, id, cur.line());
        }
      }
    }
    expect_end("Elements");
  }

  void nodes22() {
    const std::int64_t n = cur.integer("number of nodes");
    for (std::int64_t i = 0; i < n; ++i) {
      node_ids.push_back(cur.integer("node number"));
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = cur.real("node coordinate");
      nodes.push_back(p);
    }
    expect_end("Nodes");
  }

  void elements22() {
    const std::int64_t n = cur.integer("number of elements");
    for (std::int64_t i = 0; i < n; ++i) {
      const std::int64_t id = cur.integer("element number");
      const long line = cur.line();
      const std::int64_t type = cur.integer("element type");
      const std::int64_t ntags = cur.integer("number of tags");
      std::int64_t phys = 0, elem = 0;
      for (std::int64_t k = 0; k < ntags; ++k) {
        const std::int64_t v = cur.integer("element tag");
        if (k == 0) phys = v;
        if (k == 1) elem = v;
      }
      const int kind = kind_of(type);
      if (kind < 0) {
        cur.rest_of_line();
        continue;
      }
      Index group;
      if (kind < 2) group = first_appearance(region_keys, phys != 0 ? std::make_pair(0, phys) : std::make_pair(1, elem));
      else group = Index((ntags >= 2 ? elem : phys) - 1);
      element(kind, type, group, id, line);
    }
    expect_end("Elements");
  }

  TetMesh read() {
    if (cur.at_end() || cur.token("$MeshFormat") != "$MeshFormat") cur.fail("not a Gmsh .msh file (no $MeshFormat)");
    const std::string version(cur.token("format version"));
    const std::int64_t file_type = cur.integer("file type");
    cur.integer("data size");
    if (file_type != 0)
      cur.fail("binary .msh is not supported, re-export with -format msh41 ASCII (gmsh -bin 0)");
    int major = 0;
    if (version == "4.1") major = 4;
    else if (version.rfind("2", 0) == 0) major = 2;
    else
      cur.fail("Gmsh format " + version + " is not supported; re-export as 4.1 or 2.2 ASCII (-format msh41)");
    expect_end("MeshFormat");
    bool saw_nodes = false, saw_elements = false;
    while (!cur.at_end()) {
      const std::string sec(cur.token("section"));
      if (sec.size() < 2 || sec[0] != '$') cur.fail("expected a section such as $Nodes, found '" + sec + "'");
      const std::string name = sec.substr(1);
      if (name == "Entities" && major == 4) entities41();
      else if (name == "Nodes") {
        if (saw_nodes) cur.fail("a second $Nodes section");
        saw_nodes = true;
        major == 4 ? nodes41() : nodes22();
      } else if (name == "Elements") {
        saw_elements = true;
        major == 4 ? elements41() : elements22();
      } else {
        skip_section(name);
      }
    }
    // A file cut at a section boundary parses cleanly: only the missing section tells.
    if (!saw_nodes || !saw_elements)
      cur.fail(std::string("no $") + (saw_nodes ? "Elements" : "Nodes") + " section (truncated file?)");
    if (!c.tet[0].ids.empty() && !c.tet[1].ids.empty())
      fail(cur.name(), std::max(c.first_line[0], c.first_line[1]), "4-node and 10-node tetrahedra in one mesh");
    TetMesh mesh;
    const bool quad = !c.tet[1].ids.empty() || (c.tet[0].ids.empty() && !c.tri[1].ids.empty());
    mesh.order = quad ? 2 : 1;
    const RawElements& other = c.tri[quad ? 0 : 1];
    if (!other.ids.empty())
      fail(cur.name(), other.lines[0], std::string(quad ? "3-node" : "6-node") + " triangle " + std::to_string(other.ids[0]) +
                                           " in a mesh of order " + std::to_string(mesh.order));
    mesh.nodes = std::move(nodes);
    finish_mesh(mesh, cur.name(), std::move(node_ids), c.tet[quad], c.tri[quad], "element");
    return mesh;
  }
};

}  // namespace

TetMesh read_msh(std::istream& in, const std::string& name) {
  MshReader r{TokenCursor(slurp(in), name), {}, {}, {}, {}, {}};
  return r.read();
}

}  // namespace bisect::meshio
