# FindOpenFOAM.cmake: OpenFOAM's libraries and headers for foamCoupling/, without wmake.
#
# Where OpenFOAM comes from, in this order:
#   1. a user's own OpenFOAM environment: FOAM_SRC and FOAM_LIBBIN set (its etc/bashrc sourced).
#      Its lnInclude/ folders already exist and are used as they are; WM_PROJECT_DIR,
#      WM_LABEL_SIZE and WM_PRECISION_OPTION are taken from the environment too.
#   2. Debian's packages (the default): libraries from `libopenfoam` in /usr/lib, the project
#      directory /usr/share/openfoam, and the headers from Debian's source package of exactly the
#      installed version, which `bash tools/setup.sh --openfoam` unpacks into
#      OPENFOAM_SOURCE_DIR (default ${QUICKSAND_CACHE_DIR:-$HOME/.cache/quicksand}/openfoam-src,
#      one openfoam-<source version>/ folder per version; OPENFOAM_SOURCE_DIR may also point
#      straight at an OpenFOAM tree holding src/). The flat include folders wmake's lnInclude/
#      would hold are made in the build tree: ${CMAKE_BINARY_DIR}/openfoam-include/<lib>/, one
#      symbolic link per .H/.C/... file below src/<lib>, made once per source tree.
#
# Results:
#   OpenFOAM_FOUND               TRUE when everything below is usable
#   OpenFOAM_VERSION             the API version, e.g. 1912 (find_package(OpenFOAM 1912) checks it)
#   OPENFOAM_PACKAGE_VERSION     Debian's source version (1912.200626-1), or WM_PROJECT_VERSION
#   OPENFOAM_FLAVOUR             "debian" or "environment"
#   OPENFOAM_SOURCE_TREE         the OpenFOAM tree whose src/ the headers come from
#   OPENFOAM_LIBRARY_DIR         where libOpenFOAM.so is (Debian: /usr/lib)
#   OPENFOAM_DUMMY_PSTREAM_DIR   the folder of the serial (no MPI) libPstream.so (Debian:
#                                /usr/lib/dummy); put it first on the run path of whatever links
#                                OpenFOAM to keep MPI out of the process
#   OPENFOAM_PROJECT_DIR         WM_PROJECT_DIR, the folder holding etc/controlDict (Debian:
#                                /usr/share/openfoam); must be in the environment before
#                                libOpenFOAM.so is loaded
#   OPENFOAM_TUTORIALS_DIR       the tutorials (FOAM_TUTORIALS, Debian's openfoam-examples, or the
#                                part of them setup.sh unpacks: incompressible/icoFoam/cavity)
#   OPENFOAM_MPI_PSTREAM_DIR     the folder of the Open MPI libPstream.so (Debian:
#                                /usr/lib/openmpi-system), for a line decomposed over MPI ranks;
#                                empty where there is none
#   OPENFOAM_BLOCKMESH           the blockMesh program
#   OPENFOAM_DECOMPOSEPAR, OPENFOAM_RECONSTRUCTPAR   decomposePar and reconstructPar
#   OPENFOAM_INCLUDE_DIRS        the include folders (also on the targets)
#   OPENFOAM_DEFINITIONS         WM_DP WM_LABEL_SIZE=32 NoRepository OPENFOAM=1912
#
# Imported targets (INTERFACE; their include folders are SYSTEM, so OpenFOAM's headers add no
# warnings; link them PRIVATE so OpenFOAM's headers stay inside foamCoupling/):
#   OpenFOAM::OpenFOAM    include folders of OpenFOAM, OSspecific/POSIX, finiteVolume, meshTools
#                         and everything icoFoam and pimpleFoam include (fileFormats, surfMesh,
#                         sampling, dynamicMesh, dynamicFvMesh, fvOptions, TurbulenceModels,
#                         transportModels); definitions as above; -ftemplate-depth-100;
#                         link -Wl,--no-as-needed -lfiniteVolume -lmeshTools -lOpenFOAM -lPstream
#                         -ldl -lm (--no-as-needed keeps libraries whose run-time selection
#                         tables, e.g. boundary conditions, are only reached by name)
#   OpenFOAM::pimpleFoam  OpenFOAM::OpenFOAM plus the libraries pimpleFoam links (fvOptions,
#                         sampling, turbulenceModels, incompressibleTurbulenceModels,
#                         incompressibleTransportModels, dynamicMesh, dynamicFvMesh,
#                         topoChangerFvMesh, atmosphericModels)
#
# Without OpenFOAM this sets OpenFOAM_FOUND to FALSE and says why in one STATUS line.

