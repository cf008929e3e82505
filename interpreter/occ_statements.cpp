// OpenCASCADE statements: primitives (Sphere, Cylinder, Cone, Torus, Wedge, Rectangle, Disk,
// whole Circle and Ellipse), Wire, Booleans, ThruSections, Fillet, Chamfer, HealShapes and
// ShapeFromFile.
// They need a factory that offers solid modeling (SetFactory("OpenCASCADE")).
#include <cmath>
#include <filesystem>
#include <numbers>

#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "kernel/geometry_error.h"
#include "kernel/solid_modeling.h"

namespace geomesh {

namespace {

using Words = std::vector<std::string>;

std::string joined(const Words& words) {
  std::string text;
  for (const auto& word : words) text += (text.empty() ? "" : " ") + word;
  return text;
}

constexpr double kPi = std::numbers::pi;
constexpr const char* kEntityKinds[4] = {"Point", "Curve", "Surface", "Volume"};

// How many numbers each primitive takes, at least and at most, and how scripts write it.
struct PrimitiveForm {
  std::string_view name;
  std::size_t fewest, most;
  const char* usage;
};

constexpr PrimitiveForm kPrimitives[] = {
    {"Cone", 8, 9, "{x, y, z, dx, dy, dz, r1, r2 <, angle>}"},
    {"Cylinder", 7, 8, "{x, y, z, dx, dy, dz, r <, angle>}"},
    {"Disk", 4, 5, "{x, y, z, rx <, ry>}"},
    {"Rectangle", 5, 6, "{x, y, z, dx, dy <, corner radius>}"},
    {"Sphere", 4, 7, "{x, y, z, r <, polar angle min, polar angle max> <, opening>}"},
    {"Torus", 5, 6, "{x, y, z, r1, r2 <, angle>}"},
    {"Wedge", 6, 7, "{x, y, z, dx, dy, dz <, top length>}"},
};

const PrimitiveForm* primitiveForm(std::string_view name) {
  for (const PrimitiveForm& form : kPrimitives)
    if (form.name == name) return &form;
  return nullptr;
}

// Builds the primitive `name` from the script's numbers; returns its (dim, tag).
EntityId buildPrimitive(SolidModeling& solids, std::string_view name, int tag,
                        const std::vector<double>& v) {
  const Vec3 p{v[0], v[1], v[2]};
  auto at = [&](std::size_t i, double otherwise) { return i < v.size() ? v[i] : otherwise; };
  if (name == "Sphere") {
    double a1 = -kPi / 2, a2 = kPi / 2, a3 = 2 * kPi;
    if (v.size() == 5) a3 = v[4];
    if (v.size() >= 6) a1 = v[4], a2 = v[5], a3 = at(6, 2 * kPi);
    return {3, solids.addSphere(tag, p, v[3], a1, a2, a3)};
  }
  if (name == "Cylinder")
    return {3, solids.addCylinder(tag, p, {v[3], v[4], v[5]}, v[6], at(7, 2 * kPi))};
  if (name == "Cone")
    return {3, solids.addCone(tag, p, {v[3], v[4], v[5]}, v[6], v[7], at(8, 2 * kPi))};
  if (name == "Torus") return {3, solids.addTorus(tag, p, v[3], v[4], at(5, 2 * kPi))};
  if (name == "Wedge") return {3, solids.addWedge(tag, p, {v[3], v[4], v[5]}, at(6, 0))};
  if (name == "Rectangle") return {2, solids.addRectangle(tag, p, v[3], v[4], at(5, 0))};
  return {2, solids.addDisk(tag, p, v[3], at(4, v[3]))};
}

SolidModeling::BooleanOperation booleanOperation(const std::string& word) {
  if (word == "BooleanUnion") return SolidModeling::BooleanOperation::Union;
  if (word == "BooleanIntersection") return SolidModeling::BooleanOperation::Intersection;
  if (word == "BooleanDifference") return SolidModeling::BooleanOperation::Difference;
  return SolidModeling::BooleanOperation::Fragments;
}

}  // namespace

SolidModeling* Interpreter::solidModeling(const std::string& statement,
                                          const SourceLocation& where) {
  SolidModeling* solids = session_.factory().solidModeling();
  if (!solids) {
    session_.noteIgnoredStatement(where);
    warn(where, "'" + statement + "' needs SetFactory(\"OpenCASCADE\"); ignored");
  }
  return solids;
}

// A tag in parentheses that may be negative (-1: the next free one), as OpenCASCADE's
// statements accept.
int Interpreter::solidTag(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle != ast::CommandStmt::Args::Paren || command.args.size() != 1 ||
      command.op != "=" || !command.value)
    fail(where, "'" + joined(command.words) + "' takes a tag in parentheses and values, as in " +
                    joined(command.words) + "(1) = {..};");
  const double tag = evaluateNumber(*command.args[0]);
  if (tag != std::floor(tag) || tag == 0)
    fail(command.args[0]->loc, "tag of '" + joined(command.words) + "' must be a non-zero integer");
  return clampedInteger<int>(tag);
}

