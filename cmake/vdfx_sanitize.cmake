# Sanitizer and fuzzing builds (issue 11; docs/reliability.md, "Sanitizers and fuzzing").
#  VDFX_SANITIZE=ON  AddressSanitizer + UndefinedBehaviorSanitizer on every target (gcc or clang);
#                    any undefined behaviour aborts (-fno-sanitize-recover), leaks fail at exit.
#                    CI (.ci/sanitize.sh) builds all of vdfx this way with clang, GL and
#                    VDFX_FUZZ, and runs the whole suite (docs/reliability.md).
#  VDFX_FUZZ=ON      the libFuzzer targets of tests/fuzz (clang only); implies the sanitizers and
#                    instruments every library for coverage (-fsanitize=fuzzer-no-link).
#                    .ci/fuzz.sh runs each target for 60 s in CI.
option(VDFX_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(VDFX_FUZZ "Build the libFuzzer targets (clang; implies VDFX_SANITIZE)" OFF)

if(VDFX_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "VDFX_FUZZ needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++-14 "
                        "-DCMAKE_C_COMPILER=clang-14 (Debian: clang-14, libclang-rt-14-dev)")
  endif()
  set(VDFX_SANITIZE ON CACHE BOOL "" FORCE)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(VDFX_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC's flow analysis sees through ASan's instrumented code badly: -Wmaybe-uninitialized then
    # fires inside libstdc++ (std::regex's std::function, xr/render/gl_program.cpp) where the plain
    # build is clean. The plain build keeps the warning, as an error with VDFX_WERROR.
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
endif()

# vdfx_keep_modules_loaded(TARGET): in a sanitizer build, TARGET's dlclose does nothing (the GL
# driver stays mapped, so what it holds at exit stays reachable; cmake/sanitize_keep_modules.c).
function(vdfx_keep_modules_loaded target)
  if(VDFX_SANITIZE)
    target_sources(${target} PRIVATE "${PROJECT_SOURCE_DIR}/cmake/sanitize_keep_modules.c")
  endif()
endfunction()
