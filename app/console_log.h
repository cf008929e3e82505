// ConsoleLog: the command's message sink, with Gmsh's verbosity levels 0 to 99.
#pragma once

#include <iosfwd>
#include <string_view>

#include "kernel/messages.h"

namespace geomesh {

// Writes log lines to a stream (standard error in the command) at Gmsh's verbosity levels:
// 0 silent, 1 errors, 2 + warnings, 3 + direct, 4 + information, 5 + status (default),
// 99 debug.
class ConsoleLog final : public MessageSink {
 public:
  ConsoleLog(std::ostream& err, int verbosity) : err_(err), verbosity_(verbosity) {}
  void info(std::string_view message) override;
  void warning(std::string_view message) override;
  void debug(std::string_view message) override;
  void error(std::string_view message);
  // Writes an already formatted multi-line diagnostic (file:line:col: error: ...).
  void diagnostic(std::string_view text);
  int warnings() const { return warnings_; }
  void setVerbosity(int v) { verbosity_ = v; }

 private:
  void write(std::string_view prefix, std::string_view message);
  std::ostream& err_;
  int verbosity_;
  int warnings_ = 0;
};

}  // namespace geomesh
