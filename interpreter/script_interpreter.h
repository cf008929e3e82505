// Interpreter: walks a script's syntax tree, with its variables, macros and source texts.
#pragma once

#include <deque>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/ast.h"
#include "interpreter/function_registry.h"
#include "interpreter/value.h"
#include "kernel/affine_map.h"
#include "kernel/extrusion_motion.h"
#include "kernel/geometry_error.h"
#include "kernel/model.h"
#include "kernel/solid_modeling.h"
#include "mesh/views/plugins.h"
#include "mesh/views/view.h"
#include "stdlib/math_functions.h"

namespace geomesh {

class Session;

// Walks the AST of a script and its Includes, keeping the variables, macros and source texts
// of one run. The member functions are spread over files by concern: statements
// (interpreter.cpp), assignments (assignments.cpp), expressions (evaluator.cpp,
// operators.cpp), built-in functions (builtin_calls.cpp, string_functions.cpp, structs.cpp, found
// through function_registry.h), commands and options (commands.cpp, each found through the
// statement table of statement_table.cpp), entity definitions (geometry_commands.cpp),
// operations on shapes (shape_operations.cpp), parameters (parameters.cpp).
class Interpreter {
 public:
  explicit Interpreter(Session& session);
  ~Interpreter();
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  void runFile(const std::string& path);
  void runText(const std::string& text, const std::string& name);

  // Every built-in function: the math library's and the interpreter's families.
  static FunctionRegistry builtinFunctions();
  // The words of each row of the statement table: "Point", "Physical Surface", and "Sleep ..."
  // for a head followed by any words. For tests: every command keyword has its place.
  static std::vector<std::string_view> statementPatterns();
  // Command keywords that never start a statement: they continue one (Loop in Curve Loop) or
  // appear inside expressions and blocks (Layers, PointsOf).
  static std::span<const std::string_view> keywordsStartingNoStatement();

 private:
  struct AbortScript {};  // thrown by `Abort;`

  // statements
  void runSource(const std::string& name, std::string text);
  void execute(const ast::StmtList& statements);
  void execute(const ast::Stmt& statement);
  void executeAssign(const ast::AssignStmt& assign, const SourceLocation& where);
  void rejectMisspelledCommand(const std::string& name, const SourceLocation& where);
  void assignElements(const ast::LValue& target, const std::string& name, const Value& value,
                      const std::string& op, const SourceLocation& where);
  void executeFor(const ast::ForStmt& loop, const SourceLocation& where);
  void executeIf(const ast::IfStmt& branches);
  void executeCall(const ast::CallStmt& call, const SourceLocation& where);
  void defineMacro(const ast::MacroStmt& macro, const SourceLocation& where);
  void executeInclude(const ast::CommandStmt& command, const SourceLocation& where);
  void executeOptionAssign(const ast::OptionAssignStmt& assign, const SourceLocation& where);

  // expressions
  Value evaluate(const ast::Expr& expr);
  double evaluateNumber(const ast::Expr& expr);
  std::string evaluateString(const ast::Expr& expr);
  std::vector<double> evaluateNumbers(const ast::Expr& expr);
  std::vector<double> evaluateNumbers(const ast::ExprList& items);
  std::string resolveName(const ast::Name& name);
  Value variableValue(const ast::Expr& expr);
  Value& requireVariable(const std::string& name, const SourceLocation& where);
  Value elementValue(const ast::Expr& expr);
  Value itemsAt(const std::string& name, const SourceLocation& where, const ast::Expr& indexExpr);
  Value listValue(const ast::ExprList& items, const SourceLocation& where);
  std::vector<double> rangeValues(const ast::Expr& range);
  Value unaryValue(const ast::Expr& expr);
  Value binaryValue(const ast::Expr& expr);
  Value optionValue(const ast::Expr& expr);
  Value shapeValue(const ast::Expr& expr);
  Value physicalQuery(const ast::Expr& expr, int dim);

