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
