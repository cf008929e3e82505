// Views in scripts: View "name" {...}; View[n].Option = v and reading view options; Delete
// View[n]; Background Mesh View[n]; Save View[n] "file"; merging view files.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <fstream>
#include <optional>

#include "api/session.h"
#include "interpreter/script_interpreter.h"
#include "io/formats.h"
#include "io/view_files.h"
#include "mesh/views/view_combine.h"
#include "stdlib/clamped_integer.h"
#include "stdlib/format.h"

namespace geomesh {

namespace {

// A record of the parsed format by its name: ST, VL, TS2, T2, T3, TIME.
struct RecordType {
  enum class Kind { Element, Text2, Text3, Time, Unknown } what = Kind::Unknown;
  post::FieldKind field = post::FieldKind::Scalar;
  post::ElementShape shape = post::ElementShape::Point;
  int order = 1;
  int nodes = 0;
};

// Nodes of a second-order element of each shape (P L T Q S H I Y).
constexpr int kSecondOrderNodes[post::kShapeCount] = {1, 3, 6, 9, 10, 27, 18, 14};

RecordType recordType(const std::string& type) {
  RecordType r;
  if (type == "T2") return {RecordType::Kind::Text2};
  if (type == "T3") return {RecordType::Kind::Text3};
  if (type == "TIME") return {RecordType::Kind::Time};
  const std::optional<post::ListType> list = post::listTypeOf(type);
  if (!list) return r;
  r.what = RecordType::Kind::Element;
  r.field = list->field;
  r.shape = list->shape;
  r.order = list->order;
  r.nodes = r.order == 2 ? kSecondOrderNodes[static_cast<int>(r.shape)]
                         : post::cornerCount(r.shape);
  return r;
}

std::string numberText(double x) {
  const FormatArgument shown[] = {x};
  return formatPrintf("%g", shown);
}

// View[n].MinX ... MaxZ: the view's bounding box (0 for a view without elements).
std::optional<double> viewBound(const post::View& view, const std::string& name) {
  static const char* const kNames[] = {"MinX", "MinY", "MinZ", "MaxX", "MaxY", "MaxZ"};
  int which = -1;
  for (int k = 0; k < 6; ++k)
    if (name == kNames[k]) which = k;
  if (which < 0) return std::nullopt;
  const int axis = which % 3;
  const bool low = which < 3;
  double bound = low ? 1e300 : -1e300;
  bool any = false;
  for (const post::ElementList& list : view.lists)
    for (std::size_t k = std::size_t(axis); k < list.coordinates.size(); k += 3) {
      bound = low ? std::min(bound, list.coordinates[k]) : std::max(bound, list.coordinates[k]);
      any = true;
    }
  return any ? bound : 0.0;
}

// Whether a file starts as an MSH 2 or 4 file does ($MeshFormat): older ones hold no data.
bool hasMeshFormat(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string word;
  in >> word;
  return word == "$MeshFormat";
}

// Whether a (text or binary) MSH file has a line starting with `section`.
bool hasSection(const std::string& path, const std::string& section) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(section, 0) == 0) return true;
  return false;
}

}  // namespace

// View "name" { ST(x1,y1,z1, ...){v1, ...}; T2(x,y,style){"text"}; TIME{t0, t1}; };
void Interpreter::defineView(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.args.size() != 1) return unsupportedStatement(command, where);
  post::View& view = session_.views().add(evaluateString(*command.args[0]));
  for (const ast::ViewItem& item : command.viewItems) addViewRecord(view, item);
  session_.log().debug(where.file + ":" + std::to_string(where.line) + ": view '" + view.name +
                       "' with " + std::to_string(view.elementCount()) + " elements");
}

