// CommandTest: runs the geomesh command in a scratch directory of its own per test, keeping what
// it printed.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/run.h"
#include "tests/scratch.h"

namespace geomesh {

class CommandTest : public testing::Test {
 protected:
  // `prefix` names the scratch directories of the fixture's tests, one per test.
  explicit CommandTest(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    dir_ = scratch::path(prefix_ +
                         std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& text) {
    std::filesystem::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }
  int run(std::vector<std::string> args) {
    out_.str("");
    err_.str("");
    return runGeomesh(args, out_, err_);
  }

  std::string prefix_;
  std::filesystem::path dir_;
  std::ostringstream out_, err_;
};

}  // namespace geomesh
