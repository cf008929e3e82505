// ConsoleLog: the command's message sink, with Gmsh's verbosity levels 0 to 99.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>

#include "kernel/messages.h"

namespace geomesh {

// Writes log lines to a stream (standard error in the command) at Gmsh's verbosity levels:
// 0 silent, 1 errors, 2 + warnings, 3 + direct, 4 + information, 5 + status (default),
// 99 debug. On a terminal, a long stage (one that has run half a second) shows a progress bar
// with the time left on one line that the next log line replaces.
class ConsoleLog final : public MessageSink {
 public:
  // Seconds from any fixed moment (a steady clock unless a test gives its own).
  using Clock = std::function<double()>;

  ConsoleLog(std::ostream& err, int verbosity) : err_(err), verbosity_(verbosity) {}
  void info(std::string_view message) override;
  void warning(std::string_view message) override;
  void debug(std::string_view message) override;
  void progress(std::string_view stage, double fraction) override;
  // Whether `err` is a terminal, where progress bars are drawn (at verbosity 5 and above).
  void setTerminal(bool terminal, Clock clock = {});
  void error(std::string_view message);
  // Writes an already formatted multi-line diagnostic (file:line:col: error: ...).
  void diagnostic(std::string_view text);
  int warnings() const { return warnings_; }
  void setVerbosity(int v) { verbosity_ = v; }

 private:
  void write(std::string_view prefix, std::string_view message);
  void clearBar();
  std::ostream& err_;
  int verbosity_;
  int warnings_ = 0;
  bool terminal_ = false;
  Clock clock_;
  std::string barStage_;  // the stage whose progress is being followed, or empty
  double barStart_ = 0, lastDraw_ = 0;
  bool barShown_ = false;
};

}  // namespace geomesh
