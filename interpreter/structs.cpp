// Structs: named groups of members, possibly in a namespace.
//   Struct NS::Name (Append) [ Tag 3, epsr 5, mu {1, 2}, label "iron", Enum, A, B ];
// A Struct's value is its tag: given as `Tag`, else one more than the largest tag of its
// namespace. Members are read as Name.member, Name.list(i), Name.list(), #Name.list(); a
// definition never overwrites a member already there (Append only adds). With `Enum`, a member
// without a value takes the next integer after the last value given (0 first); elsewhere such
// a member is a flag worth 1.
#include "interpreter/script_interpreter.h"

namespace geomesh {

namespace {

std::string qualified(const std::string& space, const std::string& name) {
  return space.empty() ? name : space + "::" + name;
}

}  // namespace

// The name of the Struct `ref` designates: written out, or given as a string by S2N[...].
std::string Interpreter::structKey(const ast::Expr& ref) {
  if (ref.name.base.empty() && ref.name.suffixes.size() == 1)
    return evaluateString(*ref.name.suffixes[0]);
  return resolveName(ref.name);
}

std::string Interpreter::structName(const ast::Expr& ref) {
  return qualified(ref.words.front(), structKey(ref));
}

Value Interpreter::defineStruct(const ast::Expr& definition) {
  const std::string& spaceName = definition.words.front();
  const std::string name = resolveName(definition.name);
  StructSpace& space = structSpaces_[spaceName];
  auto existing = space.structs.find(name);
  const bool append = definition.text == "Append";
  if (existing != space.structs.end() && !append)
    fail(definition.loc, "Struct '" + qualified(spaceName, name) +
                             "' is already defined; add members with 'Struct " +
                             qualified(spaceName, name) + " (Append) [...]'");
  if (existing != space.structs.end()) {
    addStructMembers(existing->second, definition);
    return Value::number(existing->second.tag);
  }
  StructData data;
  addStructMembers(data, definition);
  auto tag = data.members.find("Tag");
  if (tag != data.members.end() && tag->second.kind() == Value::Kind::Number) {
    data.tag = tag->second.numbers()[0];
  } else {
    data.tag = space.maxTag + 1;
    data.members.insert_or_assign("Tag", Value::number(data.tag));
  }
  space.maxTag = std::max(space.maxTag, data.tag);
  const double value = data.tag;
  space.structs.emplace(name, std::move(data));
  return Value::number(value);
}

void Interpreter::addStructMembers(StructData& data, const ast::Expr& definition) {
  bool enumerating = false;
  for (const auto& member : definition.attributes) {
    if (member.name == "Enum" && member.values.empty()) {
      enumerating = true;
      continue;
    }
    Value value;
    if (!member.values.empty()) {
      value = evaluate(*member.values[0]);
      if (value.kind() == Value::Kind::Number) data.enumValue = value.numbers()[0];
    } else {
      value = Value::number(enumerating ? ++data.enumValue : 1);
    }
    if (member.name == "Tag" && value.kind() != Value::Kind::Number)
      fail(member.loc, "the Tag of a Struct is a number");
    data.members.emplace(member.name, std::move(value));  // the first definition stays
  }
}

Interpreter::StructData* Interpreter::findStruct(const ast::Expr& ref) {
  auto space = structSpaces_.find(ref.words.front());
  if (space == structSpaces_.end()) return nullptr;
  auto found = space->second.structs.find(structKey(ref));
  return found == space->second.structs.end() ? nullptr : &found->second;
}

Interpreter::StructData& Interpreter::requireStruct(const ast::Expr& ref) {
  if (StructData* data = findStruct(ref)) return *data;
  const std::string& spaceName = ref.words.front();
  auto space = structSpaces_.find(spaceName);
  if (space == structSpaces_.end() && !spaceName.empty()) {
    std::vector<std::string> known;
    for (const auto& [other, unused] : structSpaces_)
      if (!other.empty()) known.push_back(other);
    fail(ref.loc, "unknown Struct namespace '" + spaceName + "'" + didYouMean(spaceName, known));
  }
  std::vector<std::string> known;
  if (space != structSpaces_.end())
    for (const auto& [other, unused] : space->second.structs)
      known.push_back(qualified(spaceName, other));
  const std::string name = structName(ref);
  fail(ref.loc, "unknown Struct '" + name + "'" + didYouMean(name, known));
}

const Value* Interpreter::findMember(const ast::Expr& ref) {
  StructData* data = findStruct(ref);
  if (!data) return nullptr;
  auto member = data->members.find(ref.text);
  return member == data->members.end() ? nullptr : &member->second;
}

// Name.member reads a number or a string (the first item of a list); Name.list(i) one item;
// Name.list() the whole list; Name alone, or NS::Name, the Struct's tag.
Value Interpreter::memberValue(const ast::Expr& ref) {
  StructData& data = requireStruct(ref);
  if (ref.text.empty()) return Value::number(data.tag);
  auto member = data.members.find(ref.text);
  if (member == data.members.end()) {
    std::vector<std::string> known;
    for (const auto& [name, unused] : data.members) known.push_back(name);
    fail(ref.loc, "unknown member '" + ref.text + "' of Struct '" + structName(ref) + "'" +
                      didYouMean(ref.text, known));
  }
  const Value& value = member->second;
  if (ref.kind == ast::ExprKind::MemberList)
    return value.isText() ? Value::stringList(value.strings()) : Value::list(value.numbers());
  std::size_t index = 0;
  if (ref.kind == ast::ExprKind::MemberItem) {
    const double at = evaluateNumber(*ref.args[0]);
    if (at < 0 || at >= static_cast<double>(value.size()))
      fail(ref.args[0]->loc, "index " + std::to_string(clampedInteger<long long>(at)) +
                                 " out of range for member '" + ref.text + "' of Struct '" +
                                 structName(ref) + "' (" + std::to_string(value.size()) +
                                 " item" + (value.size() == 1 ? "" : "s") + ")");
    index = clampedInteger<std::size_t>(at);
  } else if (value.size() == 0) {
    fail(ref.loc, "member '" + ref.text + "' of Struct '" + structName(ref) + "' is empty");
  }
  return value.isText() ? Value::string(value.strings()[index])
                        : Value::number(value.numbers()[index]);
}

// Struct ...; as a statement. Members are set by their definition only: Gmsh refuses
// `Name.member = value;`, and so does this.
void Interpreter::executeStructStatement(const ast::CommandStmt& command,
                                         const SourceLocation& where) {
  const ast::Expr& target = *command.args[0];
  if (command.op.empty()) {
    evaluate(target);
    return;
  }
  requireStruct(target);
  fail(where, "members of a Struct cannot be assigned: give '" + target.text +
                  "' its value in the Struct definition");
}

// The value of a variable, list item or Struct member if it exists (GetForced, Exists).
std::optional<Value> Interpreter::valueIfDefined(const ast::Expr& expr) {
  using ast::ExprKind;
  switch (expr.kind) {
    case ExprKind::Variable: {
      const std::string name = resolveName(expr.name);
      if (auto it = variables_.find(name); it != variables_.end()) return it->second;
      auto global = structSpaces_.find("");
      if (global != structSpaces_.end())
        if (auto it = global->second.structs.find(name); it != global->second.structs.end())
          return Value::number(it->second.tag);
      return std::nullopt;
    }
    case ExprKind::Element:
    case ExprKind::Call: {
      // a[i], or the old a(i) when `a` is a variable and no function
      if (expr.kind == ExprKind::Call && expr.args.size() > 1) break;
      const std::string name =
          expr.kind == ExprKind::Call ? expr.text : resolveName(expr.name);
      auto it = variables_.find(name);
      if (it == variables_.end()) {
        if (expr.kind == ExprKind::Element || !functions_.find(name)) return std::nullopt;
        break;
      }
      if (expr.args.empty()) return evaluate(expr);
      const double at = evaluateNumber(*expr.args[0]);
      if (at < 0 || at >= static_cast<double>(it->second.size())) return std::nullopt;
      return evaluate(expr);
    }
    case ExprKind::Member:
    case ExprKind::MemberItem:
    case ExprKind::MemberList: {
      if (!findStruct(expr)) return std::nullopt;
      if (expr.text.empty()) return memberValue(expr);
      const Value* member = findMember(expr);
      if (!member) return std::nullopt;
      if (expr.kind == ExprKind::MemberItem) {
        const double at = evaluateNumber(*expr.args[0]);
        if (at < 0 || at >= static_cast<double>(member->size())) return std::nullopt;
      }
      return memberValue(expr);
    }
    default: break;
  }
  return evaluate(expr);
}

// GetForced(x[, default]), DimNameSpace([namespace]), NameStruct[NS::#t] (the name of the
// Struct of tag t in a namespace) and S2N["name"] (the tag of a global Struct).
std::span<const ScriptFunction> Interpreter::structFunctions() {
  using Call = const ast::Expr&;
  static constexpr ScriptFunction kRows[] = {
      {"NameStruct", 1, 1, "NameStruct takes a tag in a namespace, as in NameStruct[NS::#1]",
       [](Interpreter& in, Call call) { return in.nameOfStruct(call); }},
      {"S2N", 1, 1, "S2N takes the name of a Struct, as a string",
       [](Interpreter& in, Call call) {
         ast::Expr ref;
         ref.kind = ast::ExprKind::Member;
         ref.loc = call.loc;
         ref.words.emplace_back();
         ref.name.base = in.evaluateString(*call.args[0]);
         return in.memberValue(ref);
       }},
      {"GetForced", 1, 2, "GetForced takes 1 or 2 arguments",
       [](Interpreter& in, Call call) {
         if (auto value = in.valueIfDefined(*call.args[0])) return *value;
         return call.args.size() > 1 ? in.evaluate(*call.args[1]) : Value::number(0);
       }},
      {"DimNameSpace", 0, 1, "DimNameSpace takes a namespace name, or nothing for the global one",
       [](Interpreter& in, Call call) {
         const auto& args = call.args;
         if (args.size() == 1 &&
             (args[0]->kind != ast::ExprKind::Variable || !args[0]->name.suffixes.empty()))
           in.fail(call.loc, "DimNameSpace takes a namespace name, or nothing for the global one");
         const std::string space = args.empty() ? "" : args[0]->name.base;
         auto it = in.structSpaces_.find(space);
         return Value::number(it == in.structSpaces_.end() ? 0 : it->second.structs.size());
       }},
  };
  return kRows;
}

Value Interpreter::nameOfStruct(const ast::Expr& call) {
  if (call.args[0]->kind != ast::ExprKind::Count)
    fail(call.loc, "NameStruct takes a tag in a namespace, as in NameStruct[NS::#1]");
  const ast::Expr& count = *call.args[0];
  const std::string space = count.words.empty() ? "" : count.words.front();
  const double tag = evaluateNumber(*count.args[0]);
  if (auto it = structSpaces_.find(space); it != structSpaces_.end())
    for (const auto& [name, data] : it->second.structs)
      if (data.tag == tag) return Value::string(name);
  warn(call.loc, "no Struct of tag " + std::to_string(clampedInteger<long long>(tag)) +
                     (space.empty() ? "" : " in namespace '" + space + "'"));
  return Value::string("");
}

}  // namespace geomesh
