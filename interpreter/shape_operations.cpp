// Operations on shapes of the built-in kernel: transformations, Duplicata, Extrude, Boundary,
// Delete, Coherence, Compound, In (embedding), Periodic; and shapes used as values.
#include <cmath>

#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "kernel/geometry_error.h"

namespace geomesh {

namespace {

using Words = std::vector<std::string>;

bool isTransform(const std::string& word) {
  return word == "Translate" || word == "Rotate" || word == "Symmetry" || word == "Dilate" ||
         word == "Affine";
}

std::vector<int> tagsOf(const std::vector<EntityId>& shapes) {
  std::vector<int> tags;
  for (const auto& shape : shapes) tags.push_back(shape.tag);
  return tags;
}

std::vector<double> asDoubles(const std::vector<int>& tags) {
  return std::vector<double>(tags.begin(), tags.end());
}

}  // namespace

int Interpreter::entityDimension(const std::vector<std::string>& words) {
  if (words.size() != 1) return -1;
  if (words[0] == "Point") return 0;
  if (words[0] == "Line" || words[0] == "Curve") return 1;
  if (words[0] == "Surface") return 2;
  if (words[0] == "Volume") return 3;
  return -1;
}

std::vector<int> Interpreter::allTags(int dim) const { return session_.factories().tags(dim); }

// The tags of Point{..}, Curve{..}, ... with ':' standing for every entity of the kind.
std::vector<int> Interpreter::shapeTags(const ast::Expr& shape, int dim) {
  std::vector<int> tags;
  for (const auto& part : shape.parts) {
    for (const auto& item : part.items) {
      std::vector<int> more = item->kind == ast::ExprKind::All ? allTags(dim) : entityTags(*item);
      tags.insert(tags.end(), more.begin(), more.end());
    }
  }
  return tags;
}

// { Point{1}; Curve{2, 3}; Duplicata{..}; Translate{..}{..}; ... }
std::vector<EntityId> Interpreter::shapesIn(const ast::ShapePart& block) {
  std::vector<EntityId> shapes;
  for (const auto& item : block.items) {
    if (item->kind != ast::ExprKind::Shape) fail(item->loc, "expected shapes such as Point{1};");
    const int dim = entityDimension(item->words);
    if (dim >= 0 && !item->parts.empty() && !item->parts[0].isBlock) {
      for (int tag : shapeTags(*item, dim)) shapes.push_back(EntityId{dim, tag});
    } else if (auto produced = shapeOperation(*item)) {
      shapes.insert(shapes.end(), produced->begin(), produced->end());
    } else if (item->words != Words{"Layers"} && item->words != Words{"Recombine"} &&
               (item->words.empty() || item->words[0] != "Using")) {
      warn(item->loc, "'" + (item->words.empty() ? std::string("?") : item->words[0]) +
                          "' is not supported here; ignored");
    }
  }
  return shapes;
}

// The numbers inside the first braces of Translate{..}, Rotate{..}, Extrude{..}, ...
std::vector<double> Interpreter::shapeArguments(const ast::Expr& shape) {
  if (shape.parts.empty() || shape.parts[0].isBlock) return {};
  return evaluateNumbers(shape.parts[0].items);
}

AffineMap Interpreter::transformMap(const ast::Expr& shape) {
  const std::string& kind = shape.words[0];
  const std::vector<double> v = shapeArguments(shape);
  auto require = [&](std::size_t count, const char* form) {
    if (v.size() != count)
      fail(shape.loc, kind + " takes " + form + ", not " + std::to_string(v.size()) + " values");
  };
  if (kind == "Translate") {
    require(3, "{dx, dy, dz}");
    return AffineMap::translation({v[0], v[1], v[2]});
  }
  if (kind == "Rotate") {
    require(7, "{{axis}, {point}, angle}");
    return AffineMap::rotation({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]);
  }
  if (kind == "Symmetry") {
    require(4, "{a, b, c, d}");
    return AffineMap::symmetry(v[0], v[1], v[2], v[3]);
  }
  if (kind == "Dilate") {
    if (v.size() == 4) return AffineMap::dilation({v[0], v[1], v[2]}, {v[3], v[3], v[3]});
    require(6, "{{center}, factor} or {{center}, {factors}}");
    return AffineMap::dilation({v[0], v[1], v[2]}, {v[3], v[4], v[5]});
  }
  if (v.size() != 12 && v.size() != 16) require(12, "12 numbers (a 3 x 4 matrix)");
  AffineMap map;
  for (std::size_t i = 0; i < 12; ++i) map.m[i] = v[i];
  return map;
}

// Using Index[i] and Using View[v] in an extrusion along normals: layers of one index share
// their normals; a view sets the layer's thickness (scalar) or direction (vector) per node.
ExtrusionMotion Interpreter::normalsMotion(const ast::ShapePart& block) {
  ExtrusionMotion motion = ExtrusionMotion::normals(0);
  for (const auto& item : block.items) {
    if (item->words.size() != 2 || item->words[0] != "Using" || item->args.empty()) continue;
    const int value = clampedInteger<int>(evaluateNumber(*item->args[0]));
    if (value < 0) fail(item->loc, "Using " + item->words[1] + " takes a number from 0");
    if (item->words[1] == "Index")
      motion.layerIndex = value;
    else if (item->words[1] == "View")
      motion.layerView = value;
    else
      warn(item->loc, "'Using " + item->words[1] +
                          "' is not supported in an extrusion along normals; ignored");
  }
  return motion;
}

ExtrusionLayers Interpreter::extrusionLayers(const ast::ShapePart& block) {
  ExtrusionLayers layers;
  for (const auto& item : block.items) {
    if (item->words == Words{"Recombine"})  // Recombine; or Recombine expr;
      layers.recombine = item->args.empty() || evaluateNumber(*item->args[0]) != 0;
    if (item->words != Words{"Layers"} || item->parts.empty()) continue;
    const auto& values = item->parts[0].items;
    if (values.size() == 1) {
      layers.elements.push_back(clampedInteger<int>(evaluateNumber(*values[0])));
      layers.heights.push_back(1);
    } else if (values.size() == 2) {
      for (double n : evaluateNumbers(*values[0]))
        layers.elements.push_back(clampedInteger<int>(n));
      layers.heights = evaluateNumbers(*values[1]);
    } else {
      fail(item->loc, "Layers takes {n} or {{n1, n2, ...}, {h1, h2, ...}}");
    }
  }
  return layers;
}

std::vector<EntityId> Interpreter::extrude(const ast::Expr& shape) {
  const std::vector<double> v = shapeArguments(shape);
  ExtrusionMotion motion;
  if (shape.parts.size() == 1)  // Extrude{ shapes; Layers{..}; }: a boundary layer
    motion = normalsMotion(shape.parts[0]);
  else if (v.size() == 3)
    motion = ExtrusionMotion::translate({v[0], v[1], v[2]});
  else if (v.size() == 7)
    motion = ExtrusionMotion::rotate({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]);
  else if (v.size() == 10)
    motion = ExtrusionMotion::twist({v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]},
                                    v[9]);
  else
    fail(shape.loc, "Extrude takes {dx, dy, dz}, {{axis}, {point}, angle} or "
                    "{{dx, dy, dz}, {axis}, {point}, angle}");
  const ast::ShapePart& block = shape.parts.back();
  std::vector<EntityId> made =
      session_.factory().extrude(shapesIn(block), motion, extrusionLayers(block));
  // What the sweep made points at it when it cannot be meshed; its inputs keep their own.
  for (const EntityId& e : made)
    if (!session_.origin(e)) session_.recordOrigin(e, shape.loc);
  return made;
}

