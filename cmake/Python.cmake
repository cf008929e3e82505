# The Python module (python/): pybind11 and the interpreter's headers, both optional. Without
# them GEOMESH_PYTHON is off and the rest of geomesh builds as before.

# Debian's numpy and pytest (scripts/setup.sh) belong to the system interpreter: prefer it to
# whatever `python3` comes first on the PATH, unless the caller names one.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 QUIET COMPONENTS Interpreter Development.Module)
if(Python3_FOUND)
  find_package(pybind11 CONFIG QUIET)
endif()
