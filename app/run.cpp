#include "app/run.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "app/command_line.h"
#include "app/console_log.h"
#include "app/mesh_summary.h"
#include "interpreter/diagnostics.h"
#include "interpreter/session.h"
#include "kernel/unrolled_geo_hooks.h"
#include "mesh/pipeline/generate.h"
#include "io/msh_reader.h"
#include "io/msh_writer.h"
#include "mesh/checks/mesh_check.h"

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

std::string formatSeconds(double s) {
  std::ostringstream os;
  os.precision(3);
  os << s << " s";
  return os.str();
}

// Every option with its default and help, one per line, as a script would set it.
void listOptions(std::ostream& out) {
  OptionRegistry options;
  for (const OptionRegistry::Option& o : options.all()) out << optionListingLine(o) << '\n';
}

void applyOptions(const CommandLine& cl, OptionRegistry& options) {
  for (const auto& [name, value] : cl.numberOptions) options.setNumber(name, value);
}

// The output file: -o, else the script's path with its extension replaced by ".msh".
std::string outputPath(const CommandLine& cl) {
  if (!cl.output.empty()) return cl.output;
  std::filesystem::path p(cl.files.front());
  p.replace_extension(".msh");
  return p.string();
}

// Without -format, Mesh.Format decides: 1 is MSH, 10 (the default) chooses by the output
// file's extension. Only MSH is written so far: anything else is refused before meshing.
void requireMshOutput(const std::string& path, double format) {
  if (format == 1) return;
  if (format != 10)
    throw CommandLineError("Mesh.Format " + std::to_string(static_cast<int>(format)) +
                           " is not supported yet: only MSH (1) is written");
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".msh")
    throw CommandLineError("cannot write '" + path + "': the '" + ext +
                           "' format is not supported yet (only .msh)");
}

MshWriteOptions writeOptions(const CommandLine& cl, const OptionRegistry& options) {
  MshWriteOptions w;
  w.saveAll = options.number("Mesh.SaveAll") != 0;
  w.binary = options.number("Mesh.Binary") != 0;
  w.version = options.number("Mesh.MshFileVersion");
  if (cl.format == "msh41" || cl.format == "msh4" || cl.format == "msh") {
    w.version = 4.1;
  } else if (cl.format == "msh22" || cl.format == "msh2") {
    w.version = 2.2;
  } else if (!cl.format.empty()) {
    throw CommandLineError("unsupported output format '" + cl.format +
                           "' (supported: msh41, msh4, msh22, msh2)");
  } else {
    requireMshOutput(outputPath(cl), options.number("Mesh.Format"));
  }
  if (w.version >= 4) {
    w.version = 4.1;
  } else {
    w.version = 2.2;
  }
  return w;
}

// Evaluates the script; returns false if the script asked to stop (Exit).
bool evaluateScript(const CommandLine& cl, Session& session, ConsoleLog& log) {
  Stopwatch watch;
  const std::string& file = cl.files.front();
  log.info("Reading '" + file + "'...");
  try {
    session.runFile(file);
  } catch (const ScriptExit&) {
    log.info("Script called Exit: stopping");
    return false;
  }
  log.info("Done reading '" + file + "' (" + formatSeconds(watch.seconds()) + ")");
  return true;
}

// Line `line` of a script file, for quoting in a diagnostic; empty if unreadable.
std::string sourceLine(const std::string& path, int line) {
  std::ifstream in(path, std::ios::binary);
  SourceFile file{path, {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()}};
  return std::string(file.lineText(line));
}

// -0: the evaluated geometry as a flat script, <script>.geo_unrolled unless -o says otherwise.
void writeUnrolled(const CommandLine& cl, Session& session, ConsoleLog& log) {
  const std::string path = cl.output.empty() ? cl.files.front() + "_unrolled" : cl.output;
  const std::string partial = path + ".partial";
  log.info("Writing '" + path + "'...");
  {
    std::ofstream out(partial, std::ios::binary);
    session.factory().writeUnrolled(out, meshConstraintHooks(session.model().meshConstraints()));
    out.close();
    if (!out) {
      std::filesystem::remove(partial);
      throw std::runtime_error("cannot write '" + path + "'");
    }
  }
  std::filesystem::rename(partial, path);
  log.info("Done writing '" + path + "'");
}

