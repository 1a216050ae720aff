# es_stb: Debian's libstb-dev (stb_image_write and stb_easy_font headers, the
# code built as libstb), for the program's --render and its tests.
if(NOT TARGET es_stb)
  find_path(STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb)
  find_library(STB_LIBRARY stb)
  if(NOT STB_INCLUDE_DIR OR NOT STB_LIBRARY)
    message(FATAL_ERROR "the program's --render needs stb: install Debian's libstb-dev")
  endif()
  add_library(es_stb INTERFACE)
  target_include_directories(es_stb INTERFACE ${STB_INCLUDE_DIR})
  target_link_libraries(es_stb INTERFACE ${STB_LIBRARY})
endif()
