#include "tet/tet_complex.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "bisect/errors.hpp"
#include "bisect/quality.hpp"
#include "bisect/tet_mesh.hpp"
#include "geom/predicates.hpp"
#include "tet/face_file.hpp"
#include "util/parallel_chunks.hpp"

namespace bisect::tet {

namespace {
constexpr std::size_t kChunk = 32768;  // tetrahedra per chunk of build() and constrain() on the threads
// the step poll() always asks the cancel hook at: between the chunked steps, on this thread
constexpr std::size_t kPollNow = TetComplex::kPollEvery - 1;
}  // namespace

void TetComplex::poll(std::size_t step) const {
  if (cancelled && step % kPollEvery == kPollEvery - 1 && cancelled()) throw Cancelled();
}

using geom::orient3d;

FaceKey face_key(Index a, Index b, Index c) {
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}

bool positive(const std::vector<Vec3>& X, const Tet& t) { return orient3d(X[t[0]], X[t[1]], X[t[2]], X[t[3]]) > 0; }

double tet_angle_key(const std::vector<Vec3>& X, const Tet& t) {
  return signed_min_solid_angle_tan_half(X[t[0]], X[t[1]], X[t[2]], X[t[3]]);
}

void TetComplex::build(std::vector<Tet> tets, std::vector<Index> tags, int threads) {
  if (tets.size() > kMaxTets) throw MeshingError("tetrahedral complex: " + std::to_string(tets.size()) + " tetrahedra, more than it can number");
  tet = std::move(tets);
  tag = std::move(tags);
  tag.resize(tet.size(), 0);
  q.resize(tet.size());
  // the keys (10^6 tetrahedra: 0.06 s on one thread), and below the pairing, in chunks on the
  // threads: each writes its own slots. The cancel hook is polled between the steps only, on
  // this thread (the optimiser's progress callback is not for other threads).
  poll(kPollNow);
  util::parallel_chunks(tet.size(), threads, kChunk, [&](std::size_t from, std::size_t to) {
    for (std::size_t t = from; t < to; ++t) q[t] = tet_angle_key(X, tet[t]);
  });
  adj.assign(tet.size(), {-1, -1, -1, -1});
  alive.assign(tet.size(), 1);
  cmask_.assign(tet.size(), 0);
  born_.assign(tet.size(), ++clock_);
  failed_.clear();
  flip_failed_.clear();
  free_.clear();
  // Faces matched through their smallest node (face_file.hpp); equal faces pair up in the
  // order of their tetrahedra (a third equal face pairs with a fourth). Every slot of adj is
  // written by one node's run alone, so the pairing too runs in chunks on the threads.
  const FaceFile file = file_faces(
      X.size(), tet.size(), threads,  // every corner is a node of X
      [&](std::size_t t, std::array<Index, 4>& v) {
        v = tet[t];
        return true;
      },
      [&] { poll(kPollNow); });
  util::parallel_chunks(X.size(), threads, kChunk / 8, [&](std::size_t from, std::size_t to) {
    for_each_face(file, from, to, [&](Index, const FiledFace* h, const FiledFace* end) {
      for (; h + 1 < end; h += 2) {  // tf is 4 t + f already: the way back comes free
        adj[h->tf / 4][h->tf % 4] = (h + 1)->tf;
        adj[(h + 1)->tf / 4][(h + 1)->tf % 4] = h->tf;
      }
    });
  });
}

std::vector<Tet> TetComplex::tets() const {
  std::vector<Tet> out;
  out.reserve(live_count());
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t]) out.push_back(tet[t]);
  return out;
}

void TetComplex::constrain(const std::unordered_set<FaceKey, FaceKeyHash>& faces, int threads) {
  if (faces.empty()) return;
  // only a face whose three nodes are all on constrained faces is looked up (four hash lookups
  // a tetrahedron took 1.6 s at 10^6)
  std::vector<char> on(X.size(), 0);
  for (const FaceKey& k : faces)
    for (Index v : {k.a, k.b, k.c})
      if (v >= 0 && static_cast<std::size_t>(v) < on.size()) on[v] = 1;
  poll(kPollNow);
  // the set is only read, and each tetrahedron's mask is its own
  util::parallel_chunks(tet.size(), threads, kChunk, [&](std::size_t from, std::size_t to) {
    for (std::size_t t = from; t < to; ++t)
      if (alive[t])
        for (int f = 0; f < 4; ++f) {
          const auto fv = face(static_cast<Index>(t), f);
          if (!on[fv[0]] || !on[fv[1]] || !on[fv[2]]) continue;
          if (faces.count(face_key(fv[0], fv[1], fv[2]))) cmask_[t] |= static_cast<unsigned char>(1u << f);
        }
  });
}

