// The geomesh executable: hands its arguments and standard streams to runGeomesh.
#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "app/run.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const char* term = std::getenv("TERM");
  const bool terminal = isatty(STDERR_FILENO) && term && std::string_view(term) != "dumb";
  return geomesh::runGeomesh(args, std::cout, std::cerr, terminal);
}
