# The dependency rule of src/ (docs/architecture.md), checked on every source file: a room may
# include only the rooms below it, nothing in src/ includes a header of demo/, and the shim
# includes nothing of src/; inside techniques/, a folder may include only the folders below it,
# and no technique another technique. Run as: cmake -DROOT=<source dir> -P check_layering.cmake
#   media <- scene <- techniques <- measure <- figures <- cli;  demo/ on top.
#   techniques: geometry <- light_passes <- texel_error, plain_gl <- projected <- technique.h
#               <- planar, depth_map, stencil_volume <- technique.cpp (src/techniques/README.md)
cmake_minimum_required(VERSION 3.20)
set(allowed_scene media scene)
set(allowed_techniques media scene techniques)
set(allowed_measure media scene techniques measure)
set(allowed_figures media scene techniques measure figures)
set(allowed_media media)
set(allowed_cli scene techniques measure figures media cli)
set(rooms scene techniques measure figures media cli)

file(GLOB demo_headers RELATIVE ${ROOT}/demo ${ROOT}/demo/*.h)
set(violations "")

foreach(room ${rooms})
  file(GLOB_RECURSE sources ${ROOT}/src/${room}/*.h ${ROOT}/src/${room}/*.cpp)
  foreach(source ${sources})
    file(STRINGS ${source} includes REGEX "^#include \"")
    foreach(line ${includes})
      string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" header "${line}")
      if(header MATCHES "^([a-z_]+)/")
        set(target_room ${CMAKE_MATCH_1})
        if(target_room IN_LIST rooms AND NOT target_room IN_LIST allowed_${room})
          list(APPEND violations "${source}: ${room} may not include ${header}")
        endif()
      endif()
      if(header IN_LIST demo_headers OR header MATCHES "^demo/")
        list(APPEND violations "${source}: src/ may not include demo/'s ${header}")
      endif()
    endforeach()
  endforeach()
endforeach()

# Inside techniques/: the folders each may use (itself included); step_clock.h at the top is
# anyone's, technique.h (the interface, which names the projected technique's options) only
# the three techniques written on it.
set(allowed_geometry geometry)
set(allowed_light_passes geometry light_passes)
set(allowed_texel_error geometry light_passes texel_error)
set(allowed_plain_gl geometry light_passes plain_gl)
set(allowed_projected geometry light_passes texel_error projected)
set(allowed_planar geometry light_passes planar)
set(allowed_depth_map geometry light_passes texel_error plain_gl depth_map)
set(allowed_stencil_volume geometry light_passes plain_gl stencil_volume)
set(technique_folders geometry light_passes texel_error plain_gl projected planar depth_map
    stencil_volume)
set(on_the_interface planar depth_map stencil_volume)
foreach(folder ${technique_folders})
  file(GLOB_RECURSE sources ${ROOT}/src/techniques/${folder}/*.h
       ${ROOT}/src/techniques/${folder}/*.cpp)
  foreach(source ${sources})
    file(STRINGS ${source} includes REGEX "^#include \"techniques/")
    foreach(line ${includes})
      string(REGEX REPLACE "^#include \"techniques/([^\"]+)\".*" "\\1" header "${line}")
      if(header MATCHES "^([a-z_]+)/")
        if(NOT CMAKE_MATCH_1 IN_LIST allowed_${folder})
          list(APPEND violations "${source}: techniques/${folder} may not include ${header}")
        endif()
      elseif(header STREQUAL "technique.h" AND NOT folder IN_LIST on_the_interface)
        list(APPEND violations "${source}: techniques/${folder} may not include technique.h")
      elseif(NOT header MATCHES "^(technique|step_clock)\\.h$")
        list(APPEND violations "${source}: techniques/${header} is in no folder")
      endif()
    endforeach()
  endforeach()
endforeach()

file(GLOB_RECURSE shim_sources ${ROOT}/glide_shim/*.h ${ROOT}/glide_shim/*.cpp)
foreach(source ${shim_sources})
  file(STRINGS ${source} includes REGEX "^#include \"(scene|techniques|measure|figures|media|cli)/")
  foreach(line ${includes})
    list(APPEND violations "${source}: the shim may not include src/: ${line}")
  endforeach()
endforeach()

if(violations)
  list(JOIN violations "\n" report)
  message(FATAL_ERROR "include direction broken:\n${report}")
endif()
list(LENGTH rooms room_count)
list(LENGTH technique_folders folder_count)
message(STATUS "layering: ${room_count} rooms of src/, ${folder_count} folders of techniques/ and the "
               "shim follow the dependency rule")
