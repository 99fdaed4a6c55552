#include "optimize/block_pass.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

#include "bisect/errors.hpp"
#include "optimize/min_max_passes.hpp"
#include "util/ordered_parallel.hpp"

namespace bisect::optimize {

using tet::FaceKey;
using tet::Tet;

namespace {

// node_block: the node is in tetrahedra of two blocks or more, or of one outside every block
constexpr Index kShared = -2;
// Grids, each shifted by 1 / kGrids of a cube along every axis from the one before. A node is
// held by a grid when it is next to one of its walls. With two grids, the nodes next to walls of
// both (along the lines where they cross) were held twice: a tenth of lug's tetrahedra at 10^5
// were at one. With three, only points are held three times (0.4% of lug's at 10^6).
constexpr int kGrids = 3;
// Where each grid's work starts and ends, as a fraction of the whole (progress): the first grid's
// blocks hold every tetrahedron, the later ones' bands a few (lug at 10^6: 1.5, 0.35 and 0.1 s).
constexpr double kGridStart[kGrids + 1] = {0, 0.75, 0.95, 1};

// One block's work and result.
struct Block {
  std::vector<Index> members;  // indices into the tetrahedra, in order
  std::vector<Tet> tets;       // the result, in the global numbering
  std::vector<Index> tags;
  std::vector<std::pair<Index, Vec3>> moved;            // free nodes' new places
  std::vector<FaceKey> surface_in;                      // its outer faces with a tag at the start
  std::vector<std::pair<FaceKey, Index>> surface_out;   // and at the end, with their tags
  std::int64_t flips = 0, moves = 0;
};

// What every block of a grid reads.
struct Shared {
  const std::vector<Tet>& tets;
  const std::vector<Index>& tags;
  const std::vector<Vec3>& X;
  const std::vector<char>& fixed;
  const FaceSet& held;
  const std::vector<char>& on_held;  // per node: on a face of `held`
  const FaceTags& surface_tag;
  const BlockOptions& opt;
  const std::vector<Index>& node_block;
  const std::vector<char>& seeds;  // empty: every face and node; else the passes start at these nodes
  const std::function<bool()>& cancelled;
};

// The grid cell of each tetrahedron's centroid, numbered densely in the order of the cells (x
// slowest); the cells are cubes of side `side` from `origin`.
std::vector<Index> grid_labels(const std::vector<Tet>& tets, const std::vector<Vec3>& X, const Vec3& origin, double side, std::size_t* count) {
  std::vector<std::int64_t> key(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& k = tets[t];
    const Vec3 c = 0.25 * (X[k[0]] + X[k[1]] + X[k[2]] + X[k[3]]);
    std::int64_t id = 0;
    for (int a = 0; a < 3; ++a) {
      // 2^21 cells per axis: far more than a mesh cut into blocks of thousands has
      const auto i = static_cast<std::int64_t>(std::floor((c[a] - origin[a]) / side));
      id = (id << 21) | std::clamp<std::int64_t>(i, 0, (std::int64_t{1} << 21) - 1);
    }
    key[t] = id;
  }
  std::vector<std::int64_t> cells = key;
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::vector<Index> label(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
    label[t] = static_cast<Index>(std::lower_bound(cells.begin(), cells.end(), key[t]) - cells.begin());
  *count = cells.size();
  return label;
}

// One block as a complex of its own, its passes, and the result in the global numbering.
void optimise_block(const Shared& s, Block& b) {
  // local numbering: the block's nodes in their global order, so that the smoothing visits them
  // in the order a whole-mesh pass does; `local` is a slot per global node (-1 when not in the
  // block), kept per thread and cleared on every way out of each block
  thread_local std::vector<Index> local;
  local.resize(s.X.size(), -1);
  std::vector<Index> nodes;
  struct Clear {
    std::vector<Index>& local;
    const std::vector<Index>& nodes;
    ~Clear() {
      for (Index g : nodes) local[g] = -1;
    }
  } clear{local, nodes};
  for (Index m : b.members)
    for (Index v : s.tets[m])
      if (local[v] < 0) nodes.push_back(v), local[v] = 0;
  std::sort(nodes.begin(), nodes.end());
  std::vector<Vec3> x(nodes.size());
  std::vector<char> held(nodes.size());
  bool any_held_face = false;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Index g = nodes[i];
    local[g] = static_cast<Index>(i);
    x[i] = s.X[g];
    held[i] = (static_cast<std::size_t>(g) < s.fixed.size() && s.fixed[g]) || s.node_block[g] == kShared;
    any_held_face = any_held_face || s.on_held[g];
  }
  std::vector<Tet> tets(b.members.size());
  std::vector<Index> tags(b.members.size());
  for (std::size_t i = 0; i < b.members.size(); ++i) {
    const Tet& k = s.tets[b.members[i]];
    tets[i] = {local[k[0]], local[k[1]], local[k[2]], local[k[3]]};
    tags[i] = s.tags[b.members[i]];
  }
  tet::TetComplex cx(x);
  cx.edge_removal_below = s.opt.edge_removal_below;
  cx.boundary_flips = s.opt.boundary_flips;
  cx.cancelled = s.cancelled;
  cx.build(std::move(tets), std::move(tags));
  // the held faces inside the block, and the surface's tags (wanted by the 2-2 transformation
  // alone) on its outer faces; a face is looked up only when its three nodes are on held faces
  const bool tagged = s.opt.boundary_flips && !s.surface_tag.empty();
  if (any_held_face || tagged) {
    FaceSet held_faces;
    for (std::size_t t = 0; t < cx.tet.size(); ++t)
      for (int f = 0; f < 4; ++f) {
        const auto fv = cx.face(static_cast<Index>(t), f);
        const FaceKey g = tet::face_key(nodes[fv[0]], nodes[fv[1]], nodes[fv[2]]);
        if (!s.on_held[g.a] || !s.on_held[g.b] || !s.on_held[g.c]) continue;
        if (cx.neighbour(t, f) >= 0) {
          if (s.held.count(g)) held_faces.insert(tet::face_key(fv[0], fv[1], fv[2]));
        } else if (tagged) {
          const auto it = s.surface_tag.find(g);
          if (it == s.surface_tag.end()) continue;
          cx.surface_tag[tet::face_key(fv[0], fv[1], fv[2])] = it->second;
          b.surface_in.push_back(g);
        }
      }
    cx.constrain(held_faces);
  }
  PassCounts pc;
  if (s.seeds.empty()) {
    pc = min_max_passes(cx, x, held, s.opt.passes, s.opt.smooth_passes, nullptr);
  } else {  // from the tetrahedra at the nodes the earlier grids held
    std::vector<Index> from;
    for (std::size_t t = 0; t < cx.tet.size(); ++t)
      for (Index v : cx.tet[t])
        if (s.seeds[nodes[v]]) {
          from.push_back(static_cast<Index>(t));
          break;
        }
    pc = min_max_passes(cx, x, held, s.opt.passes, s.opt.smooth_passes, &from);
  }
  b.flips = pc.flips, b.moves = pc.moves;
  b.tets = cx.tets();
  b.tags = cx.tags();
  for (Tet& k : b.tets)
    for (Index& v : k) v = nodes[v];
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!held[i] && x[i] != s.X[nodes[i]]) b.moved.push_back({nodes[i], x[i]});
  for (const auto& [k, tag] : cx.surface_tag) b.surface_out.push_back({tet::face_key(nodes[k.a], nodes[k.b], nodes[k.c]), tag});
}

}  // namespace

