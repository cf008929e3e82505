// ScratchDirTest: a test whose scripts run in a directory of their own, made empty for it.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "script_runner.h"
#include "tests/scratch.h"

namespace geomesh::testing {

// The directory is named after `prefix` and the test, and removed after the test.
class ScratchDirTest : public ::testing::Test {
 protected:
  explicit ScratchDirTest(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    dir_ = scratch::path(prefix_ +
                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Runs `text` as the script main.geo of the directory.
  std::string runMain(ScriptRun& run, const std::string& text) {
    return run.run(text, (dir_ / "main.geo").string());
  }

  std::filesystem::path dir_;

 private:
  std::string prefix_;
};

}  // namespace geomesh::testing
