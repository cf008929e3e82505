// Parsing of geomesh's command line, Gmsh's batch-mode flags included, and the -help text.
#include "app/command_line.h"

#include <charconv>
#include <cmath>
#include <map>
#include <string>

#include "io/formats.h"

#include "mesh/surfaces/surface_algorithms.h"
#include "mesh/volumes/volume_algorithms.h"

namespace geomesh {

namespace {

// Reads the arguments one at a time and reports the flag a missing value belongs to.
class ArgumentReader {
 public:
  explicit ArgumentReader(const std::vector<std::string>& args) : args_(args) {}
  bool done() const { return next_ >= args_.size(); }
  const std::string& take() { return args_[next_++]; }
  const std::string& value(const std::string& flag) {
    if (done()) throw CommandLineError("option '" + flag + "' needs a value");
    return take();
  }
  double number(const std::string& flag) {
    const std::string& text = value(flag);
    double v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
      throw CommandLineError("option '" + flag + "' needs a number, got '" + text + "'");
    return v;
  }

 private:
  const std::vector<std::string>& args_;
  std::size_t next_ = 0;
};

// Flags that set one numeric option.
const std::map<std::string, std::string>& numberOptionFlags() {
  static const std::map<std::string, std::string> flags = {
      {"-clmin", "Mesh.MeshSizeMin"},      {"-clmax", "Mesh.MeshSizeMax"},
      {"-clscale", "Mesh.MeshSizeFactor"}, {"-nt", "General.NumThreads"},
      {"-order", "Mesh.ElementOrder"},     {"-smooth", "Mesh.Smoothing"},
      {"-rand", "Mesh.RandomFactor"},      {"-part", "Mesh.NbPartitions"},
  };
  return flags;
}

// -algo names, as Gmsh spells them, found in the 2D and 3D algorithm registries.
bool applyAlgorithm(const std::string& name, CommandLine& cl) {
  if (const SurfaceAlgorithm* row = findSurfaceAlgorithm(name)) {
    cl.numberOptions.emplace_back("Mesh.Algorithm", row->code);
    return true;
  }
  if (const VolumeAlgorithm* row = findVolumeAlgorithm(name)) {
    cl.numberOptions.emplace_back("Mesh.Algorithm3D", row->code);
    return true;
  }
  return false;
}

bool parseFlag(const std::string& flag, ArgumentReader& in, CommandLine& cl) {
  if (flag.size() == 2 && flag[1] >= '0' && flag[1] <= '3') {
    cl.dimension = flag[1] - '0';
  } else if (flag == "-o") {
    cl.output = in.value(flag);
  } else if (flag == "-format" || flag == "-f") {
    cl.format = in.value(flag);
  } else if (flag == "-bin") {
    cl.binary = true;
  } else if (flag == "-save_all" || flag == "-saveall") {
    cl.saveAll = true;
  } else if (flag == "-part_split") {
    cl.numberOptions.emplace_back("Mesh.PartitionSplitMeshFiles", 1);
  } else if (flag == "-part_ghosts") {
    cl.numberOptions.emplace_back("Mesh.PartitionCreateGhostCells", 1);
  } else if (flag == "-check") {
    cl.check = true;
  } else if (flag == "-allow_system_calls") {
    cl.allowSystemCalls = true;
  } else if (flag == "-keep_partial") {
    cl.keepPartial = true;
  } else if (flag == "-view") {
    cl.view = true;
  } else if (flag == "-v") {
    cl.verbosity = static_cast<int>(in.number(flag));
  } else if (flag == "-setnumber") {
    const std::string name = in.value(flag);
    cl.setNumbers.emplace_back(name, in.number(flag));
  } else if (flag == "-setstring") {
    const std::string name = in.value(flag);
    cl.setStrings.emplace_back(name, in.value(flag));
  } else if (flag == "-algo") {
    const std::string name = in.value(flag);
    if (!applyAlgorithm(name, cl))
      throw CommandLineError("unknown algorithm '" + name + "' for -algo");
  } else if (flag == "-help" || flag == "-h" || flag == "--help") {
    cl.help = true;
  } else if (flag == "-version" || flag == "--version") {
    cl.version = true;
  } else if (flag == "-help-options" || flag == "-help_options") {
    cl.helpOptions = true;
  } else if (auto it = numberOptionFlags().find(flag); it != numberOptionFlags().end()) {
    cl.numberOptions.emplace_back(it->second, in.number(flag));
  } else {
    return false;
  }
  return true;
}

}  // namespace

CommandLine parseCommandLine(const std::vector<std::string>& args) {
  CommandLine cl;
  ArgumentReader in(args);
  if (!args.empty() && args.front() == "view") {
    in.take();
    cl.viewCommand = cl.view = true;
  }
  while (!in.done()) {
    const std::string& arg = in.take();
    if (arg.size() > 1 && arg[0] == '-') {
      if (!parseFlag(arg, in, cl))
        throw CommandLineError("unknown option '" + arg + "' (see -help)");
    } else {
      cl.files.push_back(arg);
    }
  }
  if (cl.saveAll) cl.numberOptions.emplace_back("Mesh.SaveAll", 1);
  if (cl.binary) cl.numberOptions.emplace_back("Mesh.Binary", 1);
  return cl;
}

std::string commandLineHelp() {
  return R"(Usage: geomesh [options] file.geo
       geomesh view [-o page.html] mesh.msh

Meshes a .geo script in batch mode and writes the mesh (MSH 4.1 by default). `geomesh view`
writes a mesh file (any format read) as a self-contained HTML page beside it, and opens it.

Mesh:
  -0, -1, -2, -3         stop after evaluating the geometry (-0), or mesh up to dimension 1, 2, 3
  -o FILE                output file (default: the script's name with .msh)
)" + std::string("  -format FORMAT         output format: ") +
         formatNameGroups() + R"(
  -bin                   binary output
  -save_all              save every element, not only those of physical groups
  -algo NAME             2D/3D algorithm: meshadapt, del2d, front2d, del3d, ...
  -clmin VALUE           minimum mesh size (Mesh.MeshSizeMin)
  -clmax VALUE           maximum mesh size (Mesh.MeshSizeMax)
  -clscale VALUE         mesh size factor (Mesh.MeshSizeFactor)
  -order N               element order (Mesh.ElementOrder)
  -smooth N              smoothing passes (Mesh.Smoothing)
  -rand VALUE            random perturbation factor (Mesh.RandomFactor)
  -part N                split the mesh into N partitions with METIS (Mesh.NbPartitions)
  -part_split            write each partition to its own file (name_1.msh, name_2.msh, ...)
  -check                 check a mesh file (.msh) and report problems; for any input, the
                         topology of each connected surface (genus, holes, defects)
  -keep_partial          when meshing fails, still write what was meshed
  -view                  also write the mesh as an HTML page (NAME.html) and open it in a
                         browser when there is a display
Script:
  -setnumber NAME VALUE  set a numeric parameter (overrides DefineConstant/DefineNumber)
  -setstring NAME VALUE  set a string parameter (overrides DefineString)
  -allow_system_calls    let the script run shell commands (SystemCall); refused otherwise
General:
  -nt N                  number of threads (General.NumThreads)
  -v N                   verbosity: 0 silent, 1 errors, 2 warnings, 4 information, 5 default, 99 debug
  -help-options          list every option with its default and help
  -version               print the version
  -help                  this help
)";
}

}  // namespace geomesh
