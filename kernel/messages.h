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
};

// A sink that drops everything.
class SilentSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view) override {}
};

}  // namespace geomesh
