// CommandLine: the geomesh command's arguments as Gmsh's batch mode spells them.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace geomesh {

// The command line, spelled as Gmsh's batch mode spells it.
struct CommandLine {
  std::vector<std::string> files;
  std::optional<int> dimension;  // -0 -1 -2 -3
  std::string output;            // -o
  std::string format;            // -format: a name of the format table (io/formats.h)
  bool binary = false;           // -bin
  bool saveAll = false;          // -save_all
  bool check = false;            // -check
  bool allowSystemCalls = false;  // -allow_system_calls: scripts may run shell commands
  bool keepPartial = false;      // -keep_partial: write what was meshed when meshing fails
  bool viewCommand = false;      // `geomesh view FILE`: FILE is a mesh to show (-o: the page)
  bool view = false;             // -view: also write the mesh as an HTML page, and open it
  bool help = false;             // -help, -h
  bool version = false;          // -version
  bool helpOptions = false;      // -help-options
  int verbosity = 5;             // -v
  // Options in the order given: name, value, applied before and after the script so that
  // the command line wins over the script, as in Gmsh.
  std::vector<std::pair<std::string, double>> numberOptions;
  // -setnumber / -setstring: parameter overrides.
  std::vector<std::pair<std::string, double>> setNumbers;
  std::vector<std::pair<std::string, std::string>> setStrings;
};

// A command line that cannot be understood; the message names the offending argument.
class CommandLineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

CommandLine parseCommandLine(const std::vector<std::string>& args);
std::string commandLineHelp();

}  // namespace geomesh