  // built-in functions and constants; each family is a table of rows (name, arity, body)
  Value callFunction(const ast::Expr& call);
  Value callMath(const MathFunction& function, const ast::Expr& call);
  static std::span<const ScriptFunction> stringFunctions();
  static std::span<const ScriptFunction> listFunctions();
  static std::span<const ScriptFunction> queryFunctions();
  static std::span<const ScriptFunction> structFunctions();
  std::vector<std::string> textPieces(const ast::Expr& call);
  Value listFromFile(const ast::Expr& call);
  Value exists(const ast::Expr& call);
  Value getValue(const ast::Expr& call);
  Value nameOfStruct(const ast::Expr& call);
  std::optional<Value> builtinConstant(std::string_view name);
  std::optional<Value> textConstant(std::string_view name, const SourceLocation& where);
  // printf-style formatting of args[1..] by the string args[0] (Printf, Sprintf). With
  // listWithoutFormat (Printf), a string with no conversion is followed by the values listed.
  std::string format(const ast::ExprList& args, const SourceLocation& where,
                     bool listWithoutFormat = false);

  // commands: executeCommand finds the statement's handler in the statement table
  // (statement_table.cpp); every handler takes the command and its location.
  using StatementHandler = void (Interpreter::*)(const ast::CommandStmt&, const SourceLocation&);
  struct StatementRow {
    std::string_view words;  // "Point", "Physical Surface"; "Exit ...": any words after Exit
    StatementHandler handler;
  };
  static std::span<const StatementRow> statementTable();
  static const StatementRow* findStatement(const std::vector<std::string>& words);
  void executeCommand(const ast::CommandStmt& command, const SourceLocation& where);
  void unsupportedStatement(const ast::CommandStmt& command, const SourceLocation& where);
  void skipInBatch(const ast::CommandStmt& command, const SourceLocation& where);
  [[noreturn]] void exitScript(const ast::CommandStmt& command, const SourceLocation& where);
  [[noreturn]] void abortScript(const ast::CommandStmt& command, const SourceLocation& where);
  void executeMessage(const ast::CommandStmt& command, const SourceLocation& where);
  void executeSetFactory(const ast::CommandStmt& command, const SourceLocation& where);
  void executePrintf(const ast::CommandStmt& command, const SourceLocation& where);
  // Homology(dims) {{domain}, {subdomain}}; and Cohomology: requests for the end of meshing
  // (homology_statements.cpp)
  void requestHomology(const ast::CommandStmt& command, const SourceLocation& where);
  // entity definitions (geometry_commands.cpp)
  void defineEntity(const ast::CommandStmt& command, const SourceLocation& where);
  void definePoint(const ast::CommandStmt& command, const SourceLocation& where);
  void defineBox(const ast::CommandStmt& command, const SourceLocation& where);
  void reportHandover(const UnsupportedOperation& unsupported);
  int physicalTagFor(int dim, const std::string& name) const;
  void defineCircleArc(const ast::CommandStmt& command, const SourceLocation& where);
  // OpenCASCADE statements (occ_statements.cpp)
  SolidModeling* solidModeling(const std::string& statement, const SourceLocation& where);
  int solidTag(const ast::CommandStmt& command, const SourceLocation& where);
  void definePrimitive(const ast::CommandStmt& command, const SourceLocation& where);
  bool defineConic(const ast::CommandStmt& command, const SourceLocation& where);
  void defineEllipse(const ast::CommandStmt& command, const SourceLocation& where);
  void defineWire(const ast::CommandStmt& command, const SourceLocation& where);
  void defineThruSections(const ast::CommandStmt& command, const SourceLocation& where);
  std::vector<EntityId> booleanArguments(const ast::ShapePart& block, bool& remove);
  std::vector<EntityId> booleanShapes(const std::string& word,
                                      const std::vector<ast::ShapePart>& parts, int tag,
                                      const SourceLocation& where);
  void executeBoolean(const ast::CommandStmt& command, const SourceLocation& where);
  void reportReplacements(const std::string& word,
                          const std::vector<SolidModeling::Replacement>& replaced,
                          const SourceLocation& where);
  std::vector<EntityId> roundedShapes(const ast::Expr& shape);
  void executeRounding(const ast::CommandStmt& command, const SourceLocation& where);
  std::vector<EntityId> shapesFromFile(const ast::Expr& shape);
  void executeHealShapes(const ast::CommandStmt& command, const SourceLocation& where);
  // interpreter/discrete_statements.cpp
  std::vector<double> braceNumbers(const ast::CommandStmt& command, const char* usage,
                                   const SourceLocation& where);
  void classifySurfaces(const ast::CommandStmt& command, const SourceLocation& where);
  void createTopology(const ast::CommandStmt& command, const SourceLocation& where);
  void createGeometry(const ast::CommandStmt& command, const SourceLocation& where);
  SolidModeling::HealingOptions healingOptions() const;
  void applyImportOptions(SolidModeling& solids) const;
  std::vector<EntityId> closestShapes(const ast::Expr& shape);
  std::vector<EntityId> extrudeAlongWire(const ast::Expr& shape, const ast::Expr& wire);
  std::vector<EntityId> pipe(const ast::ShapePart& block, const ast::ShapePart& wire,
                             const SourceLocation& where, const SourceLocation& wireWhere);
  std::optional<std::vector<EntityId>> solidOperation(const ast::Expr& shape);
  void mergeCadFile(const std::string& file, const SourceLocation& where);
  void saveCadFile(const std::string& path, const SourceLocation& where);
  void executePhysical(const ast::CommandStmt& command, const SourceLocation& where);
  void definePhysical(const ast::CommandStmt& command, int dim, const SourceLocation& where);
  int entityTag(const ast::CommandStmt& command, const SourceLocation& where);
  static int tagKind(const std::vector<std::string>& words);
  static bool isCurveThroughPoints(const std::string& word);
  std::optional<Vec3> circlePlaneNormal(const ast::CommandStmt& command);
  void executePeriodicByTranslation(const ast::CommandStmt& command, const SourceLocation& where);
  Value intersectCurvesWithSurface(const ast::Expr& expr);
  void executeCoherencePoints(const ast::CommandStmt& command, const SourceLocation& where);
  void rejectReservedWord(const ast::CommandStmt& command, const SourceLocation& where);
  void rejectOlderForms(const std::vector<std::string>& words, bool braces,
                        const SourceLocation& where);
  void definePolarSphere(const ast::CommandStmt& command, const SourceLocation& where);
  void executeSplitCurve(const ast::CommandStmt& command, const SourceLocation& where);
  void warnIfNearlyPlane(int tag, const SourceLocation& where);
  void defineCurveThroughPoints(const ast::CommandStmt& command, int tag, std::vector<int> points);
  void defineNurbs(const ast::CommandStmt& command, int tag, const std::vector<int>& points);
  std::vector<int> entityTags(const ast::Expr& list);
  std::vector<int> fillingPoints(const ast::CommandStmt& command, const SourceLocation& where);
  void optionChanged(const std::string& name);
  void executeSetter(const ast::CommandStmt& command, const SourceLocation& where);

