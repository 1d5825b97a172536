# The installed glide2x package (the glideshadows Glide 2.x shim): find_package(glide2x) defines
# glide2x::glide2x, the shared library with its include directory (include/glide2x), found
# relative to this file so the prefix may be moved after installing.
include(${CMAKE_CURRENT_LIST_DIR}/glide2xTargets.cmake)