void Interpreter::addViewRecord(post::View& view, const ast::ViewItem& item) {
  const RecordType type = recordType(item.type);
  switch (type.what) {
    case RecordType::Kind::Unknown:
      fail(item.loc, "'" + item.type + "' is not a view record (SP, VL, TT, ST2, T2, T3, " +
                         "TIME, ...)");
    case RecordType::Kind::Time:
      view.times = evaluateNumbers(item.values);
      return;
    case RecordType::Kind::Text2:
    case RecordType::Kind::Text3: {
      const std::size_t place = type.what == RecordType::Kind::Text2 ? 3 : 4;
      std::vector<double> at = evaluateNumbers(item.coordinates);
      if (at.size() != place)
        fail(item.loc, item.type + " takes " + std::to_string(place) + " values: the " +
                           (place == 3 ? "x, y" : "x, y, z") + " position and a style");
      post::TextItem text;
      text.dimension = place == 3 ? 2 : 3;
      text.x = at[0];
      text.y = at[1];
      if (place == 4) text.z = at[2];
      text.style = at.back();
      for (const auto& value : item.values) {
        const Value v = evaluate(*value);
        if (v.isText())
          for (const std::string& s : v.strings()) text.text.push_back(s);
        else
          for (double x : v.numbers()) text.text.push_back(std::to_string(x));
      }
      view.texts.push_back(std::move(text));
      return;
    }
    case RecordType::Kind::Element: break;
  }
  const std::vector<double> xyz = evaluateNumbers(item.coordinates);
  if (xyz.size() != 3 * std::size_t(type.nodes))
    fail(item.loc, item.type + " takes the coordinates of " + std::to_string(type.nodes) +
                       " nodes (" + std::to_string(3 * type.nodes) + " values), not " +
                       std::to_string(xyz.size()));
  const std::vector<double> values = evaluateNumbers(item.values);
  const std::size_t perStep = std::size_t(type.nodes) * std::size_t(post::componentCount(type.field));
  if (values.empty() || values.size() % perStep != 0)
    fail(item.loc, item.type + " takes " + std::to_string(perStep) +
                       " values per time step, not " + std::to_string(values.size()));
  post::ElementList& list = view.list(type.shape, type.field, type.order);
  list.nodesPerElement = type.nodes;
  const int steps = static_cast<int>(values.size() / perStep);
  if (list.size() == 0) {
    list.steps = steps;
  } else if (list.steps != steps) {
    fail(item.loc, item.type + " has " + std::to_string(steps) + " time steps where the view's " +
                       "earlier " + item.type + " records have " + std::to_string(list.steps));
  }
  list.coordinates.insert(list.coordinates.end(), xyz.begin(), xyz.end());
  list.values.insert(list.values.end(), values.begin(), values.end());
}

namespace {

// The view at index n; null when n names none.
post::View* viewIndexed(post::ViewStore& views, double n) {
  if (!(n >= 0) || n != std::floor(n) || n >= double(views.size())) return nullptr;
  return &views.at(static_cast<std::size_t>(n));
}

// "no view 3 (views are numbered 0 to 1)": why index n names no view.
std::string noViewAt(const post::ViewStore& views, double n) {
  const auto count = views.size();
  return "no view " + numberText(n) + " (" +
         (count == 0 ? std::string("there is no view")
                     : "views are numbered 0 to " + std::to_string(count - 1)) +
         ")";
}

}  // namespace

// The index of the view a script names (View[n], Delete View[n], ...), or a located error.
std::size_t Interpreter::viewIndexAt(const ast::Expr& index) {
  const double n = evaluateNumber(index);
  if (!viewIndexed(session_.views(), n)) fail(index.loc, noViewAt(session_.views(), n));
  return static_cast<std::size_t>(n);
}

post::View& Interpreter::viewAt(const ast::Expr& index) {
  return session_.views().at(viewIndexAt(index));
}

// View[n].X = v; (a number, a text, or a list such as a colour table); View.X = v sets
// defaults for the display only.
void Interpreter::setViewOption(const ast::OptionAssignStmt& assign, const SourceLocation& where) {
  const std::string name = assign.path.substr(assign.path.find('.') + 1);
  // Colours (names, or lists of them: Red, {Green, Blue}) only change the display.
  const bool colour = name == "ColorTable" || name.starts_with("Color.");
  const auto displayOnly = [&] {
    session_.log().debug(where.file + ":" + std::to_string(where.line) + ": option '" +
                         assign.path + "' changes only the display");
  };
  if (!assign.index) {
    displayOnly();
    if (!colour) evaluate(*assign.value);
    return;
  }
  const double index = evaluateNumber(*assign.index);
  post::View* found = viewIndexed(session_.views(), index);
  if (!found) {
    warn(where, noViewAt(session_.views(), index) + "; option '" + assign.path + "' ignored");
    return;
  }
  if (colour) return displayOnly();
  post::View& view = *found;
  const Value value = evaluate(*assign.value);
  if (value.isText() && value.size() == 1) {
    if (name == "Name")
      view.name = value.strings().front();
    else
      view.strings[name] = value.strings().front();
    return;
  }
  if (value.isNumeric() && value.size() == 1) {
    double& slot = view.numbers[name];
    slot = applyAssignment(slot, value.numbers().front(), assign.op);
    return;
  }
  session_.log().debug(where.file + ":" + std::to_string(where.line) + ": option '" +
                       assign.path + "' (a list) changes only the display");
}