  // shapes (shape_operations.cpp)
  static int entityDimension(const std::vector<std::string>& words);
  std::vector<int> allTags(int dim) const;
  std::vector<int> shapeTags(const ast::Expr& shape, int dim);
  std::vector<EntityId> shapesIn(const ast::ShapePart& block);
  std::vector<double> shapeArguments(const ast::Expr& shape);
  AffineMap transformMap(const ast::Expr& shape);
  ExtrusionLayers extrusionLayers(const ast::ShapePart& block);
  ExtrusionMotion normalsMotion(const ast::ShapePart& block);
  std::vector<EntityId> extrude(const ast::Expr& shape);
  std::optional<std::vector<EntityId>> shapeOperation(const ast::Expr& shape);
  void executeShapeOperation(const ast::CommandStmt& command, const SourceLocation& where);
  void executeCoherence(const ast::CommandStmt& command, const SourceLocation& where);
  void executePeriodicSurface(const ast::CommandStmt& command, const SourceLocation& where);
  void executePeriodic(const ast::CommandStmt& command, const SourceLocation& where);
  void executeDeletePhysicals(const ast::CommandStmt& command, const SourceLocation& where);
  void deleteShapes(const ast::CommandStmt& command, const SourceLocation& where);
  void executeCompound(const ast::CommandStmt& command, const SourceLocation& where);
  void embedEntities(const ast::CommandStmt& command, const SourceLocation& where);

