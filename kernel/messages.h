// MessageSink: where the library reports progress and warnings; SilentSink drops them.
#pragma once

#include <string_view>

namespace geomesh {

// Where the library reports progress and warnings. The session implements it (writing to
// standard error at the chosen verbosity); tests may collect the messages instead.
class MessageSink {
 public:
  virtual ~MessageSink() = default;
  virtual void info(std::string_view message) = 0;
  virtual void warning(std::string_view message) = 0;
  // Extra detail shown only at high verbosity.
  virtual void debug(std::string_view) {}
  // How far a long stage ("Meshing 3D") has come, from 0 to 1; 1 ends it. Called from one
  // thread at a time, often: a sink that shows it decides how often to redraw.
  virtual void progress(std::string_view /*stage*/, double /*fraction*/) {}
};

// A sink that drops everything.
class SilentSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view) override {}
};

}  // namespace geomesh
