// BrepChecker: OpenCASCADE's own answers (extrema, classifier, global properties) about the
// shape a BrepInput came from.
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_ExtPC.hxx>
#include <BRepExtrema_ExtPF.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

#include "bisect/occ_checker.hpp"
#include "occ_guard.hpp"
#include "occ_shape.hpp"

namespace bisect {

using occ::guard;

// BRepGProp's adaptive integration to this relative error: its fixed-order default is 0.2% off
// on a B-spline solid, more than a test of a tessellation's volume can afford.
constexpr double kRelativeError = 1e-9;

struct BrepChecker::Impl {
  std::shared_ptr<const void> keep;  // the input's shape, alive while the checker is
  const occ::OccShape* m = nullptr;
  // built on first use: the extrema keep their sampling of the surface or curve between points
  std::vector<std::unique_ptr<BRepExtrema_ExtPF>> face_ext;
  std::vector<std::unique_ptr<BRepExtrema_ExtPC>> edge_ext;
  std::vector<std::unique_ptr<BRepClass3d_SolidClassifier>> classifiers;
  std::vector<std::vector<Index>> face_edges;

  void check(Index i, int n, const char* what) const {
    if (i < 0 || i >= n)
      throw InputError(m->source + ": there is no " + what + " " + std::to_string(i + 1) + " (it has " +
                       std::to_string(n) + ")");
  }

  double vertex_distance(Index v, const gp_Pnt& p) const {
    return p.Distance(BRep_Tool::Pnt(TopoDS::Vertex(m->vertices(v + 1))));
  }

  // The nearest of the curve's interior extrema and its two ends.
  double edge_distance(Index e, const gp_Pnt& p, const TopoDS_Vertex& pv) {
    const TopoDS_Edge& edge = TopoDS::Edge(m->edges(e + 1));
    TopoDS_Vertex a, b;
    TopExp::Vertices(edge, a, b);
    double best = std::min(p.Distance(BRep_Tool::Pnt(a)), p.Distance(BRep_Tool::Pnt(b)));
    if (BRep_Tool::Degenerated(edge)) return best;
    if (!edge_ext[e]) {
      edge_ext[e] = std::make_unique<BRepExtrema_ExtPC>();
      edge_ext[e]->Initialize(edge);
    }
    BRepExtrema_ExtPC& ext = *edge_ext[e];
    ext.Perform(pv);
    if (ext.IsDone())
      for (int i = 1; i <= ext.NbExt(); ++i) best = std::min(best, std::sqrt(ext.SquareDistance(i)));
    return best;
  }

