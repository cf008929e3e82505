// The .geo lexer. re2c turns this file into generated/grammar/lexer.cpp at build time.
#include "grammar/tokenizer.h"
#include "grammar/keywords.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <span>
#include <string_view>

namespace geomesh {
namespace {

using Token = Parser::token;

bool contains(std::span<const std::string_view> table, std::string_view word) {
  return std::find(table.begin(), table.end(), word) != table.end();
}

}  // namespace

Lexer::Lexer(std::string fileName, std::string_view text)
    : fileName_(std::move(fileName)), text_(text) {
  cursor_ = text_.c_str();
  limit_ = cursor_ + text_.size();
  lineStart_ = cursor_;
  currentLocation_.initialize(&fileName_);
  previousLocation_.initialize(&fileName_);
}

Parser::location_type Lexer::tokenLocation() const {
  Parser::location_type where;
  where.begin.filename = where.end.filename = &fileName_;
  where.begin.line = line_;
  where.begin.column = static_cast<int>(token_ - lineStart_) + 1;
  where.end.line = line_;
  where.end.column = static_cast<int>(cursor_ - lineStart_) + 1;
  return where;
}

void Lexer::fail(const Parser::location_type& where, const std::string& message) const {
  throw SyntaxError(SourceLocation{fileName_, where.begin.line, where.begin.column}, message);
}

void Lexer::countLines(const char* from, const char* to) {
  for (const char* p = from; p < to; ++p) {
    if (*p == '\n') {
      ++line_;
      lineStart_ = p + 1;
    }
  }
}

// "Using Wire" is read as one token: Extrude{..} Using Wire{..} needs no semicolon after it.
bool Lexer::followedByWord(std::string_view word) {
  const char* p = cursor_;
  while (p < limit_ && (*p == ' ' || *p == '\t')) ++p;
  const auto rest = static_cast<std::size_t>(limit_ - p);
  if (rest < word.size() || std::string_view(p, word.size()) != word) return false;
  const char* end = p + word.size();
  if (end < limit_ && (std::isalnum(static_cast<unsigned char>(*end)) || *end == '_')) return false;
  cursor_ = end;
  return true;
}

bool Lexer::nextNonSpaceIs(char c) const {
  const char* p = cursor_;
  while (p < limit_ && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')) ++p;
  return p < limit_ && *p == c;
}

Parser::symbol_type Lexer::next() {
  Parser::symbol_type symbol = scan();
  previousText_ = std::move(currentText_);
  previousLocation_ = currentLocation_;
  currentText_ = symbol.kind() == Parser::symbol_kind::S_YYEOF
                     ? std::string("end of file")
                     : std::string(token_, cursor_);
  currentLocation_ = symbol.location;
  return symbol;
}

Parser::symbol_type Lexer::word(std::string text, const Parser::location_type& where) {
  if (afterDot_) {
    afterDot_ = false;
    return Parser::make_IDENT(std::move(text), where);
  }
  // Inside DefineConstant[...], attribute names win over keywords (Macro "Gmsh", ...).
  if (defineDepth_ > 0 && contains(attributeNames(), text) && !nextNonSpaceIs('('))
    return Parser::make_ATTR(std::move(text), where);
  if (text == "For") return opening(Parser::make_FOR(where), text);
  if (text == "EndFor") return closing(Parser::make_ENDFOR(where));
  if (text == "In") return Parser::make_IN(where);
  if (text == "If") return opening(Parser::make_IF(where), text);
  if (text == "ElseIf") return Parser::make_ELSEIF(where);
  if (text == "Else") return Parser::make_ELSE(where);
  if (text == "EndIf") return closing(Parser::make_ENDIF(where));
  if (text == "Macro" || text == "Function") return opening(Parser::make_MACRO(where), text);
  if (text == "Return") return closing(Parser::make_RETURN(where));
  if (text == "Call") return Parser::make_CALL(where);
  if (text == "Plugin") return Parser::make_PLUGIN(where);
  if (text == "Struct") return Parser::make_STRUCT(where);
  // Their own tokens: two shapes follow each (Split Curve{1} Point{2}).
  if (text == "Split") return Parser::make_SPLIT(where);
  if (text == "Intersect") return Parser::make_INTERSECT(where);
  if (text == "DefineConstant" || text == "DefineNumber" || text == "DefineString") {
    defineAhead_ = true;
    if (text == "DefineConstant") return Parser::make_DEFINECONSTANT(where);
    if (text == "DefineNumber") return Parser::make_DEFINENUMBER(where);
    return Parser::make_DEFINESTRING(where);
  }
  // Circle(1) = {2, 1, 3} Plane{0, 0, 1}: there Plane only follows a definition.
  if (text == "Plane" && nextNonSpaceIs('{')) return Parser::make_TAILWORD(std::move(text), where);
  if (contains(commandWords(), text)) return Parser::make_WORD(std::move(text), where);
  if (text == "Using" && followedByWord("Wire")) return Parser::make_USINGWIRE(where);
  if (contains(tailWords(), text)) return Parser::make_TAILWORD(std::move(text), where);
  return Parser::make_IDENT(std::move(text), where);
}

Parser::symbol_type Lexer::number(const Parser::location_type& where) {
  std::string digits(token_, cursor_);
  std::replace_if(digits.begin(), digits.end(), [](char c) { return c == 'd' || c == 'D'; },
                  'e');
  double value = 0;
  auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range)
    fail(where, "number '" + digits + "' is out of range");
  if (error != std::errc() || end != digits.data() + digits.size())
    fail(where, "malformed number '" + digits + "'");
  return Parser::make_NUMBER(value, where);
}

// A string literal keeps its characters as written, except that \" (or \' in a string
// between single quotes) stands for the quote.
Parser::symbol_type Lexer::quoted(const Parser::location_type& where) {
  std::string value;
  const char quote = *token_;
  for (const char* p = token_ + 1; p < cursor_ - 1; ++p) {
    if (*p == '\\' && p + 1 < cursor_ - 1 && p[1] == quote) ++p;
    value += *p;
  }
  countLines(token_, cursor_);
  return Parser::make_STRING(std::move(value), where);
}

// Parsing, evaluating and destroying the syntax tree recurse once per level of nesting: a
// bound keeps hostile inputs from exhausting the stack.
constexpr int kMaxNesting = 256;

Parser::symbol_type Lexer::opening(Parser::symbol_type symbol, std::string text) {
  if (open_.size() >= kMaxNesting)
    fail(symbol.location, "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
  open_.push_back({std::move(text), symbol.location});
  return symbol;
}

Parser::symbol_type Lexer::closing(Parser::symbol_type symbol) {
  if (!open_.empty()) open_.pop_back();
  return symbol;
}

Parser::symbol_type Lexer::punctuation(int token, const Parser::location_type& where) {
  afterDot_ = token == '.';
  if (token == '[') {
    if (defineAhead_ || defineDepth_ > 0) ++defineDepth_;
  } else if (token == ']' && defineDepth_ > 0) {
    --defineDepth_;
  }
  defineAhead_ = false;
  if (token == '(' || token == '[' || token == '{')
    return opening(Parser::symbol_type(token, where), std::string(1, static_cast<char>(token)));
  if (token == ')' || token == ']' || token == '}')
    return closing(Parser::symbol_type(token, where));
  return Parser::symbol_type(token, where);
}

void Lexer::skipBlockComment(const Parser::location_type& where) {
  std::string_view rest(cursor_, static_cast<std::size_t>(limit_ - cursor_));
  auto close = rest.find("*/");
  if (close == std::string_view::npos) fail(where, "unterminated block comment");
  const char* end = cursor_ + close + 2;
  countLines(cursor_, end);
  cursor_ = end;
}

Parser::symbol_type Lexer::scan() {
  for (;;) {
    token_ = cursor_;
    const char* marker = nullptr;
    /*!re2c
      re2c:api:style = free-form;
      re2c:define:YYCTYPE = char;
      re2c:define:YYCURSOR = cursor_;
      re2c:define:YYMARKER = marker;
      re2c:yyfill:enable = 0;

      digit = [0-9];
      exponent = [eEdD] [+-]? digit+;
      number = digit+ exponent? | digit+ "." digit* exponent? | "." digit+ exponent?;
      ident = [a-zA-Z_] [a-zA-Z0-9_]*;
      string = ["] ([^"\\\x00] | "\\" [^\x00])* ["];
      sstring = ['] ([^'\\\x00] | "\\" [^\x00])* ['];

      "\x00" {
        if (cursor_ - 1 < limit_) fail(tokenLocation(), "unexpected NUL character");
        cursor_ = limit_;
        return Parser::make_YYEOF(tokenLocation());
      }
      [ \t\r\f\v]+ { continue; }
      "\n" { countLines(token_, cursor_); continue; }
      "//" [^\n\x00]* { continue; }
      "/*" { skipBlockComment(tokenLocation()); continue; }
      number { afterDot_ = false; defineAhead_ = false; return number(tokenLocation()); }
      ident { auto where = tokenLocation(); return word(std::string(token_, cursor_), where); }
      string { afterDot_ = false; return quoted(tokenLocation()); }
      sstring { afterDot_ = false; return quoted(tokenLocation()); }  // 'text' as "text"
      ["'] { fail(tokenLocation(), "unterminated string"); }
      "==" { return Parser::make_EQ(tokenLocation()); }
      "!=" { return Parser::make_NE(tokenLocation()); }
      "<=" { return Parser::make_LE(tokenLocation()); }
      ">=" { return Parser::make_GE(tokenLocation()); }
      "&&" { return Parser::make_AND(tokenLocation()); }
      "||" { return Parser::make_OR(tokenLocation()); }
      "++" { return Parser::make_INCR(tokenLocation()); }
      "--" { return Parser::make_DECR(tokenLocation()); }
      "+=" { return Parser::make_PLUSEQ(tokenLocation()); }
      "-=" { return Parser::make_MINUSEQ(tokenLocation()); }
      "*=" { return Parser::make_TIMESEQ(tokenLocation()); }
      "/=" { return Parser::make_DIVEQ(tokenLocation()); }
      ">>" { return Parser::make_APPEND(tokenLocation()); }
      "::" { return Parser::make_SCOPE(tokenLocation()); }
      "..." { return Parser::make_DOTS(tokenLocation()); }
      [-+*/%^()[\]{},;=<>!?:.#~] {
        return punctuation(static_cast<unsigned char>(*token_), tokenLocation());
      }
      * { fail(tokenLocation(), std::string("unexpected character '") + *token_ + "'"); }
    */
  }
}

}  // namespace geomesh
