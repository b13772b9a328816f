# One static library per top-level folder (style: Monado's drivers/CMakeLists.txt).
# Every .cpp in the folder belongs to the library, so adding a file needs no CMake edit.

function(vdfx_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -pedantic)
  if(VDFX_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# vdfx_add_module(NAME [PUBLIC_LIBS libs...] [PRIVATE_LIBS libs...] [INCLUDE_REGEX regex]
#                  [EXCLUDE_REGEX regex]): the folder's .cpp files (those matching INCLUDE_REGEX,
# less those matching EXCLUDE_REGEX) as the static library vdfx_NAME, alias vdfx::NAME.
function(vdfx_add_module name)
  cmake_parse_arguments(ARG "" "INCLUDE_REGEX;EXCLUDE_REGEX" "PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.cpp")
  if(ARG_INCLUDE_REGEX)
    list(FILTER sources INCLUDE REGEX "${ARG_INCLUDE_REGEX}")
  endif()
  if(ARG_EXCLUDE_REGEX)
    list(FILTER sources EXCLUDE REGEX "${ARG_EXCLUDE_REGEX}")
  endif()
  add_library(vdfx_${name} STATIC ${sources})
  add_library(vdfx::${name} ALIAS vdfx_${name})
  # Includes are written as "effects/rbf_interpolator.h", relative to the repository root.
  target_include_directories(vdfx_${name} PUBLIC "${PROJECT_SOURCE_DIR}")
  target_link_libraries(vdfx_${name} PUBLIC ${ARG_PUBLIC_LIBS} PRIVATE ${ARG_PRIVATE_LIBS})
  vdfx_warnings(vdfx_${name})
endfunction()

# vdfx_source_dir_definition(SOURCES...): the few files that find bundled data in the source tree
# (HMD profiles, the demo) get VDFX_SOURCE_DIR; no other compile line names the checkout, so the
# objects of two checkouts are the same (a compiler cache shares them between worktrees).
function(vdfx_source_dir_definition)
  set_property(SOURCE ${ARGN} APPEND PROPERTY COMPILE_DEFINITIONS VDFX_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endfunction()

# vdfx_room(NAME [GL_FREE]): after vdfx_add_module(NAME ...) in a room of xr/ (xr/input is
# vdfx_xr_input, xr/input/glfw vdfx_xr_input_glfw). The rooms a room may include are the ones its
# target links (vdfx::xr_a_b is xr/a/b, vdfx::math xr/math); before the library compiles, the
# build checks its #include "xr/..." lines against them (cmake/vdfx_room_check.cmake) and fails
# naming the file and the include. A GL-free room links no GL room or GL library and includes no
# GL header, so the light `vdfx` executable and the fuzzers that link it stay GL-free.
function(vdfx_room name)
  cmake_parse_arguments(ARG "GL_FREE" "" "" ${ARGN})
  file(RELATIVE_PATH room "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
  get_target_property(libs vdfx_${name} LINK_LIBRARIES)
  set(allowed "")
  foreach(lib ${libs})
    if(lib STREQUAL "vdfx::math")
      list(APPEND allowed xr/math)
    elseif(lib MATCHES "^vdfx::(xr_.+)$")
      set(dep vdfx_${CMAKE_MATCH_1})
      string(REPLACE "_" "/" folder "${CMAKE_MATCH_1}")
      list(APPEND allowed "${folder}")
      get_target_property(dep_gl_free ${dep} VDFX_GL_FREE)
      if(ARG_GL_FREE AND NOT dep_gl_free)
        message(FATAL_ERROR "${room}/ is GL-free but links ${lib}, a GL room")
      endif()
    elseif(ARG_GL_FREE AND lib MATCHES "EPOXY|glfw|OpenGL|X11|OPENXR")
      message(FATAL_ERROR "${room}/ is GL-free but links ${lib}")
    endif()
  endforeach()
  if(ARG_GL_FREE)
    set(gl_free ON)
  else()
    set(gl_free OFF)
  endif()
  set_target_properties(vdfx_${name} PROPERTIES VDFX_GL_FREE ${gl_free})
  string(REPLACE ";" "," allowed_arg "${allowed}")
  file(GLOB files CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.h"
    "${CMAKE_CURRENT_SOURCE_DIR}/*.cpp")
  set(stamp "${CMAKE_CURRENT_BINARY_DIR}/vdfx_${name}.includes")
  set(script "${PROJECT_SOURCE_DIR}/cmake/vdfx_room_check.cmake")
  add_custom_command(OUTPUT "${stamp}"
    COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR} -DROOM=${room}
      -DALLOWED=${allowed_arg} -DGL_FREE=${gl_free} -DSTAMP=${stamp} -P ${script}
    DEPENDS ${files} "${script}" "${CMAKE_CURRENT_LIST_FILE}"
    COMMENT "Checking the includes of ${room}/"
    VERBATIM)
  add_custom_target(vdfx_${name}_includes DEPENDS "${stamp}")
  add_dependencies(vdfx_${name} vdfx_${name}_includes)
endfunction()
