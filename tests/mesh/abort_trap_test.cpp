// Tests of runTrappingAbort: an abort inside the call becomes a result, the process goes on.
#include "mesh/volumes/abort_trap.h"

#include <gtest/gtest.h>

#include <cassert>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <stdexcept>

#include <sys/stat.h>
#include <unistd.h>

namespace geomesh {
namespace {

TEST(AbortTrap, AbortBecomesFalseAndTheProcessGoesOn) {
  int reached = 0;
  EXPECT_FALSE(runTrappingAbort([&] {
    ++reached;
    std::abort();
  }));
  EXPECT_EQ(reached, 1);
  EXPECT_FALSE(runTrappingAbort([] { std::abort(); }));  // trapped again
}

TEST(AbortTrap, CallThatReturnsIsTrue) {
  int calls = 0;
  EXPECT_TRUE(runTrappingAbort([&] { ++calls; }));
  EXPECT_EQ(calls, 1);
}

TEST(AbortTrap, ExceptionsPassThroughAndTheHandlerIsRestored) {
  EXPECT_THROW(runTrappingAbort([] { throw std::runtime_error("x"); }), std::runtime_error);
  struct sigaction now {};
  sigaction(SIGABRT, nullptr, &now);
  EXPECT_EQ(now.sa_handler, SIG_DFL);
}

TEST(AbortTrap, StandardErrorIsSilencedDuringTheCallOnly) {
  struct stat before {}, during {}, after {};
  ASSERT_EQ(fstat(STDERR_FILENO, &before), 0);
  EXPECT_FALSE(runTrappingAbort([&] {
    std::fprintf(stderr, "this assertion message is discarded\n");
    fstat(STDERR_FILENO, &during);
    std::abort();
  }));
  ASSERT_EQ(fstat(STDERR_FILENO, &after), 0);
  EXPECT_TRUE(S_ISCHR(during.st_mode));  // /dev/null
  EXPECT_EQ(after.st_dev, before.st_dev);
  EXPECT_EQ(after.st_ino, before.st_ino);
}

}  // namespace
}  // namespace geomesh
