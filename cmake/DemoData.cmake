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

# The LAS files of libcgal-demo ship in its examples and demo archives.
set(ES_LAS_DATA_DIR "")
set(_es_las_archives
  "/usr/share/doc/libcgal-demo/examples.tar.gz|examples/Point_set_processing_3/data/urban.las"
  "/usr/share/doc/libcgal-demo/examples.tar.gz|examples/Point_set_processing_3/data/pig_points.las"
  "/usr/share/doc/libcgal-demo/demo.tar.gz|demo/Polyhedron/testing/data/oni.las")
set(_es_las_root "${CMAKE_BINARY_DIR}/cgal_data/las")
foreach(_es_entry ${_es_las_archives})
  string(REPLACE "|" ";" _es_entry "${_es_entry}")
  list(GET _es_entry 0 _es_archive)
  list(GET _es_entry 1 _es_member)
  get_filename_component(_es_name "${_es_member}" NAME)
  if(EXISTS "${_es_archive}" AND NOT EXISTS "${_es_las_root}/${_es_name}")
    file(MAKE_DIRECTORY "${_es_las_root}/unpacked")
    execute_process(COMMAND tar xzf "${_es_archive}" "${_es_member}" WORKING_DIRECTORY "${_es_las_root}/unpacked")
    configure_file("${_es_las_root}/unpacked/${_es_member}" "${_es_las_root}/${_es_name}" COPYONLY)
  endif()
endforeach()
if(EXISTS "${_es_las_root}/urban.las" AND EXISTS "${_es_las_root}/pig_points.las" AND EXISTS "${_es_las_root}/oni.las")
  set(ES_LAS_DATA_DIR "${_es_las_root}")
endif()
