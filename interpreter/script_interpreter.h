#pragma once

#include <deque>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "grammar/ast.h"
#include "interpreter/value.h"
#include "kernel/affine_map.h"
#include "kernel/extrusion_motion.h"
#include "kernel/geometry_error.h"
#include "kernel/model.h"
#include "stdlib/math_functions.h"

namespace geomesh {

class Session;

// Walks the AST of a script and its Includes, keeping the variables, macros and source texts
// of one run. The member functions are spread over files by concern: statements
// (interpreter.cpp), assignments (assignments.cpp), expressions (evaluator.cpp,
// operators.cpp), built-in functions (builtin_calls.cpp, string_functions.cpp), commands
// and options (commands.cpp), entity definitions (geometry_commands.cpp), operations on
// shapes (shape_operations.cpp), parameters (parameters.cpp).
class Interpreter {
 public:
  explicit Interpreter(Session& session);
  ~Interpreter();
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  void runFile(const std::string& path);
  void runText(const std::string& text, const std::string& name);

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
  Value listValue(const ast::ExprList& items, const SourceLocation& where);
  std::vector<double> rangeValues(const ast::Expr& range);
  Value unaryValue(const ast::Expr& expr);
  Value binaryValue(const ast::Expr& expr);
  Value optionValue(const ast::Expr& expr);
  Value shapeValue(const ast::Expr& expr);
  Value physicalQuery(const ast::Expr& expr, int dim);

  // built-in functions and constants
  Value callFunction(const ast::Expr& call);
  std::optional<Value> callStringFunction(const ast::Expr& call);
  std::optional<Value> callListFunction(const ast::Expr& call);
  std::optional<Value> callQueryFunction(const ast::Expr& call);
  std::optional<Value> builtinConstant(std::string_view name);
  std::string format(const ast::ExprList& args, const SourceLocation& where);

  // commands
  void executeCommand(const ast::CommandStmt& command, const SourceLocation& where);
  void executePrintf(const ast::CommandStmt& command, const SourceLocation& where);
  bool executeGeometry(const ast::CommandStmt& command, const SourceLocation& where);
  void definePoint(const ast::CommandStmt& command, const SourceLocation& where);
  void defineBox(const ast::CommandStmt& command, const SourceLocation& where);
  void reportHandover(const UnsupportedOperation& unsupported);
  int physicalTagFor(int dim, const std::string& name) const;
  bool defineCircleArc(const ast::CommandStmt& command, const SourceLocation& where);
  void definePhysical(const ast::CommandStmt& command, int dim, const SourceLocation& where);
  int entityTag(const ast::CommandStmt& command, const SourceLocation& where);
  std::vector<int> entityTags(const ast::Expr& list);
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
  std::vector<EntityId> extrude(const ast::Expr& shape);
  std::optional<std::vector<EntityId>> shapeOperation(const ast::Expr& shape);
  bool executeShapeCommand(const ast::CommandStmt& command, const SourceLocation& where);

  // the whole model and its mesh: Mesh n, Save, Merge, Delete Model, ... (model_commands.cpp)
  bool executeModelCommand(const ast::CommandStmt& command, const SourceLocation& where);
  void meshNow(const ast::Expr& dimension, const SourceLocation& where);
  void startNewModel();
  void synchronizeModel(const SourceLocation& where);
  std::optional<double> modelStatistic(std::string_view name);
  void saveFile(const ast::CommandStmt& command, const SourceLocation& where);
  void mergeFile(const ast::CommandStmt& command, const SourceLocation& where);
  bool deleteByName(const ast::Expr& what, const SourceLocation& where);

  // mesh constraints: Transfinite, Recombine, Field, Background Field (mesh_constraints.cpp)
  bool executeMeshConstraint(const ast::CommandStmt& command, const SourceLocation& where);
  void defineTransfiniteCurve(const ast::CommandStmt& command, const SourceLocation& where);
  void defineTransfiniteSurface(const ast::CommandStmt& command, const SourceLocation& where);
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
  std::optional<Value> callStructFunction(const ast::Expr& call);

  // diagnostics
  [[noreturn]] void fail(const SourceLocation& where, const std::string& message) const;
  // Resource limits, from the options General.MaxLoopIterations / General.MaxMacroDepth.
  double maxLoopIterations() const;
  [[noreturn]] void failTooManyIterations(const SourceLocation& where) const;
  // MeshSize{points} = size; (Characteristic Length{..}); false when not that statement.
  bool executeMeshSize(const ast::CommandStmt& command, const SourceLocation& where);
  void executeSystemCall(const ast::CommandStmt& command, const SourceLocation& where);
  void warn(const SourceLocation& where, const std::string& message) const;
  std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) const;
  std::string directoryOf(const std::string& file) const;

  Session& session_;
  std::map<std::string, Value> variables_;
  std::map<std::string, const ast::StmtList*> macros_;
  std::map<std::string, double> parameterNumbers_;
  std::map<std::string, std::string> parameterStrings_;
  std::map<std::string, StructSpace> structSpaces_;  // by namespace; "" is the global one
  std::deque<SourceFile> sources_;
  std::deque<ast::StmtList> programs_;  // kept alive: macros point into them
  std::vector<std::string> includeStack_;
  mutable std::set<std::string> warned_;
  const SourceLocation* statementLocation_ = nullptr;  // of the statement being executed
  std::set<std::string> handedOver_;  // operations reportHandover() has reported
  int callDepth_ = 0;
  int deletedPhysicalTag_ = 0;  // the largest tag of the groups Delete Physicals removed
  RandomEngine random_;
};

}  // namespace geomesh
