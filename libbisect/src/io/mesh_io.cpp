// read_mesh / write_mesh: dispatch on the file extension (case-insensitive), plus the helpers
// every tetrahedral mesh reader and writer shares (number formatting, id resolution).
#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <numeric>
#include <unordered_map>

#include "bisect/io.hpp"
#include "io/file_paths.hpp"
#include "io/mesh_formats.hpp"

namespace bisect {
namespace meshio {

std::string slurp(std::istream& in) {
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void fail(const std::string& name, long line, const std::string& what) {
  if (line > 0) throw InputError(name + ":" + std::to_string(line) + ": " + what);
  throw InputError(name + ": " + what);
}

void put_real(std::string& out, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);  // shortest form that reads back exactly
  out.append(buf, r.ptr);
}

void put_point(std::string& out, const Vec3& p) {
  put_real(out, p.x());
  out += ' ';
  put_real(out, p.y());
  out += ' ';
  put_real(out, p.z());
}

void put_int(std::string& out, std::int64_t v) {
  char buf[24];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void spill(std::string& buf, std::ostream& out, bool force) {
  if (!force && buf.size() < (std::size_t(1) << 20)) return;
  out.write(buf.data(), std::streamsize(buf.size()));
  buf.clear();
}

void check_writable(const TetMesh& mesh, const std::string& format) {
  auto bad = [&](const std::string& what) { throw InputError("cannot write " + format + ": " + what); };
  if (mesh.order != 1 && mesh.order != 2) bad("order " + std::to_string(mesh.order) + " (expected 1 or 2)");
  const std::size_t npt = mesh.nodes_per_tet(), npf = mesh.nodes_per_tri();
  if (mesh.tets.size() % npt != 0) bad("tets holds " + std::to_string(mesh.tets.size()) + " indices, not a multiple of " + std::to_string(npt));
  if (mesh.tris.size() % npf != 0) bad("tris holds " + std::to_string(mesh.tris.size()) + " indices, not a multiple of " + std::to_string(npf));
  const std::size_t nt = mesh.num_tets(), nf = mesh.num_tris(), nn = mesh.nodes.size();
  if (mesh.region.size() != nt) bad("region has " + std::to_string(mesh.region.size()) + " entries for " + std::to_string(nt) + " tetrahedra");
  if (mesh.tri_tag.size() != nf) bad("tri_tag has " + std::to_string(mesh.tri_tag.size()) + " entries for " + std::to_string(nf) + " triangles");
  if (!mesh.node_ids.empty() && mesh.node_ids.size() != nn) bad("node_ids does not match the node count");
  if (!mesh.tet_ids.empty() && mesh.tet_ids.size() != nt) bad("tet_ids does not match the tetrahedron count");
  for (std::size_t t = 0; t < nt; ++t) {
    for (std::size_t i = 0; i < npt; ++i) {
      Index v = mesh.tets[t * npt + i];
      if (v < 0 || std::size_t(v) >= nn)
        bad("tetrahedron " + std::to_string(mesh.tet_id(t)) + " refers to node index " + std::to_string(v) + " of " + std::to_string(nn));
    }
    if (mesh.region[t] < 0) bad("tetrahedron " + std::to_string(mesh.tet_id(t)) + " has region " + std::to_string(mesh.region[t]));
  }
  for (std::size_t f = 0; f < nf; ++f) {
    for (std::size_t i = 0; i < npf; ++i) {
      Index v = mesh.tris[f * npf + i];
      if (v < 0 || std::size_t(v) >= nn)
        bad("triangle " + std::to_string(f) + " refers to node index " + std::to_string(v) + " of " + std::to_string(nn));
    }
    if (mesh.tri_tag[f] < 0) bad("triangle " + std::to_string(f) + " has tag " + std::to_string(mesh.tri_tag[f]));
  }
}

namespace {

// Ids equal to 1..n carry no information: TetMesh leaves them empty.
void drop_trivial_ids(std::vector<std::int64_t>& ids) {
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] != std::int64_t(i) + 1) return;
  ids.clear();
}

// Element order: increasing id. Files written by grouping elements (per region or per surface)
// list them out of their original order; their ids still carry it.
std::vector<std::size_t> id_order(const std::vector<std::int64_t>& ids) {
  std::vector<std::size_t> perm(ids.size());
  std::iota(perm.begin(), perm.end(), std::size_t(0));
  if (!std::is_sorted(ids.begin(), ids.end()))
    std::stable_sort(perm.begin(), perm.end(), [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  return perm;
}

}  // namespace

void finish_mesh(TetMesh& mesh, const std::string& name, std::vector<std::int64_t> node_ids,
                 const RawElements& tets, const RawElements& tris, const char* elem_word) {
  std::unordered_map<std::int64_t, Index> index;
  index.reserve(node_ids.size() * 2);
  for (std::size_t i = 0; i < node_ids.size(); ++i)
    if (!index.emplace(node_ids[i], Index(i)).second)
      fail(name, 0, "node " + std::to_string(node_ids[i]) + " is defined more than once");

  auto resolve = [&](const RawElements& raw, int npe, std::vector<Index>& conn, std::vector<Index>& group,
                     const char* word) {
    const std::vector<std::size_t> perm = id_order(raw.ids);
    conn.resize(perm.size() * npe);
    group.resize(perm.size());
    for (std::size_t k = 0; k < perm.size(); ++k) {
      const std::size_t e = perm[k];
      for (int i = 0; i < npe; ++i) {
        const std::int64_t id = raw.nodes[e * npe + i];
        auto it = index.find(id);
        if (it == index.end())
          fail(name, raw.lines[e], std::string(word) + " " + std::to_string(raw.ids[e]) + " references node " +
                                       std::to_string(id) + ", which is not defined");
        conn[k * npe + i] = it->second;
      }
      group[k] = raw.group[e];
    }
    return perm;
  };
  const std::vector<std::size_t> perm = resolve(tets, mesh.nodes_per_tet(), mesh.tets, mesh.region, elem_word);
  resolve(tris, mesh.nodes_per_tri(), mesh.tris, mesh.tri_tag, elem_word);

  mesh.tet_ids.resize(perm.size());
  for (std::size_t k = 0; k < perm.size(); ++k) mesh.tet_ids[k] = tets.ids[perm[k]];
  for (std::size_t k = 1; k < perm.size(); ++k)
    if (mesh.tet_ids[k] == mesh.tet_ids[k - 1])
      fail(name, tets.lines[perm[k]], std::string(elem_word) + " " + std::to_string(mesh.tet_ids[k]) + " is defined more than once");
  drop_trivial_ids(mesh.tet_ids);
  drop_trivial_ids(node_ids);
  mesh.node_ids = std::move(node_ids);
}

namespace {

std::string extension(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace
}  // namespace meshio

TetMesh read_mesh(const std::string& path) {
  const std::string ext = meshio::extension(path);
  using Reader = TetMesh (*)(std::istream&, const std::string&);
  Reader reader = nullptr;
  if (ext == ".vtu") reader = meshio::read_vtu;
  else if (ext == ".msh") reader = meshio::read_msh;
  else if (ext == ".inp") reader = meshio::read_inp;
  else
    throw InputError(path + ": cannot read a tetrahedral mesh from '" + (ext.empty() ? std::string("(no extension)") : ext) +
                     "' files; supported: .vtu, .msh (Gmsh 4.1 or 2.2 ASCII), .inp (Abaqus/CalculiX)");
  io::check_readable_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open for reading");
  return reader(in, path);
}

namespace {

using MeshWriter = void (*)(const TetMesh&, std::ostream&);

MeshWriter mesh_writer(const std::string& path) {
  const std::string ext = meshio::extension(path);
  if (ext == ".vtu") return meshio::write_vtu;
  if (ext == ".msh") return meshio::write_msh;
  if (ext == ".inp") return meshio::write_inp;
  if (ext == ".unv") return meshio::write_unv;
  throw InputError(path + ": cannot write a tetrahedral mesh as '" + (ext.empty() ? std::string("(no extension)") : ext) +
                   "'; supported: .vtu, .msh (Gmsh 4.1 ASCII), .inp (Abaqus/CalculiX), .unv (I-DEAS universal)");
}

}  // namespace

void check_mesh_format(const std::string& path) { mesh_writer(path); }

void write_mesh(const TetMesh& mesh, const std::string& path) {
  const std::string ext = meshio::extension(path);
  const MeshWriter writer = mesh_writer(path);
  // Checked before the file is opened: a mesh that cannot be written leaves no empty file.
  meshio::check_writable(mesh, ext);
  io::write_output_file(path, [&](std::ostream& out) { writer(mesh, out); });
}

}  // namespace bisect
