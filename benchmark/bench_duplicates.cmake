# bench_duplicates (bench_duplicates.cpp): time, peak memory and invariants on
# coincident points. Included by benchmark/CMakeLists.txt and by
# test/CMakeLists.txt, whose smoke test runs it: it needs neither TBB nor the
# rest of the benchmark, so the test suite builds it on its own. Always
# optimised (-O3 -DNDEBUG), like the benchmark.
if(NOT TARGET bench_duplicates)
  add_executable(bench_duplicates ${CMAKE_CURRENT_LIST_DIR}/bench_duplicates.cpp)
  target_link_libraries(bench_duplicates PRIVATE CGAL::Entropy_simplification)
  target_compile_options(bench_duplicates PRIVATE -O3)
  target_compile_definitions(bench_duplicates PRIVATE NDEBUG)
endif()