// Sphere(1) = {..}; Cylinder, Cone, Torus, Wedge, Rectangle, Disk.
void Interpreter::definePrimitive(const ast::CommandStmt& command, const SourceLocation& where) {
  const std::string& name = command.words[0];
  const PrimitiveForm* form = primitiveForm(name);
  if (!form || command.words.size() != 1) return unsupportedStatement(command, where);
  const int tag = solidTag(command, where);
  const std::vector<double> v = evaluateNumbers(*command.value);
  if (v.size() < form->fewest || v.size() > form->most)
    fail(command.value->loc, name + " takes " + form->usage + ", not " +
                                 std::to_string(v.size()) + " values");
  SolidModeling* solids = solidModeling(name, where);
  if (!solids) return;
  try {
    session_.recordOrigin(buildPrimitive(*solids, name, tag, v), where);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// Circle(t) = {x, y, z, r <, angle1, angle2>}; Ellipse(t) = {x, y, z, rx, ry <, a1, a2>}:
// OpenCASCADE's whole curves and arcs. False when the values are not of that form.
bool Interpreter::defineConic(const ast::CommandStmt& command, const SourceLocation& where) {
  const bool circle = command.words == Words{"Circle"};
  const std::vector<double> v = evaluateNumbers(*command.value);
  const std::size_t base = circle ? 4 : 5;
  if (v.size() != base && v.size() != base + 2) return false;
  const int tag = solidTag(command, where);
  SolidModeling* solids = solidModeling(joined(command.words), where);
  if (!solids) return true;
  const std::vector<double> angles(v.begin() + static_cast<std::ptrdiff_t>(base), v.end());
  try {
    const Vec3 c{v[0], v[1], v[2]};
    const int made = circle ? solids->addCircle(tag, c, v[3], angles)
                            : solids->addEllipse(tag, c, v[3], v[4], angles);
    session_.recordOrigin({1, made}, where);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  return true;
}

void Interpreter::defineEllipse(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle == ast::CommandStmt::Args::Paren && command.value && command.op == "=" &&
      defineConic(command, where))
    return;
  defineEntity(command, where);
}

// Wire(t) = {curves};
void Interpreter::defineWire(const ast::CommandStmt& command, const SourceLocation& where) {
  const int tag = solidTag(command, where);
  SolidModeling* solids = solidModeling("Wire", where);
  if (!solids) return;
  try {
    solids->addWire(tag, entityTags(*command.value));
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// ThruSections(t) = {wires}; Ruled ThruSections(t) = {wires};
void Interpreter::defineThruSections(const ast::CommandStmt& command,
                                     const SourceLocation& where) {
  const int tag = solidTag(command, where);
  SolidModeling* solids = solidModeling(joined(command.words), where);
  if (!solids) return;
  try {
    for (const EntityId& e : solids->addThruSections(tag, entityTags(*command.value),
                                                     command.words[0] == "Ruled", true))
      session_.recordOrigin(e, where);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// { Volume{1}; Surface{2:4}; Delete; }: the shapes of a Boolean's argument, and whether to
// delete them.
std::vector<EntityId> Interpreter::booleanArguments(const ast::ShapePart& block, bool& remove) {
  std::vector<EntityId> shapes;
  remove = false;
  for (const auto& item : block.items) {
    if (item->kind == ast::ExprKind::Shape && item->parts.empty() &&
        (item->words == Words{"Delete"} || item->words == Words{"Recursive", "Delete"})) {
      remove = true;
      continue;
    }
    const int dim = entityDimension(item->words);
    if (item->kind == ast::ExprKind::Shape && dim >= 0 && item->parts.size() == 1 &&
        !item->parts[0].isBlock) {
      for (int tag : shapeTags(*item, dim)) shapes.push_back({dim, tag});
    } else if (auto produced = item->kind == ast::ExprKind::Shape ? shapeOperation(*item)
                                                                  : std::nullopt) {
      shapes.insert(shapes.end(), produced->begin(), produced->end());
    } else {
      fail(item->loc, "expected shapes such as Volume{1}; or Delete;");
    }
  }
  return shapes;
}

// BooleanUnion{..}{..} and the other Booleans, as statements (with or without a tag) and as
// values. Returns the result's entities.
std::vector<EntityId> Interpreter::booleanShapes(const std::string& word,
                                                 const std::vector<ast::ShapePart>& parts,
                                                 int tag, const SourceLocation& where) {
  // `{}` parses as an empty list, not a block; it stands for a block with no shapes, as in
  // BooleanFragments{ Volume{1:3}; Delete; }{}, the usual way to glue many volumes.
  auto isBlock = [](const ast::ShapePart& part) { return part.isBlock || part.items.empty(); };
  if (parts.size() != 2 || !isBlock(parts[0]) || !isBlock(parts[1]))
    fail(where, word + " takes two blocks of shapes, as in " + word +
                    "{ Volume{1}; Delete; }{ Volume{2}; Delete; }");
  bool deleteObjects = false, deleteTools = false;
  const std::vector<EntityId> objects = booleanArguments(parts[0], deleteObjects);
  const std::vector<EntityId> tools = booleanArguments(parts[1], deleteTools);
  SolidModeling* solids = solidModeling(word, where);
  if (!solids) return {};
  // The reference does nothing, deletes nothing and gives an empty list when there is no
  // object, and likewise for fragments of fewer than two shapes; without a tool, the other
  // operations fail (in the kernel, below).
  if (objects.empty()) {
    warn(where, word + " has no object to operate on: nothing done");
    return {};
  }
  if (booleanOperation(word) == SolidModeling::BooleanOperation::Fragments &&
      objects.size() + tools.size() < 2) {
    warn(where, word + " of a single shape: nothing done");
    return {};
  }
  for (const std::vector<EntityId>* list : {&objects, &tools})
    for (const EntityId& e : *list)
      if (!solids->owns(e) && session_.factory().contains({e.dim, std::abs(e.tag)}))
        fail(where, word + ": " + kEntityKinds[e.dim] + " " + std::to_string(std::abs(e.tag)) +
                        " was made by the built-in kernel; OpenCASCADE operations take "
                        "OpenCASCADE entities only");
  const OptionRegistry& options = session_.options();
  solids->setBooleanOptions({options.number("Geometry.ToleranceBoolean"),
                             options.number("Geometry.OCCBooleanSimplify") != 0,
                             options.number("Geometry.OCCBooleanPreserveNumbering") != 0});
  std::vector<EntityId> result;
  try {
    result = solids->boolean(booleanOperation(word), objects, tools, deleteObjects, deleteTools,
                             tag);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  reportReplacements(word, solids->lastReplacements(), where);
  return result;
}

namespace {

std::string entityList(const std::vector<EntityId>& entities) {
  std::string text;
  for (const EntityId& e : entities)
    text += (text.empty() ? "" : ", ") + std::string(kEntityKinds[e.dim]) + " " +
            std::to_string(e.tag);
  return text;
}

}  // namespace

// Logs what a Boolean made of each input it deleted (-v 4), and warns of each physical group
// that names an input now gone or renumbered: the reference renumbers silently.
void Interpreter::reportReplacements(const std::string& word,
                                     const std::vector<SolidModeling::Replacement>& replaced,
                                     const SourceLocation& where) {
  for (const SolidModeling::Replacement& r : replaced) {
    const std::string input = entityList({r.input});
    const std::string images = r.images.empty() ? "nothing" : entityList(r.images);
    session_.log().info(word + " (" + where.file + ":" + std::to_string(where.line) + "): " +
                        input + " -> " + images);
    if (r.images.size() == 1 && r.images[0] == r.input) continue;
    for (const auto& [id, group] : session_.factory().physicalGroups()) {
      if (id.dim != r.input.dim ||
          std::find(group.entities.begin(), group.entities.end(), r.input.tag) ==
              group.entities.end())
        continue;
      warn(where, "Physical " + std::string(kEntityKinds[id.dim]) + " " + std::to_string(id.tag) +
                      (group.name.empty() ? "" : " (\"" + group.name + "\")") + " names " +
                      input + ", which " + word +
                      (r.images.empty() ? " deleted" : " replaced by " + images));
    }
  }
}

void Interpreter::executeBoolean(const ast::CommandStmt& command, const SourceLocation& where) {
  const std::string& word = command.words[0];
  if (command.shape) {
    booleanShapes(word, command.shape->parts, -1, where);
    return;
  }
  const int tag = solidTag(command, where);
  if (command.value->kind != ast::ExprKind::Shape || !command.value->words.empty())
    fail(command.value->loc, word + "(" + std::to_string(tag) +
                                 ") takes two blocks of shapes after '='");
  booleanShapes(word, command.value->parts, tag, where);
}

// Fillet{volumes}{curves}{radii}; Chamfer{volumes}{curves}{surfaces}{distances}: the new
// volumes.
std::vector<EntityId> Interpreter::roundedShapes(const ast::Expr& shape) {
  const std::string& word = shape.words[0];
  const bool fillet = word == "Fillet";
  if (shape.parts.size() != (fillet ? 3u : 4u))
    fail(shape.loc, fillet ? "Fillet takes {volumes}{curves}{radii}"
                           : "Chamfer takes {volumes}{curves}{surfaces}{distances}");
  std::vector<int> lists[3];
  for (std::size_t i = 0; i + 1 < shape.parts.size(); ++i) {
    for (double x : evaluateNumbers(shape.parts[i].items))
      lists[i].push_back(clampedInteger<int>(x));
  }
  const std::vector<double> sizes = evaluateNumbers(shape.parts.back().items);
  SolidModeling* solids = solidModeling(word, shape.loc);
  if (!solids) return {};
  try {
    return fillet ? solids->fillet(lists[0], lists[1], sizes)
                  : solids->chamfer(lists[0], lists[1], lists[2], sizes);
  } catch (const GeometryError& error) {
    fail(shape.loc, error.what());
  }
}

// Geometry.Tolerance and the Geometry.OCCFix*, OCCSewFaces and OCCMakeSolids options.
SolidModeling::HealingOptions Interpreter::healingOptions() const {
  const OptionRegistry& options = session_.options();
  auto on = [&](const char* name) { return options.number(name) != 0; };
  return {options.number("Geometry.Tolerance"), on("Geometry.OCCFixDegenerated"),
          on("Geometry.OCCFixSmallEdges"),      on("Geometry.OCCFixSmallFaces"),
          on("Geometry.OCCSewFaces"),           on("Geometry.OCCMakeSolids")};
}

// What reading a CAD file takes from the options: scaling, target unit, healing.
void Interpreter::applyImportOptions(SolidModeling& solids) const {
  const OptionRegistry& options = session_.options();
  solids.setImportOptions({options.number("Geometry.OCCScaling"),
                           options.string("Geometry.OCCTargetUnit"), healingOptions()});
}

// HealShapes; heals every OpenCASCADE shape, HealShapes{ Volume{1}; Surface{2}; } those given
// (an extension: the reference reads only the first form), with the healing options.
void Interpreter::executeHealShapes(const ast::CommandStmt& command, const SourceLocation& where) {
  std::vector<EntityId> shapes;
  if (command.shape) {
    const ast::Expr& block = *command.shape;
    if (block.parts.size() != 1 || !block.parts[0].isBlock)
      fail(where, "HealShapes takes shapes in one block, as in HealShapes{ Volume{1}; }");
    shapes = shapesIn(block.parts[0]);
    if (shapes.empty()) return;
  } else if (command.argStyle != ast::CommandStmt::Args::None || command.value) {
    fail(where, "HealShapes takes no values: HealShapes; or HealShapes{ Volume{1}; }");
  }
  SolidModeling* solids = solidModeling("HealShapes", where);
  if (!solids) return;
  try {
    for (const EntityId& e : solids->healShapes(shapes, healingOptions()))
      session_.recordOrigin(e, where);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// ShapeFromFile("part.step"): the highest-dimensional entities the file holds.
std::vector<EntityId> Interpreter::shapesFromFile(const ast::Expr& shape) {
  if (shape.parts.size() != 1 || shape.parts[0].items.size() != 1)
    fail(shape.loc, "ShapeFromFile takes a file name, as in ShapeFromFile(\"part.step\")");
  std::string path = evaluateString(*shape.parts[0].items[0]);
  if (!std::filesystem::path(path).is_absolute())
    path = (std::filesystem::path(directoryOf(shape.loc.file)) / path).string();
  SolidModeling* solids = solidModeling("ShapeFromFile", shape.loc);
  if (!solids) return {};
  try {
    applyImportOptions(*solids);
    return solids->importShapes(path);
  } catch (const GeometryError& error) {
    fail(shape.loc, error.what());
  }
}

// Closest{x, y, z}{ Surface{..}; }: the shapes, nearest first.
std::vector<EntityId> Interpreter::closestShapes(const ast::Expr& shape) {
  const std::vector<double> p = shapeArguments(shape);
  if (shape.parts.size() != 2 || p.size() != 3 || !shape.parts[1].isBlock)
    fail(shape.loc, "Closest takes a point and shapes, as in Closest{x, y, z}{ Surface{1:4}; }");
  const std::vector<EntityId> shapes = shapesIn(shape.parts[1]);
  SolidModeling* solids = solidModeling("Closest", shape.loc);
  if (!solids) return {};
  try {
    return solids->closest({p[0], p[1], p[2]}, shapes);
  } catch (const GeometryError& error) {
    fail(shape.loc, error.what());
  }
}

// Extrude{ Surface{..}; } Using Wire{w}: a pipe, as a statement.
std::vector<EntityId> Interpreter::extrudeAlongWire(const ast::Expr& shape, const ast::Expr& wire) {
  if (shape.words != Words{"Extrude"} || shape.parts.size() != 1 || !shape.parts[0].isBlock ||
      wire.parts.size() != 1)
    fail(shape.loc, "Extrude Using Wire takes shapes, as in Extrude{ Surface{1}; } Using Wire{2}");
  return pipe(shape.parts[0], wire.parts[0], shape.loc, wire.loc);
}

// The shapes of `block` swept along the wire `wire` names.
std::vector<EntityId> Interpreter::pipe(const ast::ShapePart& block, const ast::ShapePart& wire,
                                        const SourceLocation& where,
                                        const SourceLocation& wireWhere) {
  const std::vector<EntityId> shapes = shapesIn(block);
  const std::vector<double> wires = evaluateNumbers(wire.items);
  if (wires.size() != 1) fail(wireWhere, "Using Wire takes one wire, as in Using Wire{2}");
  SolidModeling* solids = solidModeling("Extrude Using Wire", where);
  if (!solids) return {};
  try {
    return solids->extrudeAlongWire(shapes, clampedInteger<int>(wires[0]));
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// The OpenCASCADE operations that give shapes as values; nullopt for the others.
std::optional<std::vector<EntityId>> Interpreter::solidOperation(const ast::Expr& shape) {
  const std::string& word = shape.words[0];
  if (word == "Closest") return closestShapes(shape);
  if (shape.words == Words{"Extrude", "Using Wire"}) {  // out[] = Extrude{..} Using Wire{w};
    if (shape.parts.size() != 2 || !shape.parts[0].isBlock)
      fail(shape.loc,
           "Extrude Using Wire takes shapes, as in Extrude{ Surface{1}; } Using Wire{2}");
    return pipe(shape.parts[0], shape.parts[1], shape.loc, shape.loc);
  }
  if (word.rfind("Boolean", 0) == 0) return booleanShapes(word, shape.parts, -1, shape.loc);
  if (word == "Fillet" || word == "Chamfer") return roundedShapes(shape);
  if (word == "ShapeFromFile") return shapesFromFile(shape);
  return std::nullopt;
}

// Merge "part.step": the file's shapes (of every dimension) join the OpenCASCADE model,
// whichever factory is selected, and an XAO file's groups become physical groups, as in the
// reference.
void Interpreter::mergeCadFile(const std::string& file, const SourceLocation& where) {
  std::filesystem::path path = file;
  if (path.is_relative()) path = std::filesystem::path(directoryOf(where.file)) / path;
  SolidModeling& solids = session_.factories().solidModeler();
  try {
    applyImportOptions(solids);
    for (const EntityId& e : solids.importShapes(path.lexically_normal().string(), true))
      session_.recordOrigin(e, where);
    for (const PhysicalGroup& g : solids.importedGroups())  // an XAO file's groups
      session_.factory().addPhysicalGroup(g.dim, g.tag, g.name, g.entities);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// Save "part.brep" / "part.step" / "part.xao": the OpenCASCADE model's shapes.
void Interpreter::saveCadFile(const std::string& path, const SourceLocation& where) {
  try {
    session_.factories().solidModeler().exportShapes(path);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  session_.log().info("Wrote '" + path + "'");
}

void Interpreter::executeRounding(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!command.shape) return unsupportedStatement(command, where);
  roundedShapes(*command.shape);
}

}  // namespace geomesh
