// The OpenCASCADE factory's surfaces, surface loops and volumes built from their boundaries.
#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepOffsetAPI_MakeFilling.hxx>
#include <BRep_Builder.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomConvert.hxx>
#include <GeomFill_BSplineCurves.hxx>
#include <GeomPlate_BuildAveragePlane.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Geom_Surface.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Solid.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

namespace {

// The loop's edges in order along it, from the first edge it stores (the script's first curve),
// each turned the way the loop runs. Empty when the edges do not chain into one loop.
std::vector<TopoDS_Edge> chainFromFirst(const TopoDS_Wire& loop) {
  std::vector<TopoDS_Edge> chain;
  for (BRepTools_WireExplorer it(loop); it.More(); it.Next()) chain.push_back(it.Current());
  std::size_t stored = 0;
  for (TopoDS_Iterator it(loop); it.More(); it.Next()) ++stored;
  if (chain.size() != stored) return {};
  const TopoDS_Shape first = TopoDS_Iterator(loop).Value();
  auto at = std::find_if(chain.begin(), chain.end(),
                         [&](const TopoDS_Edge& e) { return e.IsSame(first); });
  std::rotate(chain.begin(), at, chain.end());
  return chain;
}

// The order in which the reference lists a loop of a plane surface it built: the outer loop as
// the script's loop runs, from its first curve; a hole as that loop reversed as a whole, which
// is how the reference puts every hole into its face, whichever way the hole ran: from its last
// curve, against the loop. Each edge is turned the way the listing runs.
std::vector<TopoDS_Edge> listingOrder(const TopoDS_Wire& loop, bool hole) {
  std::vector<TopoDS_Edge> chain = chainFromFirst(loop);
  if (!hole || chain.empty()) return chain;
  std::reverse(chain.begin() + 1, chain.end());
  for (TopoDS_Edge& e : chain) e.Reverse();
  TopoDS_Shape last;
  for (TopoDS_Iterator it(loop); it.More(); it.Next()) last = it.Value();
  auto at = std::find_if(chain.begin(), chain.end(),
                         [&](const TopoDS_Edge& e) { return e.IsSame(last); });
  std::rotate(chain.begin(), at, chain.end());
  return chain;
}

// The face's wire made of the same edges as `listed`, or null.
TopoDS_Wire wireOfEdges(const TopoDS_Face& face, const std::vector<TopoDS_Edge>& listed) {
  for (TopoDS_Iterator w(face, true, false); w.More(); w.Next()) {
    if (w.Value().ShapeType() != TopAbs_WIRE) continue;
    std::size_t count = 0, found = 0;
    for (TopoDS_Iterator e(w.Value(), true, false); e.More(); e.Next(), ++count)
      found += std::any_of(listed.begin(), listed.end(),
                           [&](const TopoDS_Edge& l) { return l.IsSame(e.Value()); });
    if (count == listed.size() && found == count) return TopoDS::Wire(w.Value());
  }
  return {};
}

// The face's loop `wire` stored in the listing's order, bounding the face as before. Where the
// listing runs against the face's loop (a hole the reference would have left turned the wrong
// way), the wire stores its edges the listing's way and is itself reversed: the face keeps its
// orientation, and the listing (the wire taken as stored, see faceEdges) keeps the reference's.
TopoDS_Wire storedInOrder(const TopoDS_Wire& wire, const std::vector<TopoDS_Edge>& listed) {
  bool against = false;
  for (TopoDS_Iterator e(wire); e.More(); e.Next())
    if (e.Value().IsSame(listed.front()))
      against = e.Value().Orientation() != listed.front().Orientation();
  BRep_Builder builder;
  TopoDS_Wire stored;
  builder.MakeWire(stored);
  for (const TopoDS_Edge& l : listed)
    for (TopoDS_Iterator e(wire, true, false); e.More(); e.Next())
      if (e.Value().IsSame(l)) {
        TopoDS_Shape edge = e.Value();
        edge.Orientation(l.Orientation());
        builder.Add(stored, edge);
      }
  stored.Closed(true);
  return TopoDS::Wire(stored.Oriented(against ? TopAbs_REVERSED : TopAbs_FORWARD));
}

// The face with each of its loops stored in the order of one of `listings` (each edge turned
// the way its listing runs). The face's geometry and its loops' edges and orientations stay as
// they are; a loop not found among the face's is left alone.
TopoDS_Face withLoopsListed(const TopoDS_Face& face,
                            const std::vector<std::vector<TopoDS_Edge>>& listings) {
  const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  std::vector<std::pair<TopoDS_Wire, TopoDS_Wire>> replaced;
  for (const std::vector<TopoDS_Edge>& listed : listings) {
    if (listed.empty()) continue;
    const TopoDS_Wire wire = wireOfEdges(forward, listed);
    if (!wire.IsNull()) replaced.emplace_back(wire, storedInOrder(wire, listed));
  }
  BRep_Builder builder;
  TopoDS_Face rebuilt = TopoDS::Face(forward.EmptyCopied());
  for (TopoDS_Iterator it(forward, false, false); it.More(); it.Next()) {
    TopoDS_Shape child = it.Value();
    for (const auto& [old, stored] : replaced)
      if (old.IsEqual(child)) child = stored;
    builder.Add(rebuilt, child);
  }
  return TopoDS::Face(rebuilt.Oriented(face.Orientation()));
}

// The plane face with each of its loops stored in the order the reference lists the script's
// loop it came from (loops[0] the outer one).
TopoDS_Face withLoopsInListingOrder(const TopoDS_Face& face,
                                    const std::vector<TopoDS_Wire>& loops) {
  std::vector<std::vector<TopoDS_Edge>> listings;
  for (std::size_t i = 0; i < loops.size(); ++i) listings.push_back(listingOrder(loops[i], i > 0));
  return withLoopsListed(face, listings);
}

}  // namespace

