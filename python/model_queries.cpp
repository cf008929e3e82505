// geomesh.model queries on the synchronized model: getBoundary, getValue, getBoundingBox,
// getEntitiesInBoundingBox, getPhysicalGroups; removeEntities; and the display calls
// (setVisibility, setColor), which have nothing to show here and do nothing.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "kernel/geometry.h"
#include "kernel/model.h"
#include "python/api_state.h"

namespace py = pybind11;

namespace geomesh::python {
namespace {

void requireEntity(const Model& model, int dim, int tag) {
  if (!model.contains({dim, tag}))
    throw py::value_error("no entity (" + std::to_string(dim) + ", " + std::to_string(tag) +
                          ") in the model");
}

// The points an entity's boundary reaches, recursively, each once, in the order met.
void collectPoints(const Model& model, EntityId e, std::vector<EntityId>& points) {
  if (e.dim == 0) {
    if (std::find(points.begin(), points.end(), e) == points.end()) points.push_back(e);
    return;
  }
  for (int tag : model.boundary(e)) collectPoints(model, {e.dim - 1, std::abs(tag)}, points);
}

// The boundaries of the entities: with `combined`, those bounding only one of them (in the
// order met); `oriented` keeps the sign of their orientation; `recursive`: down to points.
std::vector<EntityId> boundaryOf(const Model& model, const std::vector<EntityId>& entities,
                                 bool combined, bool oriented, bool recursive) {
  std::vector<EntityId> out;
  if (recursive) {
    for (const EntityId& e : entities) collectPoints(model, {e.dim, std::abs(e.tag)}, out);
    return out;
  }
  std::map<EntityId, int> count;
  for (const EntityId& e : entities) {
    if (e.dim == 0) continue;
    const int sign = e.tag < 0 ? -1 : 1;
    for (int tag : model.boundary({e.dim, std::abs(e.tag)})) {
      out.push_back({e.dim - 1, sign * tag});
      ++count[{e.dim - 1, std::abs(tag)}];
    }
  }
  if (combined)
    std::erase_if(out, [&](const EntityId& b) { return count[{b.dim, std::abs(b.tag)}] > 1; });
  if (!oriented)
    for (EntityId& b : out) b.tag = std::abs(b.tag);
  return out;
}

// Points of a curve (t) or a surface ((u, v) pairs) at parametric coordinates, flat.
std::vector<double> valuesOf(const Model& model, int dim, int tag,
                             const std::vector<double>& parameters) {
  requireEntity(model, dim, tag);
  std::vector<Vec3> points;
  if (dim == 0) {
    points.push_back(model.point(tag)->xyz);
  } else if (dim == 1) {
    const auto& geometry = model.curve(tag)->geometry;
    if (!geometry) throw py::value_error("curve " + std::to_string(tag) + " has no geometry");
    for (double t : parameters) points.push_back(geometry->point(t));
  } else if (dim == 2) {
    const auto& geometry = model.surface(tag)->geometry;
    if (!geometry) throw py::value_error("surface " + std::to_string(tag) + " has no geometry");
    for (std::size_t i = 0; i + 1 < parameters.size(); i += 2)
      points.push_back(geometry->point({parameters[i], parameters[i + 1]}));
  } else {
    throw py::value_error("getValue evaluates points, curves and surfaces");
  }
  std::vector<double> xyz;
  for (const Vec3& p : points) xyz.insert(xyz.end(), {p.x, p.y, p.z});
  return xyz;
}

bool inside(const BoundingBox& inner, const BoundingBox& outer) {
  return !inner.empty() && inner.min.x >= outer.min.x && inner.min.y >= outer.min.y &&
         inner.min.z >= outer.min.z && inner.max.x <= outer.max.x &&
         inner.max.y <= outer.max.y && inner.max.z <= outer.max.z;
}

}  // namespace

void defineModelQueries(py::module_& model, const State& state) {
  model.def(
      "getBoundary",
      [state](const DimTags& dimTags, bool combined, bool oriented, bool recursive) {
        const std::vector<EntityId> ids = entityIds(dimTags);
        // The pieces of a partitioned mesh bound each other (not recursively).
        if (ids.size() == 1 && !recursive)
          if (auto pieces = partitionBoundary(state->session(), ids[0], oriented))
            return dimTagList(*pieces);
        return dimTagList(boundaryOf(state->session().model(), ids, combined, oriented,
                                     recursive));
      },
      py::arg("dimTags"), py::arg("combined") = true, py::arg("oriented") = true,
      py::arg("recursive") = false,
      "The boundaries of the entities [(dim, tag)]: combined, those bounding only one of them; "
      "oriented, signed by orientation; recursive, the points they reach.");
  model.def(
      "getValue",
      [state](int dim, int tag, const std::vector<double>& parametricCoord) {
        return valuesOf(state->session().model(), dim, tag, parametricCoord);
      },
      py::arg("dim"), py::arg("tag"), py::arg("parametricCoord"),
      "The points of an entity at parametric coordinates (t for a curve, u, v for a surface; "
      "none for a point), flat [x, y, z, ...].");
  model.def(
      "getBoundingBox",
      [state](int dim, int tag) {
        const Model& m = state->session().model();
        BoundingBox box;
        if (dim < 0) {
          box = m.boundingBox();
        } else {
          requireEntity(m, dim, tag);
          box = m.boundingBox({dim, tag});
        }
        return py::make_tuple(box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z);
      },
      py::arg("dim"), py::arg("tag"),
      "(xmin, ymin, zmin, xmax, ymax, zmax) of an entity; of the whole model when dim < 0.");
  model.def(
      "getEntitiesInBoundingBox",
      [state](double xmin, double ymin, double zmin, double xmax, double ymax, double zmax,
              int dim) {
        const Model& m = state->session().model();
        BoundingBox box;
        box.include(Vec3{xmin, ymin, zmin});
        box.include(Vec3{xmax, ymax, zmax});
        std::vector<EntityId> found;
        for (const EntityId& e : m.entities(dim))
          if (inside(m.boundingBox(e), box)) found.push_back(e);
        return dimTagList(found);
      },
      py::arg("xmin"), py::arg("ymin"), py::arg("zmin"), py::arg("xmax"), py::arg("ymax"),
      py::arg("zmax"), py::arg("dim") = -1,
      "The entities [(dim, tag)] whose bounding box lies in the box (dimension dim; all: -1).");
  model.def(
      "getPhysicalGroups",
      [state](int dim) {
        py::list groups;
        for (const auto& [id, group] : state->session().model().physicalGroups())
          if (dim < 0 || group.dim == dim) groups.append(py::make_tuple(group.dim, group.tag));
        return groups;
      },
      py::arg("dim") = -1, "The physical groups [(dim, tag)].");
  model.def(
      "removeEntities",
      [state](const DimTags& dimTags, bool recursive) {
        LiveSession& s = state->live();
        std::vector<EntityId> builtIn, occ;
        for (const EntityId& id : entityIds(dimTags))
          (s.builtIn().contains({id.dim, std::abs(id.tag)}) ? builtIn : occ).push_back(id);
        if (!builtIn.empty()) s.builtIn().remove(builtIn, recursive);
        if (!occ.empty()) s.occ->remove(occ, recursive);
        synchronize(s.session);
      },
      py::arg("dimTags"), py::arg("recursive") = false,
      "Removes the entities from the geometry and the model (recursive: with their boundary "
      "that nothing else uses).");
  // Display calls: nothing is displayed, so they change nothing.
  model.def(
      "setVisibility", [](const DimTags&, bool, bool) {}, py::arg("dimTags"), py::arg("value"),
      py::arg("recursive") = false, "Accepted and ignored: nothing is displayed.");
  model.def(
      "setColor", [](const DimTags&, int, int, int, int, bool) {}, py::arg("dimTags"),
      py::arg("r"), py::arg("g"), py::arg("b"), py::arg("a") = 255,
      py::arg("recursive") = false, "Accepted and ignored: nothing is displayed.");
}

}  // namespace geomesh::python