include(FindPackageHandleStandardArgs)

if(DEFINED ENV{QUICKSAND_CACHE_DIR} AND NOT "$ENV{QUICKSAND_CACHE_DIR}" STREQUAL "")
  set(_of_cache_root "$ENV{QUICKSAND_CACHE_DIR}")
else()
  set(_of_cache_root "$ENV{HOME}/.cache/quicksand")
endif()
set(OPENFOAM_SOURCE_DIR "${_of_cache_root}/openfoam-src" CACHE PATH
    "OpenFOAM sources for the headers: tools/setup.sh's cache (openfoam-<version>/ folders) or a tree holding src/")

# Libraries whose flat include folders are made (relative to src/), in wmake's order: the
# application's own first, OpenFOAM and OSspecific/POSIX last.
set(_of_lninclude_libs
    finiteVolume meshTools sampling
    TurbulenceModels/turbulenceModels TurbulenceModels/incompressible
    dynamicMesh dynamicFvMesh fvOptions fileFormats surfMesh
    OpenFOAM OSspecific/POSIX)
# Folders pimpleFoam includes as they are (no lnInclude).
set(_of_plain_dirs transportModels transportModels/incompressible/singlePhaseTransportModel)
set(_of_core_libs finiteVolume meshTools OpenFOAM Pstream)
set(_of_pimple_libs fvOptions sampling turbulenceModels incompressibleTurbulenceModels
    incompressibleTransportModels dynamicMesh dynamicFvMesh topoChangerFvMesh atmosphericModels)

set(_of_reason "")
set(_of_label_size 32)
set(_of_precision DP)
set(OPENFOAM_INCLUDE_DIRS "")
set(_of_link_dirs "")

# wmakeLnInclude in CMake: a flat folder of links to every source file below src/<lib>
# (Make/, config/, noLink/ and lnInclude/ folders skipped), remade only when the tree changes.
function(_openfoam_lninclude libdir outdir)
  set(_stamp "${outdir}/.lninclude-of")
  if(EXISTS "${_stamp}")
    file(READ "${_stamp}" _was)
    if(_was STREQUAL libdir)
      return()
    endif()
  endif()
  file(REMOVE_RECURSE "${outdir}")
  file(MAKE_DIRECTORY "${outdir}")
  file(GLOB_RECURSE _files LIST_DIRECTORIES false RELATIVE "${libdir}" "${libdir}/*")
  list(FILTER _files INCLUDE REGEX "\\.(C|H|h|cxx|hxx|cpp|hpp|type)$")
  list(FILTER _files EXCLUDE REGEX "(^|/)(lnInclude|Make|config|noLink)/")
  list(SORT _files)
  foreach(_f IN LISTS _files)
    get_filename_component(_name "${_f}" NAME)
    if(NOT EXISTS "${outdir}/${_name}" AND NOT IS_SYMLINK "${outdir}/${_name}")
      file(CREATE_LINK "${libdir}/${_f}" "${outdir}/${_name}" SYMBOLIC)
    endif()
  endforeach()
  file(WRITE "${_stamp}" "${libdir}")
endfunction()

