// The geomesh command: evaluates scripts or reads .msh files, meshes, and writes the output.
#include "app/run.h"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "api/meshing.h"
#include "api/options.h"
#include "api/output.h"
#include "api/partitioning.h"
#include "api/session.h"
#include "app/command_line.h"
#include "app/console_log.h"
#include "app/mesh_page_view.h"
#include "app/mesh_summary.h"
#include "app/script_run.h"
#include "app/surface_check.h"
#include "interpreter/diagnostics.h"
#include "io/formats.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/core/mesh_error.h"
#include "mesh/discrete/mesh_triangles.h"
#include "stdlib/clamped_integer.h"

namespace geomesh {

namespace {

constexpr const char* kVersion = "0.1.0";

// Wall time of a stage, in seconds.
class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Every option with its default and help, one per line, as a script would set it.
void listOptions(std::ostream& out) {
  OptionRegistry options;
  for (const OptionRegistry::Option& o : options.all()) out << optionListingLine(o) << '\n';
}

void applyOptions(const CommandLine& cl, OptionRegistry& options) {
  for (const auto& [name, value] : cl.numberOptions) options.setNumber(name, value);
}

// The output file: -o, else the script's path with its extension replaced by that of the
// format -format names (t1.png for -format png), ".msh" without one.
std::string outputPath(const CommandLine& cl) {
  if (!cl.output.empty()) return cl.output;
  std::filesystem::path p(cl.files.front());
  const MeshFormat* named = cl.format.empty() ? nullptr : findFormatByName(cl.format);
  const std::string_view extensions = named ? named->extensions : ".msh";
  p.replace_extension(std::string(extensions.substr(0, extensions.find(' '))));
  return p.string();
}

// -0: the evaluated geometry as a flat script, <script>.geo_unrolled unless -o says otherwise.
void writeUnrolled(const CommandLine& cl, Session& session, ConsoleLog& log) {
  const std::string path = cl.output.empty() ? cl.files.front() + "_unrolled" : cl.output;
  log.info("Writing '" + path + "'...");
  api::writeUnrolledGeometry(session, path);
  log.info("Done writing '" + path + "'");
}

// Meshes; when meshing fails and -keep_partial asks for it, writes what was meshed first.
void generate(const CommandLine& cl, Session& session, const MeshFormat& format,
              const std::string& path, ConsoleLog& log) {
  auto writePartial = [&] {
    if (!cl.keepPartial) return;
    api::writeMesh(session, path, format);
    log.warning("meshing failed; the partial mesh was written to '" + path + "' (-keep_partial)");
  };
  try {
    api::generate(session, *cl.dimension);
  } catch (const MeshError&) {
    writePartial();
    throw;
  } catch (const ScriptError&) {  // a MeshError located at the statement of its entity
    writePartial();
    throw;
  }
}

void logSummary(const MeshSummary& summary, ConsoleLog& log) {
  log.info(formatSummary(summary));
  if (summary.highOrder) log.info(formatCurvedValidity(summary));
  if (summary.layerElements > 0) log.info(formatLayerQuality(summary));
  if (const std::string quads = formatQuadStructure(summary); !quads.empty()) log.info(quads);
  if (const std::string hexes = formatHexShare(summary); !hexes.empty()) log.info(hexes);
}

void meshAndWrite(const CommandLine& cl, Session& session, ConsoleLog& log) {
  if (*cl.dimension == 0) {
    session.synchronize();
    log.info("Geometry: " + describeModel(session.model()));
    writeUnrolled(cl, session, log);
    return;
  }
  const std::string path = outputPath(cl);
  const MeshFormat& format = api::outputFormat(session.options(), path, cl.format);
  checkElementOrder(session, &format, path);
  api::requireSomethingToMesh(session, *cl.dimension);
  Stopwatch watch;
  generate(cl, session, format, path, log);
  log.info("Meshing done (" + formatSeconds(watch.seconds()) + ")");
  Stopwatch writeWatch;
  log.info("Writing '" + path + "'...");
  api::writeMesh(session, path, format);
  log.info("Done writing '" + path + "' (" + formatSeconds(writeWatch.seconds()) + ")");
  logSummary(summarizeMesh(session.model(), session.mesh()), log);
  if (!cl.view) return;
  if (format.isNamed("html"))
    openPage(path, log);  // -o page.html: the mesh file is the page
  else
    writeMeshPage(session, pagePathBeside(path), log);
}

bool isMeshFile(const std::string& path) {
  return findReaderByExtension(std::filesystem::path(path).extension().string()) != nullptr;
}

// -check on surfaces: the topology of each connected part of the mesh's surface elements (of
// the merged triangulation when the mesh has none), whatever their entities.
void logSurfaceTopology(Session& session, ConsoleLog& log) {
  Triangulation surface = meshTriangles(session.mesh()).triangulation;
  if (surface.triangles.empty())
    if (const Triangulation* merged = session.mergedTriangulation()) surface = *merged;
  for (const std::string& line : surfaceTopologyLines(surface)) log.info(line);
}

// -check: conformity and orientation, curved elements whose Jacobian is not positive
// everywhere, and the surfaces' topology. Returns the exit status.
int checkMeshRead(Session& session, const MeshSummary& summary, ConsoleLog& log) {
  const MeshCheckReport report = checkMesh(session.model(), session.mesh());
  logSurfaceTopology(session, log);
  if (!report.ok())
    log.error("Check: " + std::to_string(report.problems.size()) + " problem(s)\n" +
              report.summary());
  if (summary.invalidElements > 0) {
    std::ostringstream os;
    os << "Check: " << summary.invalidElements << " invalid curved element(s): scaled Jacobian min "
       << summary.minScaledJacobian;
    log.error(os.str());
  }
  if (report.ok() && summary.invalidElements == 0) {
    log.info("Check: no problem found");
    return 0;
  }
  return 1;
}

// A mesh file as input: read it, check it if asked (-check), convert it if asked (-o/-format).
int runMeshFile(const CommandLine& cl, std::ostream& out, ConsoleLog& log) {
  const std::string& path = cl.files.front();
  Session session(log, out);
  Stopwatch watch;
  log.info("Reading '" + path + "'...");
  session.readMesh(path);
  log.info("Done reading '" + path + "' (" + formatSeconds(watch.seconds()) + ")");
  const MeshSummary summary = summarizeMesh(session.model(), session.mesh());
  logSummary(summary, log);
  const int status = cl.check ? checkMeshRead(session, summary, log) : 0;
  applyOptions(cl, session.options());
  const int partitions = clampedInteger<int>(session.options().number("Mesh.NbPartitions"));
  if (partitions > 0) api::partitionMesh(session, partitions);
  if (cl.viewCommand) {  // -o names the page
    writeMeshPage(session, cl.output.empty() ? pagePathBeside(path) : cl.output, log);
    return status;
  }
  if (!cl.output.empty()) {
    api::writeMesh(session, cl.output, api::outputFormat(session.options(), cl.output, cl.format));
    log.info("Wrote '" + cl.output + "'");
  }
  if (cl.view) writeMeshPage(session, pagePathBeside(path), log);
  return status;
}

int runSession(const CommandLine& cl, std::ostream& out, ConsoleLog& log) {
  if (isMeshFile(cl.files.front())) return runMeshFile(cl, out, log);
  if (cl.viewCommand)
    throw std::invalid_argument("geomesh view shows a mesh file (" + readExtensionList() +
                                "), not '" + cl.files.front() + "': to mesh a script and see " +
                                "its mesh, give -view with -1, -2 or -3");
  Session session(log, out);
  applySettings(cl, session);
  if (!evaluateScriptFile(cl.files.front(), session, log)) return 0;
  if (!cl.dimension) {
    session.synchronize();
    log.info("Geometry: " + describeModel(session.model()));
    if (session.mesh().nodeCount() > 0)
      log.info("The script meshed (Mesh n): only its Save statements write files");
    else
      log.info("Nothing meshed: give -1, -2 or -3 to mesh, -0 to check the geometry");
    if (cl.view && session.mesh().nodeCount() > 0)
      writeMeshPage(session, pagePathBeside(outputPath(cl)), log);
    else if (cl.view)
      log.warning("-view: nothing meshed to show (give -1, -2 or -3)");
    if (cl.check) logSurfaceTopology(session, log);
    return 0;
  }
  meshAndWrite(cl, session, log);
  if (cl.check) logSurfaceTopology(session, log);
  return 0;
}

}  // namespace

int runGeomesh(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
               bool terminal) {
  ConsoleLog log(err, 5);
  log.setTerminal(terminal);
  CommandLine cl;
  try {
    cl = parseCommandLine(args);
  } catch (const CommandLineError& e) {
    log.error(e.what());
    return 1;
  }
  log.setVerbosity(cl.verbosity);
  if (cl.help) {
    out << commandLineHelp();
    return 0;
  }
  if (cl.version) {
    out << kVersion << '\n';
    return 0;
  }
  if (cl.helpOptions) {
    listOptions(out);
    return 0;
  }
  if (cl.files.empty()) {
    log.error("no input file given (see -help)");
    return 1;
  }
  if (cl.files.size() > 1) {
    log.error("only one input file is supported, got " + std::to_string(cl.files.size()));
    return 1;
  }
  try {
    return runSession(cl, out, log);
  } catch (const ScriptError& e) {
    log.diagnostic(e.what());
  } catch (const std::bad_alloc&) {
    log.error("out of memory");
  } catch (const std::exception& e) {
    // Mesh, geometry, file and command-line errors: their messages name what failed.
    log.error(e.what());
  }
  return 1;
}

}  // namespace geomesh
