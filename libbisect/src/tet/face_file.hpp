// The faces of a set of tetrahedra, filed under their smallest node: the one way this code base
// matches faces (the complex's neighbours, the mesh's neighbours, the validator's boundary and
// non-manifold faces, the B-rep route's check for faces of three tetrahedra).
//
// A counting sort by the smallest node, then each node's few dozen faces sorted by their other
// two nodes and their id 4 t + f, so that equal faces lie next to each other in the order of
// their tetrahedra. A hash map of the open faces cost 1.2 s at 10^6 tetrahedra, a tenth of the
// run; this is a quarter of a second for the scatter and an eighth for the sorts, on one thread.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "bisect/tet_mesh.hpp"
#include "util/parallel_chunks.hpp"

namespace bisect::tet {

// One face of one tetrahedron: its two larger nodes (b < c; the smallest is the node it is
// filed under) and 4 t + f, f being the face opposite corner f (kTetFace's numbering).
struct FiledFace {
  Index b, c, tf;
  bool same_face(const FiledFace& o) const { return b == o.b && c == o.c; }
};

struct FaceFile {
  // node v's faces are faces[first[v] .. first[v + 1]), sorted by (b, c, tf)
  std::vector<std::uint32_t> first;
  std::vector<FiledFace> faces;
  std::size_t nodes() const { return first.empty() ? 0 : first.size() - 1; }
};

// 4 t + 3 must fit in an Index
constexpr std::size_t kMaxFiledTets = std::size_t{1} << 29;
// parts of the counting sort at most: each keeps a count per node, so one per thread on a
// machine of many cores would cost as much memory as the complex itself (64 parts at 5*10^6
// tetrahedra: 230 MB), for a scatter that memory bounds anyway
constexpr std::size_t kFileParts = 4;

// Files the faces of tetrahedra 0 .. tets-1. corners(t, std::array<Index, 4>& v) writes t's
// corners and returns false to leave t out. A face naming a node outside [0, nodes) is left
// out (the validator reports such nodes on its own). poll() is called between the steps, on
// the calling thread (a cancel hook may throw from it); the steps run on `threads` threads
// and the file is the same for every thread count.
template <class Corners, class Poll>
FaceFile file_faces(std::size_t nodes, std::size_t tets, int threads, Corners&& corners, Poll&& poll) {
  if (tets > kMaxFiledTets)
    throw std::length_error("face matching: " + std::to_string(tets) + " tetrahedra, more than it can number (" +
                            std::to_string(kMaxFiledTets) + ")");
  // the face f of corners v, sorted; false when it names a node that is not there
  const auto sorted_face = [nodes](const std::array<Index, 4>& v, int f, std::array<Index, 3>& k) {
    const auto& c = kTetFace[static_cast<std::size_t>(f)];
    Index a = v[c[0]], b = v[c[1]], d = v[c[2]];
    if (a > b) std::swap(a, b);
    if (b > d) std::swap(b, d);
    if (a > b) std::swap(a, b);
    k = {a, b, d};
    return a >= 0 && static_cast<std::size_t>(d) < nodes;
  };
  // Each part of the tetrahedra counts its faces per node, then writes them from its own
  // offsets: within a node's run the faces lie in tetrahedron order for any number of parts.
  const std::size_t parts = std::min<std::size_t>(kFileParts, static_cast<std::size_t>(std::max(1, util::thread_count(threads))));
  const std::size_t per_part = std::max<std::size_t>(1, (tets + parts - 1) / parts);
  const std::size_t n_parts = (tets + per_part - 1) / per_part;
  std::vector<std::vector<std::uint32_t>> at(n_parts, std::vector<std::uint32_t>(nodes, 0));
  // visit(part's counts, t, f, sorted face) for every face kept, part by part in parallel
  const auto each_face = [&](auto&& visit) {
    util::parallel_chunks(tets, threads, per_part, [&](std::size_t from, std::size_t to) {
      std::vector<std::uint32_t>& mine = at[from / per_part];
      std::array<Index, 4> v{};
      std::array<Index, 3> k{};
      for (std::size_t t = from; t < to; ++t) {
        if (!corners(t, v)) continue;
        for (int f = 0; f < 4; ++f)
          if (sorted_face(v, f, k)) visit(mine, t, f, k);
      }
    });
  };
  each_face([](std::vector<std::uint32_t>& count, std::size_t, int, const std::array<Index, 3>& k) {
    ++count[static_cast<std::size_t>(k[0])];
  });
  poll();
  FaceFile file;
  file.first.assign(nodes + 1, 0);
  for (std::size_t v = 0; v < nodes; ++v) {  // at[p][v] becomes where part p writes its first face of v
    std::uint32_t next = file.first[v];
    for (std::vector<std::uint32_t>& count : at) {
      const std::uint32_t c = count[v];
      count[v] = next;
      next += c;
    }
    file.first[v + 1] = next;
  }
  file.faces.resize(file.first[nodes]);
  each_face([&file](std::vector<std::uint32_t>& next, std::size_t t, int f, const std::array<Index, 3>& k) {
    file.faces[next[static_cast<std::size_t>(k[0])]++] = FiledFace{k[1], k[2], static_cast<Index>(4 * t + static_cast<std::size_t>(f))};
  });
  at = {};
  poll();
  constexpr std::size_t kNodesPerChunk = 4096;
  util::parallel_chunks(nodes, threads, kNodesPerChunk, [&](std::size_t from, std::size_t to) {
    for (std::size_t v = from; v < to; ++v)
      std::sort(file.faces.begin() + file.first[v], file.faces.begin() + file.first[v + 1], [](const FiledFace& x, const FiledFace& y) {
        return x.b != y.b ? x.b < y.b : x.c != y.c ? x.c < y.c : x.tf < y.tf;
      });
  });
  poll();
  return file;
}

// run(a, begin, end) for every face of node a: [begin, end) are the filed copies of one face
// (its tetrahedra in order), for the nodes [from, to).
template <class Run>
void for_each_face(const FaceFile& file, std::size_t from, std::size_t to, Run&& run) {
  for (std::size_t v = from; v < to; ++v) {
    const FiledFace* const end = file.faces.data() + file.first[v + 1];
    for (const FiledFace* i = file.faces.data() + file.first[v]; i != end;) {
      const FiledFace* j = i + 1;
      while (j != end && j->same_face(*i)) ++j;
      run(static_cast<Index>(v), i, j);
      i = j;
    }
  }
}

}  // namespace bisect::tet
