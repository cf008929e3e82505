// The statement table: the words that start a command, mapped to the member function that
// carries it out, as a parser's statement() switches once on its first token. A row's words are
// the command's words exactly ("Physical Surface"), or a head followed by " ..." for any words
// after it. A handler checks the form of its statement (parentheses, braces, '=') and reports
// the forms it does not carry out through unsupportedStatement or skipInBatch.
#include <algorithm>

#include "interpreter/diagnostics.h"
#include "interpreter/script_interpreter.h"
#include "api/session.h"

namespace geomesh {

namespace {

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const auto& word : words) text += (text.empty() ? "" : " ") + word;
  return text;
}

// How a warning names a command: "Transfinite Curve", "Point In Surface".
std::string commandName(const ast::CommandStmt& command) {
  std::string name = joined(command.words);
  if (!command.tail.empty() && command.tail[0].word == "In" && command.tail[0].value)
    name += " In " + joined(command.tail[0].value->words);
  return name;
}

// Command keywords that start no statement of their own.
constexpr std::string_view kNoStatement[] = {
    // words that continue a statement: Characteristic Length, Curve Loop, Delete Physicals, ...
    "Closest", "Filling", "Length", "Loop", "Physicals", "QuadTriAddVerts", "QuadTriNoNewVerts",
    // inside expressions and blocks: Extrude{..}{ Layers{..}; }, PointsOf{..}, ShapeFromFile(..)
    "Layers", "PointsOf", "ShapeFromFile",
    // option categories: General.Verbosity = 3;
    "General", "Geometry",
};

}  // namespace

