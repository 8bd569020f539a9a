# CHOLMOD (SuiteSparse) as the imported target Conforma::cholmod. Debian's SuiteSparse 5.x ships no CMake config,
# so the header and library are found by name. Included by the top-level CMakeLists (conforma_base links it
# PRIVATE) and by the installed ConformaConfig.cmake: the static conforma_base carries $<LINK_ONLY:Conforma::cholmod>
# in the exported targets, so a consumer of the package needs the same target.
if(TARGET Conforma::cholmod)
  return()
endif()
find_path(CONFORMA_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CONFORMA_CHOLMOD_LIBRARY cholmod)
if(NOT CONFORMA_CHOLMOD_INCLUDE_DIR OR NOT CONFORMA_CHOLMOD_LIBRARY)
  set(_conforma_cholmod_message "CHOLMOD (SuiteSparse) not found: header ${CONFORMA_CHOLMOD_INCLUDE_DIR}, library "
                                "${CONFORMA_CHOLMOD_LIBRARY} (Debian: libsuitesparse-dev)")
  if(CMAKE_FIND_PACKAGE_NAME)  # inside find_package(Conforma): report, do not stop the consumer's configure
    set(${CMAKE_FIND_PACKAGE_NAME}_FOUND FALSE)
    set(${CMAKE_FIND_PACKAGE_NAME}_NOT_FOUND_MESSAGE "${_conforma_cholmod_message}")
  else()
    message(FATAL_ERROR "${_conforma_cholmod_message}")
  endif()
  return()
endif()
add_library(Conforma::cholmod UNKNOWN IMPORTED)
set_target_properties(Conforma::cholmod PROPERTIES IMPORTED_LOCATION "${CONFORMA_CHOLMOD_LIBRARY}"
                                                   INTERFACE_INCLUDE_DIRECTORIES "${CONFORMA_CHOLMOD_INCLUDE_DIR}")
