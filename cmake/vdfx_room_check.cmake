# cmake -P script: checks one room's #include lines against the rooms it declares.
#   -DROOT=<repository root> -DROOM=<folder, e.g. xr/input> -DALLOWED=<folders, ,-separated>
#   -DGL_FREE=ON|OFF [-DSTAMP=<file written when the room passes>]
# Every `#include "xr/FOLDER/name.h"` in ROOM's .h and .cpp files (not its sub-folders, which are
# rooms of their own) must name ROOM itself or a folder in ALLOWED; a GL-free room includes no
# GL, GLX, EGL, GLFW or Xlib header. Fails naming the file, the line and the include.
cmake_minimum_required(VERSION 3.20)
foreach(var ROOT ROOM)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "vdfx_room_check.cmake: -D${var}= is required")
  endif()
endforeach()

string(REPLACE "," ";" ALLOWED "${ALLOWED}")
file(GLOB files "${ROOT}/${ROOM}/*.h" "${ROOT}/${ROOM}/*.cpp")
list(SORT files)
set(errors "")
foreach(file ${files})
  file(RELATIVE_PATH rel "${ROOT}" "${file}")
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include")
  foreach(line ${lines})
    if(line MATCHES "#[ \t]*include[ \t]*\"(xr/.*)/[^/\"]+\"")
      set(folder "${CMAKE_MATCH_1}")
      if(NOT folder STREQUAL ROOM AND NOT folder IN_LIST ALLOWED)
        string(APPEND errors "${rel}: ${line}: ${folder}/ is a room ${ROOM}/ does not declare "
          "(declared: ${ALLOWED})\n")
      endif()
    elseif(GL_FREE AND line MATCHES "#[ \t]*include[ \t]*<(epoxy|GL|GLFW|EGL|X11)/")
      string(APPEND errors "${rel}: ${line}: ${ROOM}/ is GL-free\n")
    endif()
  endforeach()
endforeach()

if(errors)
  message(FATAL_ERROR "room includes:\n${errors}")
endif()
if(DEFINED STAMP)
  file(WRITE "${STAMP}" "${ROOM}: ${ALLOWED}\n")
endif()