// View[n].Max, View[n].Min, View[n].NbTimeStep, View[n].NbElements, View[n].X as set;
// PostProcessing.NbViews.
std::optional<Value> Interpreter::viewOptionValue(const ast::Expr& expr) {
  if (expr.text == "PostProcessing.NbViews")
    return Value::number(double(session_.views().size()));
  if (!expr.text.starts_with("View.")) return std::nullopt;
  const std::string name = expr.text.substr(5);
  if (expr.args.empty()) return Value::number(0);
  const post::View& view = viewAt(*expr.args[0]);
  if (name == "Max") return Value::number(view.maximum());
  if (name == "Min") return Value::number(view.minimum());
  if (name == "NbTimeStep") return Value::number(double(view.stepCount()));
  if (name == "NbElements") return Value::number(double(view.elementCount()));
  if (name == "Name") return Value::string(view.name);
  if (auto bound = viewBound(view, name)) return Value::number(*bound);
  if (auto it = view.strings.find(name); it != view.strings.end()) return Value::string(it->second);
  if (auto it = view.numbers.find(name); it != view.numbers.end()) return Value::number(it->second);
  return Value::number(0);
}

// Field[n].ViewIndex = i; (ViewTag, IView; an Adapt field's View): the view must exist when
// the script names it, so that a wrong number is reported where it was written.
void Interpreter::checkFieldView(const std::string& type, const std::string& option,
                                 const Value& value, const ast::Expr& where) {
  const bool byIndex = (type == "PostView" && (option == "ViewIndex" || option == "IView")) ||
                       (type == "Adapt" && option == "View");
  const bool byTag = type == "PostView" && option == "ViewTag";
  if ((!byIndex && !byTag) || !value.isNumeric() || value.size() != 1) return;
  const double n = value.numbers().front();
  if (byIndex && n < 0) return;  // -1: unset
  const post::ViewStore& views = session_.views();
  const bool found = byTag ? n == std::floor(n) && views.indexOfTag(clampedInteger<int>(n)) >= 0
                           : n == std::floor(n) && n < double(views.size());
  if (!found)
    fail(where.loc, "Field " + type + "." + option + " = " + numberText(n) + ": no view " +
                        (byTag ? "has tag " : "has index ") + numberText(n) + " (" +
                        std::to_string(views.size()) + " views defined so far)");
}

// Combine ElementsByViewName; Combine TimeStepsByViewName; Combine Views; (or Elements)
// Combine TimeSteps;
void Interpreter::combineViews(const ast::CommandStmt& command, const SourceLocation& where) {
  const ast::Expr* what = command.args.size() == 1 ? command.args[0].get() : nullptr;
  const std::string how = what && what->kind == ast::ExprKind::Variable ? what->name.base : "";
  int merged = 0;
  if (how == "ElementsByViewName")
    merged = post::combineElements(session_.views(), post::CombineGroups::ByName);
  else if (how == "TimeStepsByViewName")
    merged = post::combineTimeSteps(session_.views(), post::CombineGroups::ByName);
  else if (how == "Views" || how == "Elements")
    merged = post::combineElements(session_.views(), post::CombineGroups::All);
  else if (how == "TimeSteps")
    merged = post::combineTimeSteps(session_.views(), post::CombineGroups::All);
  else
    return unsupportedStatement(command, where);
  session_.log().debug(where.file + ":" + std::to_string(where.line) + ": " +
                       std::to_string(merged) + " views combined into others");
}

// Delete View[n];
void Interpreter::deleteView(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle != ast::CommandStmt::Args::Bracket || command.args.size() != 1)
    return unsupportedStatement(command, where);
  session_.views().remove(viewIndexAt(*command.args[0]));
}

