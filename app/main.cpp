// The geomesh executable: hands its arguments and standard streams to runGeomesh.
#include <iostream>
#include <string>
#include <vector>

#include "app/run.h"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  return geomesh::runGeomesh(args, std::cout, std::cerr);
}
