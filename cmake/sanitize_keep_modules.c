/* Sanitizer builds only (cmake/vdfx_sanitize.cmake links this into the vdfx executable and every
 * test binary): dlclose does nothing, so a shared library loaded at run time stays mapped until
 * the process ends. GLFW and libglvnd unload the GL driver (Mesa's libGLX_mesa, the swrast DRI
 * driver, LLVM) before LeakSanitizer looks at exit; the memory the driver still held then had no
 * owner left, and LeakSanitizer reported it with stacks ending in "<unknown module>" (128 to 240
 * bytes in every GL test), which no suppression could tell from a leak of vdfx's. Kept mapped,
 * the driver's own globals still point at that memory, so it is reachable and not reported, and
 * no suppression is needed for it: what vdfx itself leaks is still found. */
#include <dlfcn.h>

int dlclose(void* handle) {
  (void)handle;
  return 0;
}