void OccFactory::addPlaneSurface(int tag, std::vector<int> curveLoops) {
  tag = primitiveTag(2, tag, "Plane Surface");
  const std::string what = "Plane Surface " + std::to_string(tag);
  if (curveLoops.empty()) throw GeometryError(what + " has no curve loop");
  std::vector<TopoDS_Wire> wires;
  for (int loop : curveLoops) wires.push_back(TopoDS::Wire(shapes_->findWire(std::abs(loop))));
  const TopoDS_Shape face = guarded(what, [&] {
    BRepBuilderAPI_MakeFace maker(wires.front(), true);
    if (!maker.IsDone())
      throw GeometryError(what + ": its outer loop " + std::to_string(std::abs(curveLoops[0])) +
                          " is not planar");
    for (std::size_t i = 1; i < wires.size(); ++i) maker.Add(wires[i]);
    // Holes may come in either orientation: the fix turns them against the outer loop.
    ShapeFix_Face fix(maker.Face());
    fix.FixOrientation();
    fix.Perform();
    return withLoopsInListingOrder(TopoDS::Face(fix.Face()), wires);
  });
  shapes_->bindTree(2, tag, face);
}

namespace {

// The face of `surface` bounded by the script's wire, whose curves lie on the surface only to
// a tolerance: the fix computes their curves in the surface's parameters (on the same edges,
// which keep their tags) and turns a loop that runs the wrong way round. A wire known to turn
// counter-clockwise about the surface's normal is left as it is: the fix's own guess can go
// either way on a plate. Null when no face is made.
std::optional<TopoDS_Face> faceOnSurface(const Handle(Geom_Surface)& surface,
                                         const TopoDS_Wire& wire,
                                         bool wireTurnsAboutNormal = false) {
  BRepBuilderAPI_MakeFace maker(surface, wire, !wireTurnsAboutNormal);
  if (!maker.IsDone()) return std::nullopt;
  ShapeFix_Face fix(maker.Face());
  fix.FixAddNaturalBoundMode() = false;
  if (wireTurnsAboutNormal) fix.FixOrientationMode() = 0;
  fix.Perform();
  return fix.Face();
}

// The face OpenCASCADE's plate filling makes, built as the reference builds it: degree 2, the
// loop's edges in the order the loop stores them, then the points it passes through. Its edges
// are new ones.
TopoDS_Face plateFilling(const TopoDS_Wire& loop, const std::vector<gp_Pnt>& through,
                         const std::string& what) {
  BRepOffsetAPI_MakeFilling filling(2);
  for (TopExp_Explorer it(loop, TopAbs_EDGE); it.More(); it.Next())
    filling.Add(TopoDS::Edge(it.Current()), GeomAbs_C0, true);
  for (const gp_Pnt& p : through) filling.Add(p);
  filling.Build();
  if (!filling.IsDone()) throw GeometryError(what + ": no surface fills this loop");
  TopExp_Explorer faces(filling.Shape(), TopAbs_FACE);
  if (!faces.More()) throw GeometryError(what + ": no surface fills this loop");
  return TopoDS::Face(faces.Current());
}

// Whether the plate's own normal (its u and v derivatives crossed) is on the side about which
// the loop turns counter-clockwise: drawn in the plate's parameter plane, the loop then encloses
// a positive area. (The face made on the plate cannot say: its loop may run either way round.)
bool plateFacesAlongLoop(const TopoDS_Face& onPlate, const TopoDS_Wire& loop) {
  double twiceArea = 0;
  for (TopExp_Explorer it(loop, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) curve = BRep_Tool::CurveOnSurface(edge, onPlate, first, last);
    if (curve.IsNull()) return true;
    if (edge.Orientation() == TopAbs_REVERSED) std::swap(first, last);
    constexpr int kSteps = 16;
    for (int i = 0; i < kSteps; ++i) {
      const gp_Pnt2d p = curve->Value(first + (last - first) * i / kSteps);
      const gp_Pnt2d q = curve->Value(first + (last - first) * (i + 1) / kSteps);
      twiceArea += p.X() * q.Y() - q.X() * p.Y();
    }
  }
  return twiceArea >= 0;
}

// The order in which the reference lists the curves of a filling. Its face faces the side the
// loop turns about, but it lists the loop the way the plate's own parameters run round it: from
// the loop's first stored edge when the plate faces that side too; otherwise against the loop,
// from the edge before the first one, ending at it.
std::vector<TopoDS_Edge> fillingListing(const TopoDS_Wire& loop, bool plateAlongLoop) {
  std::vector<TopoDS_Edge> chain = chainFromFirst(loop);
  if (plateAlongLoop) return chain;
  std::reverse(chain.begin(), chain.end());
  for (TopoDS_Edge& e : chain) e.Reverse();
  return chain;
}

// The normal of a plane: its u and v derivatives crossed.
gp_Vec planeNormal(const Handle(Geom_Surface) & plane) {
  gp_Pnt origin;
  gp_Vec du, dv;
  plane->D1(0, 0, origin, du, dv);
  return du.Crossed(dv);
}

// The normal of the plane from which OpenCASCADE's plate filling of `loop` starts, and whose
// parameters the plate keeps (GeomPlate_BuildPlateSurface with curves only): the plane its
// GeomPlate_BuildAveragePlane fits to 20 points on each edge, the edges taken in the order
// and sense of the chain they make from the first one, as it chains them. Found so without
// the plate, which is costly; null when the points make no plane.
std::optional<gp_Vec> plateStartNormal(const TopoDS_Wire& loop) {
  std::vector<BRepAdaptor_Curve> curves;
  for (TopExp_Explorer it(loop, TopAbs_EDGE); it.More(); it.Next())
    curves.emplace_back(TopoDS::Edge(it.Current()));
  const std::size_t n = curves.size();
  if (n == 0) return std::nullopt;
  constexpr double kTolerance = 1e-4;  // the filling's 3D tolerance
  std::vector<bool> reversed(n, false);
  const auto end = [&](std::size_t i) {
    const BRepAdaptor_Curve& c = curves[i];
    return c.Value(reversed[i] ? c.FirstParameter() : c.LastParameter());
  };
  for (std::size_t j = 0; j + 1 < n; ++j)
    for (std::size_t i = j + 1; i < n; ++i) {
      const gp_Pnt reached = end(j);
      const BRepAdaptor_Curve& c = curves[i];
      const bool fromStart = reached.Distance(c.Value(c.FirstParameter())) < kTolerance;
      if (!fromStart && reached.Distance(c.Value(c.LastParameter())) >= kTolerance) continue;
      std::swap(curves[j + 1], curves[i]);
      reversed[j + 1] = !fromStart;
      break;
    }
  constexpr int kPerCurve = 20;
  const int count = kPerCurve * static_cast<int>(n);
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, count);
  int at = 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double first = curves[i].FirstParameter(), last = curves[i].LastParameter();
    const double from = reversed[i] ? last : first;
    const double span = reversed[i] ? -(last - first) : last - first;
    for (int j = 0; j < kPerCurve; ++j)
      points->SetValue(at++, curves[i].Value(from + j * span / kPerCurve));
  }
  // Options 2 and 2: the normal from the polygon of the points, the plane's axes from their
  // inertia (which, not the polygon, decides which way the plane faces).
  GeomPlate_BuildAveragePlane plane(points, count, kTolerance / 1000, 2, 2);
  if (!plane.IsPlane()) return std::nullopt;
  return planeNormal(plane.Plane());
}

