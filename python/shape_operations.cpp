// Operations on shapes in geomesh.model.geo and geomesh.model.occ: translate, rotate, dilate,
// mirror, copy, remove, revolve, twist, as a script's Translate{..}{..}, Duplicata{..},
// Recursive Delete{..} and Extrude{..}{..} make them; and the OpenCASCADE kernel's queries
// (getEntities, getBoundingBox, getClosestEntities) and file import.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "kernel/affine_map.h"
#include "kernel/geometry_factory.h"
#include "kernel/solid_modeling.h"
#include "python/api_state.h"

namespace py = pybind11;

namespace geomesh::python {

ExtrusionLayers layersOf(const std::vector<int>& numElements, const std::vector<double>& heights,
                         bool recombine) {
  ExtrusionLayers layers{numElements, heights, recombine};
  const auto count = static_cast<double>(numElements.size());
  if (heights.empty())
    for (std::size_t k = 1; k <= numElements.size(); ++k)
      layers.heights.push_back(static_cast<double>(k) / count);
  return layers;
}

namespace {

using FactoryOf = std::function<GeometryFactory&(LiveSession&)>;

// translate, rotate, dilate, mirror/symmetrize, copy, remove, revolve and twist of one kernel.
void defineTransforms(py::module_& kernel, const State& state, const FactoryOf& factoryOf) {
  auto transform = [state, factoryOf](const DimTags& dimTags, const AffineMap& map) {
    factoryOf(state->live()).transform(entityIds(dimTags), map);
  };
  kernel.def(
      "translate",
      [transform](const DimTags& dimTags, double dx, double dy, double dz) {
        transform(dimTags, AffineMap::translation({dx, dy, dz}));
      },
      py::arg("dimTags"), py::arg("dx"), py::arg("dy"), py::arg("dz"),
      "Moves the shapes by (dx, dy, dz), as Translate{dx, dy, dz}{..}.");
  kernel.def(
      "rotate",
      [transform](const DimTags& dimTags, double x, double y, double z, double ax, double ay,
                  double az, double angle) {
        transform(dimTags, AffineMap::rotation({ax, ay, az}, {x, y, z}, angle));
      },
      py::arg("dimTags"), py::arg("x"), py::arg("y"), py::arg("z"), py::arg("ax"),
      py::arg("ay"), py::arg("az"), py::arg("angle"),
      "Turns the shapes by angle (radians) about the axis (ax, ay, az) through (x, y, z).");
  kernel.def(
      "dilate",
      [transform](const DimTags& dimTags, double x, double y, double z, double a, double b,
                  double c) { transform(dimTags, AffineMap::dilation({x, y, z}, {a, b, c})); },
      py::arg("dimTags"), py::arg("x"), py::arg("y"), py::arg("z"), py::arg("a"), py::arg("b"),
      py::arg("c"), "Scales the shapes about (x, y, z) by a, b, c along x, y, z.");
  auto mirror = [transform](const DimTags& dimTags, double a, double b, double c, double d) {
    transform(dimTags, AffineMap::symmetry(a, b, c, d));
  };
  for (const char* name : {"mirror", "symmetrize"})
    kernel.def(name, mirror, py::arg("dimTags"), py::arg("a"), py::arg("b"), py::arg("c"),
               py::arg("d"), "Mirrors the shapes through the plane a x + b y + c z + d = 0.");
  kernel.def(
      "affineTransform",
      [transform](const DimTags& dimTags, const std::vector<double>& affineTransform) {
        if (affineTransform.size() != 12 && affineTransform.size() != 16)
          throw py::value_error("affineTransform takes 12 or 16 numbers (a 3 x 4 or 4 x 4 "
                                "row-major matrix)");
        AffineMap map;
        for (std::size_t i = 0; i < 12; ++i) map.m[i] = affineTransform[i];
        transform(dimTags, map);
      },
      py::arg("dimTags"), py::arg("affineTransform"));
  kernel.def(
      "copy",
      [state, factoryOf](const DimTags& dimTags) {
        return dimTagList(factoryOf(state->live()).duplicate(entityIds(dimTags)));
      },
      py::arg("dimTags"), "Copies of the shapes, as Duplicata{..}; returns their [(dim, tag)].");
  kernel.def(
      "remove",
      [state, factoryOf](const DimTags& dimTags, bool recursive) {
        factoryOf(state->live()).remove(entityIds(dimTags), recursive);
      },
      py::arg("dimTags"), py::arg("recursive") = false,
      "Deletes the shapes (recursive: with what bounds them and nothing else uses), as "
      "Delete{..} and Recursive Delete{..}.");
  kernel.def(
      "revolve",
      [state, factoryOf](const DimTags& dimTags, double x, double y, double z, double ax,
                         double ay, double az, double angle, const std::vector<int>& numElements,
                         const std::vector<double>& heights, bool recombine) {
        return dimTagList(factoryOf(state->live())
                              .extrude(entityIds(dimTags),
                                       ExtrusionMotion::rotate({ax, ay, az}, {x, y, z}, angle),
                                       layersOf(numElements, heights, recombine)));
      },
      py::arg("dimTags"), py::arg("x"), py::arg("y"), py::arg("z"), py::arg("ax"),
      py::arg("ay"), py::arg("az"), py::arg("angle"),
      py::arg("numElements") = std::vector<int>{}, py::arg("heights") = std::vector<double>{},
      py::arg("recombine") = false,
      "Extrudes the shapes by turning them about an axis, as Extrude{{axis}, {point}, angle}.");
  kernel.def(
      "twist",
      [state, factoryOf](const DimTags& dimTags, double x, double y, double z, double dx,
                         double dy, double dz, double ax, double ay, double az, double angle,
                         const std::vector<int>& numElements, const std::vector<double>& heights,
                         bool recombine) {
        return dimTagList(
            factoryOf(state->live())
                .extrude(entityIds(dimTags),
                         ExtrusionMotion::twist({dx, dy, dz}, {ax, ay, az}, {x, y, z}, angle),
                         layersOf(numElements, heights, recombine)));
      },
      py::arg("dimTags"), py::arg("x"), py::arg("y"), py::arg("z"), py::arg("dx"),
      py::arg("dy"), py::arg("dz"), py::arg("ax"), py::arg("ay"), py::arg("az"),
      py::arg("angle"), py::arg("numElements") = std::vector<int>{},
      py::arg("heights") = std::vector<double>{}, py::arg("recombine") = false,
      "Extrudes the shapes by moving and turning them at once, as "
      "Extrude{{dx, dy, dz}, {axis}, {point}, angle}.");
}

// Curves, wires, lofts, pipes and fillets of the OpenCASCADE kernel, as ThruSections,
// Extrude{..} Using Wire{..} and Fillet{..}{..}{..} make them.
void defineOccSolids(py::module_& occ, const State& state) {
  auto solids = [state]() -> SolidModeling& {
    return state->session().factories().solidModeler();
  };
  occ.def(
      "addSpline",
      tagged(state, 1,
             [](LiveSession& s, int tag, const Tags& tags) { s.occ->addSpline(tag, tags); }),
      py::arg("pointTags"), py::arg("tag") = -1, "A spline through the points.");
  occ.def(
      "addCircleArc",
      [state](int startTag, int centerTag, int endTag, int tag) {
        LiveSession& s = state->live();
        if (tag < 0) tag = s.nextTag(1);
        s.occ->addCircleArc(tag, startTag, centerTag, endTag);
        return tag;
      },
      py::arg("startTag"), py::arg("centerTag"), py::arg("endTag"), py::arg("tag") = -1);
  occ.def(
      "addWire",
      [state, solids](const std::vector<int>& curveTags, int tag, bool) {
        LiveSession& s = state->live();
        if (tag < 0) tag = s.nextTag(GeometryFactory::kCurveLoop);
        solids().addWire(tag, curveTags);
        return tag;
      },
      py::arg("curveTags"), py::arg("tag") = -1, py::arg("checkClosed") = false,
      "A chain of curves, closed or not.");
  occ.def(
      "addThruSections",
      [solids](const std::vector<int>& wireTags, int tag, bool makeSolid, bool makeRuled) {
        return dimTagList(solids().addThruSections(tag, wireTags, makeRuled, makeSolid));
      },
      py::arg("wireTags"), py::arg("tag") = -1, py::arg("makeSolid") = true,
      py::arg("makeRuled") = false,
      "The loft through the wires (a volume, or surfaces without makeSolid), as ThruSections.");
  occ.def(
      "addPipe",
      [solids](const DimTags& dimTags, int wireTag, const std::string&) {
        return dimTagList(solids().extrudeAlongWire(entityIds(dimTags), wireTag));
      },
      py::arg("dimTags"), py::arg("wireTag"), py::arg("trihedron") = "",
      "Sweeps the shapes along the wire, as Extrude{..} Using Wire{..}.");
  occ.def(
      "fillet",
      [solids](const std::vector<int>& volumeTags, const std::vector<int>& curveTags,
               const std::vector<double>& radii, bool) {
        return dimTagList(solids().fillet(volumeTags, curveTags, radii));
      },
      py::arg("volumeTags"), py::arg("curveTags"), py::arg("radii"),
      py::arg("removeVolume") = true, "Rounds the volumes' edges, as Fillet{..}{..}{..}.");
  occ.def(
      "addCone",
      [solids](double x, double y, double z, double dx, double dy, double dz, double r1,
               double r2, int tag, double angle) {
        return solids().addCone(tag, {x, y, z}, {dx, dy, dz}, r1, r2, angle);
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("dx"), py::arg("dy"), py::arg("dz"),
      py::arg("r1"), py::arg("r2"), py::arg("tag") = -1, py::arg("angle") = 2 * std::numbers::pi);
  occ.def(
      "addTorus",
      [solids](double x, double y, double z, double r1, double r2, int tag, double angle) {
        return solids().addTorus(tag, {x, y, z}, r1, r2, angle);
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("r1"), py::arg("r2"),
      py::arg("tag") = -1, py::arg("angle") = 2 * std::numbers::pi);
}

// mesh.setSize of one kernel: the size at the points among dimTags.
void defineSetSize(py::module_& mesh, const State& state, const FactoryOf& factoryOf) {
  mesh.def(
      "setSize",
      [state, factoryOf](const DimTags& dimTags, double size) {
        std::vector<int> points;
        for (const auto& [dim, tag] : dimTags)
          if (dim == 0) points.push_back(tag);
        factoryOf(state->live()).setMeshSize(points, size);
      },
      py::arg("dimTags"), py::arg("size"), "The mesh size at the points among dimTags.");
}

py::tuple boxTuple(const BoundingBox& box) {
  return py::make_tuple(box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z);
}

}  // namespace

void defineGeoOperations(py::module_& geo, const State& state) {
  defineTransforms(geo, state, [](LiveSession& s) -> GeometryFactory& { return s.builtIn(); });
  py::module_ mesh = geo.attr("mesh");
  defineSetSize(mesh, state, [](LiveSession& s) -> GeometryFactory& { return s.builtIn(); });
}

void defineOccOperations(py::module_& occ, const State& state) {
  defineTransforms(occ, state, [](LiveSession& s) -> GeometryFactory& { return *s.occ; });
  defineOccSolids(occ, state);
  occ.def(
      "extrude",
      [state](const DimTags& dimTags, double dx, double dy, double dz,
              const std::vector<int>& numElements, const std::vector<double>& heights,
              bool recombine) {
        return dimTagList(state->live().occ->extrude(entityIds(dimTags),
                                                     ExtrusionMotion::translate({dx, dy, dz}),
                                                     layersOf(numElements, heights, recombine)));
      },
      py::arg("dimTags"), py::arg("dx"), py::arg("dy"), py::arg("dz"),
      py::arg("numElements") = std::vector<int>{}, py::arg("heights") = std::vector<double>{},
      py::arg("recombine") = false, "Extrudes the shapes by (dx, dy, dz).");
  occ.def(
      "getEntities",
      [state](int dim) {
        if (dim < -1 || dim > 3)
          throw py::value_error("dim must be -1 (all), 0, 1, 2 or 3, got " + std::to_string(dim));
        std::vector<EntityId> ids;
        for (int d = dim < 0 ? 0 : dim; d <= (dim < 0 ? 3 : dim); ++d)
          for (int tag : state->live().occ->tags(d)) ids.push_back({d, tag});
        return dimTagList(ids);
      },
      py::arg("dim") = -1,
      "The kernel's shapes [(dim, tag)], synchronized or not (all dimensions: dim = -1).");
  occ.def(
      "getBoundingBox",
      [state](int dim, int tag) { return boxTuple(state->live().occ->boundingBox({dim, tag})); },
      py::arg("dim"), py::arg("tag"), "(xmin, ymin, zmin, xmax, ymax, zmax) of one shape.");
  occ.def(
      "getClosestEntities",
      [state](double x, double y, double z, const DimTags& dimTags, int n) {
        std::vector<EntityId> closest =
            state->session().factories().solidModeler().closest({x, y, z}, entityIds(dimTags));
        if (n >= 0 && closest.size() > static_cast<std::size_t>(n)) closest.resize(n);
        return py::make_tuple(dimTagList(closest), py::list(), py::list());
      },
      py::arg("x"), py::arg("y"), py::arg("z"), py::arg("dimTags"), py::arg("n") = 1,
      "(outDimTags, distances, coord): the n shapes of dimTags closest to (x, y, z), nearest "
      "first; distances and coord are left empty.");
  occ.def(
      "importShapes",
      [state](const std::string& fileName, bool highestDimOnly, const std::string&) {
        return dimTagList(
            state->session().factories().solidModeler().importShapes(fileName, !highestDimOnly));
      },
      py::arg("fileName"), py::arg("highestDimOnly") = true, py::arg("format") = "",
      "Reads the shapes of a STEP, IGES or BREP file, as ShapeFromFile; returns [(dim, tag)].");
  occ.def(
      "addCurveLoop",
      [state](const std::vector<int>& curveTags, int tag) {
        LiveSession& s = state->live();
        if (tag < 0) tag = s.nextTag(GeometryFactory::kCurveLoop);
        s.occ->addCurveLoop(tag, curveTags);
        return tag;
      },
      py::arg("curveTags"), py::arg("tag") = -1, "A closed loop of curves.");
  occ.def(
      "addSurfaceFilling",
      [state](int wireTag, int tag, const std::vector<int>& pointTags) {
        LiveSession& s = state->live();
        if (tag < 0) tag = s.nextTag(2);
        s.occ->addFillingSurface(tag, {wireTag}, pointTags);
        return tag;
      },
      py::arg("wireTag"), py::arg("tag") = -1, py::arg("pointTags") = std::vector<int>{},
      "A surface filling a curve loop, through the points given.");
  occ.def(
      "addPlaneSurface",
      tagged(state, 2,
             [](LiveSession& s, int tag, const Tags& tags) { s.occ->addPlaneSurface(tag, tags); }),
      py::arg("wireTags"), py::arg("tag") = -1);
  py::module_ mesh = occ.def_submodule("mesh", "Mesh constraints of OpenCASCADE shapes.");
  defineSetSize(mesh, state, [](LiveSession& s) -> GeometryFactory& { return *s.occ; });
}

}  // namespace geomesh::python