// Background Mesh View[n]; the view's values are the mesh sizes (with a Background Field
// too, the smaller of the two).
void Interpreter::setBackgroundView(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle != ast::CommandStmt::Args::Bracket || command.args.size() != 1)
    return unsupportedStatement(command, where);
  const std::size_t index = viewIndexAt(*command.args[0]);
  const post::View& view = session_.views().at(index);
  if (view.elementCount() == 0)
    fail(command.args[0]->loc, "view '" + view.name + "' has no element to read sizes from");
  for (const post::ElementList& list : view.lists)
    for (std::size_t k = 0; k < list.values.size(); ++k) {
      const double v = list.values[k];
      const bool negativeSize = list.kind == post::FieldKind::Scalar && v <= 0;
      if (std::isfinite(v) && !negativeSize) continue;
      const std::size_t node = (k % list.valuesPerElement()) / std::size_t(list.components()) %
                               std::size_t(list.nodesPerElement);
      const std::size_t element = k / list.valuesPerElement();
      const double* at = &list.coordinates[3 * (element * std::size_t(list.nodesPerElement) + node)];
      fail(command.args[0]->loc,
           "view '" + view.name + "' holds the size " + numberText(v) + " at (" + numberText(at[0]) +
               ", " + numberText(at[1]) + ", " + numberText(at[2]) +
               "): background sizes must be positive numbers");
    }
  session_.model().meshConstraints().backgroundView = static_cast<int>(index);
}

// Save View[n] "file.pos" | "file.msh";
void Interpreter::saveView(const ast::CommandStmt& command, const SourceLocation& where) {
  if (command.argStyle != ast::CommandStmt::Args::Bracket || command.args.size() != 2)
    return unsupportedStatement(command, where);
  const post::View& view = viewAt(*command.args[0]);
  const ast::Expr& name = *command.args[1];
  std::filesystem::path path = evaluateString(name);
  if (path.is_relative()) path = std::filesystem::path(directoryOf(where.file)) / path;
  const std::string shown = path.lexically_normal().string();
  if (session_.sandboxed()) {
    warn(where, "'Save View' of '" + shown + "' skipped: this session writes no file");
    return;
  }
  const std::string ext = path.extension().string();
  if (ext != ".pos" && ext != ".msh")
    fail(name.loc, "'Save View' writes .pos (parsed format) or .msh files, not '" + ext + "'");
  try {
    writeView(view, shown, session_.mesh(), session_.options().number("Mesh.MshFileVersion"));
  } catch (const std::runtime_error& error) {
    fail(name.loc, error.what());
  }
  session_.log().info("Wrote view '" + view.name + "' to '" + shown + "'");
}

// Merge "f.pos"; a list-based file is read by io/, a parsed one runs as a script.
void Interpreter::mergeViewFile(const ast::CommandStmt& command, const SourceLocation& where) {
  const ast::Expr& name = *command.args[0];
  std::filesystem::path path = evaluateString(name);
  if (path.is_relative()) path = std::filesystem::path(directoryOf(where.file)) / path;
  const std::string shown = path.lexically_normal().string();
  std::error_code unreadable;
  if (!std::filesystem::exists(path, unreadable)) fail(name.loc, "cannot open '" + shown + "'");
  try {
    if (!isListBasedPosFile(shown)) return executeInclude(command, where);
    const int added = readListBasedPos(shown, session_.views());
    session_.log().info("Merged '" + shown + "': " + std::to_string(added) + " views");
  } catch (const ViewReadError& error) {
    fail(where, error.what());
  }
}

// Merge "f.msh"; into a model that has geometry or a mesh already: a file of data sections
// only is read as views on the session's mesh (node and element tags as the session's mesh
// numbers them in files); a file with a mesh of its own gives its data as views over that
// mesh, which is not added to the model (with a warning). False when the file holds no data.
bool Interpreter::mergeDataOnly(const std::string& path, const SourceLocation& where) {
  if (!hasMeshFormat(path)) return false;
  try {
    if (!hasSection(path, "$Nodes")) {
      const int added = readMshViews(path, session_.mesh(), session_.views());
      session_.log().info("Read " + std::to_string(added) + " views on the mesh from '" + path +
                          "'");
      return added > 0;
    }
    Model model;
    Mesh mesh;
    readMeshFile(path, *findReaderByExtension(".msh"), model, mesh);
    const int added = readMshViews(path, mesh, session_.views());
    if (added == 0) return false;
    warn(where, "the mesh of '" + path + "' is not added to a model that has one already; " +
                    "its data are read as " + std::to_string(added) + " views");
    return true;
  } catch (const ViewReadError& error) {
    fail(where, error.what());
  } catch (const std::runtime_error& error) {
    fail(where, error.what());
  }
}

// The data sections of a merged MSH file become views over its mesh.
void Interpreter::readViewsOfMesh(const std::string& path, const SourceLocation& where) {
  if (!hasMeshFormat(path)) return;
  try {
    const int added = readMshViews(path, session_.mesh(), session_.views());
    if (added > 0) session_.log().info("Read " + std::to_string(added) + " views from '" + path + "'");
  } catch (const ViewReadError& error) {
    fail(where, error.what());
  }
}

}  // namespace geomesh
