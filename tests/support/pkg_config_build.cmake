# Builds SOURCE with the C compiler and pkg-config only (no CMake target), runs it, and checks
# that it wrote its PNG. Used by the porting.pkg_config_build test.
file(MAKE_DIRECTORY ${OUTPUT_DIR})
set(ENV{PKG_CONFIG_PATH} ${PKG_CONFIG_PATH})
execute_process(COMMAND pkg-config --cflags --libs glide2x
  OUTPUT_VARIABLE flags RESULT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "pkg-config does not know glide2x (PKG_CONFIG_PATH=${PKG_CONFIG_PATH})")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
# EXTRA_FLAGS: compiler flags the library's build needs in its programs too (sanitizers).
separate_arguments(extra_flags UNIX_COMMAND "${EXTRA_FLAGS}")
execute_process(COMMAND cc -std=c99 -Wall -Wextra -Werror -pedantic ${extra_flags} ${SOURCE} -o ${OUTPUT_DIR}/hello ${flags}
  RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "compiling ${SOURCE} against glide.h failed:\n${errors}")
endif()
file(REMOVE ${OUTPUT_DIR}/hello.png)
execute_process(COMMAND ${OUTPUT_DIR}/hello ${OUTPUT_DIR}/hello.png RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT EXISTS ${OUTPUT_DIR}/hello.png)
  message(FATAL_ERROR "the pkg-config build ran but did not write its PNG")
endif()