  // the whole model and its mesh: Mesh n, Save, Merge, Delete Model, ... (model_commands.cpp)
  void executeMesh(const ast::CommandStmt& command, const SourceLocation& where);
  void executeSetOrder(const ast::CommandStmt& command, const SourceLocation& where);
  void executePartitionMesh(const ast::CommandStmt& command, const SourceLocation& where);
  // Plugin(name).option = value; and Plugin(name).Run; (plugins.cpp)
  void executePlugin(const ast::PluginStmt& plugin, const SourceLocation& where);
  void partitionBySlices(const SourceLocation& where);
  void simplifyMergedTriangles(const SourceLocation& where);
  void fairMergedTriangles(const SourceLocation& where);
  void executeSave(const ast::CommandStmt& command, const SourceLocation& where);
  void executePrint(const ast::CommandStmt& command, const SourceLocation& where);
  void executeMerge(const ast::CommandStmt& command, const SourceLocation& where);
  void executeNewModel(const ast::CommandStmt& command, const SourceLocation& where);
  void executeAlreadyDone(const ast::CommandStmt& command, const SourceLocation& where);
  void executeCoherenceMesh(const ast::CommandStmt& command, const SourceLocation& where);
  void executeDelete(const ast::CommandStmt& command, const SourceLocation& where);
  void meshNow(const ast::Expr& dimension, const SourceLocation& where);
  void startNewModel();
  void synchronizeModel(const SourceLocation& where);
  std::optional<double> modelStatistic(std::string_view name);
  void saveFile(const ast::CommandStmt& command, const SourceLocation& where);
  void mergeFile(const ast::CommandStmt& command, const SourceLocation& where);
  bool deleteByName(const ast::Expr& what, const SourceLocation& where);

  // views: View "name" {...}, View[n].X, Delete/Save View, Background Mesh View, merging view
  // files (view_statements.cpp)
  void defineView(const ast::CommandStmt& command, const SourceLocation& where);
  void addViewRecord(post::View& view, const ast::ViewItem& item);
  std::size_t viewIndexAt(const ast::Expr& index);
  post::View& viewAt(const ast::Expr& index);
  void setViewOption(const ast::OptionAssignStmt& assign, const SourceLocation& where);
  std::optional<Value> viewOptionValue(const ast::Expr& expr);
  void deleteView(const ast::CommandStmt& command, const SourceLocation& where);
  static double applyAssignment(double old, double operand, const std::string& op);
  void combineViews(const ast::CommandStmt& command, const SourceLocation& where);
  void checkFieldView(const std::string& type, const std::string& option, const Value& value,
                      const ast::Expr& where);
  void setBackgroundView(const ast::CommandStmt& command, const SourceLocation& where);
  void saveView(const ast::CommandStmt& command, const SourceLocation& where);
  void mergeViewFile(const ast::CommandStmt& command, const SourceLocation& where);
  void readViewsOfMesh(const std::string& path, const SourceLocation& where);
  bool mergeDataOnly(const std::string& path, const SourceLocation& where);

