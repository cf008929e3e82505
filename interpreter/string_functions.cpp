// String functions: StrCat, Sprintf, StrSub, StrFind, UpperCase, DirName, GetEnv, ..., the string
// family of the function registry.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>

#include "interpreter/script_interpreter.h"
#include "stdlib/format.h"

namespace geomesh {

namespace {

std::string withoutExtension(const std::string& s) {
  auto dot = s.find_last_of('.');
  auto slash = s.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return s;
  return s.substr(0, dot);
}

std::string withoutDirectory(const std::string& s) {
  auto slash = s.find_last_of("/\\");
  return slash == std::string::npos ? s : s.substr(slash + 1);
}

std::string directoryWithSlash(const std::string& s) {
  auto slash = s.find_last_of("/\\");
  return slash == std::string::npos ? std::string() : s.substr(0, slash + 1);
}

// As C's strcmp: the difference of the first differing bytes (0 when equal).
int compareBytes(const std::string& a, const std::string& b) {
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  const int left = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
  const int right = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
  return left - right;
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = from.empty() ? std::string::npos : s.find(from); at != std::string::npos;
       at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

std::string upperCase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string lowerCase(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

using Call = const ast::Expr&;
constexpr std::size_t kAnyCount = ScriptFunction::kAnyCount;

}  // namespace

// The pieces StrCat and Str put together: strings as they are, numbers as %g writes them.
std::vector<std::string> Interpreter::textPieces(const ast::Expr& call) {
  std::vector<std::string> parts;
  for (const auto& arg : call.args) {
    Value v = evaluate(*arg);
    if (v.isText())
      parts.insert(parts.end(), v.strings().begin(), v.strings().end());
    else
      for (double x : v.numbers())
        parts.push_back(formatPrintf("%g", std::vector<FormatArgument>{x}));
  }
  return parts;
}

std::span<const ScriptFunction> Interpreter::stringFunctions() {
  // the string argument i of the call
  static constexpr auto text = [](Interpreter& in, Call call, std::size_t i) {
    return in.evaluateString(*call.args[i]);
  };
  static constexpr ScriptFunction kRows[] = {
      {"StrCat", 0, kAnyCount, "",
       [](Interpreter& in, Call call) {
         std::string joined;
         for (const auto& piece : in.textPieces(call)) joined += piece;
         return Value::string(joined);
       }},
      {"Str", 0, kAnyCount, "",  // a list of strings, unless there is only one
       [](Interpreter& in, Call call) {
         std::vector<std::string> pieces = in.textPieces(call);
         if (pieces.size() != 1) return Value::stringList(std::move(pieces));
         return Value::string(pieces[0]);
       }},
      {"Sprintf", 1, 1000, "",
       [](Interpreter& in, Call call) { return Value::string(in.format(call.args, call.loc)); }},
      {"StrPrefix", 1, 1, "",
       [](Interpreter& in, Call call) {
         return Value::string(withoutExtension(text(in, call, 0)));
       }},
      {"StrRelative", 1, 1, "",
       [](Interpreter& in, Call call) {
         return Value::string(withoutDirectory(text(in, call, 0)));
       }},
      {"DirName", 1, 1, "",
       [](Interpreter& in, Call call) {
         return Value::string(directoryWithSlash(text(in, call, 0)));
       }},
      {"AbsolutePath", 1, 1, "",
       [](Interpreter& in, Call call) {
         std::filesystem::path p = text(in, call, 0);
         std::error_code ignored;
         if (p.is_relative())
           p = std::filesystem::absolute(std::filesystem::path(in.directoryOf(call.loc.file)) / p,
                                         ignored);
         return Value::string(p.lexically_normal().string());
       }},
      {"StrSub", 2, 3, "",  // StrSub(s, from[, count])
       [](Interpreter& in, Call call) {
         const std::string s = text(in, call, 0);
         auto from = clampedInteger<std::size_t>(std::max(0.0, in.evaluateNumber(*call.args[1])));
         std::size_t count = std::string::npos;
         if (call.args.size() > 2)
           count = clampedInteger<std::size_t>(std::max(0.0, in.evaluateNumber(*call.args[2])));
         return Value::string(from < s.size() ? s.substr(from, count) : std::string());
       }},
      {"TextAttributes", 0, kAnyCount, "",  // the style of a view's text: display only
       [](Interpreter& in, Call call) {
         if (call.args.size() % 2 != 0)
           in.fail(call.loc, "TextAttributes takes pairs of texts: \"Font\", \"Helvetica\", ...");
         for (std::size_t i = 0; i < call.args.size(); ++i) text(in, call, i);
         return Value::number(0);
       }},
      {"StrLen", 1, 1, "",
       [](Interpreter& in, Call call) {
         return Value::number(static_cast<double>(text(in, call, 0).size()));
       }},
      {"StrFind", 2, 2, "",
       [](Interpreter& in, Call call) {
         return Value::number(text(in, call, 0).find(text(in, call, 1)) != std::string::npos ? 1
                                                                                            : 0);
       }},
      {"StrCmp", 2, 2, "",
       [](Interpreter& in, Call call) {
         const std::string a = text(in, call, 0), b = text(in, call, 1);
         return Value::number(compareBytes(a, b));
       }},
      {"StrChoice", 3, 3, "",
       [](Interpreter& in, Call call) {
         return Value::string(in.evaluateNumber(*call.args[0]) != 0 ? text(in, call, 1)
                                                                    : text(in, call, 2));
       }},
      {"StrReplace", 3, 3, "",
       [](Interpreter& in, Call call) {
         std::string s = text(in, call, 0), from = text(in, call, 1), to = text(in, call, 2);
         return Value::string(replaceAll(std::move(s), from, to));
       }},
      {"UpperCase", 1, 1, "",
       [](Interpreter& in, Call call) { return Value::string(upperCase(text(in, call, 0))); }},
      {"LowerCaseIn", 1, 1, "",  // lower case but the first character: "ABC" -> "Abc"
       [](Interpreter& in, Call call) {
         std::string s = text(in, call, 0);
         return Value::string(s.empty() ? s : s.front() + lowerCase(s.substr(1)));
       }},
      {"LowerCase", 1, 1, "",
       [](Interpreter& in, Call call) { return Value::string(lowerCase(text(in, call, 0))); }},
      {"GetEnv", 1, 1, "",
       [](Interpreter& in, Call call) {
         const char* value = std::getenv(text(in, call, 0).c_str());
         return Value::string(value ? value : "");
       }},
      {"NameToString", 1, 1, "",
       [](Interpreter& in, Call call) {
         if (call.args[0]->kind != ast::ExprKind::Variable)
           in.fail(call.args[0]->loc, "NameToString takes a variable name");
         return Value::string(in.resolveName(call.args[0]->name));
       }},
  };
  return kRows;
}

}  // namespace geomesh
