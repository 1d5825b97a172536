# Builds SOURCE with the C compiler and pkg-config only (no CMake target), runs it with ARGS
# (a command line, quoted as in a shell; GLIDESHIM_DUMP_DIR set to OUTPUT_DIR/frames), and checks that EXPECT, a file the
# run must write, exists. Used by the porting.pkg_config_build.* tests.
#   LIBS: libraries the program needs beyond glide2x (-lm); EXTRA_FLAGS: compiler flags the
#   library's build needs in its programs too (sanitizers).
get_filename_component(program ${SOURCE} NAME_WE)
file(REMOVE_RECURSE ${OUTPUT_DIR})
file(MAKE_DIRECTORY ${OUTPUT_DIR}/frames)
set(ENV{PKG_CONFIG_PATH} ${PKG_CONFIG_PATH})
execute_process(COMMAND pkg-config --cflags --libs glide2x
  OUTPUT_VARIABLE flags RESULT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "pkg-config does not know glide2x (PKG_CONFIG_PATH=${PKG_CONFIG_PATH})")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
separate_arguments(extra_flags UNIX_COMMAND "${EXTRA_FLAGS}")
separate_arguments(libs UNIX_COMMAND "${LIBS}")
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND cc -std=c99 -Wall -Wextra -Werror -pedantic ${extra_flags} ${SOURCE}
                        -o ${OUTPUT_DIR}/${program} ${flags} ${libs}
  RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "compiling ${SOURCE} against glide.h failed:\n${errors}")
endif()
set(ENV{GLIDESHIM_DUMP_DIR} ${OUTPUT_DIR}/frames)
execute_process(COMMAND ${OUTPUT_DIR}/${program} ${args} RESULT_VARIABLE status
  OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the pkg-config build of ${program} exited with ${status}:\n${output}")
endif()
if(NOT EXISTS ${EXPECT})
  message(FATAL_ERROR "the pkg-config build of ${program} ran but did not write ${EXPECT}")
endif()
