/// @file
/// @brief `vdfx hmd list` and `vdfx hmd show NAME|FILE`: the simulated headsets; `vdfx hmd
/// openxr` (a real one) runs from the media module.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include "app/cli/command_functions.h"
#include "effects/coords.h"
#include "xr/headset/hmd_profile.h"

namespace vdfx::app {
namespace {

constexpr const char* kUsage =
    "usage: vdfx hmd list              list the HMD profiles (name, resolution, FOV, refresh)\n"
    "       vdfx hmd show NAME|FILE    print one profile and what follows from it\n"
    "       vdfx hmd openxr            what the active OpenXR runtime and headset offer (runtime,\n"
    "                                  system, views, refresh, swapchain formats, controller\n"
    "                                  profiles; docs/openxr.md)\n";

/// `vdfx hmd openxr`, installed by the media module (it needs GL and the OpenXR loader).
CommandFn g_hmd_openxr = nullptr;

std::string fov_text(const xr::FovDeg& f) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.0fx%.0f deg (L%+.1f R%+.1f U%+.1f D%+.1f)",
                f.angle_right - f.angle_left, f.angle_up - f.angle_down, f.angle_left,
                f.angle_right, f.angle_up, f.angle_down);
  return buf;
}

int list() {
  const auto names = xr::list_hmd_profiles();
  std::printf("%-14s %-11s %-40s %s\n", "name", "per eye", "left eye FOV", "refresh");
  for (const auto& name : names) {
    const xr::HmdProfile p = xr::load_hmd_profile(name);
    const xr::EyeProfile& e = p.eye(xr::Eye::Left);
    const std::string res = std::to_string(e.width) + "x" + std::to_string(e.height);
    std::printf("%-14s %-11s %-40s %.0f Hz\n", p.name.c_str(), res.c_str(), fov_text(e.fov).c_str(),
                p.refresh_hz);
  }
  if (names.empty()) std::cerr << "no profiles in " << xr::hmd_profile_dir().string() << "\n";
  return kExitOk;
}

int show(const std::string& arg) {
  const xr::HmdProfile p = xr::load_hmd_profile(arg);
  std::printf("name         %s\nfile         %s\n", p.name.c_str(), p.source.c_str());
  if (!p.description.empty()) std::printf("description  %s\n", p.description.c_str());
  std::printf("refresh      %.3f Hz\nipd          %.4f m\n", p.refresh_hz, p.ipd_m);
  const effects::LensModel lens(p.lens);
  std::printf("distortion   r_d = r_u + %.4g r_u^3 + %.4g r_u^5, r = tan / %.4g\n", p.lens.c1,
              p.lens.c2, p.lens.radius);
  if (std::isfinite(lens.max_undistorted_radius())) {
    std::printf("monotonic    up to r_u = %.6g (panel r_d = %.6g); beyond: black\n",
                lens.max_undistorted_radius(), lens.max_distorted_radius());
  } else {
    std::printf("monotonic    everywhere\n");
  }
  std::printf("lca scale    R %.4f  G %.4f  B %.4f\n", p.lens.lca_scale[0], p.lens.lca_scale[1],
              p.lens.lca_scale[2]);
  for (const xr::Eye e : xr::kEyes) {
    const xr::EyeProfile& ep = p.eye(e);
    const effects::EyeLens eye = p.eye_lens(e);
    const Eigen::Vector2d c = eye.centre_pixel();
    // What the panel's edge midpoints show through the lens (the visible FOV, channel G).
    const auto seen = [&](double x, double y) {
      const auto t =
          eye.lens.panel_to_view(eye.pixel_to_tan({x, y}), 1, effects::InverseMethod::Newton);
      return t ? *t : Eigen::Vector2d::Constant(std::nan(""));
    };
    const double deg = effects::kRadToDeg;
    std::printf("%-5s eye    %dx%d px, FOV %s\n", std::string(xr::eye_name(e)).c_str(), ep.width,
                ep.height, fov_text(ep.fov).c_str());
    std::printf("             lens centre [%.5f, %.5f] = pixel (%.1f, %.1f)\n", ep.lens_centre[0],
                ep.lens_centre[1], c.x(), c.y());
    std::printf("             visible through the lens: L%+.1f R%+.1f U%+.1f D%+.1f deg\n",
                std::atan(seen(0, c.y()).x()) * deg, std::atan(seen(ep.width, c.y()).x()) * deg,
                std::atan(seen(c.x(), 0).y()) * deg, std::atan(seen(c.x(), ep.height).y()) * deg);
  }
  return kExitOk;
}

}  // namespace

void set_hmd_openxr_command(CommandFn command) {
  g_hmd_openxr = command;
}

int cmd_hmd(const Args& args) {
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << kUsage;
    return kExitOk;
  }
  if (args.size() == 1 && args[0] == "list") return list();
  if (args.size() == 2 && args[0] == "show") return show(args[1]);
  if (!args.empty() && args[0] == "openxr")
    return g_hmd_openxr ? g_hmd_openxr(Args(args.begin() + 1, args.end())) : kExitRunInMediaModule;
  std::cerr << kUsage;
  return kExitUsage;
}

}  // namespace vdfx::app
