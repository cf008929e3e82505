// Memory in use and installed, and the executable's path (Memory, General.ExecutableFileName).
#pragma once

#include <string>

namespace geomesh {

// Memory used by this process and installed in the machine, in megabytes (the Memory and
// TotalMemory constants of scripts); 0 where the system does not tell.
double processMemoryMegabytes();
double totalMemoryMegabytes();

// The path of the running program (General.ExecutableFileName); empty where the system does
// not tell.
std::string executablePath();

}  // namespace geomesh