std::size_t block_size(std::size_t tets) { return std::max(kBlockTets, tets / 16); }

BlockPassCounts block_pass(std::vector<Tet>& tets, std::vector<Index>& tags, std::vector<Vec3>& X, const std::vector<char>& fixed,
                           const FaceSet& held, FaceTags& surface_tag, const BlockOptions& opt, const std::function<bool(double)>& progress) {
  BlockPassCounts n;
  if (tets.size() < 2 * kBlockTets) return n;
  tags.resize(tets.size(), 0);
  std::vector<char> on_held(X.size(), 0);
  for (const FaceKey& k : held)
    for (Index v : {k.a, k.b, k.c})
      if (v >= 0 && static_cast<std::size_t>(v) < X.size()) on_held[v] = 1;
  // the grid: cubes that hold block_size() tetrahedra each where the mesh fills them
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
  double volume = 0;
  for (const Tet& k : tets) {
    for (Index v : k) lo = lo.cwiseMin(X[v]);
    volume += std::abs((X[k[1]] - X[k[0]]).dot((X[k[2]] - X[k[0]]).cross(X[k[3]] - X[k[0]]))) / 6;
  }
  const double side = std::cbrt(volume * static_cast<double>(block_size(tets.size())) / static_cast<double>(tets.size()));
  // Stop: asked on this thread, a flag for the others
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> stop{false};
  double done = 0;  // the fraction of the work done (set on this thread, as blocks are taken up)
  const std::function<bool()> hook = [&] {
    if (progress && std::this_thread::get_id() == caller && !progress(done)) stop.store(true);
    return stop.load();
  };
  std::vector<char> seeds;  // the nodes every grid so far had at a wall (none before the first)
  for (int grid = 0; grid < kGrids; ++grid) {
    const Vec3 origin = lo - Vec3::Constant(side * grid / kGrids);
    std::size_t count = 0;
    std::vector<Index> label = grid_labels(tets, X, origin, side, &count);
    if (grid == 0) n.blocks = count;
    if (grid > 0) {
      // only the band round the seeds: the tetrahedra two layers of nodes from one (the passes
      // start there and seldom go further); the rest stays as it is, outside every block (-1)
      std::vector<char> near = seeds;
      for (const Tet& k : tets)
        if (seeds[k[0]] || seeds[k[1]] || seeds[k[2]] || seeds[k[3]])
          for (Index v : k) near[v] = 1;
      for (std::size_t t = 0; t < tets.size(); ++t) {
        const Tet& k = tets[t];
        if (!(near[k[0]] || near[k[1]] || near[k[2]] || near[k[3]])) label[t] = -1;
      }
    }
    std::vector<Block> blocks(count);
    std::vector<Index> node_block(X.size(), -1);
    std::vector<Tet> out_tets;  // the result: the tetrahedra outside the blocks, then block by block
    std::vector<Index> out_tags;
    for (std::size_t t = 0; t < tets.size(); ++t) {
      const Index l = label[t];
      if (l >= 0) {
        blocks[l].members.push_back(static_cast<Index>(t));
      } else {
        out_tets.push_back(tets[t]);
        out_tags.push_back(tags[t]);
      }
      for (Index v : tets[t]) node_block[v] = l >= 0 && (node_block[v] == -1 || node_block[v] == l) ? l : kShared;
    }
    // the largest blocks first, so that no thread is left with a big one at the end
    std::vector<std::size_t> order(count);
    for (std::size_t i = 0; i < count; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return blocks[a].members.size() > blocks[b].members.size(); });
    FaceTags out_surface;  // each block's outer faces' tags are replaced by what it made
    if (opt.boundary_flips) out_surface = surface_tag;
    const Shared shared{tets, tags, X, fixed, held, on_held, surface_tag, opt, node_block, seeds, hook};
    std::size_t members = 0, taken = 0;  // tetrahedra in the grid's blocks, and in those taken up
    for (const Block& b : blocks) members += b.members.size();
    util::ordered_parallel(
        count, util::thread_count(opt.threads),
        [&](std::size_t i) {
          if (!blocks[i].members.empty()) optimise_block(shared, blocks[i]);
        },
        [&](std::size_t i) {
          Block& b = blocks[i];
          out_tets.insert(out_tets.end(), b.tets.begin(), b.tets.end());
          out_tags.insert(out_tags.end(), b.tags.begin(), b.tags.end());
          // a moved node is in this block's tetrahedra alone: no other block reads it
          for (const auto& [v, p] : b.moved) X[v] = p;
          for (const FaceKey& k : b.surface_in) out_surface.erase(k);
          for (const auto& [k, tag] : b.surface_out) out_surface[k] = tag;
          n.flips += b.flips, n.moves += b.moves;
          taken += b.members.size();
          done = kGridStart[grid] + (kGridStart[grid + 1] - kGridStart[grid]) * static_cast<double>(taken) / static_cast<double>(std::max<std::size_t>(members, 1));
          b = Block{};
        },
        order, [&] { hook(); });
    if (stop.load()) throw Cancelled();
    tets = std::move(out_tets);
    tags = std::move(out_tags);
    if (opt.boundary_flips) surface_tag = std::move(out_surface);
    if (grid == 0) seeds.assign(X.size(), 1);
    // fixed nodes too: a tetrahedron with every node on the surface can sit at a wall without a
    // free node (lug at 10^6: one at 5.3 degrees was left so, which the passes over the whole
    // mesh had flipped away)
    for (std::size_t v = 0; v < X.size(); ++v) seeds[v] = seeds[v] && node_block[v] == kShared;
  }
  n.held_throughout = std::move(seeds);
  return n;
}

}  // namespace bisect::optimize