void TetComplex::undo(std::vector<Replacement>& entries, const std::vector<Index>* among) {
  std::vector<Replacement>* const keep = journal;
  journal = nullptr;  // the undoing is not journalled
  // the tetrahedra by their nodes, not their ids: an id freed by a later change may have been
  // taken again, and what an undone change puts back comes under new ids
  std::unordered_map<FaceKey, std::vector<std::pair<Tet, Index>>, FaceKeyHash> where;
  const auto key = [](const Tet& t) { return face_key(t[0], t[1], t[2]); };
  for (const Replacement& r : entries)
    for (const Tet& t : r.made) where[key(t)];
  const auto look = [&](Index t) {
    if (!alive[t]) return;
    const auto it = where.find(key(tet[t]));
    if (it != where.end()) it->second.push_back({tet[t], t});
  };
  if (among) {
    std::vector<Index> ids = *among;  // once each
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for (Index t : ids) look(t);
  } else {
    for (std::size_t t = 0; t < tet.size(); ++t) look(static_cast<Index>(t));
  }
  const auto id_of = [&](const Tet& t) {
    for (const auto& [u, id] : where[key(t)])
      if (u == t && alive[id] && tet[id] == t) return id;
    throw MeshingError("tetrahedral complex: a change to undo is not in the complex");
  };
  for (auto r = entries.rbegin(); r != entries.rend(); ++r) {
    std::vector<Index> made;
    for (const Tet& t : r->made) made.push_back(id_of(t));
    const std::vector<Index> back = r->new_boundary ? undo_boundary_change(made, r->old) : replace(made, r->old);
    for (std::size_t i = 0; i < back.size(); ++i) {
      tag[back[i]] = r->old_tags[i];
      where[key(r->old[i])].push_back({r->old[i], back[i]});
    }
  }
  entries.clear();
  journal = keep;
}

std::vector<Index> TetComplex::undo_boundary_change(const std::vector<Index>& made, const std::vector<Tet>& old) {
  // The outer boundary's triangles of `made` that `old` has not go, with their input face (one:
  // a 2-2 flip stays within its face); `old`'s that `made` has not come back with it. Without
  // this, replace() took the old boundary triangles for faces meeting nothing (part.stl at 10^5
  // with --boundary-flips: the sliver repair's undone second go threw).
  const auto faces_of = [](const Tet& t) {
    return std::array<FaceKey, 4>{face_key(t[1], t[2], t[3]), face_key(t[0], t[2], t[3]), face_key(t[0], t[1], t[3]), face_key(t[0], t[1], t[2])};
  };
  std::unordered_set<FaceKey, FaceKeyHash> old_faces, made_faces;
  for (const Tet& t : old)
    for (const FaceKey& k : faces_of(t)) old_faces.insert(k);
  Index input_face = -1;
  for (Index m : made)
    for (int f = 0; f < 4; ++f) {
      const auto fv = face(m, f);
      const FaceKey k = face_key(fv[0], fv[1], fv[2]);
      made_faces.insert(k);
      if (neighbour(m, f) >= 0 || old_faces.count(k)) continue;
      const auto it = surface_tag.find(k);
      if (it == surface_tag.end()) continue;
      if (input_face >= 0 && it->second != input_face) throw MeshingError("tetrahedral complex: a boundary change to undo spans two input faces");
      input_face = it->second;
      surface_tag.erase(it);
    }
  std::vector<Index> back = replace(made, old, true);
  if (input_face >= 0)
    for (Index b : back)
      for (int f = 0; f < 4; ++f) {
        if (neighbour(b, f) >= 0) continue;
        const auto fv = face(b, f);
        const FaceKey k = face_key(fv[0], fv[1], fv[2]);
        if (!made_faces.count(k)) surface_tag.emplace(k, input_face);
      }
  return back;
}

