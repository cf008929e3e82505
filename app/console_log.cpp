// ConsoleLog: prefixed log lines and diagnostics on standard error, filtered by verbosity.
#include "app/console_log.h"

#include <ostream>

namespace geomesh {

void ConsoleLog::write(std::string_view prefix, std::string_view message) {
  err_ << prefix << message << '\n';
  err_.flush();
}

void ConsoleLog::info(std::string_view message) {
  if (verbosity_ >= 4) write("Info    : ", message);
}

void ConsoleLog::warning(std::string_view message) {
  ++warnings_;
  if (verbosity_ < 2) return;
  // A warning about a script statement already reads "file:line:col: warning: ...".
  const bool located = message.find(": warning: ") != std::string_view::npos;
  write(located ? "" : "Warning : ", message);
}

void ConsoleLog::debug(std::string_view message) {
  if (verbosity_ >= 99) write("Debug   : ", message);
}

void ConsoleLog::error(std::string_view message) {
  if (verbosity_ >= 1) write("Error   : ", message);
}

void ConsoleLog::diagnostic(std::string_view text) {
  if (verbosity_ < 1) return;
  err_ << text;
  if (!text.empty() && text.back() != '\n') err_ << '\n';
  err_.flush();
}

}  // namespace geomesh
