// ScratchFiles: a test fixture writing files into a directory of its own, removed afterwards.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/scratch.h"

namespace geomesh {

class ScratchFiles : public ::testing::Test {
 protected:
  explicit ScratchFiles(const std::string& name) : dir_(scratch::path(name)) {}
  void SetUp() override { std::filesystem::create_directories(dir_); }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // Writes `content` to `name` in the directory; returns its path.
  std::string file(const std::string& name, const std::string& content) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }

  std::filesystem::path dir_;
};

}  // namespace geomesh
