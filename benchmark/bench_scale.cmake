# bench_scale (bench_scale.cpp): time and peak memory from 100k to 10M
# points against one pca_estimate_normals pass. Included by
# benchmark/CMakeLists.txt and by test/CMakeLists.txt, whose smoke test runs
# it on 20k and 50k points. Always optimised (-O3 -DNDEBUG).
if(NOT TARGET bench_scale)
  add_executable(bench_scale ${CMAKE_CURRENT_LIST_DIR}/bench_scale.cpp)
  target_link_libraries(bench_scale PRIVATE CGAL::Entropy_simplification CGAL::TBB_support)
  target_compile_options(bench_scale PRIVATE -O3)
  target_compile_definitions(bench_scale PRIVATE NDEBUG)
endif()