// Whether the plate filling a plane loop would face the side about which the loop turns
// counter-clockwise: the side the plane face made on the loop faces. Taken as facing it when
// unknown.
bool planeLoopPlateFacesAlong(const TopoDS_Wire& loop, const TopoDS_Face& planeFace) {
  const std::optional<gp_Vec> start = plateStartNormal(loop);
  if (!start) return true;
  const gp_Vec normal = planeNormal(BRep_Tool::Surface(planeFace));
  return (planeFace.Orientation() == TopAbs_REVERSED ? -1 : 1) * start->Dot(normal) > 0;
}

}  // namespace

// A surface through the loop's curves (OpenCASCADE's plate filling), bounded by them: the
// filling's own face has new edges, so the face is rebuilt on the loop's wire, which keeps the
// script's curves (and their tags) as its boundary. It faces the side about which the loop
// turns counter-clockwise, as in the reference; its curves are listed as the reference lists
// them, which hangs on the side the plate faces.
void OccFactory::addFillingSurface(int tag, std::vector<int> curveLoops,
                                   const std::vector<int>& through) {
  tag = primitiveTag(2, tag, "Surface");
  const std::string what = "Surface " + std::to_string(tag);
  if (curveLoops.size() != 1) throw GeometryError(what + ": a filling takes one curve loop");
  const TopoDS_Wire loop = TopoDS::Wire(shapes_->findWire(std::abs(curveLoops[0])));
  std::vector<gp_Pnt> points;
  for (int point : through)
    points.push_back(BRep_Tool::Pnt(TopoDS::Vertex(shapes_->find(0, std::abs(point)))));
  const TopoDS_Shape face = guarded(what, [&] {
    // A plane loop is filled by its plane, made on the loop so that its normal follows the
    // loop: exact, so that Booleans with other plane faces find the faces coplanar (the plate
    // is plane only to its tolerance).
    if (through.empty()) {
      BRepBuilderAPI_MakeFace plane(loop, true);
      if (plane.IsDone()) {
        const bool plateAlong = planeLoopPlateFacesAlong(loop, plane.Face());
        return TopoDS_Shape(withLoopsListed(plane.Face(), {fillingListing(loop, plateAlong)}));
      }
    }
    const TopoDS_Face filled = plateFilling(loop, points, what);
    const Handle(Geom_Surface) plate = BRep_Tool::Surface(filled);
    const auto onPlate = faceOnSurface(plate, loop);
    if (!onPlate) return TopoDS_Shape(filled);
    // A plate facing the other way has its parameters turned round: meshes follow a
    // surface's parameters, not its face's orientation. Either way the loop then turns
    // counter-clockwise about the surface's normal.
    const bool plateAlong = plateFacesAlongLoop(*onPlate, loop);
    const auto turned = faceOnSurface(plateAlong ? plate : plate->UReversed(), loop, true);
    return TopoDS_Shape(
        withLoopsListed(turned.value_or(*onPlate), {fillingListing(loop, plateAlong)}));
  });
  shapes_->bindTree(2, tag, face);
}

