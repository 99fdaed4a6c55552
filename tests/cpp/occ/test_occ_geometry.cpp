// The adapter's surfaces and curves: exact derivatives, closest points, and evaluation from
// several threads at once that gives the serial results bit for bit.
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Extrema_GenLocateExtPS.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_OffsetSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>

#include "occ_checks.hpp"
#include "occ_geometry.hpp"
#include "occ_shapes.hpp"

namespace bisect {
namespace {

using test::input_of;

// A wavy bicubic B-spline patch over [0,4] x [0,3] with uniform knots and many spans (what makes
// adaptor caches matter), and an offset surface over it (whose evaluator nests the B-spline).
Handle(Geom_BSplineSurface) wavy_bspline() {
  const int nu = 12, nv = 9;
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  for (int i = 1; i <= nu; ++i)
    for (int j = 1; j <= nv; ++j) {
      const double x = 4.0 * (i - 1) / (nu - 1), y = 3.0 * (j - 1) / (nv - 1);
      poles(i, j) = gp_Pnt(x, y, 0.3 * std::sin(1.5 * x) * std::cos(2 * y));
    }
  auto knots = [](int n, TColStd_Array1OfReal& k, TColStd_Array1OfInteger& m) {
    for (int i = 1; i <= n - 2; ++i) k(i) = i - 1, m(i) = (i == 1 || i == n - 2) ? 4 : 1;
  };
  TColStd_Array1OfReal uk(1, nu - 2), vk(1, nv - 2);
  TColStd_Array1OfInteger um(1, nu - 2), vm(1, nv - 2);
  knots(nu, uk, um);
  knots(nv, vk, vm);
  return new Geom_BSplineSurface(poles, uk, vk, um, vm, 3, 3);
}

TopoDS_Face face_on(const Handle(Geom_Surface)& s) { return BRepBuilderAPI_MakeFace(s, 1e-7).Face(); }

// Derivatives against central differences of the next lower order.
void expect_exact_derivatives(const BrepInput& in) {
  for (size_t f = 0; f < in.faces.size(); ++f) {
    const ParametricSurface& s = *in.faces[f].surface;
    const Vec2 lo = s.uv_min(), hi = s.uv_max(), span = hi - lo;
    const double hu = 1e-6 * span.x(), hv = 1e-6 * span.y();
    for (int i = 1; i <= 3; ++i)
      for (int j = 1; j <= 3; ++j) {
        const Vec2 uv = lo + Vec2(0.25 * i * span.x(), 0.25 * j * span.y());
        Vec3 du, dv, duu, duv, dvv, a, b, c, d;
        s.derivatives(uv, &du, &dv);
        s.second_derivatives(uv, &duu, &duv, &dvv);
        const Vec3 fu = (s.point(uv + Vec2(hu, 0)) - s.point(uv - Vec2(hu, 0))) / (2 * hu);
        const Vec3 fv = (s.point(uv + Vec2(0, hv)) - s.point(uv - Vec2(0, hv))) / (2 * hv);
        const double scale = 1 + du.norm() + dv.norm();
        EXPECT_LT((du - fu).norm(), 1e-5 * scale) << in.source << " " << face_name(f);
        EXPECT_LT((dv - fv).norm(), 1e-5 * scale) << in.source << " " << face_name(f);
        s.derivatives(uv + Vec2(hu, 0), &a, &b);
        s.derivatives(uv - Vec2(hu, 0), &c, &d);
        const double scale2 = 1 + duu.norm() + duv.norm() + dvv.norm();
        EXPECT_LT((duu - (a - c) / (2 * hu)).norm(), 1e-4 * scale2) << in.source << " " << face_name(f);
        EXPECT_LT((duv - (b - d) / (2 * hu)).norm(), 1e-4 * scale2) << in.source << " " << face_name(f);
      }
  }
  for (size_t e = 0; e < in.edges.size(); ++e) {
    if (!in.edges[e].curve) continue;
    const ParametricCurve& c = *in.edges[e].curve;
    const double h = 1e-6 * (c.t_max() - c.t_min());
    for (int i = 1; i <= 3; ++i) {
      const double t = c.t_min() + 0.25 * i * (c.t_max() - c.t_min());
      const Vec3 d1 = c.derivative(t), d2 = c.second_derivative(t);
      EXPECT_LT((d1 - (c.point(t + h) - c.point(t - h)) / (2 * h)).norm(), 1e-5 * (1 + d1.norm())) << edge_name(e);
      EXPECT_LT((d2 - (c.derivative(t + h) - c.derivative(t - h)) / (2 * h)).norm(), 1e-4 * (1 + d2.norm())) << edge_name(e);
    }
  }
}

TEST(OccGeometry, DerivativesAreExact) {
  for (auto make : {test::make_cylinder, test::make_sphere, test::make_nurbs_part, test::make_revolved_bspline})
    expect_exact_derivatives(input_of(make()));
}

TEST(OccGeometry, CurvatureOfCirclesAndSpheres) {
  const BrepInput cyl = input_of(test::make_cylinder());
  for (const BrepEdge& e : cyl.edges)
    if (e.v0 == e.v1) {
      EXPECT_NEAR(e.curve->curvature(0.7), 1.0, 1e-12) << "a circle of radius 1";
    }
  const BrepInput nurbs = input_of(test::make_nurbs_part());
  for (const BrepFace& f : nurbs.faces) {
    if (f.surface->period_u() > 0 || f.surface->period_v() > 0) continue;
    const Vec2 mid = 0.5 * (f.surface->uv_min() + f.surface->uv_max());
    const double k = f.surface->max_curvature(mid);
    // the bore (radius 1) as a rational B-spline, the rest planes
    EXPECT_TRUE(std::abs(k) < 1e-9 || std::abs(k - 1) < 1e-9) << k;
  }
}

TEST(OccGeometry, ClosestPointsComeBack) {
  for (auto make : {test::make_box_minus_cylinder, test::make_sphere, test::make_nurbs_part, test::make_revolved_bspline})
    test::check_closest_points(input_of(make()));
  // on a periodic parameter the answer is the one nearest the guess, not the box's
  const BrepInput cyl = input_of(test::make_cylinder());
  for (const BrepFace& f : cyl.faces) {
    if (f.planar) continue;
    const Vec2 uv(0.05, 1.0);
    const Vec2 back = f.surface->closest_point(f.surface->point(uv), Vec2(2 * M_PI - 0.02, 0.9));
    EXPECT_NEAR(back.x(), 2 * M_PI + 0.05, 1e-9);
    EXPECT_NEAR(back.y(), 1.0, 1e-9);
  }
}

// Everything one surface gives at the parameters, evaluated in the given order: points, first
// and second derivatives.
std::vector<double> evaluate_all(const ParametricSurface& s, const std::vector<Vec2>& uv, const std::vector<size_t>& order) {
  std::vector<double> out(uv.size() * 18);
  for (size_t i : order) {
    Vec3 v[6];
    v[0] = s.point(uv[i]);
    s.derivatives(uv[i], &v[1], &v[2]);
    s.second_derivatives(uv[i], &v[3], &v[4], &v[5]);
    for (int k = 0; k < 6; ++k)
      for (int j = 0; j < 3; ++j) out[18 * i + 3 * k + j] = v[k][j];
  }
  return out;
}

std::vector<size_t> shuffled(size_t n, unsigned seed) {
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  if (seed) std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  return order;
}

// Parameters spread over the box, with some a few ulps below the B-spline's knots: where a
// cached span and a fresh lookup disagree (knot_snap.hpp).
std::vector<Vec2> samples(const ParametricSurface& s, const Handle(Geom_BSplineSurface)& bs) {
  std::vector<Vec2> uv;
  const Vec2 lo = s.uv_min(), hi = s.uv_max();
  for (int i = 0; i < 4000; ++i) {
    const double a = std::fmod(i * 0.6180339887498949, 1.0), b = std::fmod(i * 0.7548776662466927, 1.0);
    uv.emplace_back(lo.x() + a * (hi.x() - lo.x()), lo.y() + b * (hi.y() - lo.y()));
  }
  auto below = [](double k, int ulps) {
    for (int i = 0; i < ulps; ++i) k = std::nextafter(k, -1e300);
    return k;
  };
  if (!bs.IsNull())
    for (int i = bs->FirstUKnotIndex(); i <= bs->LastUKnotIndex(); ++i)
      for (int j = bs->FirstVKnotIndex(); j <= bs->LastVKnotIndex(); ++j)
        for (int k = 0; k <= 3; ++k) uv.emplace_back(below(bs->UKnot(i), k), below(bs->VKnot(j), 3 - k));
  return uv;
}

TEST(OccGeometry, ConcurrentEvaluationGivesTheSerialResults) {
  const Handle(Geom_BSplineSurface) bs = wavy_bspline();
  const Handle(Geom_Surface) offset = new Geom_OffsetSurface(bs, 0.05);
  const BrepInput revolved = input_of(test::make_revolved_bspline());
  std::vector<std::shared_ptr<const ParametricSurface>> surfaces = {
      std::make_shared<occ::OccSurface>(face_on(bs), 0), std::make_shared<occ::OccSurface>(face_on(offset), 0)};
  for (const BrepFace& f : revolved.faces) surfaces.push_back(f.surface);
  for (size_t k = 0; k < surfaces.size(); ++k) {
    const ParametricSurface& s = *surfaces[k];
    const std::vector<Vec2> uv = samples(s, k == 0 ? bs : Handle(Geom_BSplineSurface)());
    const std::vector<double> serial = evaluate_all(s, uv, shuffled(uv.size(), 0));
    // four threads at once, each in its own order: their caches hold other spans before each
    // point than the serial run's did
    std::vector<std::vector<double>> results(4);
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < 4; ++t)
      threads.emplace_back([&, t] { results[t] = evaluate_all(s, uv, shuffled(uv.size(), t + 1)); });
    for (auto& th : threads) th.join();
    for (int t = 0; t < 4; ++t) EXPECT_TRUE(results[t] == serial) << "surface " << k << ", thread " << t;
  }
}

TEST(OccGeometry, ConcurrentCurvesAndPcurvesGiveTheSerialResults) {
  const BrepInput in = input_of(test::make_nurbs_part());
  std::vector<std::pair<const ParameterCurve*, const ParametricCurve*>> pcurves;  // with its edge's curve (range)
  for (const BrepFace& f : in.faces)
    for (const auto& w : f.wires)
      for (const auto& u : w) pcurves.emplace_back(u.pcurve.get(), in.edges[u.edge].curve.get());
  auto run = [&](size_t offset) {
    std::vector<double> out;
    for (size_t k = 0; k < in.edges.size(); ++k) {
      const ParametricCurve& c = *in.edges[(k + offset) % in.edges.size()].curve;
      for (int i = 0; i <= 200; ++i) {
        const double t = c.t_min() + (c.t_max() - c.t_min()) * ((i * 37) % 201) / 200.0;
        const Vec3 p = c.point(t), d = c.derivative(t), dd = c.second_derivative(t);
        out.insert(out.end(), {p.x(), p.y(), p.z(), d.x(), d.y(), d.z(), dd.x(), dd.y(), dd.z()});
      }
    }
    for (size_t k = 0; k < pcurves.size(); ++k)
      for (int i = 0; i <= 200; ++i) {
        const auto& [pc, c] = pcurves[(k + offset) % pcurves.size()];
        const Vec2 q = pc->uv(c->t_min() + (c->t_max() - c->t_min()) * ((i * 37) % 201) / 200.0);
        out.insert(out.end(), {q.x(), q.y()});
      }
    return out;
  };
  // each run visits the curves in its own order; the serial run in the same order is the reference
  std::vector<std::vector<double>> serial(3), threaded(3);
  for (int t = 0; t < 3; ++t) serial[t] = run(t * 5);
  std::vector<std::thread> threads;
  for (int t = 0; t < 3; ++t) threads.emplace_back([&, t] { threaded[t] = run(t * 5); });
  for (auto& th : threads) th.join();
  for (int t = 0; t < 3; ++t) EXPECT_TRUE(threaded[t] == serial[t]) << "thread " << t;
}

TEST(OccGeometry, ValuesDoNotDependOnTheCachedSpan) {
  // a parameter one ulp below a knot, evaluated after a point in the span below and after one in
  // the span above: the same value both times
  const Handle(Geom_BSplineSurface) bs = wavy_bspline();
  const occ::OccSurface s(face_on(bs), 0);
  ASSERT_GT(bs->NbUKnots(), 3);
  for (int i = bs->FirstUKnotIndex() + 1; i < bs->LastUKnotIndex(); ++i) {
    const double k = bs->UKnot(i), below = bs->UKnot(i - 1), above = bs->UKnot(i + 1);
    const Vec2 at(std::nextafter(k, -1e300), 1.3);
    s.point(Vec2(0.5 * (below + k), 1.3));
    const Vec3 a = s.point(at);
    s.point(Vec2(0.5 * (k + above), 1.3));
    const Vec3 b = s.point(at);
    EXPECT_EQ(a, b) << "knot " << i;
  }
}

TEST(OccGeometry, ClosestPointSpeedAgainstPeers) {
  // the adapter's Newton against the base class's (Newton, then a 9 x 9 grid around the guess)
  // and OpenCASCADE's Extrema_GenLocateExtPS, from guesses 2% of the box away
  const Handle(Geom_BSplineSurface) bs = wavy_bspline();
  const TopoDS_Face face = face_on(bs);
  const occ::OccSurface s(face, 0);
  struct Base : ParametricSurface {
    const ParametricSurface& s;
    explicit Base(const ParametricSurface& x) : s(x) {}
    Vec3 point(const Vec2& uv) const override { return s.point(uv); }
    void derivatives(const Vec2& uv, Vec3* a, Vec3* b) const override { s.derivatives(uv, a, b); }
    void second_derivatives(const Vec2& uv, Vec3* a, Vec3* b, Vec3* c) const override { s.second_derivatives(uv, a, b, c); }
    Vec2 uv_min() const override { return s.uv_min(); }
    Vec2 uv_max() const override { return s.uv_max(); }
  } base(s);
  GeomAdaptor_Surface adaptor(bs);
  std::vector<Vec3> pts;
  std::vector<Vec2> guesses;
  const Vec2 lo = s.uv_min(), box = s.uv_max() - s.uv_min();
  for (int i = 0; i < 3000; ++i) {
    const Vec2 uv = lo + Vec2(0.05 + 0.9 * std::fmod(i * 0.618034, 1.0), 0.05 + 0.9 * std::fmod(i * 0.754878, 1.0)).cwiseProduct(box);
    Vec3 du, dv;
    s.derivatives(uv, &du, &dv);
    pts.push_back(s.point(uv) + 0.01 * du.cross(dv).normalized());
    guesses.push_back(uv + Vec2(0.02, -0.02).cwiseProduct(box));
  }
  auto time = [&](auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    double worst = 0;
    for (size_t i = 0; i < pts.size(); ++i) worst = std::max(worst, f(i));
    return std::make_pair(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), worst);
  };
  const auto ours = time([&](size_t i) { return (s.point(s.closest_point(pts[i], guesses[i])) - pts[i]).norm(); });
  const auto theirs = time([&](size_t i) { return (s.point(base.closest_point(pts[i], guesses[i])) - pts[i]).norm(); });
  const auto occt = time([&](size_t i) {
    const gp_Pnt p(pts[i].x(), pts[i].y(), pts[i].z());
    Extrema_GenLocateExtPS ext(adaptor);
    ext.Perform(p, guesses[i].x(), guesses[i].y());
    if (!ext.IsDone()) return 1e9;
    return std::sqrt(ext.SquareDistance());
  });
  std::printf("[ closest  ] 3000 points: adapter %.1f us, base class %.1f us (%.1fx), Extrema_GenLocateExtPS %.1f us "
              "(%.1fx); farthest answer %.4f / %.4f / %.4f (lift 0.01)\n",
              1e6 * ours.first / 3000, 1e6 * theirs.first / 3000, theirs.first / ours.first, 1e6 * occt.first / 3000,
              occt.first / ours.first, ours.second, theirs.second, occt.second);
  EXPECT_LE(ours.second, 0.01 + 1e-9) << "the answer is no farther than the point it was lifted from";
  EXPECT_LE(ours.second, theirs.second + 1e-9);
}

}  // namespace
}  // namespace bisect
