# Finds every third-party dependency; a missing one stops the configuration with the name of
# the Debian package that provides it (scripts/setup.sh installs them all).

function(geomesh_require found what package)
  if(NOT ${found})
    message(FATAL_ERROR "geomesh needs ${what}: install the Debian package '${package}' "
                        "(or run scripts/setup.sh, which installs every dependency)")
  endif()
endfunction()

find_program(RE2C_EXECUTABLE re2c)
geomesh_require(RE2C_EXECUTABLE "re2c (lexer generator)" "re2c")
find_package(BISON 3.7 QUIET)
geomesh_require(BISON_FOUND "bison >= 3.7 (parser generator)" "bison")

find_path(CGAL_INCLUDE_DIR CGAL/Exact_predicates_inexact_constructions_kernel.h)
geomesh_require(CGAL_INCLUDE_DIR "CGAL headers" "libcgal-dev")
find_library(GMP_LIBRARY gmp)
geomesh_require(GMP_LIBRARY "GMP" "libgmp-dev")
find_library(MPFR_LIBRARY mpfr)
geomesh_require(MPFR_LIBRARY "MPFR" "libmpfr-dev")
add_library(geomesh_cgal INTERFACE)
target_include_directories(geomesh_cgal SYSTEM INTERFACE ${CGAL_INCLUDE_DIR})
target_link_libraries(geomesh_cgal INTERFACE ${MPFR_LIBRARY} ${GMP_LIBRARY})

find_path(TETGEN_INCLUDE_DIR tetgen.h)
find_library(TETGEN_LIBRARY tet)
geomesh_require(TETGEN_INCLUDE_DIR "TetGen headers" "libtet1.5-dev")
geomesh_require(TETGEN_LIBRARY "the TetGen library" "libtet1.5-dev")
add_library(geomesh_tetgen INTERFACE)
target_include_directories(geomesh_tetgen SYSTEM INTERFACE ${TETGEN_INCLUDE_DIR})
target_compile_definitions(geomesh_tetgen INTERFACE TETLIBRARY)
target_link_libraries(geomesh_tetgen INTERFACE ${TETGEN_LIBRARY})

# LEMON (header-only use): maximum matchings for quadrangle recombination.
find_path(LEMON_INCLUDE_DIR lemon/matching.h)
geomesh_require(LEMON_INCLUDE_DIR "LEMON headers" "liblemon-dev")
add_library(geomesh_lemon INTERFACE)
target_include_directories(geomesh_lemon SYSTEM INTERFACE ${LEMON_INCLUDE_DIR})

find_path(OCC_INCLUDE_DIR Standard_Version.hxx PATH_SUFFIXES opencascade)
geomesh_require(OCC_INCLUDE_DIR "OpenCASCADE headers" "libocct-foundation-dev")
# Debian 12 ships this header, which the foundation and modeling headers include, in the
# visualization package rather than beside them.
find_path(OCC_ALIASED_ARRAY_DIR NCollection_AliasedArray.hxx PATHS ${OCC_INCLUDE_DIR} NO_DEFAULT_PATH)
geomesh_require(OCC_ALIASED_ARRAY_DIR "the OpenCASCADE header NCollection_AliasedArray.hxx"
                "libocct-visualization-dev")
set(GEOMESH_OCC_LIBS TKernel TKMath TKG2d TKG3d TKGeomBase TKBRep TKGeomAlgo TKTopAlgo TKPrim
                     TKBO TKBool TKFillet TKOffset TKShHealing TKXSBase TKSTEP TKIGES)
set(GEOMESH_OCC_PACKAGES
    TKernel=libocct-foundation-dev TKMath=libocct-foundation-dev
    TKPrim=libocct-modeling-algorithms-dev TKBO=libocct-modeling-algorithms-dev
    TKBool=libocct-modeling-algorithms-dev TKFillet=libocct-modeling-algorithms-dev
    TKOffset=libocct-modeling-algorithms-dev TKShHealing=libocct-modeling-algorithms-dev
    TKTopAlgo=libocct-modeling-algorithms-dev TKGeomAlgo=libocct-modeling-algorithms-dev
    TKXSBase=libocct-data-exchange-dev TKSTEP=libocct-data-exchange-dev
    TKIGES=libocct-data-exchange-dev)
add_library(geomesh_occ INTERFACE)
target_include_directories(geomesh_occ SYSTEM INTERFACE ${OCC_INCLUDE_DIR})
foreach(lib ${GEOMESH_OCC_LIBS})
  find_library(OCC_${lib}_LIBRARY ${lib})
  set(package libocct-modeling-data-dev)
  foreach(pair ${GEOMESH_OCC_PACKAGES})
    if(pair MATCHES "^${lib}=(.*)$")
      set(package ${CMAKE_MATCH_1})
    endif()
  endforeach()
  geomesh_require(OCC_${lib}_LIBRARY "the OpenCASCADE library ${lib}" "${package}")
  target_link_libraries(geomesh_occ INTERFACE ${OCC_${lib}_LIBRARY})
endforeach()

# A library with one header and one shared object, as the INTERFACE target `target`.
function(geomesh_system_library target header library what package)
  find_path(${target}_INCLUDE_DIR ${header})
  find_library(${target}_LIBRARY ${library})
  geomesh_require(${target}_INCLUDE_DIR "${what} headers" "${package}")
  geomesh_require(${target}_LIBRARY "the ${what} library" "${package}")
  add_library(${target} INTERFACE)
  target_include_directories(${target} SYSTEM INTERFACE ${${target}_INCLUDE_DIR})
  target_link_libraries(${target} INTERFACE ${${target}_LIBRARY})
endfunction()

# METIS: graph partitioning of meshes (PartitionMesh, -part).
geomesh_system_library(geomesh_metis metis.h metis "METIS" libmetis-dev)
# CGNS: the CFD General Notation System files (.cgns), HDF5-based.
geomesh_system_library(geomesh_cgns cgnslib.h cgns "CGNS" libcgns-dev)
# libpng: pictures of meshes (.png), linked by io/ only.
find_package(PNG QUIET)
geomesh_require(PNG_FOUND "libpng" "libpng-dev")

if(GEOMESH_TESTS)
  find_package(GTest QUIET)
  geomesh_require(GTest_FOUND "GoogleTest" "libgtest-dev")
endif()
find_package(Threads REQUIRED)

# Eigen: sparse linear solves (maps of merged triangulations to the plane), header-only.
find_package(Eigen3 3.3 QUIET NO_MODULE)
geomesh_require(Eigen3_FOUND "Eigen" "libeigen3-dev")
