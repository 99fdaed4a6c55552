// The section of a region by a plane, worked out without touching the model (the first steps of
// thesis 7.3.1 and 7.3.2, shared by the cut face, splitting, edge following and contour
// splitting methods): each node's side and distance, where the plane crosses faces (chords) and
// where it runs along edges into the region, all directed so that the section lies on their left
// seen from the plane's positive side, closed into loops and grouped into polygons (outer loop,
// counter-clockwise by the A3 angle sum, and its holes).
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "bisect/edge_wedges.hpp"
#include "bisect/plane_cut.hpp"

namespace bisect {

struct NodeInfo {
  double d = 0;        // signed distance to the plane
  int side = 0;        // -1, 0 (on), +1
  double min_len = 1e300;  // shortest edge at the node
};

struct SectionPoint {
  Index vertex = -1;   // a node on the plane, or
  Index ea = -1, eb = -1;  // the edge the plane crosses (ea < eb)
  Vec3 p;
  Vec2 q;              // in the plane's frame
};

struct Piece {
  int from, to;
  Index face;          // the face it crosses (a chord), or -1 along an existing edge
  const char* flaw;    // why this piece is unacceptable, or nullptr
};

class Section {
 public:
  Section(const PolyhedralModel& m, const CutPlane& pl) : m_(m), frame_(pl.n, pl.n * pl.c) {}
  std::vector<SectionPoint> pts;
  std::vector<Piece> pieces;

  int vertex_point(Index v) { return point(edge_key(v, v), [&] { return SectionPoint{v, -1, -1, m_.nodes[v], {}}; }); }
  int edge_point(Index a, Index b, double da, double db) {
    if (a > b) std::swap(a, b), std::swap(da, db);
    return point(edge_key(a, b), [&] {
      const double t = da / (da - db);
      return SectionPoint{-1, a, b, m_.nodes[a] + t * (m_.nodes[b] - m_.nodes[a]), {}};
    });
  }
  const PlaneFrame& frame() const { return frame_; }

 private:
  template <class Make>
  int point(std::uint64_t key, Make make) {
    auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    SectionPoint sp = make();
    sp.q = frame_.to2d(sp.p);
    pts.push_back(sp);
    return index_[key] = static_cast<int>(pts.size() - 1);
  }
  const PolyhedralModel& m_;
  PlaneFrame frame_;
  std::unordered_map<std::uint64_t, int> index_;
};

// What build_section needs of region r that no plane changes, made once while planes are tried
// one after another (the region is the same until a cut succeeds): its edge table, its live
// faces, its nodes in the order those faces first use them with their shortest edges, and each
// face's nodes as indices into that list. corpus/Zylkopf.brep's decomposition built 29,252
// sections, and measuring every node's shortest edge again for each was half their time.
//
// Every plane used to walk the whole edge table (a hash map: a cache miss an edge) for the few
// edges lying in the plane, and every face's nodes for the few faces it crosses: a third and a
// quarter of the sections' time on corpus/wrenchnut.brep's finest proxy. The edges at each node
// and a sphere round each face let a section look only where the plane is, in the same order.
struct RegionSnapshot {
  RegionEdges edges;
  std::vector<Index> faces;                        // m.live_faces(r)
  std::vector<int> slot;                           // per model node: its entry below, -1 when not the region's
  std::vector<std::pair<Index, NodeInfo>> nodes;   // min_len set
  std::vector<int> face_start, face_entry;         // faces[i]'s nodes: face_entry[face_start[i] .. face_start[i + 1])
  // the edges' keys in `edges`' own order, and per node entry the edges at it, as indices into
  // edge_keys: edge_at[edge_start[k] .. edge_start[k + 1]) (each edge under both its nodes);
  // empty when an edge's node has no entry (then the sections walk `edges` as before)
  std::vector<std::uint64_t> edge_keys;
  std::vector<int> edge_start, edge_at;
  double edge_length_sum = 0;                      // over edge_keys, in their order
  // per face: a centre and a radius holding its nodes (a plane farther away does not cross it)
  std::vector<Vec3> face_centre;
  std::vector<double> face_radius;
};
RegionSnapshot region_snapshot(const PolyhedralModel& m, Index r);

// Per-node data of one section, for the region's nodes only, looked up by node id. (A hash
// map here was the largest cost of a decomposition: every candidate plane builds one.) From a
// snapshot it starts with the region's nodes and their shortest edges, and shares the lookup.
class NodeTable {
 public:
  explicit NodeTable(std::size_t nodes) : own_(nodes, -1) {}
  explicit NodeTable(const RegionSnapshot& s) : shared_(&s.slot), entries_(s.nodes) {}
  NodeInfo& operator[](Index v) {
    if (shared_) {
      const int s = static_cast<std::size_t>(v) < shared_->size() ? (*shared_)[v] : -1;
      if (s >= 0) return entries_[s].second;
      // a node not of the region, or made after the snapshot (none is asked for): its own entry
      const auto [it, fresh] = extra_.try_emplace(v, static_cast<int>(entries_.size()));
      if (fresh) entries_.push_back({v, NodeInfo{}});
      return entries_[it->second].second;
    }
    int& s = own_[v];
    if (s < 0) {
      s = static_cast<int>(entries_.size());
      entries_.push_back({v, NodeInfo{}});
    }
    return entries_[s].second;
  }
  const NodeInfo& entry(int k) const { return entries_[k].second; }
  Index node(int k) const { return entries_[k].first; }
  auto begin() { return entries_.begin(); }
  auto end() { return entries_.end(); }
  auto begin() const { return entries_.begin(); }
  auto end() const { return entries_.end(); }
  int size() const { return static_cast<int>(entries_.size()); }

 private:
  const std::vector<int>* shared_ = nullptr;
  std::vector<int> own_;
  std::unordered_map<Index, int> extra_;
  std::vector<std::pair<Index, NodeInfo>> entries_;
};

struct SectionResult {
  const char* reject = nullptr;       // why no section could be built
  NodeTable info;
  std::vector<Index> near;            // nodes off the plane but too near it
  std::vector<int> on_plane;          // the entries of info on the plane, in info's order
  int measured = 0;                   // info's entries when their sides were set (later ones: on_plane too)
  Section sec;
  std::vector<std::vector<int>> loops;   // piece ids
  std::vector<std::vector<Vec2>> loop2d;
  std::vector<int> loop_of;           // per piece
  std::vector<int> poly_of;           // per loop
  std::vector<std::vector<int>> polys;   // loop ids, outer first
  SectionResult(const PolyhedralModel& m, const CutPlane& pl, const RegionSnapshot* snap)
      : info(snap ? NodeTable(*snap) : NodeTable(m.nodes.size())), sec(m, pl) {}
};

// Dry run of a face split before the model changes: whether splitting face f along `chords`
// gives simple polygons. New points have provisional negative ids: new_point(a, b) is the one
// that will be inserted into edge (a, b), or 0 for none; pos gives any id's position.
bool face_splits_cleanly(const PolyhedralModel& m, Index f, const std::vector<std::array<Index, 2>>& chords,
                         const std::function<Index(Index, Index)>& new_point, const std::function<Vec3(Index)>& pos);

// Builds the section of region r. With whole_plane, a node too near the plane rejects at once.
// `snap` is the region's snapshot when the caller keeps one (made with region_snapshot and
// unchanged while planes are tried one after another); without, the same is worked out here.
SectionResult build_section(const PolyhedralModel& m, Index r, const CutPlane& pl, bool whole_plane,
                            const DecomposeOptions& opt, const RegionSnapshot* snap = nullptr);

}  // namespace bisect