if(DEFINED ENV{FOAM_SRC} AND DEFINED ENV{FOAM_LIBBIN}
   AND NOT "$ENV{FOAM_SRC}" STREQUAL "" AND NOT "$ENV{FOAM_LIBBIN}" STREQUAL "")
  # 1. The user's own OpenFOAM environment.
  set(OPENFOAM_FLAVOUR environment)
  set(_of_src "$ENV{FOAM_SRC}")
  get_filename_component(OPENFOAM_SOURCE_TREE "${_of_src}/.." ABSOLUTE)
  set(OPENFOAM_LIBRARY_DIR "$ENV{FOAM_LIBBIN}")
  set(OPENFOAM_DUMMY_PSTREAM_DIR "${OPENFOAM_LIBRARY_DIR}/dummy")
  if(DEFINED ENV{WM_PROJECT_DIR} AND NOT "$ENV{WM_PROJECT_DIR}" STREQUAL "")
    set(OPENFOAM_PROJECT_DIR "$ENV{WM_PROJECT_DIR}")
  else()
    set(OPENFOAM_PROJECT_DIR "${OPENFOAM_SOURCE_TREE}")
  endif()
  if(DEFINED ENV{FOAM_TUTORIALS} AND EXISTS "$ENV{FOAM_TUTORIALS}")
    set(OPENFOAM_TUTORIALS_DIR "$ENV{FOAM_TUTORIALS}")
  else()
    set(OPENFOAM_TUTORIALS_DIR "${OPENFOAM_PROJECT_DIR}/tutorials")
  endif()
  if(DEFINED ENV{WM_LABEL_SIZE} AND NOT "$ENV{WM_LABEL_SIZE}" STREQUAL "")
    set(_of_label_size "$ENV{WM_LABEL_SIZE}")
  endif()
  if(DEFINED ENV{WM_PRECISION_OPTION} AND NOT "$ENV{WM_PRECISION_OPTION}" STREQUAL "")
    set(_of_precision "$ENV{WM_PRECISION_OPTION}")
  endif()
  set(OPENFOAM_PACKAGE_VERSION "$ENV{WM_PROJECT_VERSION}")
  if(NOT EXISTS "${OPENFOAM_LIBRARY_DIR}/libOpenFOAM.so")
    set(_of_reason "FOAM_LIBBIN=${OPENFOAM_LIBRARY_DIR} holds no libOpenFOAM.so")
  elseif(NOT EXISTS "${_of_src}/OpenFOAM/lnInclude/Time.H")
    set(_of_reason "FOAM_SRC=${_of_src} has no OpenFOAM/lnInclude (OpenFOAM not built?)")
  else()
    foreach(_lib IN LISTS _of_lninclude_libs)
      if(IS_DIRECTORY "${_of_src}/${_lib}/lnInclude")
        list(APPEND OPENFOAM_INCLUDE_DIRS "${_of_src}/${_lib}/lnInclude")
      endif()
    endforeach()
    list(APPEND _of_link_dirs "${OPENFOAM_LIBRARY_DIR}")
    if(DEFINED ENV{FOAM_MPI} AND IS_DIRECTORY "${OPENFOAM_LIBRARY_DIR}/$ENV{FOAM_MPI}")
      list(APPEND _of_link_dirs "${OPENFOAM_LIBRARY_DIR}/$ENV{FOAM_MPI}")
    endif()
    list(APPEND _of_link_dirs "${OPENFOAM_DUMMY_PSTREAM_DIR}")
  endif()
