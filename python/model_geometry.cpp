// geomesh.model.geo and geomesh.model.occ: entities of the built-in and OpenCASCADE kernels
// defined one call at a time, each the factory call a script's statement makes.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "kernel/geometry_factory.h"
#include "python/api_state.h"

namespace py = pybind11;

namespace geomesh::python {
namespace {

// ---- geomesh.model.occ: the OpenCASCADE kernel ----

using BooleanOperation = SolidModeling::BooleanOperation;

// What a Boolean made: (outDimTags, outDimTagsMap), the map holding for every input (objects,
// then tools) the entities of the result that came from it.
py::tuple booleanResult(Session& session, BooleanOperation operation, const DimTags& objectDimTags,
                        const DimTags& toolDimTags, int tag, bool removeObject, bool removeTool) {
  SolidModeling& solids = session.factories().solidModeler();
  const OptionRegistry& options = session.options();
  solids.setBooleanOptions({options.number("Geometry.ToleranceBoolean"),
                            options.number("Geometry.OCCBooleanSimplify") != 0,
                            options.number("Geometry.OCCBooleanPreserveNumbering") != 0});
  const std::vector<EntityId> objects = entityIds(objectDimTags);
  const std::vector<EntityId> tools = entityIds(toolDimTags);
  const std::vector<EntityId> result =
      solids.boolean(operation, objects, tools, removeObject, removeTool, tag);
  py::list map;
  for (const std::vector<EntityId>* inputs : {&objects, &tools})
    for (const EntityId& input : *inputs) {
      const auto& replaced = solids.lastReplacements();
      const auto it = std::find_if(replaced.begin(), replaced.end(),
                                   [&](const auto& r) { return r.input == input; });
      if (it != replaced.end())
        map.append(dimTagList(it->images));
      else
        map.append(dimTagList(solids.owns(input) ? std::vector<EntityId>{input}
                                                 : std::vector<EntityId>{}));
    }
  return py::make_tuple(dimTagList(result), map);
}

void defineBooleans(py::module_& occ, const State& state) {
  const std::pair<const char*, BooleanOperation> operations[] = {
      {"fuse", BooleanOperation::Union},
      {"cut", BooleanOperation::Difference},
      {"intersect", BooleanOperation::Intersection},
      {"fragment", BooleanOperation::Fragments}};
  for (const auto& [name, kind] : operations) {
    const BooleanOperation operation = kind;
    occ.def(
        name,
        [state, operation](const DimTags& objectDimTags, const DimTags& toolDimTags, int tag,
                           bool removeObject, bool removeTool) {
          return booleanResult(state->session(), operation, objectDimTags, toolDimTags, tag,
                               removeObject, removeTool);
        },
        py::arg("objectDimTags"), py::arg("toolDimTags"), py::arg("tag") = -1,
        py::arg("removeObject") = true, py::arg("removeTool") = true,
        "A Boolean of the objects and tools; returns (outDimTags, outDimTagsMap).");
  }
}

}  // namespace

void defineGeo(py::module_& geo, const State& state) {
  geo.def(
      "addPoint",
      [state](double x, double y, double z, double meshSize, int tag) {
        LiveSession& s = state->live();
        if (tag < 0) tag = s.nextTag(0);
        s.builtIn().addPoint(tag, {x, y, z}, meshSize);
        return tag;
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("meshSize") = 0., py::arg("tag") = -1,
      "A point; meshSize > 0: the mesh size there. Returns its tag.");
  geo.def(
      "addLine",
      [state](int startTag, int endTag, int tag) {
        LiveSession& s = state->live();
        if (tag < 0) tag = s.nextTag(1);
        s.builtIn().addLine(tag, startTag, endTag);
        return tag;
      },
      py::arg("startTag"), py::arg("endTag"), py::arg("tag") = -1);
  geo.def(
      "addCircleArc",
      [state](int startTag, int centerTag, int endTag, int tag) {
        LiveSession& s = state->live();
        if (tag < 0) tag = s.nextTag(1);
        s.builtIn().addCircleArc(tag, startTag, centerTag, endTag);
        return tag;
      },
      py::arg("startTag"), py::arg("centerTag"), py::arg("endTag"), py::arg("tag") = -1,
      "An arc of circle of less than pi from start to end about center.");
  geo.def(
      "addSpline",
      tagged(state, 1, [](LiveSession& s, int tag, const Tags& tags) {
        s.builtIn().addSpline(tag, tags);
      }),
      py::arg("pointTags"), py::arg("tag") = -1, "A spline through the points.");
  geo.def(
      "addCurveLoop",
      tagged(state, GeometryFactory::kCurveLoop, [](LiveSession& s, int tag, const Tags& tags) {
        s.builtIn().addCurveLoop(tag, tags);
      }),
      py::arg("curveTags"), py::arg("tag") = -1,
      "A closed loop of curves (a negative tag: the curve reversed).");
  geo.def(
      "addPlaneSurface",
      tagged(state, 2, [](LiveSession& s, int tag, const Tags& tags) {
        s.builtIn().addPlaneSurface(tag, tags);
      }),
      py::arg("wireTags"), py::arg("tag") = -1,
      "A plane surface: the first curve loop its outline, the others its holes.");
  geo.def(
      "addSurfaceFilling",
      tagged(state, 2, [](LiveSession& s, int tag, const Tags& tags) {
        s.builtIn().addFillingSurface(tag, tags, {});
      }),
      py::arg("wireTags"), py::arg("tag") = -1,
      "A surface filling a loop of 3 or 4 curves (transfinite interpolation).");
  geo.def(
      "addSurfaceLoop",
      tagged(state, GeometryFactory::kSurfaceLoop, [](LiveSession& s, int tag, const Tags& tags) {
        s.builtIn().addSurfaceLoop(tag, tags);
      }),
      py::arg("surfaceTags"), py::arg("tag") = -1);
  geo.def(
      "addVolume",
      tagged(state, 3, [](LiveSession& s, int tag, const Tags& tags) {
        s.builtIn().addVolume(tag, tags);
      }),
      py::arg("shellTags"), py::arg("tag") = -1,
      "A volume: the first surface loop its outside, the others its holes.");
  geo.def(
      "extrude",
      [state](const DimTags& dimTags, double dx, double dy, double dz,
              const std::vector<int>& numElements, const std::vector<double>& heights,
              bool recombine) {
        return dimTagList(state->live().builtIn().extrude(
            entityIds(dimTags), ExtrusionMotion::translate({dx, dy, dz}),
            layersOf(numElements, heights, recombine)));
      },
      py::arg("dimTags"), py::arg("dx"), py::arg("dy"), py::arg("dz"),
      py::arg("numElements") = std::vector<int>{}, py::arg("heights") = std::vector<double>{},
      py::arg("recombine") = false,
      "Extrudes the shapes by (dx, dy, dz), in layers when numElements is given; returns "
      "[(dim, tag)] as a script's Extrude does: for each shape, its top, the new entity, then "
      "the sides.");
  geo.def(
      "synchronize", [state] { synchronize(state->session()); },
      "Makes the model from the geometry defined so far.");

  py::module_ mesh = geo.def_submodule("mesh", "Mesh constraints of built-in entities.");
  mesh.def(
      "setTransfiniteCurve",
      [state](int tag, int nPoints, const std::string& meshType, double coef) {
        TransfiniteCurve law;
        if (nPoints < 2) throw py::value_error("a transfinite curve needs at least 2 nodes");
        law.nodes = nPoints;
        if (meshType == "Progression" || meshType == "Power")
          law.law = TransfiniteCurve::Law::Progression;
        else if (meshType == "Bump")
          law.law = TransfiniteCurve::Law::Bump;
        else if (meshType == "Beta")
          law.law = TransfiniteCurve::Law::Beta;
        else
          throw py::value_error("meshType is Progression, Bump or Beta, not '" + meshType + "'");
        law.coefficient = coef;
        law.reversed = tag < 0;
        state->session().model().meshConstraints().transfiniteCurves[std::abs(tag)] = law;
      },
      py::arg("tag"), py::arg("nPoints"), py::arg("meshType") = "Progression",
      py::arg("coef") = 1.,
      "The curve gets exactly nPoints nodes, spaced by the law.");
  mesh.def(
      "setTransfiniteSurface",
      [state](int tag, const std::string& arrangement, const std::vector<int>& cornerTags) {
        using A = TransfiniteSurface::Arrangement;
        const std::map<std::string, A> arrangements = {{"Left", A::Left},
                                                       {"Right", A::Right},
                                                       {"AlternateLeft", A::AlternateLeft},
                                                       {"AlternateRight", A::AlternateRight},
                                                       {"Alternate", A::AlternateRight}};
        const auto it = arrangements.find(arrangement);
        if (it == arrangements.end())
          throw py::value_error("arrangement is Left, Right, AlternateLeft or AlternateRight, "
                                "not '" + arrangement + "'");
        TransfiniteSurface surface;
        surface.arrangement = it->second;
        for (int corner : cornerTags) surface.corners.push_back(std::abs(corner));
        state->session().model().meshConstraints().transfiniteSurfaces[std::abs(tag)] = surface;
      },
      py::arg("tag"), py::arg("arrangement") = "Left",
      py::arg("cornerTags") = std::vector<int>{},
      "A structured mesh of the surface from its transfinite curves.");
  mesh.def(
      "setRecombine",
      [state](int dim, int tag, double angle) {
        if (dim != 2) throw py::value_error("setRecombine recombines surfaces (dim 2) only");
        state->session().model().meshConstraints().recombinedSurfaces[std::abs(tag)] = angle;
      },
      py::arg("dim"), py::arg("tag"), py::arg("angle") = 45.,
      "The surface's triangles are recombined into quadrangles.");
}

void defineOcc(py::module_& occ, const State& state) {
  occ.def(
      "addPoint",
      [state](double x, double y, double z, double meshSize, int tag) {
        LiveSession& s = state->live();
        if (tag < 0) tag = s.nextTag(0);
        s.occ->addPoint(tag, {x, y, z}, meshSize);
        return tag;
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("meshSize") = 0., py::arg("tag") = -1);
  occ.def(
      "addLine",
      [state](int startTag, int endTag, int tag) {
        LiveSession& s = state->live();
        if (tag < 0) tag = s.nextTag(1);
        s.occ->addLine(tag, startTag, endTag);
        return tag;
      },
      py::arg("startTag"), py::arg("endTag"), py::arg("tag") = -1);
  auto solids = [state]() -> SolidModeling& {
    return state->session().factories().solidModeler();
  };
  occ.def(
      "addCircle",
      [solids](double x, double y, double z, double r, int tag, double angle1, double angle2) {
        std::vector<double> angles;
        if (angle1 != 0 || angle2 != 2 * std::numbers::pi) angles = {angle1, angle2};
        return solids().addCircle(tag, {x, y, z}, r, angles);
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("r"), py::arg("tag") = -1,
      py::arg("angle1") = 0., py::arg("angle2") = 2 * std::numbers::pi,
      "A circle (or an arc from angle1 to angle2) about (x, y, z) in its plane z.");
  occ.def(
      "addRectangle",
      [solids](double x, double y, double z, double dx, double dy, int tag,
               double roundedRadius) {
        return solids().addRectangle(tag, {x, y, z}, dx, dy, roundedRadius);
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("dx"), py::arg("dy"),
      py::arg("tag") = -1, py::arg("roundedRadius") = 0.);
  occ.def(
      "addDisk",
      [solids](double xc, double yc, double zc, double rx, double ry, int tag) {
        return solids().addDisk(tag, {xc, yc, zc}, rx, ry);
      },
      py::arg("xc"), py::arg("yc"), py::arg("zc"), py::arg("rx"), py::arg("ry"),
      py::arg("tag") = -1);
  occ.def(
      "addBox",
      [state](double x, double y, double z, double dx, double dy, double dz, int tag) {
        return state->live().occ->addBox(tag, {x, y, z}, {dx, dy, dz});
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("dx"), py::arg("dy"), py::arg("dz"),
      py::arg("tag") = -1);
  occ.def(
      "addSphere",
      [solids](double xc, double yc, double zc, double radius, int tag, double angle1,
               double angle2, double angle3) {
        return solids().addSphere(tag, {xc, yc, zc}, radius, angle1, angle2, angle3);
      },
      py::arg("xc"), py::arg("yc"), py::arg("zc"), py::arg("radius"), py::arg("tag") = -1,
      py::arg("angle1") = -std::numbers::pi / 2, py::arg("angle2") = std::numbers::pi / 2,
      py::arg("angle3") = 2 * std::numbers::pi);
  occ.def(
      "addCylinder",
      [solids](double x, double y, double z, double dx, double dy, double dz, double r, int tag,
               double angle) {
        return solids().addCylinder(tag, {x, y, z}, {dx, dy, dz}, r, angle);
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("dx"), py::arg("dy"), py::arg("dz"),
      py::arg("r"), py::arg("tag") = -1, py::arg("angle") = 2 * std::numbers::pi,
      "A cylinder: base centre (x, y, z), axis (dx, dy, dz) as long as it is high.");
  defineBooleans(occ, state);
  occ.def(
      "synchronize", [state] { synchronize(state->session()); },
      "Makes the model from the geometry defined so far.");
}

}  // namespace geomesh::python
