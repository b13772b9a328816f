# cmake -P -DROOT=<repository root> -DWORK=<scratch folder>: the build's room check
# (cmake/vdfx_room_check.cmake, run before each xr/ room compiles) on rooms written here: what a
# room declares passes, an undeclared room or a GL header in a GL-free room fails naming the file.
cmake_minimum_required(VERSION 3.20)
set(failures "")

# check(ROOM ALLOWED GL_FREE INCLUDE EXPECT): ROOM/a.cpp holds INCLUDE; EXPECT is "" (passes) or
# text the failure must contain.
function(check room allowed gl_free include expect)
  file(REMOVE_RECURSE "${WORK}/xr")
  file(WRITE "${WORK}/${room}/a.cpp" "#include \"${room}/a.h\"\n${include}\nint f();\n")
  file(WRITE "${WORK}/${room}/sub/b.cpp" "#include \"xr/render/gl_context.h\"\n")  # not ROOM's
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${WORK} -DROOM=${room} -DALLOWED=${allowed}
    -DGL_FREE=${gl_free} -P "${ROOT}/cmake/vdfx_room_check.cmake"
    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
  string(REGEX REPLACE "[ \n]+" " " err "${err}")
  set(what "${room} [${allowed}] gl_free=${gl_free} '${include}'")
  if(expect STREQUAL "" AND NOT rc EQUAL 0)
    set(failures "${failures}${what}: should pass, failed: ${err}\n" PARENT_SCOPE)
  elseif(NOT expect STREQUAL "")
    string(FIND "${err}" "${expect}" at)
    if(rc EQUAL 0 OR at EQUAL -1)
      set(failures "${failures}${what}: should fail with '${expect}', rc ${rc}: ${err}\n"
        PARENT_SCOPE)
    endif()
  endif()
endfunction()

check(xr/input "xr/headset" ON "#include \"xr/headset/pose.h\"" "")
check(xr/input "xr/headset" ON "#include \"xr/render/compositor.h\""
  "xr/input/a.cpp: #include \"xr/render/compositor.h\": xr/render/ is a room xr/input/ does not declare")
check(xr/input "xr/headset" ON "#include \"xr/input/glfw/glfw_input_glue.h\""
  "xr/input/glfw/ is a room xr/input/ does not declare")
check(xr/openxr "xr/input,xr/headset" ON "#include \"xr/headset/session.h\"" "")
check(xr/headset "xr/math" ON "#include <epoxy/gl.h>" "xr/headset/a.cpp: #include <epoxy/gl.h>: xr/headset/ is GL-free")
check(xr/input "xr/headset" ON "#include <GLFW/glfw3.h>" "xr/input/ is GL-free")
check(xr/render "xr/headset,xr/input" OFF "#include <epoxy/gl.h>" "")
check(xr/render "xr/headset,xr/input" OFF "#include \"xr/openxr/gl/openxr_runtime.h\""
  "xr/openxr/gl/ is a room xr/render/ does not declare")
file(REMOVE_RECURSE "${WORK}/xr")

if(failures)
  message(FATAL_ERROR "room check:\n${failures}")
endif()
message(STATUS "room check: 8 cases as expected")
