// Writing a mesh's HTML page and handing it to the desktop's browser.
#include "app/mesh_page_view.h"

#include <fcntl.h>
#include <spawn.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "api/output.h"
#include "io/formats.h"

extern char** environ;

namespace geomesh {

namespace {

bool hasDisplay() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"})
    if (const char* value = std::getenv(name); value && *value) return true;
  return false;
}

// Starts xdg-open on the page, its output discarded; false when it could not be started.
bool startXdgOpen(const std::string& path) {
  posix_spawn_file_actions_t actions;
  if (posix_spawn_file_actions_init(&actions) != 0) return false;
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  std::string program = "xdg-open";
  std::string argument = path;
  char* argv[] = {program.data(), argument.data(), nullptr};
  pid_t pid = 0;
  const int status = posix_spawnp(&pid, "xdg-open", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  return status == 0;
}

}  // namespace

std::string pagePathBeside(const std::string& meshPath) {
  std::filesystem::path page(meshPath);
  page.replace_extension(".html");
  return page.string();
}

void writeMeshPage(const Session& session, const std::string& path, ConsoleLog& log) {
  const MeshFormat* html = findFormatByName("html");
  if (!html) throw std::logic_error("the format table has no html row");
  writeMeshFile(path, *html, session.model(), session.mesh(), api::writeOptions(session.options()));
  log.info("Wrote '" + path + "'");
  openPage(path, log);
}

void openPage(const std::string& path, ConsoleLog& log) {
  std::error_code error;
  const std::filesystem::path absolute = std::filesystem::absolute(path, error);
  const std::string shown = error ? path : absolute.string();
  if (hasDisplay() && startXdgOpen(shown)) {
    log.info("Opening '" + shown + "' in a browser");
    return;
  }
  log.info("Open '" + shown + "' in a browser to look at the mesh");
}

}  // namespace geomesh
