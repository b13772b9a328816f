/// @file
/// @brief OpenXR with its OpenGL/Xlib platform types. GL and GLX come from libepoxy (the one GL
/// loader of vdfx); X11's headers define macros such as None and Bool, so include this last.
#pragma once

#include <epoxy/gl.h>
#include <epoxy/glx.h>

#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>
