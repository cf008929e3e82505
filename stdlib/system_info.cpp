// Process and total memory from /proc, and the running executable's path.
#include "stdlib/system_info.h"

#include <filesystem>
#include <fstream>
#include <string>

namespace geomesh {

namespace {

// Reads "Key:   1234 kB" from a /proc file; the value in megabytes.
double kilobyteField(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string word;
  while (in >> word) {
    if (word == key) {
      double kilobytes = 0;
      in >> kilobytes;
      return kilobytes / 1024.0;
    }
  }
  return 0;
}

}  // namespace

double processMemoryMegabytes() { return kilobyteField("/proc/self/status", "VmRSS:"); }

double totalMemoryMegabytes() { return kilobyteField("/proc/meminfo", "MemTotal:"); }

std::string executablePath() {
  std::error_code error;
  std::filesystem::path path = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::string() : path.string();
}

}  // namespace geomesh