namespace {

// The loop's curves in order along it, each turned to run along the loop, as B-spline curves.
std::vector<Handle(Geom_BSplineCurve)> loopCurves(const TopoDS_Wire& wire,
                                                 const std::string& what) {
  std::vector<Handle(Geom_BSplineCurve)> curves;
  for (BRepTools_WireExplorer it(wire); it.More(); it.Next()) {
    double first = 0, last = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(it.Current(), first, last);
    if (curve.IsNull()) throw GeometryError(what + ": a curve of its loop has no geometry");
    Handle(Geom_BSplineCurve) spline = GeomConvert::CurveToBSplineCurve(
        new Geom_TrimmedCurve(curve, first, last), Convert_TgtThetaOver2);
    if (it.Current().Orientation() == TopAbs_REVERSED) spline->Reverse();
    curves.push_back(spline);
  }
  return curves;
}

}  // namespace

void OccFactory::addCurveFilling(int tag, int curveLoop, bool bezier) {
  tag = primitiveTag(2, tag, bezier ? "Bezier Surface" : "BSpline Surface");
  const std::string what = (bezier ? "Bezier Surface " : "BSpline Surface ") + std::to_string(tag);
  const TopoDS_Wire wire = TopoDS::Wire(shapes_->findWire(std::abs(curveLoop)));
  const TopoDS_Shape face = guarded(what, [&] {
    const std::vector<Handle(Geom_BSplineCurve)> c = loopCurves(wire, what);
    if (c.size() < 2 || c.size() > 4)
      throw GeometryError(what + ": its loop has " + std::to_string(c.size()) +
                          " curves; it takes 2, 3 or 4");
    if (bezier)
      for (const Handle(Geom_BSplineCurve)& curve : c)
        if (curve->NbKnots() != 2)
          throw GeometryError(what + ": the curves of its loop must be Bezier curves");
    GeomFill_BSplineCurves fill;
    if (c.size() == 2) fill.Init(c[0], c[1], GeomFill_CurvedStyle);
    if (c.size() == 3) fill.Init(c[0], c[1], c[2], GeomFill_CurvedStyle);
    if (c.size() == 4) fill.Init(c[0], c[1], c[2], c[3], GeomFill_CurvedStyle);
    const auto face = faceOnSurface(Handle(Geom_Surface)(fill.Surface()), wire);
    if (!face) throw GeometryError(what + ": no surface fills its loop");
    return TopoDS_Shape(*face);
  });
  shapes_->bindTree(2, tag, face);
}