void TetComplex::refresh_quality() {
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t]) q[t] = tet_angle_key(X, tet[t]);
  failed_.clear();
  flip_failed_.clear();
}

void TetComplex::moved(const std::vector<Index>& tets) {
  for (Index t : tets) q[t] = tet_angle_key(X, tet[t]);
  stamp_moved(tets);
}

void TetComplex::moved(const std::vector<Index>& tets, const std::vector<double>& keys) {
  for (std::size_t i = 0; i < tets.size(); ++i) q[tets[i]] = keys[i];
  stamp_moved(tets);
}

void TetComplex::stamp_moved(const std::vector<Index>& tets) {
  ++clock_;
  for (Index t : tets) born_[t] = clock_;
  if (changed) changed->insert(changed->end(), tets.begin(), tets.end());
}

std::vector<Index> TetComplex::tags() const {
  std::vector<Index> out;
  out.reserve(live_count());
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t]) out.push_back(tag[t]);
  return out;
}

std::array<Index, 3> TetComplex::face(Index t, int f) const {
  const auto& c = kTetFace[f];
  return {tet[t][c[0]], tet[t][c[1]], tet[t][c[2]]};
}

bool TetComplex::is_constrained(Index t, int f) const { return adj[t][f] < 0 || (cmask_[t] >> f & 1u); }

void TetComplex::hold(Index t, int f) {
  cmask_[t] |= static_cast<unsigned char>(1u << f);
  const Index n = neighbour(t, f);
  if (n >= 0) cmask_[n] |= static_cast<unsigned char>(1u << neighbour_face(t, f));
}

int TetComplex::corner_of(Index t, Index v) const {
  for (int k = 0; k < 4; ++k)
    if (tet[t][k] == v) return k;
  return -1;
}

std::vector<Index> TetComplex::tets_at(Index v) const {
  std::vector<Index> around;
  for (std::size_t t = 0; t < tet.size(); ++t)
    if (alive[t] && corner_of(static_cast<Index>(t), v) >= 0) around.push_back(static_cast<Index>(t));
  return around;
}

std::vector<Index> TetComplex::star(Index v, Index t0, std::size_t limit) const {
  // a stamp per tetrahedron marks what is in the list (a search of the list made this
  // quadratic in the star's size, a twentieth of the optimiser's time)
  const unsigned in = new_stamp();
  std::vector<Index> around{t0};
  mark_[t0] = in;
  for (std::size_t i = 0; i < around.size() && around.size() <= limit; ++i) {
    const Index t = around[i];
    for (int f = 0; f < 4; ++f) {
      if (tet[t][f] == v) continue;  // face f is opposite corner f: the others hold v
      const Index n = neighbour(t, f);
      if (n < 0 || marked(n, in)) continue;
      mark_[n] = in;
      around.push_back(n);
    }
  }
  return around;
}

int TetComplex::face_towards(Index t, Index other) const {
  for (int f = 0; f < 4; ++f)
    if (neighbour(t, f) == other) return f;
  return -1;
}

