#include "generated_solids.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bisect::testing {
namespace {

constexpr double kRb = 0.7, kCb = 1.2, kRh = 0.3;  // the second sphere and the hole

}  // namespace

PolyInput sphere_polyhedron(int facets, double radius) {
  // 2 * M * (L - 1) triangles for L latitude bands and M longitudes, with M = 2 L
  const int bands = std::max(3, static_cast<int>(std::lround(std::sqrt(facets / 4.0 + 0.25) + 0.5)));
  const int lon = std::max(3, static_cast<int>(std::lround(facets / (2.0 * (bands - 1)))));
  PolyInput in;
  in.source = "sphere-" + std::to_string(facets);
  in.nodes.push_back(Vec3(0, 0, radius));
  for (int i = 1; i < bands; ++i) {
    const double phi = M_PI * i / bands;
    for (int j = 0; j < lon; ++j) {
      const double th = 2 * M_PI * j / lon;
      in.nodes.push_back(radius * Vec3(std::sin(phi) * std::cos(th), std::sin(phi) * std::sin(th), std::cos(phi)));
    }
  }
  in.nodes.push_back(Vec3(0, 0, -radius));
  const Index south = static_cast<Index>(in.nodes.size() - 1);
  auto ring = [&](int i, int j) { return static_cast<Index>(1 + (i - 1) * lon + (j % lon)); };
  auto tri = [&](Index a, Index b, Index c) { in.faces.push_back({{a, b, c}, -1}); };
  for (int j = 0; j < lon; ++j) tri(0, ring(1, j), ring(1, j + 1));
  for (int i = 1; i + 1 < bands; ++i)
    for (int j = 0; j < lon; ++j) {
      tri(ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      tri(ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
  for (int j = 0; j < lon; ++j) tri(south, ring(bands - 1, j + 1), ring(bands - 1, j));
  PolyRegion r;
  for (std::size_t f = 0; f < in.faces.size(); ++f) r.faces.push_back(static_cast<Index>(f));
  in.regions.push_back(r);
  return in;
}

PolyInput double_sphere_with_hole(int facets) {
  // Profile in the (r, z) half-plane, counter-clockwise: up the outside of sphere A to the
  // circle where the spheres meet, up sphere B to the hole, down the hole wall.
  const double z_meet = (1.0 - kRb * kRb + kCb * kCb) / (2 * kCb);
  const double a_bottom = std::atan2(-std::sqrt(1 - kRh * kRh), kRh);   // angle on sphere A
  const double a_meet = std::atan2(z_meet, std::sqrt(1 - z_meet * z_meet));
  const double b_meet = std::atan2(z_meet - kCb, std::sqrt(1 - z_meet * z_meet));
  const double b_top = std::atan2(std::sqrt(kRb * kRb - kRh * kRh), kRh);
  const double z_bottom = -std::sqrt(1 - kRh * kRh), z_top = kCb + std::sqrt(kRb * kRb - kRh * kRh);
  // segment counts in proportion to arc lengths, about square faces
  const double len_a = a_meet - a_bottom, len_b = kRb * (b_top - b_meet), len_h = z_top - z_bottom;
  const double total = len_a + len_b + len_h;
  const double mean_r = 0.7;
  const int segments = std::max(8, static_cast<int>(std::lround(std::sqrt(facets * 2 * M_PI * mean_r / total))));
  const int profile = std::max(6, facets / segments);
  const int na = std::max(2, static_cast<int>(std::lround(profile * len_a / total)));
  const int nb = std::max(2, static_cast<int>(std::lround(profile * len_b / total)));
  const int nh = std::max(2, profile - na - nb);
  std::vector<Vec2> prof;  // (r, z)
  for (int i = 0; i < na; ++i) {
    const double t = a_bottom + (a_meet - a_bottom) * i / na;
    prof.push_back({std::cos(t), std::sin(t)});
  }
  for (int i = 0; i < nb; ++i) {
    const double t = b_meet + (b_top - b_meet) * i / nb;
    prof.push_back({kRb * std::cos(t), kCb + kRb * std::sin(t)});
  }
  for (int i = 0; i < nh; ++i) prof.push_back({kRh, z_top - (z_top - z_bottom) * i / nh});
  PolyInput in;
  in.source = "double-sphere-hole-" + std::to_string(facets);
  const int np = static_cast<int>(prof.size());
  for (int j = 0; j < segments; ++j) {
    const double th = 2 * M_PI * j / segments;
    for (const Vec2& p : prof) in.nodes.push_back(Vec3(p.x() * std::cos(th), p.x() * std::sin(th), p.y()));
  }
  auto id = [&](int j, int i) { return static_cast<Index>((j % segments) * np + (i % np)); };
  PolyRegion r;
  for (int j = 0; j < segments; ++j)
    for (int i = 0; i < np; ++i) {
      in.faces.push_back({{id(j, i), id(j, i + 1), id(j + 1, i + 1), id(j + 1, i)}, -1});
      r.faces.push_back(static_cast<Index>(in.faces.size() - 1));
    }
  in.regions.push_back(r);
  return in;
}

double double_sphere_with_hole_volume() {
  // volume of revolution of the profile minus the hole: integrate pi (r(z)^2 - rh^2) dz
  const double z_meet = (1.0 - kRb * kRb + kCb * kCb) / (2 * kCb);
  auto cap = [](double R, double z0, double z1) {  // integral of pi (R^2 - z^2) dz
    return M_PI * (R * R * (z1 - z0) - (z1 * z1 * z1 - z0 * z0 * z0) / 3);
  };
  const double z_bottom = -std::sqrt(1 - kRh * kRh), z_top = kCb + std::sqrt(kRb * kRb - kRh * kRh);
  const double outer = cap(1.0, z_bottom, z_meet) + cap(kRb, z_meet - kCb, z_top - kCb);
  return outer - M_PI * kRh * kRh * (z_top - z_bottom);
}

}  // namespace bisect::testing