// Sorted by words, for a binary search. Rows ending in " ..." take the head followed by any
// words: the interface-only statements, which a batch run skips (Draw, Sleep, View, ...), and
// the statements recognised but not supported yet, which warn.
std::span<const Interpreter::StatementRow> Interpreter::statementTable() {
  static constexpr StatementRow kRows[] = {
      {"Abort ...", &Interpreter::abortScript},
      {"AdaptMesh ...", &Interpreter::unsupportedStatement},
      {"Affine", &Interpreter::executeShapeOperation},
      {"BSpline", &Interpreter::defineEntity},
      {"BSpline Surface", &Interpreter::defineEntity},
      {"Background ...", &Interpreter::unsupportedStatement},
      {"Background Field", &Interpreter::setBackgroundField},
      {"Background Mesh View", &Interpreter::setBackgroundView},
      {"Bezier", &Interpreter::defineEntity},
      {"Bezier Surface", &Interpreter::defineEntity},
      {"Block ...", &Interpreter::unsupportedStatement},
      {"BooleanDifference ...", &Interpreter::executeBoolean},
      {"BooleanFragments ...", &Interpreter::executeBoolean},
      {"BooleanIntersection ...", &Interpreter::executeBoolean},
      {"BooleanUnion ...", &Interpreter::executeBoolean},
      {"Boundary", &Interpreter::executeShapeOperation},
      {"BoundaryLayer Field", &Interpreter::addBoundaryLayerField},
      {"BoundingBox ...", &Interpreter::skipInBatch},
      {"Box", &Interpreter::defineBox},
      {"CatmullRom", &Interpreter::defineEntity},
      {"Chamfer", &Interpreter::executeRounding},
      {"Characteristic Length", &Interpreter::executeMeshSize},
      {"Circle", &Interpreter::defineCircleArc},
      {"ClassifySurfaces ...", &Interpreter::classifySurfaces},
      {"Coherence", &Interpreter::executeCoherence},
      {"Coherence Mesh", &Interpreter::executeCoherenceMesh},
      {"Coherence Point", &Interpreter::executeCoherencePoints},
      {"Cohomology ...", &Interpreter::requestHomology},
      {"Color ...", &Interpreter::skipInBatch},
      {"Combine ...", &Interpreter::combineViews},
      {"CombinedBoundary", &Interpreter::executeShapeOperation},
      {"Compound Curve", &Interpreter::executeCompound},
      {"Compound Line", &Interpreter::executeCompound},
      {"Compound Surface", &Interpreter::executeCompound},
      {"Compound Volume", &Interpreter::executeCompound},
      {"Cone", &Interpreter::definePrimitive},
      {"CreateGeometry ...", &Interpreter::createGeometry},
      {"CreateTopology ...", &Interpreter::createTopology},
      {"Curve", &Interpreter::embedEntities},
      {"Curve Loop", &Interpreter::defineEntity},
      {"Cylinder", &Interpreter::definePrimitive},
      {"Delete", &Interpreter::executeDelete},
      {"Delete Physicals", &Interpreter::executeDeletePhysicals},
      {"Delete View", &Interpreter::deleteView},
      {"Dilate", &Interpreter::executeShapeOperation},
      {"Disk", &Interpreter::definePrimitive},
      {"Draw ...", &Interpreter::skipInBatch},
      {"Duplicata", &Interpreter::executeShapeOperation},
      {"Ellipse", &Interpreter::defineEllipse},
      {"Ellipsis", &Interpreter::defineEntity},
      {"Error ...", &Interpreter::executeMessage},
      {"Exit ...", &Interpreter::exitScript},
      {"Extrude", &Interpreter::executeShapeOperation},
      {"Field", &Interpreter::defineField},
      {"Fillet", &Interpreter::executeRounding},
      {"HealShapes", &Interpreter::executeHealShapes},
      {"Hide ...", &Interpreter::skipInBatch},
      {"Hole ...", &Interpreter::rejectReservedWord},
      {"Homology ...", &Interpreter::requestHomology},
      {"Include", &Interpreter::executeInclude},
      {"Line", &Interpreter::defineEntity},
      {"Line Loop", &Interpreter::defineEntity},
      {"Merge", &Interpreter::executeMerge},
      {"Mesh", &Interpreter::executeMesh},
      {"MeshAlgorithm Surface", &Interpreter::setSurfaceAlgorithm},
      {"MeshSize", &Interpreter::executeMeshSize},
      {"NewModel", &Interpreter::executeNewModel},
      {"NonBlockingSystem ...", &Interpreter::executeSystemCall},
      {"NonBlockingSystemCall ...", &Interpreter::executeSystemCall},
      {"Nurbs", &Interpreter::defineEntity},
      {"OptimizeMesh ...", &Interpreter::unsupportedStatement},
      {"PartitionMesh", &Interpreter::executePartitionMesh},
      {"Periodic Curve", &Interpreter::executePeriodic},
      {"Periodic Line", &Interpreter::executePeriodic},
      {"Periodic Surface", &Interpreter::executePeriodicSurface},
      {"Periodic Volume", &Interpreter::executePeriodic},
      {"Physical Curve", &Interpreter::executePhysical},
      {"Physical Line", &Interpreter::executePhysical},
      {"Physical Point", &Interpreter::executePhysical},
      {"Physical Surface", &Interpreter::executePhysical},
      {"Physical Volume", &Interpreter::executePhysical},
      {"Plane Surface", &Interpreter::defineEntity},
      {"Point", &Interpreter::definePoint},
      {"PolarSphere", &Interpreter::definePolarSphere},
      {"PostProcessing ...", &Interpreter::skipInBatch},
      {"Print", &Interpreter::executePrint},
      {"Print ...", &Interpreter::skipInBatch},
      {"Printf", &Interpreter::executePrintf},
      {"Recombine Surface", &Interpreter::recombineSurfaces},
      {"Rectangle", &Interpreter::definePrimitive},
      {"Recursive Delete", &Interpreter::deleteShapes},
      {"RefineMesh ...", &Interpreter::unsupportedStatement},
      {"RelocateMesh ...", &Interpreter::unsupportedStatement},
      {"RenumberMeshElements", &Interpreter::executeAlreadyDone},
      {"RenumberMeshNodes", &Interpreter::executeAlreadyDone},
      {"ReorientMesh ...", &Interpreter::unsupportedStatement},
      {"Reverse ...", &Interpreter::unsupportedStatement},
      {"Rotate", &Interpreter::executeShapeOperation},
      {"Ruled Surface", &Interpreter::defineEntity},
      {"Ruled ThruSections", &Interpreter::defineThruSections},
      {"Save", &Interpreter::executeSave},
      {"Save View", &Interpreter::saveView},
      {"SetChanged ...", &Interpreter::skipInBatch},
      {"SetFactory ...", &Interpreter::executeSetFactory},
      {"SetNumber ...", &Interpreter::executeSetter},
      {"SetOrder", &Interpreter::executeSetOrder},
      {"SetString ...", &Interpreter::executeSetter},
      {"Show ...", &Interpreter::skipInBatch},
      {"Sleep ...", &Interpreter::skipInBatch},
      {"Smoother ...", &Interpreter::unsupportedStatement},
      {"Solver ...", &Interpreter::skipInBatch},
      {"Sphere", &Interpreter::definePrimitive},
      {"Spline", &Interpreter::defineEntity},
      {"Split Curve", &Interpreter::executeSplitCurve},
      {"Split Line", &Interpreter::executeSplitCurve},
      {"Struct", &Interpreter::executeStructStatement},
      {"Surface", &Interpreter::defineEntity},

      {"Surface Loop", &Interpreter::defineEntity},
      {"Symmetry", &Interpreter::executeShapeOperation},
      {"SyncModel", &Interpreter::executeAlreadyDone},
      {"System ...", &Interpreter::executeSystemCall},
      {"SystemCall ...", &Interpreter::executeSystemCall},
      {"ThruSections", &Interpreter::defineThruSections},
      {"Torus", &Interpreter::definePrimitive},
      {"Transfinite Curve", &Interpreter::defineTransfiniteCurve},
      {"Transfinite Line", &Interpreter::defineTransfiniteCurve},
      {"Transfinite Surface", &Interpreter::defineTransfiniteSurface},
      {"Transfinite Volume", &Interpreter::defineTransfiniteVolume},
      {"Translate", &Interpreter::executeShapeOperation},
      {"View", &Interpreter::defineView},
      {"View ...", &Interpreter::skipInBatch},
      {"Volume", &Interpreter::defineEntity},
      {"Warning ...", &Interpreter::executeMessage},
      {"Wedge", &Interpreter::definePrimitive},
      {"Wire", &Interpreter::defineWire},
  };
  static_assert(std::ranges::is_sorted(kRows, {}, &StatementRow::words));
  return kRows;
}