void meshAndWrite(const CommandLine& cl, Session& session, ConsoleLog& log) {
  const int dim = *cl.dimension;
  if (dim == 0) {
    session.synchronize();
    log.info("Geometry: " + describeModel(session.model()));
    writeUnrolled(cl, session, log);
    return;
  }
  const MshWriteOptions w = writeOptions(cl, session.options());
  Stopwatch watch;
  const std::string path = outputPath(cl);
  try {
    session.generate(dim);
  } catch (const MeshError& error) {
    if (cl.keepPartial) {
      writeMshFile(path, session.model(), session.mesh(), w);
      log.warning("meshing failed; the partial mesh was written to '" + path + "' (-keep_partial)");
    }
    // Point at the statement that defined the entity, when the script did.
    if (auto where = session.origin(error.entity))
      throw ScriptError(*where, error.what(), sourceLine(where->file, where->line));
    throw;
  }
  log.info("Meshing done (" + formatSeconds(watch.seconds()) + ")");
  Stopwatch writeWatch;
  log.info("Writing '" + path + "'...");
  writeMshFile(path, session.model(), session.mesh(), w);
  log.info("Done writing '" + path + "' (" + formatSeconds(writeWatch.seconds()) + ")");
  log.info(formatSummary(summarizeMesh(session.model(), session.mesh())));
}

bool isMeshFile(const std::string& path) {
  return std::filesystem::path(path).extension() == ".msh";
}

// A mesh file as input: read it, check it if asked (-check), convert it if asked (-o/-format).
int runMeshFile(const CommandLine& cl, ConsoleLog& log) {
  const std::string& path = cl.files.front();
  Model model;
  Mesh mesh;
  Stopwatch watch;
  log.info("Reading '" + path + "'...");
  readMshFile(path, model, mesh);
  log.info("Done reading '" + path + "' (" + formatSeconds(watch.seconds()) + ")");
  log.info(formatSummary(summarizeMesh(model, mesh)));
  int status = 0;
  if (cl.check) {
    MeshCheckReport report = checkMesh(model, mesh);
    if (report.ok()) {
      log.info("Check: no problem found");
    } else {
      log.error("Check: " + std::to_string(report.problems.size()) + " problem(s)\n" +
                report.summary());
      status = 1;
    }
  }
  if (!cl.output.empty()) {
    OptionRegistry options;
    applyOptions(cl, options);
    writeMshFile(cl.output, model, mesh, writeOptions(cl, options));
    log.info("Wrote '" + cl.output + "'");
  }
  return status;
}

int runSession(const CommandLine& cl, std::ostream& out, ConsoleLog& log) {
  if (isMeshFile(cl.files.front())) return runMeshFile(cl, log);
  Session session(log, out);
  session.options().setNumber("General.Verbosity", cl.verbosity);
  session.allowSystemCalls(cl.allowSystemCalls);
  // -setnumber / -setstring set the option of that name if there is one, else a parameter.
  for (const auto& [name, value] : cl.setNumbers) {
    if (session.options().hasNumber(name))
      session.options().setNumber(name, value);
    else
      session.numberOverrides()[name] = value;
  }
  for (const auto& [name, value] : cl.setStrings) {
    if (session.options().hasString(name))
      session.options().setString(name, value);
    else
      session.stringOverrides()[name] = value;
  }
  applyOptions(cl, session.options());
  if (!evaluateScript(cl, session, log)) return 0;
  if (!cl.dimension) {
    session.synchronize();
    log.info("Geometry: " + describeModel(session.model()));
    if (session.mesh().nodeCount() > 0)
      log.info("The script meshed (Mesh n): only its Save statements write files");
    else
      log.info("Nothing meshed: give -1, -2 or -3 to mesh, -0 to check the geometry");
    return 0;
  }
  meshAndWrite(cl, session, log);
  return 0;
}

}  // namespace

int runGeomesh(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  ConsoleLog log(err, 5);
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