  // mesh constraints: Transfinite, Recombine, Field, Background Field (mesh_constraints.cpp)
  void defineTransfiniteCurve(const ast::CommandStmt& command, const SourceLocation& where);
  void defineTransfiniteSurface(const ast::CommandStmt& command, const SourceLocation& where);
  void recombineSurfaces(const ast::CommandStmt& command, const SourceLocation& where);
  void defineTransfiniteVolume(const ast::CommandStmt& command, const SourceLocation& where);
  void copyMeshingMethod(const std::vector<EntityId>& sources, const std::vector<EntityId>& copies);
  void setSurfaceAlgorithm(const ast::CommandStmt& command, const SourceLocation& where);
  void defineField(const ast::CommandStmt& command, const SourceLocation& where);
  void setBackgroundField(const ast::CommandStmt& command, const SourceLocation& where);
  void addBoundaryLayerField(const ast::CommandStmt& command, const SourceLocation& where);
  bool executeFieldOption(const ast::OptionAssignStmt& assign, const SourceLocation& where);

  // parameters (DefineConstant, DefineNumber, DefineString)
  void executeDefineConstant(const ast::DefineConstantStmt& define);
  Value defineNumber(const ast::Expr& expr);
  Value defineString(const ast::Expr& expr);
  std::optional<std::string> parameterName(const std::vector<ast::Attribute>& attributes);

  // Struct definitions and members (structs.cpp)
  struct StructData {
    double tag = 0;
    std::map<std::string, Value> members;
    double enumValue = -1;  // the last value given, continued by Enum members without one
  };
  struct StructSpace {
    std::map<std::string, StructData> structs;
    double maxTag = 0;
  };
  Value defineStruct(const ast::Expr& definition);
  void addStructMembers(StructData& data, const ast::Expr& definition);
  std::string structKey(const ast::Expr& ref);
  std::string structName(const ast::Expr& ref);
  StructData* findStruct(const ast::Expr& ref);
  StructData& requireStruct(const ast::Expr& ref);
  const Value* findMember(const ast::Expr& ref);
  Value memberValue(const ast::Expr& ref);
  void executeStructStatement(const ast::CommandStmt& command, const SourceLocation& where);
  std::optional<Value> valueIfDefined(const ast::Expr& expr);

  // diagnostics
  [[noreturn]] void fail(const SourceLocation& where, const std::string& message) const;
  // Resource limits, from the options General.MaxLoopIterations / General.MaxMacroDepth.
  double maxLoopIterations() const;
  [[noreturn]] void failTooManyIterations(const SourceLocation& where) const;
  // MeshSize{points} = size; (Characteristic Length{..})
  void executeMeshSize(const ast::CommandStmt& command, const SourceLocation& where);
  void executeSystemCall(const ast::CommandStmt& command, const SourceLocation& where);
  void warn(const SourceLocation& where, const std::string& message) const;
  std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) const;
  std::string directoryOf(const std::string& file) const;

  Session& session_;
  FunctionRegistry functions_;
  std::map<std::string, Value> variables_;
  std::map<std::string, const ast::StmtList*> macros_;
  std::map<std::string, double> parameterNumbers_;
  std::map<std::string, post::PluginOptions> pluginOptions_;  // by plugin name
  std::map<std::string, std::string> parameterStrings_;
  std::map<std::string, StructSpace> structSpaces_;  // by namespace; "" is the global one
  std::deque<SourceFile> sources_;
  std::deque<ast::StmtList> programs_;  // kept alive: macros point into them
  std::vector<std::string> includeStack_;
  mutable std::set<std::string> warned_;
  const SourceLocation* statementLocation_ = nullptr;  // of the statement being executed
  std::set<std::string> handedOver_;                   // operations reportHandover() has reported
  int callDepth_ = 0;
  int deletedPhysicalTag_ = 0;  // the largest tag of the groups Delete Physicals removed
  RandomEngine random_;
};

}  // namespace geomesh
