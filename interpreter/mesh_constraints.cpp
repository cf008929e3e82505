// Mesh constraints in scripts: Transfinite Curve/Surface, Recombine Surface, MeshAlgorithm
// Surface, Field[n] = Type, Field[n].Option = value, Background Field = n. They are recorded
// in the model's MeshConstraints, which outlive synchronization, and read by the mesher.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "interpreter/script_interpreter.h"
#include "api/session.h"
#include "mesh/sizes/math_expression.h"

namespace geomesh {

namespace {

std::optional<TransfiniteCurve::Law> lawNamed(const std::string& word) {
  // Power: the older name of Progression.
  if (word == "Progression" || word == "Power") return TransfiniteCurve::Law::Progression;
  if (word == "Bump") return TransfiniteCurve::Law::Bump;
  if (word == "Beta") return TransfiniteCurve::Law::Beta;
  return std::nullopt;
}

std::optional<TransfiniteSurface::Arrangement> arrangementNamed(const std::string& word) {
  using A = TransfiniteSurface::Arrangement;
  if (word == "Left") return A::Left;
  if (word == "Right") return A::Right;
  if (word == "AlternateLeft") return A::AlternateLeft;
  if (word == "AlternateRight" || word == "Alternate" || word == "Alternated")
    return A::AlternateRight;
  return std::nullopt;
}

}  // namespace

// Recombine Surface{..} [= angle];
void Interpreter::recombineSurfaces(const ast::CommandStmt& command, const SourceLocation& where) {
  if (!command.shape) return unsupportedStatement(command, where);
  const double angle = command.value ? evaluateNumber(*command.value) : 45;
  for (int tag : shapeTags(*command.shape, 2))
    session_.model().meshConstraints().recombinedSurfaces[std::abs(tag)] = angle;
}

// MeshAlgorithm Surface{..} = algorithm;
void Interpreter::setSurfaceAlgorithm(const ast::CommandStmt& command,
                                      const SourceLocation& where) {
  if (!command.shape || !command.value) return unsupportedStatement(command, where);
  const int algorithm = static_cast<int>(std::lround(evaluateNumber(*command.value)));
  for (int tag : shapeTags(*command.shape, 2))
    session_.model().meshConstraints().surfaceAlgorithms[std::abs(tag)] = algorithm;
}

// Field[n] = Type;
void Interpreter::defineField(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle != ast::CommandStmt::Args::Bracket || command.args.size() != 1 ||
      !command.value)
    return unsupportedStatement(command, where);
  const int tag = static_cast<int>(std::lround(evaluateNumber(*command.args[0])));
  // The type is a bare word (Field[1] = Distance;), sometimes a string.
  const ast::Expr& rhs = *command.value;
  const std::string type = rhs.kind == ast::ExprKind::String     ? rhs.text
                           : rhs.kind == ast::ExprKind::Variable ? rhs.name.base
                                                                 : evaluateString(rhs);
  session_.model().meshConstraints().sizeFields[tag] = SizeFieldDefinition{type};
}

// Background Field = n;
void Interpreter::setBackgroundField(const ast::CommandStmt& command,
                                     const SourceLocation& where) {
  if (!command.value) return unsupportedStatement(command, where);
  session_.model().meshConstraints().backgroundField =
      static_cast<int>(std::lround(evaluateNumber(*command.value)));
}

// BoundaryLayer Field = n: field n (a BoundaryLayer field) builds a layer in the surfaces it
// touches; given several times, each field is kept once, in order.
void Interpreter::addBoundaryLayerField(const ast::CommandStmt& command,
                                        const SourceLocation& where) {
  if (!command.value) return unsupportedStatement(command, where);
  const int tag = static_cast<int>(std::lround(evaluateNumber(*command.value)));
  std::vector<int>& fields = session_.model().meshConstraints().boundaryLayerFields;
  if (std::find(fields.begin(), fields.end(), tag) == fields.end()) fields.push_back(tag);
}

void Interpreter::defineTransfiniteCurve(const ast::CommandStmt& command,
                                         const SourceLocation& where) {
  if (!command.shape) return unsupportedStatement(command, where);
  if (!command.value) fail(where, "Transfinite Curve needs a number of nodes: {..} = n");
  TransfiniteCurve law;
  const double nodes = evaluateNumber(*command.value);
  if (!(nodes >= 2)) fail(command.value->loc, "a transfinite curve needs at least 2 nodes");
  law.nodes = clampedInteger<int>(nodes);
  for (const ast::TailItem& item : command.tail) {
    if (item.word == "Using" && !item.value) continue;
    const auto kind = lawNamed(item.word);
    if (!kind || !item.value)
      fail(where, "expected 'Using Progression r', 'Using Bump r' or 'Using Beta r' after "
                  "Transfinite Curve");
    law.law = *kind;
    law.coefficient = evaluateNumber(*item.value);
  }
  if (law.law == TransfiniteCurve::Law::Beta && !(law.coefficient > 1))
    warn(where, "Using Beta needs a coefficient above 1; the nodes are evenly spaced");
  for (int tag : shapeTags(*command.shape, 1)) {
    TransfiniteCurve signedLaw = law;
    signedLaw.reversed = tag < 0;
    session_.model().meshConstraints().transfiniteCurves[std::abs(tag)] = signedLaw;
  }
}