void OccFactory::addSurfaceLoop(int tag, std::vector<int> surfaces) {
  if (tag < 0) tag = maxTag(kSurfaceLoop) + 1;
  const std::string what = "Surface Loop " + std::to_string(tag);
  if (shapes_->shells.contains(tag)) throw GeometryError(what + " already exists");
  if (surfaces.empty()) throw GeometryError(what + " has no surface");
  TopoDS_Shell shell;
  BRep_Builder builder;
  builder.MakeShell(shell);
  for (int s : surfaces) builder.Add(shell, shapes_->find(2, std::abs(s)));
  shell.Closed(BRep_Tool::IsClosed(shell));
  if (!shell.Closed()) throw GeometryError(what + " is not closed");
  shapes_->shells[tag] = shell;
}

void OccFactory::addVolume(int tag, std::vector<int> surfaceLoops) {
  tag = primitiveTag(3, tag, "Volume");
  const std::string what = "Volume " + std::to_string(tag);
  if (surfaceLoops.empty()) throw GeometryError(what + " has no surface loop");
  const TopoDS_Shape solid = guarded(what, [&] {
    BRepBuilderAPI_MakeSolid maker;
    for (int loop : surfaceLoops) maker.Add(TopoDS::Shell(shapes_->findShell(std::abs(loop))));
    if (!maker.IsDone()) throw GeometryError(what + ": its surface loops make no solid");
    // Orients the shells: the outer one outwards, the others (cavities) inwards.
    ShapeFix_Solid fix(maker.Solid());
    fix.Perform();
    TopExp_Explorer it(fix.Solid(), TopAbs_SOLID);
    if (!it.More()) throw GeometryError(what + ": its surface loops make no solid");
    return it.Current();
  });
  shapes_->bindTree(3, tag, solid);
}

}  // namespace geomesh
