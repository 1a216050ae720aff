# bench_ablation (bench_ablation.cpp): the default mode with each of its
# terms switched off in turn. Included by benchmark/CMakeLists.txt and by
# test/CMakeLists.txt, whose smoke test runs it on small samples. Always
# optimised (-O3 -DNDEBUG).
if(NOT TARGET bench_ablation)
  add_executable(bench_ablation ${CMAKE_CURRENT_LIST_DIR}/bench_ablation.cpp)
  target_link_libraries(bench_ablation PRIVATE CGAL::Entropy_simplification CGAL::TBB_support)
  target_compile_options(bench_ablation PRIVATE -O3)
  target_compile_definitions(bench_ablation PRIVATE NDEBUG)
endif()