void Interpreter::defineTransfiniteSurface(const ast::CommandStmt& command,
                                           const SourceLocation& where) {
  if (!command.shape) return unsupportedStatement(command, where);
  TransfiniteSurface surface;
  if (command.value) surface.corners = entityTags(*command.value);
  for (const ast::TailItem& item : command.tail) {
    const auto arrangement = arrangementNamed(item.word);
    if (!arrangement || item.value)
      fail(where, "expected Left, Right, AlternateLeft or AlternateRight after Transfinite "
                  "Surface, not '" + item.word + "'");
    surface.arrangement = *arrangement;
  }
  for (int& corner : surface.corners) corner = std::abs(corner);
  for (int tag : shapeTags(*command.shape, 2))
    session_.model().meshConstraints().transfiniteSurfaces[std::abs(tag)] = surface;
}

// Transfinite Volume{tags} <= {8 corners}>;
void Interpreter::defineTransfiniteVolume(const ast::CommandStmt& command,
                                          const SourceLocation& where) {
  if (!command.shape || !command.tail.empty()) return unsupportedStatement(command, where);
  std::vector<int> corners;
  if (command.value) corners = entityTags(*command.value);
  if (!corners.empty() && corners.size() != 8)
    fail(command.value->loc, "Transfinite Volume takes 8 corner points, not " +
                                 std::to_string(corners.size()));
  for (int& corner : corners) corner = std::abs(corner);
  for (int tag : shapeTags(*command.shape, 3))
    session_.model().meshConstraints().transfiniteVolumes[std::abs(tag)] = corners;
}

bool Interpreter::executeFieldOption(const ast::OptionAssignStmt& assign,
                                     const SourceLocation& where) {
  if (!assign.path.starts_with("Field.") || !assign.index) return false;
  const int tag = static_cast<int>(std::lround(evaluateNumber(*assign.index)));
  auto& fields = session_.model().meshConstraints().sizeFields;
  const auto it = fields.find(tag);
  if (it == fields.end()) {
    warn(where, "Field[" + std::to_string(tag) + "] is not defined; option ignored");
    return true;
  }
  const std::string option = assign.path.substr(6);
  const Value value = evaluate(*assign.value);
  if (value.isText()) {
    if (value.kind() != Value::Kind::String || assign.op != "=")
      fail(assign.value->loc, "Field option '" + option + "' takes one string");
    if (option == "F" && it->second.type == "MathEval") {
      try {
        MathExpression check(value.strings()[0]);  // report a bad formula here, not when meshing
      } catch (const ExpressionError& e) {
        fail(assign.value->loc, std::string("bad MathEval formula: ") + e.what());
      }
    }
    it->second.strings[option] = value.strings()[0];
    return true;
  }
  checkFieldView(it->second.type, option, value, *assign.value);
  std::vector<double>& numbers = it->second.numbers[option];
  if (assign.op == "=") {
    numbers = value.numbers();
  } else if (assign.op == "+=") {
    numbers.insert(numbers.end(), value.numbers().begin(), value.numbers().end());
  } else {
    fail(where, "Field options take '=' or '+='");
  }
  return true;
}

// Geometry.CopyMeshingMethod: a Duplicata's copies take the transfinite and recombination
// constraints of what they copy, down to their curves (matched through the boundaries, which
// list a copy's curves in its source's order) and, for transfinite corners, their points.
void Interpreter::copyMeshingMethod(const std::vector<EntityId>& sources,
                                    const std::vector<EntityId>& copies) {
  MeshConstraints& mc = session_.model().meshConstraints();
  GeometryFactory& factory = session_.factory();
  std::map<int, int> pointCopies;
  std::function<void(EntityId, EntityId)> copy = [&](EntityId from, EntityId to) {
    const int f = std::abs(from.tag), t = std::abs(to.tag);
    if (from.dim == 0) {
      pointCopies[f] = t;
      return;
    }
    const std::vector<EntityId> a = factory.boundary({{from.dim, f}}, false);
    const std::vector<EntityId> b = factory.boundary({{to.dim, t}}, false);
    if (a.size() == b.size())
      for (std::size_t k = 0; k < a.size(); ++k) copy(a[k], b[k]);
    if (from.dim == 1)
      if (const auto it = mc.transfiniteCurves.find(f); it != mc.transfiniteCurves.end())
        mc.transfiniteCurves[t] = it->second;
    if (from.dim == 2) {
      if (const auto it = mc.recombinedSurfaces.find(f); it != mc.recombinedSurfaces.end())
        mc.recombinedSurfaces[t] = it->second;
      if (const auto it = mc.transfiniteSurfaces.find(f); it != mc.transfiniteSurfaces.end()) {
        TransfiniteSurface law = it->second;
        for (int& corner : law.corners)
          if (const auto p = pointCopies.find(corner); p != pointCopies.end()) corner = p->second;
        mc.transfiniteSurfaces[t] = law;
      }
    }
  };
  for (std::size_t k = 0; k < sources.size() && k < copies.size(); ++k) copy(sources[k], copies[k]);
}

}  // namespace geomesh
