// geomesh.model.mesh beyond generate and the node and element queries: size fields
// (geomesh.model.mesh.field), per-entity constraints (embed, setPeriodic, setCompound,
// setAlgorithm), discrete surfaces (classifySurfaces, createGeometry) and homology requests.
// Each records what the script statement of the same meaning records: Field[n] = ...,
// Background Field, Point{..} In Surface{..}, Periodic Surface{..} = {..} Affine{..},
// Compound Surface{..}, MeshAlgorithm Surface{..}, ClassifySurfaces{..}, CreateGeometry,
// Homology.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/affine_map.h"
#include "kernel/model.h"
#include "mesh/homology/homology.h"
#include "python/api_state.h"

namespace py = pybind11;

namespace geomesh::python {
namespace {

SizeFieldDefinition& fieldOf(Session& session, int tag) {
  auto& fields = session.model().meshConstraints().sizeFields;
  const auto it = fields.find(tag);
  if (it == fields.end()) raiseError("Error", "no field " + std::to_string(tag));
  return it->second;
}

void defineFields(py::module_& field, const State& state) {
  field.def(
      "add",
      [state](const std::string& fieldType, int tag) {
        auto& fields = state->session().model().meshConstraints().sizeFields;
        if (tag < 0) tag = fields.empty() ? 1 : fields.rbegin()->first + 1;
        fields[tag] = SizeFieldDefinition{fieldType};
        return tag;
      },
      py::arg("fieldType"), py::arg("tag") = -1,
      "A size field of the type named (Distance, Threshold, MathEval, Box, Min, ...), as "
      "Field[tag] = type; returns its tag.");
  field.def(
      "remove",
      [state](int tag) { state->session().model().meshConstraints().sizeFields.erase(tag); },
      py::arg("tag"));
  field.def(
      "list",
      [state] {
        std::vector<int> tags;
        for (const auto& [tag, definition] : state->session().model().meshConstraints().sizeFields)
          tags.push_back(tag);
        return tags;
      },
      "The tags of the fields.");
  field.def(
      "getType", [state](int tag) { return fieldOf(state->session(), tag).type; },
      py::arg("tag"));
  field.def(
      "setNumber",
      [state](int tag, const std::string& option, double value) {
        fieldOf(state->session(), tag).numbers[option] = {value};
      },
      py::arg("tag"), py::arg("option"), py::arg("value"), "Field[tag].option = value;");
  field.def(
      "setNumbers",
      [state](int tag, const std::string& option, const std::vector<double>& values) {
        fieldOf(state->session(), tag).numbers[option] = values;
      },
      py::arg("tag"), py::arg("option"), py::arg("values"), "Field[tag].option = {values};");
  field.def(
      "setString",
      [state](int tag, const std::string& option, const std::string& value) {
        fieldOf(state->session(), tag).strings[option] = value;
      },
      py::arg("tag"), py::arg("option"), py::arg("value"), "Field[tag].option = \"value\";");
  field.def(
      "setAsBackgroundMesh",
      [state](int tag) { state->session().model().meshConstraints().backgroundField = tag; },
      py::arg("tag"), "The field sets the mesh size everywhere, as Background Field = tag;.");
  field.def(
      "setAsBoundaryLayer",
      [state](int tag) {
        auto& layers = state->session().model().meshConstraints().boundaryLayerFields;
        if (std::find(layers.begin(), layers.end(), tag) == layers.end()) layers.push_back(tag);
      },
      py::arg("tag"), "The BoundaryLayer field builds its layer, as BoundaryLayer Field = tag;.");
}

// Runs a discrete-surface operation of the session; what prevents it raises Error.
template <typename Operation>
void onMergedSurfaces(const State& state, Operation operation) {
  state->meshWillChange();
  try {
    operation(state->session());
    // The model changes at once, as the reference's does.
    state->session().synchronize();
  } catch (const std::runtime_error& e) {
    raiseError("Error", e.what());
  }
}

void defineConstraints(py::module_& mesh, const State& state) {
  mesh.def(
      "embed",
      [state](int dim, const std::vector<int>& tags, int inDim, int inTag) {
        LiveSession& s = state->live();
        s.factoryOf({inDim, inTag}).embed(dim, tags, inDim, inTag);
      },
      py::arg("dim"), py::arg("tags"), py::arg("inDim"), py::arg("inTag"),
      "The entities of dimension dim are meshed inside entity (inDim, inTag), as "
      "Point{..} In Surface{..};.");
  mesh.def(
      "setPeriodic",
      [state](int dim, const std::vector<int>& tags, const std::vector<int>& tagsMaster,
              const std::vector<double>& affineTransform) {
        if (affineTransform.size() != 16)
          throw py::value_error("affineTransform takes 16 numbers (a 4 x 4 row-major matrix)");
        AffineMap map;
        for (std::size_t i = 0; i < 12; ++i) map.m[i] = affineTransform[i];
        if (tags.empty()) return;
        LiveSession& s = state->live();
        s.factoryOf({dim, std::abs(tags.front())}).setPeriodic(dim, tags, tagsMaster, map);
      },
      py::arg("dim"), py::arg("tags"), py::arg("tagsMaster"), py::arg("affineTransform"),
      "The mesh of each entity of tags is the mesh of its master moved by the transform, as "
      "Periodic Surface{..} = {..} Affine{..};.");
  mesh.def(
      "setCompound",
      [state](int dim, const std::vector<int>& tags) {
        if (dim == 3)
          warnUnsupported(state, "setCompound(3, ..)", "its volumes are meshed one by one");
        if (tags.empty()) return;
        LiveSession& s = state->live();
        s.factoryOf({dim, std::abs(tags.front())}).addCompound(dim, tags);
      },
      py::arg("dim"), py::arg("tags"), "The entities are meshed as one, as Compound Surface{..};.");
  mesh.def(
      "setAlgorithm",
      [state](int dim, int tag, int val) {
        if (dim != 2) {
          warnUnsupported(state, "setAlgorithm(" + std::to_string(dim) + ", ..)",
                          "a per-entity algorithm is read for surfaces only; ignored");
          return;
        }
        state->session().model().meshConstraints().surfaceAlgorithms[std::abs(tag)] = val;
      },
      py::arg("dim"), py::arg("tag"), py::arg("val"),
      "The 2D algorithm of one surface, as MeshAlgorithm Surface{tag} = val;.");
  mesh.def(
      "setSizeCallback",
      [state](const py::object&) {
        warnUnsupported(state, "model.mesh.setSizeCallback",
                        "mesh size callbacks are not supported; the sizes ignore it");
      },
      py::arg("callback"), "Accepted with a warning: the sizes do not use the callback.");
  mesh.def(
      "removeSizeCallback", [] {}, "Nothing to remove: callbacks are not used.");
  mesh.def(
      "recombine",
      [state] {
        warnUnsupported(state, "model.mesh.recombine",
                        "recombining a finished mesh is not supported; set Recombine on the "
                        "surfaces before generate");
      },
      "Accepted with a warning: not supported.");
  mesh.def(
      "refine",
      [state] {
        warnUnsupported(state, "model.mesh.refine", "refining a finished mesh is not supported");
      },
      "Accepted with a warning: not supported.");
}

void defineDiscrete(py::module_& mesh, const State& state) {
  mesh.def(
      "classifySurfaces",
      [state](double angle, bool boundary, bool forReparametrization, double curveAngle,
              bool) {
        onMergedSurfaces(state, [&](Session& s) {
          s.classifySurfaces(angle, boundary, forReparametrization, curveAngle);
        });
      },
      py::arg("angle"), py::arg("boundary") = true, py::arg("forReparametrization") = false,
      py::arg("curveAngle") = std::numbers::pi, py::arg("exportDiscrete") = true,
      "Splits the merged triangles into surfaces where they meet at more than angle (radians), "
      "as ClassifySurfaces{angle, boundary, forReparametrization, curveAngle};.");
  mesh.def(
      "createTopology",
      [state](bool, bool) { onMergedSurfaces(state, [](Session& s) { s.createTopology(); }); },
      py::arg("makeSimplyConnected") = true, py::arg("exportDiscrete") = true,
      "Curves and points for the merged surfaces as they are, as CreateTopology;.");
  mesh.def(
      "createGeometry",
      [state](const DimTags& dimTags) {
        if (!dimTags.empty())
          warnUnsupported(state, "model.mesh.createGeometry(dimTags)",
                          "every discrete entity gets a geometry, not only those given");
        onMergedSurfaces(state, [](Session& s) { s.createGeometry(); });
      },
      py::arg("dimTags") = DimTags{},
      "Gives the discrete curves and surfaces a geometry, as CreateGeometry;.");
  mesh.def(
      "addHomologyRequest",
      [state](const std::string& type, const std::vector<int>& domainTags,
              const std::vector<int>& subdomainTags, const std::vector<int>& dims) {
        if (type != "Homology" && type != "Cohomology")
          throw py::value_error("type is Homology or Cohomology, not '" + type + "'");
        HomologyRequest request;
        request.kind = type == "Homology" ? HomologyKind::Homology : HomologyKind::Cohomology;
        request.domain = domainTags;
        request.subdomain = subdomainTags;
        request.dims = dims;
        request.origin = "model.mesh.addHomologyRequest";
        state->session().homologyRequests().push_back(std::move(request));
      },
      py::arg("type") = "Homology", py::arg("domainTags") = std::vector<int>{},
      py::arg("subdomainTags") = std::vector<int>{}, py::arg("dims") = std::vector<int>{},
      "A (co)homology computation carried out after each generate, its bases saved as "
      "physical groups, as Homology{{domain}, {subdomain}};.");
  mesh.def(
      "clearHomologyRequests", [state] { state->session().homologyRequests().clear(); });
}

}  // namespace

void defineMeshConstraints(py::module_& mesh, const State& state) {
  py::module_ field = mesh.def_submodule("field", "Mesh size fields.");
  defineFields(field, state);
  defineConstraints(mesh, state);
  defineDiscrete(mesh, state);
}

}  // namespace geomesh::python
