/* @file
 * @brief LD_PRELOADed into Khronos's hello_xr by its test: hello_xr's OpenGL window code
 * (OpenXR-SDK's gfxwrapper_opengl.c, ksGpuWindow_Create) calls XF86VidModeGetAllModeLines
 * without checking that the X server has the XFree86-VidModeExtension, and reads the first mode
 * it returns. Xvfb (the test display) has no such extension, so hello_xr would crash before
 * talking to the runtime. This stands in for libXxf86vm's three calls hello_xr makes: one mode,
 * the screen's size at 60 Hz; switching modes does nothing (the window is not fullscreen).
 */
#include <X11/Xlib.h>
#include <stdlib.h>

/* libXxf86vm's public XF86VidModeModeInfo (X11/extensions/xf86vmode.h, not installed here). */
typedef struct {
  unsigned int dotclock; /* kHz */
  unsigned short hdisplay, hsyncstart, hsyncend, htotal, hskew;
  unsigned short vdisplay, vsyncstart, vsyncend, vtotal;
  unsigned int flags;
  int privsize;
  int* private_data;
} VidModeInfo;

__attribute__((visibility("default"))) Bool XF86VidModeGetAllModeLines(Display* display, int screen,
                                                                       int* count,
                                                                       VidModeInfo*** modes) {
  /* One block, array then mode, as the library allocates it: the caller frees it with XFree. */
  VidModeInfo** list = calloc(1, sizeof(VidModeInfo*) + sizeof(VidModeInfo));
  if (!list) return False;
  VidModeInfo* mode = (VidModeInfo*)(list + 1);
  mode->hdisplay = mode->htotal = (unsigned short)DisplayWidth(display, screen);
  mode->vdisplay = mode->vtotal = (unsigned short)DisplayHeight(display, screen);
  mode->dotclock = (unsigned int)(60.0 * mode->htotal * mode->vtotal / 1000.0);
  list[0] = mode;
  *count = 1;
  *modes = list;
  return True;
}

__attribute__((visibility("default"))) Bool XF86VidModeSwitchToMode(Display* display, int screen,
                                                                    VidModeInfo* mode) {
  (void)display;
  (void)screen;
  (void)mode;
  return True;
}

__attribute__((visibility("default"))) Bool XF86VidModeSetViewPort(Display* display, int screen,
                                                                   int x, int y) {
  (void)display;
  (void)screen;
  (void)x;
  (void)y;
  return True;
}