// Operations that produce shapes; nullopt when `shape` is none of them.
std::optional<std::vector<EntityId>> Interpreter::shapeOperation(const ast::Expr& shape) {
  if (shape.words == std::vector<std::string>{"Extrude", "Using Wire"}) return solidOperation(shape);
  if (shape.words.size() != 1 || shape.parts.empty()) return std::nullopt;
  const std::string& kind = shape.words[0];
  // The shapes come last, in braces: { Point{1}; } or, without semicolons, { Duplicata{..} }.
  try {
    if (kind == "Duplicata" && shape.parts.size() == 1) {
      const std::vector<EntityId> sources = shapesIn(shape.parts[0]);
      std::vector<EntityId> copies = session_.factory().duplicate(sources);
      if (session_.options().number("Geometry.CopyMeshingMethod") != 0)
        copyMeshingMethod(sources, copies);
      return copies;
    }
    if ((kind == "Boundary" || kind == "CombinedBoundary") && shape.parts.size() == 1)
      return session_.factory().boundary(shapesIn(shape.parts[0]), kind == "CombinedBoundary");
    if (isTransform(kind) && shape.parts.size() == 2) {
      const AffineMap map = transformMap(shape);
      std::vector<EntityId> shapes = shapesIn(shape.parts[1]);
      session_.factory().transform(shapes, map);
      return shapes;
    }
    if (kind == "Extrude" && shape.parts.size() == 2) return extrude(shape);
    if (kind == "Extrude" && shape.parts.size() == 1 && shape.parts[0].isBlock)
      return extrude(shape);
    if (auto made = solidOperation(shape)) return made;
  } catch (const GeometryError& error) {
    fail(shape.loc, error.what());
  }
  return std::nullopt;
}

