# bench_thin_walls (bench_thin_walls.cpp): the machined parts' point-to-plane
# error by the thickness of their walls. Included by
# benchmark/CMakeLists.txt and by test/CMakeLists.txt, whose smoke test runs
# it on a small sample of rotor. Always optimised (-O3 -DNDEBUG).
if(NOT TARGET bench_thin_walls)
  add_executable(bench_thin_walls ${CMAKE_CURRENT_LIST_DIR}/bench_thin_walls.cpp)
  target_link_libraries(bench_thin_walls PRIVATE CGAL::Entropy_simplification CGAL::TBB_support)
  target_compile_options(bench_thin_walls PRIVATE -O3)
  target_compile_definitions(bench_thin_walls PRIVATE NDEBUG)
endif()