else()
  # 2. Debian's packages, headers from setup.sh's cache of the source package.
  set(OPENFOAM_FLAVOUR debian)
  find_library(OPENFOAM_LIBRARY NAMES OpenFOAM PATHS /usr/lib /usr/lib/openfoam
               NO_DEFAULT_PATH DOC "Debian's libOpenFOAM.so")
  find_program(OPENFOAM_DPKG_QUERY dpkg-query)
  mark_as_advanced(OPENFOAM_LIBRARY OPENFOAM_DUMMY_PSTREAM_LIBRARY OPENFOAM_DPKG_QUERY)
  set(OPENFOAM_PACKAGE_VERSION "")
  if(OPENFOAM_DPKG_QUERY)
    execute_process(COMMAND "${OPENFOAM_DPKG_QUERY}" -W "-f=\${source:Version}" libopenfoam
                    OUTPUT_VARIABLE OPENFOAM_PACKAGE_VERSION ERROR_QUIET
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
  endif()
  if(NOT OPENFOAM_LIBRARY)
    set(_of_reason "no libOpenFOAM.so (install Debian's openfoam: bash tools/setup.sh --openfoam)")
  else()
    get_filename_component(OPENFOAM_LIBRARY_DIR "${OPENFOAM_LIBRARY}" DIRECTORY)
    # The source tree: OPENFOAM_SOURCE_DIR itself, or its folder for the installed version.
    string(REGEX REPLACE "^[0-9]+:" "" _of_upstream "${OPENFOAM_PACKAGE_VERSION}")
    if(EXISTS "${OPENFOAM_SOURCE_DIR}/src/OpenFOAM/db/Time/Time.H")
      set(OPENFOAM_SOURCE_TREE "${OPENFOAM_SOURCE_DIR}")
    elseif(NOT _of_upstream STREQUAL ""
           AND EXISTS "${OPENFOAM_SOURCE_DIR}/openfoam-${_of_upstream}/.quicksand-complete")
      set(OPENFOAM_SOURCE_TREE "${OPENFOAM_SOURCE_DIR}/openfoam-${_of_upstream}")
    else()
      set(_of_reason "libraries in ${OPENFOAM_LIBRARY_DIR} but no headers for version '${OPENFOAM_PACKAGE_VERSION}' in ${OPENFOAM_SOURCE_DIR} (run bash tools/setup.sh --openfoam)")
    endif()
    find_file(OPENFOAM_DUMMY_PSTREAM_LIBRARY libPstream.so
              PATHS "${OPENFOAM_LIBRARY_DIR}/dummy" /usr/lib/dummy NO_DEFAULT_PATH
              DOC "OpenFOAM's serial (no MPI) libPstream.so")
    if(OPENFOAM_DUMMY_PSTREAM_LIBRARY)
      get_filename_component(OPENFOAM_DUMMY_PSTREAM_DIR "${OPENFOAM_DUMMY_PSTREAM_LIBRARY}" DIRECTORY)
    else()
      set(OPENFOAM_DUMMY_PSTREAM_DIR "")
    endif()
    set(OPENFOAM_PROJECT_DIR /usr/share/openfoam)
    if(NOT EXISTS "${OPENFOAM_PROJECT_DIR}/etc/controlDict" AND _of_reason STREQUAL "")
      set(_of_reason "no ${OPENFOAM_PROJECT_DIR}/etc/controlDict (Debian's openfoam package incomplete?)")
    endif()
    if(EXISTS /usr/share/doc/openfoam-examples/examples/incompressible)
      set(OPENFOAM_TUTORIALS_DIR /usr/share/doc/openfoam-examples/examples)
    elseif(OPENFOAM_SOURCE_TREE)
      set(OPENFOAM_TUTORIALS_DIR "${OPENFOAM_SOURCE_TREE}/tutorials")
    endif()
  endif()
  if(_of_reason STREQUAL "")
    set(_of_flat "${CMAKE_BINARY_DIR}/openfoam-include")
    foreach(_lib IN LISTS _of_lninclude_libs)
      if(IS_DIRECTORY "${OPENFOAM_SOURCE_TREE}/src/${_lib}")
        _openfoam_lninclude("${OPENFOAM_SOURCE_TREE}/src/${_lib}" "${_of_flat}/${_lib}")
        list(APPEND OPENFOAM_INCLUDE_DIRS "${_of_flat}/${_lib}")
      endif()
    endforeach()
    set(_of_src "${OPENFOAM_SOURCE_TREE}/src")
    list(APPEND _of_link_dirs "${OPENFOAM_LIBRARY_DIR}")
  endif()
endif()

if(_of_reason STREQUAL "")
  foreach(_dir IN LISTS _of_plain_dirs)
    if(IS_DIRECTORY "${_of_src}/${_dir}")
      list(APPEND OPENFOAM_INCLUDE_DIRS "${_of_src}/${_dir}")
    endif()
  endforeach()
  # The API version: META-INFO/api-info (api=1912), else the leading number of the version.
  set(OpenFOAM_VERSION "")
  foreach(_meta "${OPENFOAM_SOURCE_TREE}/META-INFO/api-info" "${OPENFOAM_PROJECT_DIR}/META-INFO/api-info")
    if(OpenFOAM_VERSION STREQUAL "" AND EXISTS "${_meta}")
      file(STRINGS "${_meta}" _api REGEX "^api=[0-9]+")
      string(REGEX REPLACE "^api=([0-9]+).*" "\\1" OpenFOAM_VERSION "${_api}")
    endif()
  endforeach()
  if(OpenFOAM_VERSION STREQUAL "" AND OPENFOAM_PACKAGE_VERSION MATCHES "^v?([0-9]+)")
    set(OpenFOAM_VERSION "${CMAKE_MATCH_1}")
  endif()
  set(OPENFOAM_DEFINITIONS WM_${_of_precision} WM_LABEL_SIZE=${_of_label_size} NoRepository)
  if(OpenFOAM_VERSION MATCHES "^[0-9]+$")
    list(APPEND OPENFOAM_DEFINITIONS OPENFOAM=${OpenFOAM_VERSION})
  endif()
  find_program(OPENFOAM_BLOCKMESH blockMesh HINTS "$ENV{FOAM_APPBIN}" /usr/bin
               DOC "OpenFOAM's blockMesh")
  find_program(OPENFOAM_DECOMPOSEPAR decomposePar HINTS "$ENV{FOAM_APPBIN}" /usr/bin
               DOC "OpenFOAM's decomposePar")
  find_program(OPENFOAM_RECONSTRUCTPAR reconstructPar HINTS "$ENV{FOAM_APPBIN}" /usr/bin
               DOC "OpenFOAM's reconstructPar")
  # the MPI libPstream: Debian's beside the serial one; a user's environment names its MPI
  set(OPENFOAM_MPI_PSTREAM_DIR "")
  foreach(_dir "${OPENFOAM_LIBRARY_DIR}/openmpi-system" "${OPENFOAM_LIBRARY_DIR}/$ENV{FOAM_MPI}")
    if(NOT OPENFOAM_MPI_PSTREAM_DIR AND EXISTS "${_dir}/libPstream.so"
       AND NOT "${_dir}" STREQUAL "${OPENFOAM_LIBRARY_DIR}/")
      set(OPENFOAM_MPI_PSTREAM_DIR "${_dir}")
    endif()
  endforeach()
  mark_as_advanced(OPENFOAM_BLOCKMESH OPENFOAM_DECOMPOSEPAR OPENFOAM_RECONSTRUCTPAR)
else()
  set(OPENFOAM_INCLUDE_DIRS "")
endif()

find_package_handle_standard_args(OpenFOAM
  REQUIRED_VARS OPENFOAM_LIBRARY_DIR OPENFOAM_INCLUDE_DIRS
  VERSION_VAR OpenFOAM_VERSION
  REASON_FAILURE_MESSAGE "${_of_reason}")

if(OpenFOAM_FOUND AND NOT TARGET OpenFOAM::OpenFOAM)
  add_library(OpenFOAM::OpenFOAM INTERFACE IMPORTED)
  set_target_properties(OpenFOAM::OpenFOAM PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OPENFOAM_INCLUDE_DIRS}"
    INTERFACE_COMPILE_DEFINITIONS "${OPENFOAM_DEFINITIONS}"
    INTERFACE_COMPILE_OPTIONS "-ftemplate-depth-100"
    INTERFACE_LINK_DIRECTORIES "${_of_link_dirs}"
    INTERFACE_LINK_OPTIONS "LINKER:--no-as-needed")
  set(_of_l "")
  foreach(_lib IN LISTS _of_core_libs)
    list(APPEND _of_l "-l${_lib}")
  endforeach()
  set_property(TARGET OpenFOAM::OpenFOAM PROPERTY INTERFACE_LINK_LIBRARIES ${_of_l} dl m)

  add_library(OpenFOAM::pimpleFoam INTERFACE IMPORTED)
  set(_of_l "")
  foreach(_lib IN LISTS _of_pimple_libs)
    list(APPEND _of_l "-l${_lib}")
  endforeach()
  set_property(TARGET OpenFOAM::pimpleFoam PROPERTY INTERFACE_LINK_LIBRARIES
               ${_of_l} OpenFOAM::OpenFOAM)
endif()

if(OpenFOAM_FOUND AND NOT OpenFOAM_FIND_QUIETLY)
  message(STATUS "OpenFOAM ${OpenFOAM_VERSION} (${OPENFOAM_FLAVOUR}): libraries ${OPENFOAM_LIBRARY_DIR}, headers ${OPENFOAM_SOURCE_TREE}/src, WM_PROJECT_DIR ${OPENFOAM_PROJECT_DIR}")
endif()

unset(_of_reason)
unset(_of_l)