std::vector<Index> TetComplex::replace(const std::vector<Index>& old, const std::vector<Tet>& fresh, bool new_boundary) {
  // the old set's outside faces, with the tetrahedron (and its face) on the other side
  std::vector<Outer>& outer = outer_;
  outer.clear();
  const unsigned in_old = new_stamp();
  for (Index o : old) mark_[o] = in_old;
  for (Index o : old)
    for (int f = 0; f < 4; ++f) {
      const Index n = neighbour(o, f);
      if (marked(n, in_old)) continue;
      const auto fv = face(o, f);
      const int nf = n >= 0 ? neighbour_face(o, f) : -1;
      outer.push_back({face_key(fv[0], fv[1], fv[2]), n, nf, is_constrained(o, f)});
    }
  const Index inherited = old.empty() ? 0 : tag[old.front()];
  if (journal) {
    journal->push_back({{}, {}, {}, new_boundary});
    for (Index o : old) journal->back().old.push_back(tet[o]), journal->back().old_tags.push_back(tag[o]);
  }
  for (Index o : old) {
    alive[o] = 0;
    free_.push_back(o);
  }
  if (touched) touched->insert(touched->end(), old.begin(), old.end());
  std::vector<Index> ids;
  ids.reserve(fresh.size());
  for (const Tet& t : fresh) {
    Index id;
    if (!free_.empty()) {
      id = free_.back();
      free_.pop_back();
      tet[id] = t;
      adj[id] = {-1, -1, -1, -1};
      alive[id] = 1;
      tag[id] = inherited;
      q[id] = tet_angle_key(X, t);
      cmask_[id] = 0;
      born_[id] = clock_ + 1;
    } else {
      if (tet.size() >= kMaxTets) throw MeshingError("tetrahedral complex: more tetrahedra than it can number");
      id = static_cast<Index>(tet.size());
      tet.push_back(t);
      adj.push_back({-1, -1, -1, -1});
      alive.push_back(1);
      tag.push_back(inherited);
      q.push_back(tet_angle_key(X, t));
      cmask_.push_back(0);
      born_.push_back(clock_ + 1);
    }
    ids.push_back(id);
  }
  if (changed) changed->insert(changed->end(), ids.begin(), ids.end());
  if (touched) touched->insert(touched->end(), ids.begin(), ids.end());
  if (journal) journal->back().made = fresh;
  // match every new face with another new one or with an old outside face: equal keys meet (a
  // new face pairs with at most one other), found through a hash table of the keys (sorting
  // them was a tenth of a run at 10^6: a Delaunay cavity or an edge's ring has a hundred faces)
  std::vector<Side>& sides = sides_;
  sides.clear();
  for (Index id : ids)
    for (int f = 0; f < 4; ++f) {
      const auto fv = face(id, f);
      sides.push_back({face_key(fv[0], fv[1], fv[2]), id, f, true, false});
    }
  for (const Outer& o : outer) sides.push_back({o.key, o.n, o.nf, false, o.held});
  std::size_t capacity = 16;
  while (capacity < 2 * sides.size()) capacity *= 2;
  std::vector<Slot>& slots = slots_;
  slots.assign(capacity, Slot{});
  const std::size_t mask = capacity - 1;
  for (std::size_t i = 0; i < sides.size(); ++i) {
    const FaceKey& k = sides[i].key;
    std::size_t h = (static_cast<std::size_t>(k.a) * 0x9E3779B97F4A7C15ull ^ static_cast<std::size_t>(k.b) * 0xC2B2AE3D27D4EB4Full ^
                     static_cast<std::size_t>(k.c) * 0x165667B19E3779F9ull) >> 20;
    for (;; h = (h + 1) & mask) {
      Slot& s = slots[h & mask];
      if (s.first < 0) {
        s.first = static_cast<int>(i);
        break;
      }
      if (sides[s.first].key == k) {
        if (s.second < 0) s.second = static_cast<int>(i);
        ++s.more;  // a third side with this key
        break;
      }
    }
  }
  for (const Slot& s : slots) {
    if (s.first < 0) continue;
    const Side& a = sides[s.first];
    const bool fresh = a.fresh || (s.second >= 0 && sides[s.second].fresh);
    if (!fresh) {  // an old face no new tetrahedron took up: with new_boundary, the outer boundary
      if (new_boundary && s.second < 0 && a.t >= 0) adj[a.t][a.f] = -1;
      continue;
    }
    if (s.second < 0 && new_boundary) continue;  // a new face of the outer boundary
    if (s.second < 0 || s.more > 1) {
      // a new face that meets nothing, or three sides on one triangle: the new set does not meet
      // itself and the old set's outside face for face
      throw MeshingError("tetrahedral complex: a replacement does not fill the space it replaces");
    }
    const Side& b = sides[s.second];
    const Side& x = a.fresh ? a : b;
    const Side& y = a.fresh ? b : a;
    adj[x.t][x.f] = y.t >= 0 ? 4 * y.t + y.f : -1;
    if (y.t >= 0) adj[y.t][y.f] = 4 * x.t + x.f;
    if (y.held && y.t >= 0) cmask_[x.t] |= static_cast<unsigned char>(1u << x.f);  // a kept constrained face
  }
  ++clock_;
  return ids;
}

}  // namespace bisect::tet
