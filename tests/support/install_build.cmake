# Installs the build tree into a temporary prefix, moves the prefix elsewhere (so nothing can
# depend on the install path), then builds SOURCE against the moved copy twice, as a program
# outside this project would: with `pkg-config --cflags --libs glide2x` alone, and as a CMake
# project with find_package(glide2x). Each build is run with the arguments OUT.png and must
# write it. Used by the porting.install.* tests.
#   BUILD_DIR: the build tree to install; WORK_DIR: scratch (removed first); MODE: pkgconfig or
#   cmake; EXTRA_FLAGS: compiler flags the library's build needs in its programs too.
file(REMOVE_RECURSE ${WORK_DIR})
set(staged ${WORK_DIR}/staged)
set(prefix ${WORK_DIR}/moved/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${staged}
  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BUILD_DIR} --prefix ${staged} failed:\n${output}")
endif()
file(MAKE_DIRECTORY ${WORK_DIR}/moved)
file(RENAME ${staged} ${prefix})
get_filename_component(program ${SOURCE} NAME_WE)
set(image ${WORK_DIR}/${program}.png)
separate_arguments(extra_flags UNIX_COMMAND "${EXTRA_FLAGS}")

if(MODE STREQUAL "pkgconfig")
  # Only the moved prefix's pkgconfig directory: neither the build tree's file nor a system one.
  set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
  set(ENV{PKG_CONFIG_LIBDIR} ${prefix}/lib/pkgconfig)
  execute_process(COMMAND pkg-config --cflags --libs glide2x
    OUTPUT_VARIABLE flags RESULT_VARIABLE status ERROR_VARIABLE errors OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "pkg-config cannot read the installed glide2x.pc:\n${errors}")
  endif()
  if(NOT flags MATCHES "-I${prefix}/lib/pkgconfig/../../include/glide2x")
    message(FATAL_ERROR "the installed glide2x.pc does not point into the moved prefix ${prefix}: ${flags}")
  endif()
  separate_arguments(flags UNIX_COMMAND "${flags}")
  execute_process(COMMAND cc -std=c99 -Wall -Wextra -Werror -pedantic ${extra_flags} ${SOURCE}
                          -o ${WORK_DIR}/${program} ${flags}
    RESULT_VARIABLE status ERROR_VARIABLE errors)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "compiling ${SOURCE} with the installed glide2x.pc failed:\n${errors}")
  endif()
  set(executable ${WORK_DIR}/${program})
elseif(MODE STREQUAL "cmake")
  set(project_dir ${WORK_DIR}/project)
  file(MAKE_DIRECTORY ${project_dir})
  file(WRITE ${project_dir}/CMakeLists.txt "cmake_minimum_required(VERSION 3.20)
project(glide_consumer C)
find_package(glide2x 0.1 REQUIRED)
add_executable(${program} \"${SOURCE}\")
set_target_properties(${program} PROPERTIES C_STANDARD 99)
target_compile_options(${program} PRIVATE ${EXTRA_FLAGS})
target_link_options(${program} PRIVATE ${EXTRA_FLAGS})
target_link_libraries(${program} PRIVATE glide2x::glide2x)
")
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${project_dir} -B ${project_dir}/build
                          -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release
    RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "configuring a project with find_package(glide2x) failed:\n${output}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${project_dir}/build
    RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "building against glide2x::glide2x failed:\n${output}")
  endif()
  set(executable ${project_dir}/build/${program})
else()
  message(FATAL_ERROR "MODE must be pkgconfig or cmake")
endif()

execute_process(COMMAND ${executable} ${image} RESULT_VARIABLE status
  OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${executable} built against the installed copy exited with ${status}:\n${output}")
endif()
if(NOT EXISTS ${image})
  message(FATAL_ERROR "${executable} ran but did not write ${image}")
endif()
# The program must have run the installed library, not the build tree's.
execute_process(COMMAND ldd ${executable} OUTPUT_VARIABLE libraries)
string(REGEX MATCH "libglide2x[^\n]*" linked "${libraries}")
if(NOT linked MATCHES "${prefix}/lib")
  message(FATAL_ERROR "${executable} loads ${linked}, not the copy in ${prefix}/lib")
endif()
