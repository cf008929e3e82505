// Reading of golden .expected files and the checks of a figure against its expectation.
#include "golden_expectation.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace geomesh::golden {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

double toNumber(const std::string& text, int line) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || trim(text.substr(used)) != "")
    throw std::runtime_error("line " + std::to_string(line) + ": not a number: '" + text + "'");
  return v;
}

Expectation parseFigure(const std::string& key, const std::string& value, int line) {
  Expectation e;
  e.key = key;
  e.line = line;
  if (value.rfind(">=", 0) == 0) {
    e.kind = Expectation::Kind::AtLeast;
    e.low = toNumber(trim(value.substr(2)), line);
  } else if (value.rfind("<=", 0) == 0) {
    e.kind = Expectation::Kind::AtMost;
    e.high = toNumber(trim(value.substr(2)), line);
  } else if (auto pm = value.find("+-"); pm != std::string::npos) {
    e.kind = Expectation::Kind::Tolerance;
    const double center = toNumber(trim(value.substr(0, pm)), line);
    std::string tol = trim(value.substr(pm + 2));
    double t = 0;
    if (!tol.empty() && tol.back() == '%') {
      t = std::abs(center) * toNumber(tol.substr(0, tol.size() - 1), line) / 100;
    } else {
      t = toNumber(tol, line);
    }
    e.low = center - t;
    e.high = center + t;
  } else if (auto dots = value.find(".."); dots != std::string::npos) {
    e.kind = Expectation::Kind::Range;
    e.low = toNumber(trim(value.substr(0, dots)), line);
    e.high = toNumber(trim(value.substr(dots + 2)), line);
  } else {
    e.kind = Expectation::Kind::Exact;
    e.low = e.high = toNumber(value, line);
  }
  return e;
}

std::vector<std::string> splitWords(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

}  // namespace

GoldenCase readExpectations(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  GoldenCase c;
  int lineNumber = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++lineNumber;
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos)
      throw std::runtime_error(path + ":" + std::to_string(lineNumber) + ": expected 'key: value'");
    const std::string key = trim(line.substr(0, colon));
    const std::string value = trim(line.substr(colon + 1));
    if (key == "args") {
      c.args = splitWords(value);
    } else if (key == "exit") {
      c.exitStatus = static_cast<int>(toNumber(value, lineNumber));
    } else if (key == "physical") {
      c.physicals.push_back(value);
    } else if (key == "stdout") {
      c.stdoutLines.push_back(value);
    } else if (key == "stderr") {
      c.stderrFragments.push_back(value);
    } else {
      c.figures.push_back(parseFigure(key, value, lineNumber));
    }
  }
  return c;
}

bool satisfies(const Expectation& e, double value, std::string& why) {
  std::ostringstream os;
  os.precision(12);
  bool ok = true;
  switch (e.kind) {
    case Expectation::Kind::AtLeast:
      ok = value >= e.low;
      os << "expected >= " << e.low;
      break;
    case Expectation::Kind::AtMost:
      ok = value <= e.high;
      os << "expected <= " << e.high;
      break;
    case Expectation::Kind::Exact:
      ok = value == e.low;
      os << "expected exactly " << e.low;
      break;
    default:
      ok = value >= e.low && value <= e.high;
      os << "expected within [" << e.low << ", " << e.high << "]";
      break;
  }
  os << ", got " << value;
  why = os.str();
  return ok;
}

}  // namespace geomesh::golden
