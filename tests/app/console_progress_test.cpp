// The progress bar of long stages: drawn on a terminal only, after half a second, with the
// time left, and replaced by the next log line.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "app/console_log.h"

namespace geomesh {
namespace {

struct ProgressFixture : ::testing::Test {
  std::ostringstream err;
  double now = 0;
  ConsoleLog log{err, 5};
  void SetUp() override {
    log.setTerminal(true, [this] { return now; });
  }
};

TEST_F(ProgressFixture, ShortStagesDrawNothing) {
  log.progress("Meshing 3D", 0.0);
  now = 0.3;
  log.progress("Meshing 3D", 0.9);
  log.progress("Meshing 3D", 1.0);
  EXPECT_EQ(err.str(), "");
}

TEST_F(ProgressFixture, LongStagesDrawABarWithTheTimeLeft) {
  log.progress("Meshing 3D", 0.0);
  now = 2.0;
  log.progress("Meshing 3D", 0.25);
  const std::string bar = err.str();
  EXPECT_NE(bar.find("\r\x1b[KMeshing 3D [#######......................."), std::string::npos)
      << bar;
  EXPECT_NE(bar.find(" 25%"), std::string::npos) << bar;
  // 2 s for a quarter: 6 s for the rest.
  EXPECT_NE(bar.find("about 6 s left"), std::string::npos) << bar;
  EXPECT_EQ(bar.find('\n'), std::string::npos);
}

TEST_F(ProgressFixture, RedrawsAreThrottled) {
  log.progress("Meshing 2D", 0.0);
  now = 1.0;
  log.progress("Meshing 2D", 0.5);
  const std::size_t once = err.str().size();
  now = 1.05;
  log.progress("Meshing 2D", 0.6);
  EXPECT_EQ(err.str().size(), once);
  now = 1.2;
  log.progress("Meshing 2D", 0.7);
  EXPECT_GT(err.str().size(), once);
}

TEST_F(ProgressFixture, TheNextLineReplacesTheBar) {
  log.progress("Meshing 3D", 0.0);
  now = 1.0;
  log.progress("Meshing 3D", 0.5);
  log.progress("Meshing 3D", 1.0);
  log.info("Meshing 3D... done");
  const std::string text = err.str();
  EXPECT_EQ(text.substr(text.rfind('\r')), "\r\x1b[KInfo    : Meshing 3D... done\n");
}

TEST_F(ProgressFixture, WarningsInTheMiddleClearTheBarFirst) {
  log.progress("Meshing 3D", 0.0);
  now = 1.0;
  log.progress("Meshing 3D", 0.5);
  log.warning("something");
  const std::string text = err.str();
  EXPECT_NE(text.find("\r\x1b[KWarning : something\n"), std::string::npos) << text;
}

TEST(ConsoleProgress, NoBarOffATerminalOrBelowVerbosity5) {
  std::ostringstream file;
  ConsoleLog plain(file, 5);
  plain.progress("Meshing 3D", 0.0);
  plain.progress("Meshing 3D", 0.5);
  EXPECT_EQ(file.str(), "");

  std::ostringstream quiet;
  double now = 0;
  ConsoleLog low(quiet, 4);
  low.setTerminal(true, [&now] { return now; });
  low.progress("Meshing 3D", 0.0);
  now = 5;
  low.progress("Meshing 3D", 0.5);
  EXPECT_EQ(quiet.str(), "");
}

}  // namespace
}  // namespace geomesh
