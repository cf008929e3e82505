# Describes this build for the read-only options General.BuildInfo and General.BuildOptions:
# geomesh's version, the compiler, and the version of each library it was built with, read
# from the libraries' own headers at configure time.

function(geomesh_header_version out header pattern)
  set(version "unknown")
  if(EXISTS "${header}")
    file(STRINGS "${header}" lines REGEX "${pattern}")
    if(lines MATCHES "${pattern}")
      set(version "${CMAKE_MATCH_1}")
    endif()
  endif()
  set(${out} "${version}" PARENT_SCOPE)
endfunction()

geomesh_header_version(GEOMESH_OCC_VERSION "${OCC_INCLUDE_DIR}/Standard_Version.hxx"
                       "#define OCC_VERSION_COMPLETE[ \t]+\"([0-9.]+)\"")
geomesh_header_version(GEOMESH_CGAL_VERSION "${CGAL_INCLUDE_DIR}/CGAL/version.h"
                       "#define CGAL_VERSION[ \t]+([0-9.]+)")
geomesh_header_version(GEOMESH_LEMON_VERSION "${LEMON_INCLUDE_DIR}/lemon/config.h"
                       "#define LEMON_VERSION[ \t]+\"([0-9.]+)\"")
geomesh_header_version(GEOMESH_TETGEN_VERSION "${TETGEN_INCLUDE_DIR}/tetgen.h"
                       "// Version ([0-9.]+)")

math(EXPR GEOMESH_POINTER_BITS "${CMAKE_SIZEOF_VOID_P} * 8")
set(GEOMESH_BUILD_OPTIONS
    "${GEOMESH_POINTER_BITS}Bit Blossom[LEMON] CGAL OpenCASCADE TetGen")
string(CONCAT GEOMESH_BUILD_INFO
    "Version: ${PROJECT_VERSION}; Build OS: ${CMAKE_SYSTEM_NAME}${GEOMESH_POINTER_BITS}; "
    "Build type: ${CMAKE_BUILD_TYPE}; "
    "Compiler: ${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}; "
    "Build options: ${GEOMESH_BUILD_OPTIONS}; OCC version: ${GEOMESH_OCC_VERSION}; "
    "CGAL version: ${GEOMESH_CGAL_VERSION}; LEMON version: ${GEOMESH_LEMON_VERSION}; "
    "TetGen version: ${GEOMESH_TETGEN_VERSION}")
configure_file(${PROJECT_SOURCE_DIR}/stdlib/build_info.h.in
               ${PROJECT_BINARY_DIR}/generated/stdlib/build_info.h @ONLY)
