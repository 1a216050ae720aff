# bench_lod (bench_lod.cpp): the cost of the whole order of levels of detail
# against one direct call, and the quality of its prefixes. Included by
# benchmark/CMakeLists.txt and by test/CMakeLists.txt, whose smoke test runs
# it on small samples. Always optimised (-O3 -DNDEBUG).
if(NOT TARGET bench_lod)
  add_executable(bench_lod ${CMAKE_CURRENT_LIST_DIR}/bench_lod.cpp)
  target_link_libraries(bench_lod PRIVATE CGAL::Entropy_simplification CGAL::TBB_support)
  target_compile_options(bench_lod PRIVATE -O3)
  target_compile_definitions(bench_lod PRIVATE NDEBUG)
endif()