// Translate{..}{ shapes }; Extrude{..}{ shapes }; Duplicata{ shapes }; ... as statements.
void Interpreter::executeShapeOperation(const ast::CommandStmt& command,
                                        const SourceLocation& where) {
  if (command.shape && command.op.empty() && command.tail.empty() &&
      shapeOperation(*command.shape))
    return;
  if (command.shape && command.op.empty() && command.tail.size() == 1 &&
      command.tail[0].word == "Using" && command.tail[0].value &&
      command.tail[0].value->words == Words{"Wire"}) {
    extrudeAlongWire(*command.shape, *command.tail[0].value);
    return;
  }
  unsupportedStatement(command, where);
}

void Interpreter::executeCoherence(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.shape || !command.args.empty()) return unsupportedStatement(command, where);
  try {
    session_.factory().coherence();
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// Periodic Surface{s} = {m} Translate{..}; or the older form Periodic Surface s {curves} = m
// {curves};
void Interpreter::executePeriodicSurface(const ast::CommandStmt& command,
                                         const SourceLocation& where) {
  if (command.shape || command.args.size() != 4) return executePeriodic(command, where);
  try {
    session_.factory().setPeriodicByCurves(
        clampedInteger<int>(evaluateNumber(*command.args[0])), entityTags(*command.args[1]),
        clampedInteger<int>(evaluateNumber(*command.args[2])), entityTags(*command.args[3]));
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// Periodic Curve{slaves} = {masters} Translate{..}; (Rotate, ... any transformation)
void Interpreter::executePeriodic(const ast::CommandStmt& command, const SourceLocation& where) {
  const bool transformed = command.shape && command.value && command.tail.size() == 1 &&
                           command.tail[0].word.empty() && command.tail[0].value &&
                           isTransform(command.tail[0].value->words.at(0));
  const int dim = entityDimension({command.words[1]});
  const bool bare = command.shape && command.value && command.tail.empty() && dim == 1;
  if (bare) return executePeriodicByTranslation(command, where);
  if (!transformed) return unsupportedStatement(command, where);
  try {
    session_.factory().setPeriodic(dim, shapeTags(*command.shape, dim),
                                   entityTags(*command.value),
                                   transformMap(*command.tail[0].value));
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// Periodic Curve{slaves} = {masters}; (the older form, without a transform): the slaves must be
// the masters moved by one translation, which the curves' ends give.
void Interpreter::executePeriodicByTranslation(const ast::CommandStmt& command,
                                               const SourceLocation& where) {
  GeometryFactory& geo = session_.factory();
  const std::vector<int> slaves = shapeTags(*command.shape, 1);
  const std::vector<int> masters = entityTags(*command.value);
  try {
    if (slaves.size() != masters.size() || slaves.empty())
      throw GeometryError("Periodic: " + std::to_string(slaves.size()) +
                          " curves cannot match " + std::to_string(masters.size()));
    std::optional<Vec3> shift;
    for (std::size_t i = 0; i < slaves.size(); ++i) {
      const auto s = geo.boundary({{1, slaves[i]}}, false);
      const auto m = geo.boundary({{1, masters[i]}}, false);
      for (std::size_t end = 0; end < 2 && end < s.size() && end < m.size(); ++end) {
        const Vec3 d = geo.pointCoordinates(s[end].tag) - geo.pointCoordinates(m[end].tag);
        if (!shift) shift = d;
        if (distance(*shift, d) > 1e-6 * (1 + norm(d)))
          fail(where, "Periodic Curve: curve " + std::to_string(slaves[i]) +
                          " is not a translate of curve " + std::to_string(masters[i]) +
                          "; give the transform: Periodic Curve{..} = {..} Rotate{..} or "
                          "Translate{..}");
      }
    }
    geo.setPeriodic(1, slaves, masters, AffineMap::translation(shift.value_or(Vec3{})));
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// Coherence Point{a, b, ..}; merges the points into the first, wherever they are.
void Interpreter::executeCoherencePoints(const ast::CommandStmt& command,
                                         const SourceLocation& where) {
  if (!command.shape || command.value) return unsupportedStatement(command, where);
  try {
    session_.factory().coherePoints(shapeTags(*command.shape, 0));
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

void Interpreter::executeDeletePhysicals(const ast::CommandStmt& command,
                                         const SourceLocation& where) {
  if (command.shape) return unsupportedStatement(command, where);
  GeometryFactory& geo = session_.factory();
  // newreg keeps counting past the deleted groups, as in Gmsh.
  for (const auto& [id, group] : geo.physicalGroups())
    deletedPhysicalTag_ = std::max(deletedPhysicalTag_, id.tag);
  geo.clearPhysicalGroups();
}

// Delete{ shapes }; Recursive Delete{ shapes }; (the latter also removes their boundaries)
void Interpreter::deleteShapes(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!command.shape || command.shape->parts.size() != 1 || !command.shape->parts[0].isBlock)
    return unsupportedStatement(command, where);
  try {
    session_.factory().remove(shapesIn(command.shape->parts[0]), command.words.size() == 2);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// Compound Curve{..}; Compound Surface{..}: recorded on the entities (and written back by -0);
// the mesher meshes each compound as one (mesh/pipeline/compound). Compound Volume is not.
void Interpreter::executeCompound(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!command.shape) return unsupportedStatement(command, where);
  const int dim = entityDimension({command.words[1]});
  try {
    session_.factory().addCompound(dim, shapeTags(*command.shape, dim));
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
  if (dim == 3) warn(where, "'Compound Volume' is not supported: its volumes are meshed one by one");
}

// Point{..} In Surface{..}; Curve{..} In Volume{..}; ...: entities embedded in a host.
void Interpreter::embedEntities(const ast::CommandStmt& command, const SourceLocation& where) {
  const bool embedding = command.shape && command.tail.size() == 1 &&
                         command.tail[0].word == "In" && command.tail[0].value;
  const int dim = entityDimension(command.words);
  const int hostDim = embedding ? entityDimension(command.tail[0].value->words) : -1;
  if (dim >= 0 && command.shape && command.value && command.words.size() == 1)
    fail(where, "'" + command.words[0] + "{..} = {..};' defines nothing: write " +
                    command.words[0] + "(tag) = {..};");  // the reference: a syntax error
  if (dim < 0 || hostDim < 0) return unsupportedStatement(command, where);
  const ast::Expr& host = *command.tail[0].value;
  GeometryFactory& geo = session_.factory();
  try {
    const std::vector<int> tags = shapeTags(*command.shape, dim);
    for (int hostTag : shapeTags(host, hostDim)) geo.embed(dim, tags, hostDim, hostTag);
  } catch (const GeometryError& error) {
    fail(where, error.what());
  }
}

// Point{t}: its coordinates. Curve{..}, Surface{:}: tags. Operations: the tags they give.
// Volume In BoundingBox{..}: the tags of the entities inside. BoundingBox Surface{..}: the
// box {xmin, ymin, zmin, xmax, ymax, zmax} around them.
// Physical Curve{:} lists the tags of the physical curves; Physical Curve{t, ...} the
// curves of those groups (none for an unknown tag, as in Gmsh).
Value Interpreter::physicalQuery(const ast::Expr& expr, int dim) {
  const auto& groups = session_.factory().physicalGroups();
  const auto& items = expr.parts[0].items;
  std::vector<double> result;
  if (items.size() == 1 && items[0]->kind == ast::ExprKind::All) {
    for (const auto& [id, group] : groups)
      if (id.dim == dim) result.push_back(id.tag);
    return Value::list(std::move(result));
  }
  for (double tag : evaluateNumbers(items)) {
    auto it = groups.find(EntityId{dim, clampedInteger<int>(tag)});
    if (it != groups.end())
      result.insert(result.end(), it->second.entities.begin(), it->second.entities.end());
  }
  return Value::list(std::move(result));
}

// Intersect Curve{curves} Surface{surface}: the tags of new points where the curves cross it.
Value Interpreter::intersectCurvesWithSurface(const ast::Expr& expr) {
  if (expr.parts.size() != 2) fail(expr.loc, "expected Intersect Curve{..} Surface{tag}");
  std::vector<int> curves;
  for (double t : evaluateNumbers(expr.parts[0].items)) curves.push_back(clampedInteger<int>(t));
  const std::vector<double> surfaces = evaluateNumbers(expr.parts[1].items);
  if (surfaces.size() != 1) fail(expr.loc, "Intersect takes one surface, not " +
                                               std::to_string(surfaces.size()));
  try {
    return Value::list(asDoubles(
        session_.factory().intersectCurvesWithSurface(curves, clampedInteger<int>(surfaces[0]))));
  } catch (const GeometryError& error) {
    fail(expr.loc, error.what());
  }
}

Value Interpreter::shapeValue(const ast::Expr& expr) {
  const Words& w = expr.words;
  // Surface "*" is Surface{:}; a physical group takes no other string (a group of that name is
  // selected by Physical Surface{tag} only).
  if (!expr.text.empty() && !w.empty() && w[0] == "Physical" && expr.text != "*")
    fail(expr.loc, "'" + w[0] + " " + w.back() + " \"" + expr.text +
                       "\"': only \"*\" (every group) may follow; use {tags} to select groups");
  rejectOlderForms(w, false, expr.loc);
  if (w == Words{"Intersect", "Curve", "Surface"} || w == Words{"Intersect", "Line", "Surface"})
    return intersectCurvesWithSurface(expr);
  // Point{n} is the point's coordinates, but Point{:} the tags of all points, as in Gmsh.
  const bool allPoints = expr.parts.size() == 1 && expr.parts[0].items.size() == 1 &&
                         expr.parts[0].items[0]->kind == ast::ExprKind::All;
  if (w == Words{"Point"} && expr.parts.size() == 1 && !expr.parts[0].isBlock && !allPoints) {
    std::vector<double> coordinates;
    for (int tag : shapeTags(expr, 0)) {
      try {
        Vec3 p = session_.factory().pointCoordinates(tag);
        coordinates.insert(coordinates.end(), {p.x, p.y, p.z});
      } catch (const GeometryError& error) {
        fail(expr.parts[0].items.front()->loc, error.what());
      }
    }
    return Value::list(std::move(coordinates));
  }
  const int dim = entityDimension(w);
  if (dim >= 0 && expr.parts.size() == 1 && !expr.parts[0].isBlock)
    return Value::list(asDoubles(shapeTags(expr, dim)));
  if (w.size() == 3 && w[1] == "In" && w[2] == "BoundingBox" && entityDimension({w[0]}) >= 0) {
    const std::vector<double> v = shapeArguments(expr);
    if (v.size() != 6) fail(expr.loc, "BoundingBox takes {xmin, ymin, zmin, xmax, ymax, zmax}");
    BoundingBox box;
    box.include(Vec3{v[0], v[1], v[2]});
    box.include(Vec3{v[3], v[4], v[5]});
    return Value::list(asDoubles(session_.factory().entitiesInBox(entityDimension({w[0]}), box)));
  }
  if (w.size() == 2 && w[0] == "BoundingBox" && entityDimension({w[1]}) >= 0 &&
      expr.parts.size() == 1) {
    const int boxDim = entityDimension({w[1]});
    BoundingBox box;
    try {
      for (int tag : shapeTags(expr, boxDim))
        box.include(session_.factory().boundingBox(EntityId{boxDim, std::abs(tag)}));
    } catch (const GeometryError& error) {
      fail(expr.loc, error.what());
    }
    if (box.empty()) fail(expr.loc, "bounding box of no entity");
    return Value::list({box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z});
  }
  if (w == Words{"PointsOf"} && expr.parts.size() == 1 && expr.parts[0].isBlock) {
    try {
      return Value::list(asDoubles(session_.factory().pointsOf(shapesIn(expr.parts[0]))));
    } catch (const GeometryError& error) {
      fail(expr.loc, error.what());
    }
  }
  if (w.size() == 2 && w[0] == "Physical" && entityDimension({w[1]}) >= 0 &&
      expr.parts.size() == 1 && !expr.parts[0].isBlock)
    return physicalQuery(expr, entityDimension({w[1]}));
  if (auto shapes = shapeOperation(expr)) return Value::list(asDoubles(tagsOf(*shapes)));
  session_.noteIgnoredStatement(expr.loc);
  warn(expr.loc, "'" + (w.empty() ? std::string("{..}") : w[0]) +
                     "' is not supported yet; gives an empty list");
  return Value::list({});
}

}  // namespace geomesh
