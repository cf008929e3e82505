# The Python module (python/): pybind11 and the interpreter's headers, both optional. Without
# them GEOMESH_PYTHON is off and the rest of geomesh builds as before.

# Debian's numpy and pytest (scripts/setup.sh) belong to the system interpreter: prefer it to
# whatever `python3` comes first on the PATH, unless the caller names one.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
find_package(Python3 QUIET COMPONENTS Interpreter Development.Module)
# A wheel (`pip install .`) takes pybind11 from its build requirements: NumPy 2, which a new
# environment installs, needs pybind11 2.12 or later, and Debian 12 ships 2.10.
if(SKBUILD AND Python3_FOUND AND NOT DEFINED pybind11_DIR)
  execute_process(COMMAND ${Python3_EXECUTABLE} -c "import pybind11; print(pybind11.get_cmake_dir())"
                  OUTPUT_VARIABLE pybind11_wheel_dir OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE pybind11_wheel_found ERROR_QUIET)
  if(pybind11_wheel_found EQUAL 0)
    set(pybind11_DIR ${pybind11_wheel_dir})
  endif()
endif()
if(Python3_FOUND)
  find_package(pybind11 CONFIG QUIET)
endif()
