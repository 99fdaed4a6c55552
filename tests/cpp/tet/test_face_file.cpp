// face_file.hpp, the one face matching of the code base, against a plain std::map of the faces:
// every face filed once under its smallest node, equal faces side by side in the order of
// their tetrahedra, the same file for every thread count, and what it leaves out.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <vector>

#include "tet/face_file.hpp"
#include "tet/tet_test_meshes.hpp"

namespace bisect::tet {
namespace {

FaceFile file_of(const TetMesh& m, int threads) {
  return file_faces(
      m.nodes.size(), m.num_tets(), threads,
      [&](std::size_t t, std::array<Index, 4>& v) {
        for (int k = 0; k < 4; ++k) v[static_cast<std::size_t>(k)] = m.tet_node(t, k);
        return true;
      },
      [] {});
}

// per sorted face: the codes 4 t + f of the tetrahedra that have it, in order
std::map<std::array<Index, 3>, std::vector<Index>> faces_by_map(const TetMesh& m) {
  std::map<std::array<Index, 3>, std::vector<Index>> out;
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      std::array<Index, 3> k{};
      for (int i = 0; i < 3; ++i) k[static_cast<std::size_t>(i)] = m.tet_node(t, kTetFace[static_cast<std::size_t>(f)][static_cast<std::size_t>(i)]);
      std::sort(k.begin(), k.end());
      out[k].push_back(static_cast<Index>(4 * t + static_cast<std::size_t>(f)));
    }
  return out;
}

std::map<std::array<Index, 3>, std::vector<Index>> faces_by_file(const FaceFile& file) {
  std::map<std::array<Index, 3>, std::vector<Index>> out;
  for_each_face(file, 0, file.nodes(), [&](Index a, const FiledFace* i, const FiledFace* j) {
    EXPECT_LT(a, i->b);
    EXPECT_LT(i->b, i->c);
    auto& codes = out[{a, i->b, i->c}];
    EXPECT_TRUE(codes.empty()) << "face " << a << " " << i->b << " " << i->c << " came in two runs";
    for (; i != j; ++i) codes.push_back(i->tf);
  });
  return out;
}

TEST(FaceFile, FilesEveryFaceOnceWithItsTetrahedraInOrder) {
  const TetMesh m = test::cube_mesh(6);  // 1296 tetrahedra
  const auto want = faces_by_map(m);
  const FaceFile file = file_of(m, 1);
  EXPECT_EQ(file.faces.size(), 4 * m.num_tets());
  EXPECT_EQ(faces_by_file(file), want);
  std::size_t shared = 0;
  for (const auto& [face, codes] : want) shared += codes.size() == 2;
  EXPECT_GT(shared, 2000u);  // the run pairs are really there, not only boundary faces
}

TEST(FaceFile, IsTheSameForEveryThreadCount) {
  const TetMesh m = test::cube_mesh(9);  // 4374 tetrahedra: four parts in the counting sort
  const FaceFile one = file_of(m, 1);
  for (int threads : {2, 3, 4}) {
    const FaceFile many = file_of(m, threads);
    ASSERT_EQ(many.first, one.first) << threads << " threads";
    ASSERT_EQ(many.faces.size(), one.faces.size());
    for (std::size_t i = 0; i < one.faces.size(); ++i) {
      ASSERT_EQ(many.faces[i].b, one.faces[i].b) << threads << " threads, face " << i;
      ASSERT_EQ(many.faces[i].c, one.faces[i].c);
      ASSERT_EQ(many.faces[i].tf, one.faces[i].tf);
    }
  }
}

TEST(FaceFile, AFaceOfThreeTetrahedraIsOneRunOfThree) {
  TetMesh m = test::two_tet_mesh();
  const Index third[4] = {0, 1, 2, 3};  // the first one again: face 0 1 2 now has three
  m.add_tet(third);
  const auto got = faces_by_file(file_of(m, 2));
  const auto it = got.find({0, 1, 2});
  ASSERT_NE(it, got.end());
  EXPECT_EQ(it->second, (std::vector<Index>{3, 4 * 1 + 3, 4 * 2 + 3}));  // face 3 of each, in tetrahedron order
}

TEST(FaceFile, LeavesOutTetrahedraRefusedAndFacesOfMissingNodes) {
  TetMesh m = test::two_tet_mesh();
  const Index bad[4] = {0, 1, 3, 7};  // node 7 does not exist: its three faces at 7 go, 0 1 3 stays
  m.add_tet(bad);
  const FaceFile all = file_of(m, 1);
  EXPECT_EQ(all.faces.size(), 8u + 1u);
  const auto got = faces_by_file(all);
  EXPECT_EQ(got.at({0, 1, 3}).size(), 2u);  // the first tetrahedron's face and the bad one's

  const FaceFile kept = file_faces(
      m.nodes.size(), m.num_tets(), 1,
      [&](std::size_t t, std::array<Index, 4>& v) {
        for (int k = 0; k < 4; ++k) v[static_cast<std::size_t>(k)] = m.tet_node(t, k);
        return t != 0;  // the first tetrahedron left out
      },
      [] {});
  const auto rest = faces_by_file(kept);
  EXPECT_EQ(kept.faces.size(), 4u + 1u);
  EXPECT_EQ(rest.at({0, 1, 2}), (std::vector<Index>{4 * 1 + 3}));  // only the second's
  EXPECT_EQ(rest.at({0, 1, 3}), (std::vector<Index>{4 * 2 + 3}));  // face 3 of the bad one
}

TEST(FaceFile, RefusesMoreTetrahedraThanItCanNumber) {
  EXPECT_THROW(file_faces(
                   4, kMaxFiledTets + 1, 1, [](std::size_t, std::array<Index, 4>&) { return false; }, [] {}),
               std::length_error);
}

TEST(FaceFile, PollsBetweenItsSteps) {
  const TetMesh m = test::cube_mesh(3);
  int polls = 0;
  struct Stop {};
  EXPECT_THROW(file_faces(
                   m.nodes.size(), m.num_tets(), 2,
                   [&](std::size_t t, std::array<Index, 4>& v) {
                     for (int k = 0; k < 4; ++k) v[static_cast<std::size_t>(k)] = m.tet_node(t, k);
                     return true;
                   },
                   [&] {
                     if (++polls == 2) throw Stop{};
                   }),
               Stop);
  EXPECT_EQ(polls, 2);
}

}  // namespace
}  // namespace bisect::tet
