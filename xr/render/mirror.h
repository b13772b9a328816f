/// @file
/// @brief The mirror window: its modes, where each eye's image lands in it, the desktop view's
/// camera, and the exact inverse: the ray through a window pixel, whatever the mode shows.
///
/// GL-free geometry shared by the compositor (which draws the mirror) and the frame loop (which
/// turns the mouse cursor into the sim's aim ray), so a click hits exactly what is drawn under
/// the cursor: the desktop view is a pinhole; the headset mirrors are undone step by step
/// (letterbox, pre-distortion with its per-pixel inverse lens model, the eye's asymmetric FOV and
/// its offset from the head).
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <optional>
#include <string_view>

#include "effects/lens_model.h"
#include "xr/headset/hmd_profile.h"
#include "xr/headset/pose.h"
#include "xr/headset/render_view.h"
#include "xr/input/input_events.h"

namespace vdfx::xr {

enum class MirrorMode {
  Desktop,         //!< one undistorted cyclopean view filling the window (the sim's default)
  PreDistorted,    //!< both panels side by side, as the displays show them
  ThroughTheLens,  //!< both eyes as the wearer sees them (forward lens model applied)
  SingleEye,       //!< the left eye buffer, undistorted (effects and quads, no lens)
};

/// "desktop", "pre", "lens", "eye".
std::string_view mirror_mode_name(MirrorMode mode);
std::optional<MirrorMode> mirror_mode_from_name(std::string_view name);

/// A rectangle of window pixels, origin top-left, y down.
struct WindowRect {
  int x = 0, y = 0, w = 0, h = 0;
  bool contains(double px, double py) const {
    return px >= x && py >= y && px < x + w && py < y + h;
  }
};

/// Where eye `eye`'s image (eye_w x eye_h) is drawn in a win_w x win_h mirror: the eye modes fit
/// it into the window (SingleEye: the whole window, left eye only) or into its half (the panel
/// modes), keeping its aspect ratio, centred. Desktop: the whole window.
WindowRect mirror_eye_rect(MirrorMode mode, int eye, int eye_w, int eye_h, int win_w, int win_h);

/// The desktop view's camera at the head pose: the head's position and orientation, horizontal
/// FOV hfov_deg, the vertical one from the window's aspect ratio (square pixels), centred.
RenderView desktop_view(const Pose& head, double hfov_deg, int width, int height);

/// What the mirror shows, enough to invert it.
struct MirrorGeometry {
  MirrorMode mode = MirrorMode::Desktop;
  int window_w = 1280, window_h = 720;
  double desktop_hfov_deg = 100.0;
  int eye_w = 1, eye_h = 1;  //!< eye buffer / panel size in pixels
  /// Each eye's view with the head at the origin looking down -z (its offset and orientation in
  /// the head frame), and the lens the pre-distortion inverts.
  std::array<RenderView, 2> eyes;
  effects::LensModel lens;
  bool lca_correction = true;

  /// From a headset profile and the compositor's eye buffer size.
  static MirrorGeometry from_profile(const HmdProfile& profile, MirrorMode mode, int eye_w,
                                     int eye_h, int window_w, int window_h,
                                     double desktop_hfov_deg);
};

/// The ray through the centre-relative window pixel position (x, y) (continuous, origin top-left,
/// as the window system reports the cursor): the ray along which the scene point drawn under
/// that position was rendered. nullopt where nothing is drawn there (letterbox bars, the black
/// beyond a lens's valid radius).
std::optional<ViewRay> mirror_ray(const MirrorGeometry& g, double x, double y);

/// The continuous window position where a head-frame point is drawn (the forward of mirror_ray;
/// tests use it to aim at widget centres). nullopt when it is not visible in the mirror.
std::optional<glm::dvec2> mirror_pixel_of(const MirrorGeometry& g, const glm::dvec3& head_point,
                                          int eye = 0);

}  // namespace vdfx::xr