const Interpreter::StatementRow* Interpreter::findStatement(const std::vector<std::string>& words) {
  const auto rows = statementTable();
  auto find = [&](std::string_view key) -> const StatementRow* {
    auto it = std::ranges::lower_bound(rows, key, {}, &StatementRow::words);
    return it != rows.end() && it->words == key ? &*it : nullptr;
  };
  if (const StatementRow* row = find(joined(words))) return row;
  return find(words.front() + " ...");
}

void Interpreter::executeCommand(const ast::CommandStmt& command, const SourceLocation& where) {
  rejectOlderForms(command.words, command.shape != nullptr, where);
  if (const StatementRow* row = findStatement(command.words))
    return (this->*row->handler)(command, where);
  unsupportedStatement(command, where);
}

std::vector<std::string_view> Interpreter::statementPatterns() {
  std::vector<std::string_view> patterns;
  for (const StatementRow& row : statementTable()) patterns.push_back(row.words);
  return patterns;
}

std::span<const std::string_view> Interpreter::keywordsStartingNoStatement() {
  return kNoStatement;
}

// Forms of Gmsh 1 and 2 that Gmsh 4 rejects: each is an error naming the form to write.
void Interpreter::rejectOlderForms(const std::vector<std::string>& words, bool braces,
                                   const SourceLocation& where) {
  if (words.size() == 3 && words[0] == "Delete" && words[1] == "Physical")
    fail(where, "'Delete Physical " + words[2] + "{..}' is not a statement; write Physical " +
                    words[2] + "(tag) -= {..}; or Delete Physicals;");
  if (words.size() != 2) return;
  const std::string& kind = words[1];
  const bool entity = kind == "Point" || kind == "Line" || kind == "Curve" || kind == "Surface" ||
                      kind == "Volume";
  if (words[0] == "Extrude" && entity)
    fail(where, "'Extrude " + kind + " {tag, {dx, dy, dz}}' is an older form that is no longer "
                "read; write Extrude {dx, dy, dz} { " + kind + "{tag}; }");
  if (words[0] == "Compound" && entity && !braces)
    fail(where, "'Compound " + kind + "(tag) = {..}' is an older form that is no longer read; "
                "write the meshing constraint Compound " + (kind == "Line" ? std::string("Curve") : kind) +
                "{..};");
  if (words[0] == "Physical" && entity && braces)
    fail(where, "a physical group is defined as Physical " + kind + "(tag) = {..}; or Physical " +
                    kind + "(\"name\") = {..};, not with braces");
}

// Words Gmsh reserves without any statement of theirs (Hole, from its first versions).
void Interpreter::rejectReservedWord(const ast::CommandStmt& command, const SourceLocation& where) {
  fail(where, "'" + command.words[0] + "' is a reserved word that starts no statement");
}

void Interpreter::unsupportedStatement(const ast::CommandStmt& command,
                                       const SourceLocation& where) {
  session_.noteIgnoredStatement(where);  // meshing a model this leaves empty is an error
  warn(where, "'" + commandName(command) + "' is not supported yet; ignored");
}

// Statements that only concern the graphical interface or post-processing: batch runs
// ignore them.
void Interpreter::skipInBatch(const ast::CommandStmt& command, const SourceLocation& where) {
  session_.log().debug(where.file + ":" + std::to_string(where.line) + ": '" +
                       joined(command.words) + "' has no effect in batch mode");
}

void Interpreter::exitScript(const ast::CommandStmt&, const SourceLocation&) { throw ScriptExit(); }

void Interpreter::abortScript(const ast::CommandStmt&, const SourceLocation&) {
  throw AbortScript();
}

}  // namespace geomesh
