# bench_quality_baseline (bench_quality_baseline.cpp): the default mode's
# quality in each cell of a run against the baseline of issue 10. Included by
# benchmark/CMakeLists.txt and by test/CMakeLists.txt, which runs it on the
# baseline itself. Reads CSV files only.
if(NOT TARGET bench_quality_baseline)
  add_executable(bench_quality_baseline ${CMAKE_CURRENT_LIST_DIR}/bench_quality_baseline.cpp)
endif()
