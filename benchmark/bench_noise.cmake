# bench_noise (bench_noise.cpp): on noisy inputs, the point-to-plane error
# against the noise the kept points carry. Included by
# benchmark/CMakeLists.txt, after it looked for PCL and Open3D, whose peers
# it then runs too, and by test/CMakeLists.txt, whose smoke test runs it on
# small replicas with CGAL's peers. Always optimised (-O3 -DNDEBUG).
if(NOT TARGET bench_noise)
  add_executable(bench_noise ${CMAKE_CURRENT_LIST_DIR}/bench_noise.cpp)
  target_link_libraries(bench_noise PRIVATE CGAL::Entropy_simplification CGAL::TBB_support)
  target_compile_options(bench_noise PRIVATE -O3)
  target_compile_definitions(bench_noise PRIVATE NDEBUG)
  if(PCL_FOUND)
    target_compile_definitions(bench_noise PRIVATE ES_BENCH_WITH_PCL)
    target_link_libraries(bench_noise PRIVATE ${PCL_LIBRARIES})
  endif()
  if(Open3D_FOUND AND TARGET Open3D::Open3D)
    target_compile_definitions(bench_noise PRIVATE ES_BENCH_WITH_OPEN3D)
    target_link_libraries(bench_noise PRIVATE Open3D::Open3D)
  endif()
endif()
