# Real point clouds and meshes ship in Debian's libcgal-demo as one archive.
# Unpack it once into the build tree; ES_DATA_DIR is empty when it is absent.
set(ENTROPY_SIMPLIFICATION_DATA_ARCHIVE "/usr/share/doc/libcgal-demo/data.tar.gz"
    CACHE FILEPATH "CGAL's demo data archive (package libcgal-demo)")
set(ES_DATA_DIR "")
if(EXISTS "${ENTROPY_SIMPLIFICATION_DATA_ARCHIVE}")
  set(_es_data_root "${CMAKE_BINARY_DIR}/cgal_data")
  if(NOT EXISTS "${_es_data_root}/data/points_3/kitten.xyz")
    message(STATUS "Unpacking ${ENTROPY_SIMPLIFICATION_DATA_ARCHIVE}")
    file(MAKE_DIRECTORY "${_es_data_root}")
    file(ARCHIVE_EXTRACT INPUT "${ENTROPY_SIMPLIFICATION_DATA_ARCHIVE}"
         DESTINATION "${_es_data_root}")
  endif()
  set(ES_DATA_DIR "${_es_data_root}/data")
else()
  message(STATUS "No CGAL demo data (${ENTROPY_SIMPLIFICATION_DATA_ARCHIVE}): "
                 "install libcgal-demo for the tests and benchmarks on real data")
endif()
