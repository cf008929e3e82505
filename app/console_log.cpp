// ConsoleLog: prefixed log lines and diagnostics on standard error, filtered by verbosity.
#include "app/console_log.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ostream>

namespace geomesh {

namespace {

constexpr double kBarDelay = 0.5;      // seconds a stage runs before its bar appears
constexpr double kBarInterval = 0.1;   // seconds between redraws
constexpr int kBarWidth = 30;

// "about 42 s left", "about 3 min 05 s left", "under a second left".
std::string timeLeft(double seconds) {
  if (seconds < 0.5) return "under a second left";
  char text[48];
  if (seconds < 60)
    std::snprintf(text, sizeof text, "about %.0f s left", seconds);
  else
    std::snprintf(text, sizeof text, "about %d min %02d s left", static_cast<int>(seconds / 60),
                  static_cast<int>(seconds) % 60);
  return text;
}

}  // namespace

void ConsoleLog::setTerminal(bool terminal, Clock clock) {
  terminal_ = terminal;
  clock_ = clock ? std::move(clock) : Clock([] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  });
}

void ConsoleLog::clearBar() {
  if (!barShown_) return;
  err_ << "\r\x1b[K";
  err_.flush();
  barShown_ = false;
}

void ConsoleLog::progress(std::string_view stage, double fraction) {
  if (!terminal_ || verbosity_ < 5) return;
  const double now = clock_();
  if (stage != barStage_) {
    clearBar();
    barStage_ = stage;
    barStart_ = now;
    lastDraw_ = now - kBarInterval;
  }
  if (fraction >= 1) {
    clearBar();
    barStage_.clear();
    return;
  }
  if (now - barStart_ < kBarDelay || now - lastDraw_ < kBarInterval) return;
  lastDraw_ = now;
  fraction = std::clamp(fraction, 0.0, 1.0);
  const int filled = static_cast<int>(fraction * kBarWidth);
  std::string line = "\r\x1b[K" + barStage_ + " [" + std::string(filled, '#') +
                     std::string(kBarWidth - filled, '.') + "] ";
  char percent[16];
  std::snprintf(percent, sizeof percent, "%3d%%", static_cast<int>(fraction * 100));
  line += percent;
  // The time left, once enough is done for the rate to mean something.
  if (fraction >= 0.02)
    line += ", " + timeLeft((now - barStart_) * (1 - fraction) / fraction);
  err_ << line;
  err_.flush();
  barShown_ = true;
}

void ConsoleLog::write(std::string_view prefix, std::string_view message) {
  clearBar();
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
  clearBar();
  err_ << text;
  if (!text.empty() && text.back() != '\n') err_ << '\n';
  err_.flush();
}

}  // namespace geomesh
