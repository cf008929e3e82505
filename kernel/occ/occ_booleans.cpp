// The OpenCASCADE factory's Booleans (union, intersection, difference, fragments) and the tags
// of their results.
#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepTools_History.hxx>
#include <BRep_Tool.hxx>
#include <Message_Report.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

namespace {

constexpr TopAbs_ShapeEnum kTypes[4] = {TopAbs_VERTEX, TopAbs_EDGE, TopAbs_FACE, TopAbs_SOLID};

const char* operationName(OccFactory::BooleanOperation op) {
  switch (op) {
    case OccFactory::BooleanOperation::Union: return "BooleanUnion";
    case OccFactory::BooleanOperation::Intersection: return "BooleanIntersection";
    case OccFactory::BooleanOperation::Difference: return "BooleanDifference";
    case OccFactory::BooleanOperation::Fragments: return "BooleanFragments";
  }
  return "Boolean";
}

// One input of a Boolean and what became of it.
struct BooleanInput {
  EntityId id;
  TopoDS_Shape shape;
  bool remove = false;  // Delete; given with its list
  bool deleted = false;
  TopTools_ListOfShape modified = {};
  bool unchanged() const { return !deleted && modified.IsEmpty(); }
};

// OpenCASCADE's alerts, in words.
constexpr std::pair<std::string_view, std::string_view> kAlerts[] = {
    {"BOPAlgo_AlertBOPNotAllowed",
     "this operation is not defined for shapes of these dimensions (a union of a volume and a "
     "point, say)"},
    {"BOPAlgo_AlertTooFewArguments", "it needs at least one object and one tool"},
    {"BOPAlgo_AlertNullInputShapes", "one of its shapes is empty"},
    {"BOPAlgo_AlertIntersectionFailed", "the shapes could not be intersected"},
    {"BOPAlgo_AlertIntersectionOfPairOfShapesFailed", "two of the shapes could not be intersected"},
    {"BOPAlgo_AlertSelfInterferingShape", "one of the shapes intersects itself"},
    {"BOPAlgo_AlertBuilderFailed", "the pieces could not be assembled"},
    {"BOPAlgo_AlertSolidBuilderFailed", "the volumes of the result could not be built"},
    {"BOPAlgo_AlertMultiDimensionalArguments",
     "its objects (or its tools) mix dimensions, which this operation does not allow"},
};

// OpenCASCADE's account of a failed operation, in one line: its alerts, in words when known.
std::string failureReason(const BRepAlgoAPI_BuilderAlgo& maker) {
  std::ostringstream report;
  if (!maker.GetReport().IsNull()) maker.GetReport()->Dump(report);
  const std::string text = report.str();
  std::string reason;
  for (const auto& [alert, words] : kAlerts)
    if (text.find(alert) != std::string::npos)
      reason += (reason.empty() ? "" : "; ") + std::string(words);
  if (!reason.empty()) return reason;
  std::string raw = text;
  for (char& c : raw)
    if (c == '\n' || c == '\r') c = ' ';
  while (!raw.empty() && raw.back() == ' ') raw.pop_back();
  return raw.empty() ? "OpenCASCADE could not compute it" : raw;
}

std::unique_ptr<BRepAlgoAPI_BuilderAlgo> makeOperation(OccFactory::BooleanOperation op) {
  switch (op) {
    case OccFactory::BooleanOperation::Union: return std::make_unique<BRepAlgoAPI_Fuse>();
    case OccFactory::BooleanOperation::Intersection: return std::make_unique<BRepAlgoAPI_Common>();
    case OccFactory::BooleanOperation::Difference: return std::make_unique<BRepAlgoAPI_Cut>();
    case OccFactory::BooleanOperation::Fragments: break;
  }
  return std::make_unique<BRepAlgoAPI_BuilderAlgo>();
}

TopTools_ListOfShape shapeList(const std::vector<BooleanInput>& inputs, bool objects,
                               std::size_t objectCount) {
  TopTools_ListOfShape list;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if ((i < objectCount) == objects) list.Append(inputs[i].shape);
  return list;
}

// Runs the operation; fragments take every input as an argument.
TopoDS_Shape runOperation(BRepAlgoAPI_BuilderAlgo& maker, OccFactory::BooleanOperation op,
                          const std::vector<BooleanInput>& inputs, std::size_t objectCount,
                          double fuzzy) {
  maker.SetRunParallel(false);
  if (fuzzy > 0) maker.SetFuzzyValue(fuzzy);
  if (op == OccFactory::BooleanOperation::Fragments) {
    TopTools_ListOfShape all;
    for (const BooleanInput& in : inputs) all.Append(in.shape);
    maker.SetArguments(all);
  } else {
    auto& boolean = static_cast<BRepAlgoAPI_BooleanOperation&>(maker);
    boolean.SetArguments(shapeList(inputs, true, objectCount));
    boolean.SetTools(shapeList(inputs, false, objectCount));
  }
  maker.Build();
  if (maker.HasErrors() || !maker.IsDone())
    throw GeometryError(std::string(operationName(op)) + " failed: " + failureReason(maker));
  return maker.Shape();
}

// Geometry.OCCUnionUnify: a union's faces and edges that lie on the same surface or curve
// merge. The inputs' histories go through the merge too.
TopoDS_Shape unify(const TopoDS_Shape& shape, std::vector<BooleanInput>& inputs) {
  ShapeUpgrade_UnifySameDomain unifier(shape, true, true, false);
  unifier.Build();
  const Handle(BRepTools_History) history = unifier.History();
  for (BooleanInput& in : inputs) {
    if (in.deleted) continue;
    TopTools_ListOfShape before = in.modified;
    if (before.IsEmpty()) before.Append(in.shape);
    TopTools_ListOfShape after;
    bool changed = !in.modified.IsEmpty();
    for (const TopoDS_Shape& s : before) {
      if (history->IsRemoved(s)) {
        changed = true;
        continue;
      }
      const TopTools_ListOfShape& images = history->Modified(s);
      if (images.IsEmpty()) {
        after.Append(s);
      } else {
        changed = true;
        // Pieces merged into one face give it once.
        for (const TopoDS_Shape& image : images)
          if (std::none_of(after.begin(), after.end(),
                           [&](const TopoDS_Shape& a) { return a.IsSame(image); }))
            after.Append(image);
      }
    }
    in.deleted = after.IsEmpty();
    in.modified = changed ? after : TopTools_ListOfShape();
  }
  return unifier.Shape();
}

// The result's shapes of its highest dimension.
std::vector<TopoDS_Shape> topShapes(const TopoDS_Shape& result, int& dim) {
  std::vector<TopoDS_Shape> top;
  for (dim = 3; dim >= 0 && top.empty(); --dim)
    for (TopExp_Explorer it(result, kTypes[dim]); it.More(); it.Next())
      if (std::none_of(top.begin(), top.end(),
                       [&](const TopoDS_Shape& s) { return s.IsSame(it.Current()); }))
        top.push_back(it.Current());
  ++dim;
  return top;
}

// BooleanUnion(tag) = ..: the result must be one shape of its highest dimension.
TopoDS_Shape taggedShape(const TopoDS_Shape& result, int tag, const std::string& name, int& dim) {
  const std::vector<TopoDS_Shape> top = topShapes(result, dim);
  if (top.size() != 1)
    throw GeometryError(name + " " + std::to_string(tag) + ": its result has " +
                        std::to_string(top.size()) + " " + entityKind(dim) +
                        " entities, which cannot all take the one tag " + std::to_string(tag));
  return top[0];
}

// Binds the result's shapes, highest dimension first, in the result's order: those not bound
// yet get new tags, depth first. Lists each shape that is not part of one listed before.
std::vector<EntityId> bindResult(OccShapes& shapes, const TopoDS_Shape& result) {
  std::vector<EntityId> out;
  std::set<EntityId> listed;
  TopTools_IndexedMapOfShape inListed;  // sub-shapes of the shapes listed so far
  for (int dim = 3; dim >= 0; --dim) {
    TopExp_Explorer it = dim == 3 ? TopExp_Explorer(result, kTypes[3])
                                  : TopExp_Explorer(result, kTypes[dim], kTypes[dim + 1]);
    for (; it.More(); it.Next()) {
      if (inListed.Contains(it.Current())) continue;
      const EntityId e{dim, shapes.bindNew(dim, it.Current())};
      if (!listed.insert(e).second) continue;
      out.push_back(e);
      for (int sub = dim - 1; sub >= 0; --sub)
        TopExp::MapShapes(it.Current(), kTypes[sub], inListed);
    }
  }
  return out;
}

// What a Boolean of inputs of different dimensions (a surface and points, say) lists, as the
// reference does: from the highest dimension down, every occurrence of a shape in the result
// (a point inside a face occurs in the face and on its own) that is an input kept as it was
// or the image that took an input's tag, and, once, each shape not bound before that is not
// part of a shape of a higher dimension not bound before (the sub-shapes of a new face are not
// listed, the curves of a face that passed its tag on are). Called before the result is bound
// (after the tags passed on); gives shapes.
std::vector<std::pair<int, TopoDS_Shape>> mixedListing(const OccShapes& shapes,
                                                       const TopoDS_Shape& result,
                                                       const std::vector<BooleanInput>& inputs) {
  TopTools_IndexedMapOfShape images, covered, listedNew;
  for (const BooleanInput& in : inputs) {
    if (in.unchanged()) images.Add(in.shape);
    for (const TopoDS_Shape& image : in.modified) images.Add(image);
  }
  std::vector<std::pair<int, TopoDS_Shape>> out;
  for (int dim = 3; dim >= 0; --dim)
    for (TopExp_Explorer it(result, kTypes[dim]); it.More(); it.Next()) {
      const TopoDS_Shape& s = it.Current();
      const bool isNew = !shapes.isBound(dim, s);
      if (!isNew && images.Contains(s)) {
        out.emplace_back(dim, s);
      } else if (isNew && !covered.Contains(s) && !listedNew.Contains(s)) {
        out.emplace_back(dim, s);
        listedNew.Add(s);
        TopExp::MapShapes(s, covered);
      }
    }
  return out;
}

struct TaggedShape {
  int dim, tag;
  TopoDS_Shape shape;
};

// The curves and faces of deleted tools that the result holds as they were, with their tags,
// which they keep, as in the reference: the curves of a plate the tools cut holes in bound the holes
// with the tools' tags (the objects' sub-shapes are numbered anew). A union of volumes makes
// all its faces anew (the reference's fused solids share no face with their inputs).
std::vector<TaggedShape> toolSubShapesKept(const OccShapes& shapes,
                                           const std::vector<BooleanInput>& inputs,
                                           std::size_t objectCount, const TopoDS_Shape& result,
                                           SolidModeling::BooleanOperation op) {
  std::vector<TaggedShape> out;
  for (int dim = 2; dim >= 1; --dim) {  // points are numbered anew
    TopTools_IndexedMapOfShape inResult;
    TopExp::MapShapes(result, kTypes[dim], inResult);
    for (std::size_t i = objectCount; i < inputs.size(); ++i) {
      const BooleanInput& in = inputs[i];
      if (!in.remove || in.unchanged() || dim >= in.id.dim) continue;
      if (op == SolidModeling::BooleanOperation::Union && in.id.dim == 3) continue;
      for (TopExp_Explorer it(in.shape, kTypes[dim]); it.More(); it.Next()) {
        // The degenerate curve at a sphere's or a cone's pole is numbered anew.
        const bool degenerate =
            dim == 1 && BRep_Tool::Degenerated(TopoDS::Edge(it.Current()));
        if (!degenerate && inResult.Contains(it.Current()) && shapes.isBound(dim, it.Current()))
          out.push_back({dim, shapes.tagOf(dim, it.Current()), it.Current()});
      }
    }
  }
  return out;
}

// The inputs that were deleted and not kept as they were, with the entities now in their place.
std::vector<SolidModeling::Replacement> replacementsOf(const OccShapes& shapes,
                                                       const std::vector<BooleanInput>& inputs) {
  std::vector<SolidModeling::Replacement> out;
  for (const BooleanInput& in : inputs) {
    if (!in.remove || in.unchanged()) continue;
    SolidModeling::Replacement r{in.id, {}};
    if (!in.deleted)
      for (const TopoDS_Shape& image : in.modified) {
        const int dim = shapeDimension(image);
        if (dim < 0 || !shapes.isBound(dim, image)) continue;
        const EntityId e{dim, shapes.tagOf(dim, image)};
        if (std::find(r.images.begin(), r.images.end(), e) == r.images.end())
          r.images.push_back(e);
      }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace

std::vector<EntityId> OccFactory::boolean(BooleanOperation op,
                                          const std::vector<EntityId>& objects,
                                          const std::vector<EntityId>& tools, bool deleteObjects,
                                          bool deleteTools, int tag) {
  const std::string name = operationName(op);
  if (objects.empty()) throw GeometryError(name + ": no object to operate on");
  if (tools.empty() && op != BooleanOperation::Fragments)
    throw GeometryError(name + ": no tool to operate with");
  std::vector<BooleanInput> inputs;
  auto add = [&](const EntityId& e, bool remove) {
    const EntityId id{e.dim, std::abs(e.tag)};
    inputs.push_back({id, shapes_->find(id.dim, id.tag), remove, false, {}});
  };
  for (const EntityId& e : objects) add(e, deleteObjects);
  for (const EntityId& e : tools) add(e, deleteTools);

  std::unique_ptr<BRepAlgoAPI_BuilderAlgo> maker = makeOperation(op);
  const TopoDS_Shape result = guarded(name, [&] {
    TopoDS_Shape shape =
        runOperation(*maker, op, inputs, objects.size(), booleanOptions_.tolerance);
    for (BooleanInput& in : inputs) {
      in.deleted = maker->IsDeleted(in.shape);
      in.modified = maker->Modified(in.shape);
    }
    return op == BooleanOperation::Union && booleanOptions_.unifyUnion ? unify(shape, inputs)
                                                                        : shape;
  });

  int taggedDim = 0;
  const TopoDS_Shape tagged =
      tag >= 0 ? taggedShape(result, tag, name, taggedDim) : TopoDS_Shape();

  // Deleted inputs go, unless the result holds them untouched; the tags of the tools'
  // sub-shapes that the result keeps as they were are noted first (see toolSubShapesKept).
  const std::vector<TaggedShape> kept =
      booleanOptions_.preserveNumbering
          ? toolSubShapesKept(*shapes_, inputs, objects.size(), result, op)
          : std::vector<TaggedShape>{};
  for (const BooleanInput& in : inputs)
    if (in.remove && !in.unchanged()) shapes_->unbind(in.id.dim, in.id.tag, true);
  for (const TaggedShape& k : kept)
    if (!shapes_->isBound(k.dim, k.shape) && !shapes_->contains(k.dim, k.tag))
      shapes_->bindShape(k.dim, k.tag, k.shape);
  // A tag given to the result goes to its shape before any other.
  if (tag >= 0 && !shapes_->isBound(taggedDim, tagged)) {
    if (shapes_->contains(taggedDim, tag))
      throw GeometryError(name + " " + std::to_string(tag) + ": " + entityName(taggedDim, tag) +
                          " already exists");
    shapes_->bindShape(taggedDim, tag, tagged);
  }
  // A deleted input turned into a single shape of its dimension passes its tag on (to that
  // shape alone: its sub-shapes are numbered with the rest of the result).
  for (const BooleanInput& in : inputs) {
    if (!booleanOptions_.preserveNumbering) break;
    if (!in.remove || in.deleted || in.modified.Extent() != 1) continue;
    const TopoDS_Shape& image = in.modified.First();
    if (shapeDimension(image) == in.id.dim && !shapes_->isBound(in.id.dim, image) &&
        !shapes_->contains(in.id.dim, in.id.tag))
      shapes_->bindShape(in.id.dim, in.id.tag, image);
  }
  const bool mixed = std::any_of(inputs.begin(), inputs.end(), [&](const BooleanInput& in) {
    return in.id.dim != inputs.front().id.dim;
  });
  std::vector<std::pair<int, TopoDS_Shape>> listing;
  if (mixed) listing = mixedListing(*shapes_, result, inputs);
  std::vector<EntityId> out = bindResult(*shapes_, result);
  if (mixed) {
    out.clear();
    for (const auto& [dim, shape] : listing)
      if (shapes_->isBound(dim, shape)) out.push_back({dim, shapes_->tagOf(dim, shape)});
  }
  replacements_ = replacementsOf(*shapes_, inputs);
  return out;
}

// Coherence: the entities of the highest dimension present, fragmented together, as the
// reference makes coincident entities one (lower-dimensional ones stay as they are).
void OccFactory::coherence() {
  for (int dim = 3; dim >= 0; --dim) {
    if (shapes_->byTag[dim].empty()) continue;
    std::vector<EntityId> all;
    for (const auto& entry : shapes_->byTag[dim]) all.push_back({dim, entry.first});
    if (all.size() > 1) boolean(BooleanOperation::Fragments, all, {}, true, true);
    return;
  }
}

}  // namespace geomesh
