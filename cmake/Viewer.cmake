# The mesh viewer: viewer/src (JavaScript, with three.js from the npm registry) bundled by
# esbuild into one script, which a generated source puts in geomesh_io for the HTML writer.
# Everything generated (node_modules, the bundle, the .cpp) lives in the build directory.

find_program(GEOMESH_NODE node)
find_program(GEOMESH_NPM npm)
if(NOT GEOMESH_NODE OR NOT GEOMESH_NPM)
  message(FATAL_ERROR "geomesh: the mesh viewer's page is built with Node.js and npm, which "
                      "were not found: run scripts/setup.sh (it installs them)")
endif()

set(viewer_source ${PROJECT_SOURCE_DIR}/viewer)
set(viewer_build ${CMAKE_BINARY_DIR}/viewer)
set(viewer_modules ${viewer_build}/node_modules)
set(viewer_cpp ${viewer_build}/viewer_script.cpp)

# npm ci installs exactly what package-lock.json pins; no install script is run.
add_custom_command(
  OUTPUT ${viewer_build}/npm-ci.stamp
  COMMAND ${CMAKE_COMMAND} -E make_directory ${viewer_build}
  COMMAND ${CMAKE_COMMAND} -E copy_if_different ${viewer_source}/package.json
          ${viewer_source}/package-lock.json ${viewer_build}
  COMMAND ${GEOMESH_NPM} ci --ignore-scripts --no-audit --no-fund --loglevel=error
  COMMAND ${CMAKE_COMMAND} -E touch ${viewer_build}/npm-ci.stamp
  WORKING_DIRECTORY ${viewer_build}
  DEPENDS ${viewer_source}/package.json ${viewer_source}/package-lock.json
  COMMENT "Installing the viewer's npm packages (npm ci)"
  VERBATIM)

file(GLOB viewer_sources CONFIGURE_DEPENDS ${viewer_source}/src/*.js ${viewer_source}/src/*.css)
add_custom_command(
  OUTPUT ${viewer_cpp} ${viewer_build}/viewer.js
  COMMAND ${GEOMESH_NODE} ${viewer_source}/build.mjs --modules ${viewer_modules}
          --out ${viewer_build} --cpp ${viewer_cpp}
  DEPENDS ${viewer_build}/npm-ci.stamp ${viewer_source}/build.mjs ${viewer_sources}
  COMMENT "Bundling the viewer (esbuild)"
  VERBATIM)

add_library(geomesh_viewer_script STATIC ${viewer_cpp})
target_include_directories(geomesh_viewer_script PRIVATE ${PROJECT_SOURCE_DIR})
target_link_libraries(geomesh_io PRIVATE geomesh_viewer_script)

# The page in a browser: headless Chromium drives pages made by the built geomesh (no
# browser is opened on a display).
if(GEOMESH_TESTS)
  set(viewer_test_environment GEOMESH_BINARY=$<TARGET_FILE:geomesh>
      GEOMESH_SOURCE_DIR=${PROJECT_SOURCE_DIR} GEOMESH_VIEWER_MODULES=${viewer_modules})
  add_test(NAME viewer_page
           COMMAND ${GEOMESH_NODE} --test ${viewer_source}/test/viewer_page.test.mjs)
  set_tests_properties(viewer_page PROPERTIES
    LABELS viewer
    TIMEOUT 600
    ENVIRONMENT "${viewer_test_environment}"
    ENVIRONMENT_MODIFICATION "DISPLAY=unset:;WAYLAND_DISPLAY=unset:")
endif()