  // The nearest of the surface's extrema inside the face and its boundary edges: the distance
  // to a trimmed face is reached at one or the other.
  double face_distance(Index f, const gp_Pnt& p) {
    const TopoDS_Face& face = TopoDS::Face(m->faces(f + 1));
    const TopoDS_Vertex pv = BRepBuilderAPI_MakeVertex(p);
    if (!face_ext[f]) {
      face_ext[f] = std::make_unique<BRepExtrema_ExtPF>();
      face_ext[f]->Initialize(face, Extrema_ExtFlag_MINMAX);
    }
    double best = std::numeric_limits<double>::infinity();
    BRepExtrema_ExtPF& ext = *face_ext[f];
    ext.Perform(pv, face);
    if (ext.IsDone())
      for (int i = 1; i <= ext.NbExt(); ++i) best = std::min(best, std::sqrt(ext.SquareDistance(i)));
    if (face_edges[f].empty()) {
      TopTools_IndexedMapOfShape edges;
      TopExp::MapShapes(face, TopAbs_EDGE, edges);
      for (int i = 1; i <= edges.Extent(); ++i) face_edges[f].push_back(m->edges.FindIndex(edges(i)) - 1);
    }
    for (Index e : face_edges[f]) best = std::min(best, edge_distance(e, p, pv));
    return best;
  }
};

BrepChecker::BrepChecker(const BrepInput& in) : impl_(std::make_unique<Impl>()) {
  impl_->m = &occ::occ_shape_of(in);
  impl_->keep = in.shape;
  impl_->face_ext.resize(impl_->m->faces.Extent());
  impl_->edge_ext.resize(impl_->m->edges.Extent());
  impl_->classifiers.resize(impl_->m->solids.size());
  impl_->face_edges.resize(impl_->m->faces.Extent());
}

BrepChecker::~BrepChecker() = default;

double BrepChecker::distance_to_face(Index face, const Vec3& p) const {
  impl_->check(face, impl_->m->faces.Extent(), "face");
  return guard([&] { return impl_->m->source + ": " + face_name(face); }, "OpenCASCADE could not measure a distance",
               [&] { return impl_->face_distance(face, gp_Pnt(p.x(), p.y(), p.z())); });
}

double BrepChecker::distance_to_edge(Index edge, const Vec3& p) const {
  impl_->check(edge, impl_->m->edges.Extent(), "edge");
  return guard([&] { return impl_->m->source + ": " + edge_name(edge); }, "OpenCASCADE could not measure a distance",
               [&] {
                 const gp_Pnt q(p.x(), p.y(), p.z());
                 return impl_->edge_distance(edge, q, BRepBuilderAPI_MakeVertex(q));
               });
}

double BrepChecker::distance_to_vertex(Index vertex, const Vec3& p) const {
  impl_->check(vertex, impl_->m->vertices.Extent(), "vertex");
  return impl_->vertex_distance(vertex, gp_Pnt(p.x(), p.y(), p.z()));
}

PointState BrepChecker::classify(Index solid, const Vec3& p, double tolerance) const {
  impl_->check(solid, static_cast<int>(impl_->m->solids.size()), "solid");
  return guard([&] { return impl_->m->source + ": " + solid_name(solid); }, "OpenCASCADE could not classify a point",
               [&] {
                 auto& c = impl_->classifiers[solid];
                 if (!c) c = std::make_unique<BRepClass3d_SolidClassifier>(impl_->m->solids[solid]);
                 c->Perform(gp_Pnt(p.x(), p.y(), p.z()), tolerance);
                 switch (c->State()) {
                   case TopAbs_IN: return PointState::inside;
                   case TopAbs_ON: return PointState::on;
                   case TopAbs_OUT: return PointState::outside;
                   default: throw MeshingError(impl_->m->source + ": " + solid_name(solid) +
                                               ": OpenCASCADE could not classify a point (state unknown)");
                 }
               });
}

double BrepChecker::solid_volume(Index solid) const {
  impl_->check(solid, static_cast<int>(impl_->m->solids.size()), "solid");
  return guard([&] { return impl_->m->source + ": " + solid_name(solid); }, "OpenCASCADE could not take its volume",
               [&] {
                 GProp_GProps props;
                 BRepGProp::VolumeProperties(impl_->m->solids[solid], props, kRelativeError);
                 return props.Mass();
               });
}

double BrepChecker::volume() const {
  return guard([&] { return impl_->m->source; }, "OpenCASCADE could not take its volume", [&] {
    TopoDS_Compound all;
    BRep_Builder b;
    b.MakeCompound(all);
    for (const TopoDS_Solid& s : impl_->m->solids) b.Add(all, s);
    GProp_GProps props;
    BRepGProp::VolumeProperties(all, props, kRelativeError);
    return props.Mass();
  });
}

double BrepChecker::face_area(Index face) const {
  impl_->check(face, impl_->m->faces.Extent(), "face");
  return guard([&] { return impl_->m->source + ": " + face_name(face); }, "OpenCASCADE could not take its area", [&] {
    GProp_GProps props;
    BRepGProp::SurfaceProperties(impl_->m->faces(face + 1), props, kRelativeError);
    return props.Mass();
  });
}

}  // namespace bisect
