// The OpenCASCADE factory's Booleans (union, intersection, difference, fragments) and the tags
// of their results.
#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepTools_History.hxx>
#include <Message_Report.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>

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
// yet get new tags, depth first. Lists each shape that is not part of one listed before. The
// shapes that took the tag of the input they replace (`passedOn`, bound alone already) number
// their sub-shapes last, after those of every new shape, as the reference does: a box
// fragmented with two overlapping boxes it touches keeps its tag, and its faces come after
// those of the overlapping boxes' pieces (the face it shares with them among these).
std::vector<EntityId> bindResult(OccShapes& shapes, const TopoDS_Shape& result,
                                 const TopTools_IndexedMapOfShape& passedOn) {
  std::vector<EntityId> out;
  std::set<EntityId> listed;
  TopTools_IndexedMapOfShape inListed;  // sub-shapes of the shapes listed so far
  std::vector<std::pair<int, TopoDS_Shape>> later;
  for (int dim = 3; dim >= 0; --dim) {
    TopExp_Explorer it = dim == 3 ? TopExp_Explorer(result, kTypes[3])
                                  : TopExp_Explorer(result, kTypes[dim], kTypes[dim + 1]);
    for (; it.More(); it.Next()) {
      if (inListed.Contains(it.Current())) continue;
      const bool passed = passedOn.Contains(it.Current());
      const EntityId e{
          dim, passed ? shapes.tagOf(dim, it.Current()) : shapes.bindNew(dim, it.Current())};
      if (!listed.insert(e).second) continue;
      out.push_back(e);
      if (passed) later.emplace_back(dim, it.Current());
      for (int sub = dim - 1; sub >= 0; --sub)
        TopExp::MapShapes(it.Current(), kTypes[sub], inListed);
    }
  }
  for (const auto& [dim, shape] : later) shapes.bindNew(dim, shape);
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

// Whether every image of the tool in the result is an image of an object too: the tool left no
// piece of its own (a cut's tool, which leaves none; an intersection's; a union's merged into
// the objects).
bool mergedIntoObjects(const BooleanInput& tool, const std::vector<BooleanInput>& inputs,
                       std::size_t objectCount) {
  TopTools_IndexedMapOfShape objectImages;
  for (std::size_t i = 0; i < objectCount; ++i) {
    if (inputs[i].unchanged()) objectImages.Add(inputs[i].shape);
    for (const TopoDS_Shape& image : inputs[i].modified) objectImages.Add(image);
  }
  return std::all_of(tool.modified.begin(), tool.modified.end(),
                     [&](const TopoDS_Shape& image) { return objectImages.Contains(image); });
}

// The tools' boundaries that keep their tags, as in the reference. A tool given with Delete,
// changed by the operation and leaving no piece of its own keeps the tags of its faces (a
// solid's), curves (a surface's) or points (a curve's) that the result holds as they were, with
// those of their curves and points (a sphere's pole curves too): the faces of a cavity are the
// faces of the tool that made it. Everything else of the deleted inputs is numbered anew: the
// objects' sub-shapes, even those kept as they were; a tool's curve or point kept while its
// faces were cut; all of a tool that left a piece of its own. Fragments have no tools (every
// input is an argument alike), and a union of volumes makes all its faces anew.
std::vector<TaggedShape> toolBoundariesKept(const OccShapes& shapes,
                                            const std::vector<BooleanInput>& inputs,
                                            std::size_t objectCount, const TopoDS_Shape& result,
                                            SolidModeling::BooleanOperation op) {
  using Op = SolidModeling::BooleanOperation;
  std::vector<TaggedShape> out;
  if (op == Op::Fragments) return out;
  for (std::size_t i = objectCount; i < inputs.size(); ++i) {
    const BooleanInput& in = inputs[i];
    if (!in.remove || in.unchanged() || in.id.dim == 0 || (op == Op::Union && in.id.dim == 3) ||
        !mergedIntoObjects(in, inputs, objectCount))
      continue;
    const int dim = in.id.dim - 1;
    TopTools_IndexedMapOfShape inResult;
    TopExp::MapShapes(result, kTypes[dim], inResult);
    for (TopExp_Explorer it(in.shape, kTypes[dim]); it.More(); it.Next()) {
      if (!inResult.Contains(it.Current())) continue;
      for (int sub = dim; sub >= 0; --sub)
        for (TopExp_Explorer part(it.Current(), kTypes[sub]); part.More(); part.Next())
          if (shapes.isBound(sub, part.Current()))
            out.push_back({sub, shapes.tagOf(sub, part.Current()), part.Current()});
    }
  }
  return out;
}

// The inputs that were deleted and are not where they were, with the entities now in their
// place: those the operation changed, and, renumbered, those it kept as they were too.
std::vector<SolidModeling::Replacement> replacementsOf(const OccShapes& shapes,
                                                       const std::vector<BooleanInput>& inputs,
                                                       bool renumbered) {
  std::vector<SolidModeling::Replacement> out;
  for (const BooleanInput& in : inputs) {
    if (!in.remove || (in.unchanged() && !renumbered)) continue;
    SolidModeling::Replacement r{in.id, {}};
    TopTools_ListOfShape images = in.modified;
    if (in.unchanged()) images.Append(in.shape);
    if (!in.deleted)
      for (const TopoDS_Shape& image : images) {
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

// Binds the result as the reference binds a shape it makes anew: its solids, then its other
// faces, edges and vertices, each under a new tag unless bound already, its sub-shapes depth
// first. Lists the shapes that were not bound before and that the reference does not reach
// through a shape listed before: it reaches the faces of a solid, the edges of a face and the
// vertices of an edge, so a vertex inside a face or a solid, on no edge, is listed on its own.
std::vector<EntityId> bindAnew(OccShapes& shapes, const TopoDS_Shape& result) {
  TopTools_IndexedMapOfShape boundBefore[4], reached[4];
  for (int dim = 0; dim <= 3; ++dim)
    for (TopExp_Explorer it(result, kTypes[dim]); it.More(); it.Next())
      if (shapes.isBound(dim, it.Current())) boundBefore[dim].Add(it.Current());
  std::vector<EntityId> out;
  for (int dim = 3; dim >= 0; --dim)
    for (TopExp_Explorer it(result, kTypes[dim]); it.More(); it.Next()) {
      const TopoDS_Shape& s = it.Current();
      if (reached[dim].Contains(s)) continue;
      const EntityId e{dim, shapes.bindNew(dim, s)};
      if (!boundBefore[dim].Contains(s)) out.push_back(e);
      reached[dim].Add(s);
      for (int sub = dim - 1; sub >= 1; --sub) TopExp::MapShapes(s, kTypes[sub], reached[sub]);
      for (TopExp_Explorer edge(s, TopAbs_EDGE); edge.More(); edge.Next())
        TopExp::MapShapes(edge.Current(), TopAbs_VERTEX, reached[0]);
    }
  return out;
}

// The reference numbers the result without regard to the inputs when the result is given a
// tag, or when Geometry.OCCBooleanPreserveNumbering is off: every deleted input goes, even one
// the operation kept as it was, then the result is bound anew. Its sub-shapes that an entity
// still bound holds keep their tags; the others take the next free ones, so the faces of a
// box cut by a sphere that was deleted with it are 1..6 again, in the box's order. A tagged
// result is the one shape of the result's highest dimension: shapes of lower dimensions beside
// it are dropped.
std::vector<EntityId> bindRenumbered(OccShapes& shapes, const std::vector<BooleanInput>& inputs,
                                     const TopoDS_Shape& result, int tag, const std::string& name) {
  int dim = 0;
  const TopoDS_Shape tagged = tag >= 0 ? taggedShape(result, tag, name, dim) : TopoDS_Shape();
  const auto deletedInput = [&](const EntityId& e) {
    return std::any_of(inputs.begin(), inputs.end(),
                       [&](const BooleanInput& in) { return in.remove && in.id == e; });
  };
  if (tag >= 0 && shapes.contains(dim, tag) && !deletedInput({dim, tag}))
    throw GeometryError(name + " " + std::to_string(tag) + ": " + entityName(dim, tag) +
                        " already exists");
  for (const BooleanInput& in : inputs)
    if (in.remove) shapes.unbind(in.id.dim, in.id.tag, true);
  if (tag < 0) return bindAnew(shapes, result);
  shapes.bindTree(dim, tag, tagged);
  return {{dim, tag}};
}

// Geometry.OCCBooleanPreserveNumbering, without a tag for the result: inputs kept as they were
// keep their tags, a deleted input turned into one shape passes its tag on, some tools'
// boundaries kept as they were keep theirs (see toolBoundariesKept); the rest is numbered after.
std::vector<EntityId> bindPreservingNumbering(OccShapes& shapes,
                                              const std::vector<BooleanInput>& inputs,
                                              std::size_t objectCount, const TopoDS_Shape& result,
                                              SolidModeling::BooleanOperation op) {
  // Deleted inputs go, unless the result holds them untouched; the tags of the tools'
  // boundaries that keep theirs are noted first.
  const std::vector<TaggedShape> kept = toolBoundariesKept(shapes, inputs, objectCount, result, op);
  for (const BooleanInput& in : inputs)
    if (in.remove && !in.unchanged()) shapes.unbind(in.id.dim, in.id.tag, true);
  for (const TaggedShape& k : kept)
    if (!shapes.isBound(k.dim, k.shape) && !shapes.contains(k.dim, k.tag))
      shapes.bindShape(k.dim, k.tag, k.shape);
  // A deleted input turned into a single shape of its dimension passes its tag on (to that
  // shape alone: its sub-shapes are numbered after the rest of the result).
  TopTools_IndexedMapOfShape passedOn;
  for (const BooleanInput& in : inputs) {
    if (!in.remove || in.deleted || in.modified.Extent() != 1) continue;
    const TopoDS_Shape& image = in.modified.First();
    if (shapeDimension(image) == in.id.dim && !shapes.isBound(in.id.dim, image) &&
        !shapes.contains(in.id.dim, in.id.tag)) {
      shapes.bindShape(in.id.dim, in.id.tag, image);
      passedOn.Add(image);
    }
  }
  const bool mixed = std::any_of(inputs.begin(), inputs.end(), [&](const BooleanInput& in) {
    return in.id.dim != inputs.front().id.dim;
  });
  if (!mixed) return bindResult(shapes, result, passedOn);
  const std::vector<std::pair<int, TopoDS_Shape>> listing = mixedListing(shapes, result, inputs);
  bindResult(shapes, result, passedOn);
  std::vector<EntityId> out;
  for (const auto& [dim, shape] : listing)
    if (shapes.isBound(dim, shape)) out.push_back({dim, shapes.tagOf(dim, shape)});
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
  // The reference refuses a tag in use in the first object's dimension before it operates,
  // the tag of an input it would delete included.
  if (tag >= 0 && shapes_->contains(objects.front().dim, tag))
    throw GeometryError(name + " " + std::to_string(tag) + ": " +
                        entityName(objects.front().dim, tag) + " already exists");
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

  const bool renumbered = tag >= 0 || !booleanOptions_.preserveNumbering;
  std::vector<EntityId> out =
      renumbered ? bindRenumbered(*shapes_, inputs, result, tag, name)
                 : bindPreservingNumbering(*shapes_, inputs, objects.size(), result, op);
  replacements_ = replacementsOf(*shapes_, inputs, renumbered);
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
