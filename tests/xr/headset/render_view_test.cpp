/// @file
/// @brief xr::RenderView and effects::ViewCamera describe the same pixel <-> ray mapping: the GPU
/// view, its camera(), the CPU reference's own constructors and the documented tangent formula
/// must agree for symmetric and asymmetric views.
#include "xr/headset/render_view.h"

#include <gtest/gtest.h>

#include <cmath>

#include "effects/view_camera.h"

namespace vdfx::xr {
namespace {

using effects::Direction;
using effects::FovAngles;
using effects::ViewCamera;

struct Case {
  const char* name;
  RenderView view;
  ViewCamera reference;  //!< built the CPU reference's way, independently of RenderView
  int width, height;
};

std::vector<Case> cases() {
  const Direction a{35, -20}, b{-170, 75};
  const FovAngles eye{-0.9, 0.5, 0.7, -0.6};  // left, right, up, down
  return {
      {"symmetric 90 deg", RenderView::look_at(a, 15, 90, 160, 120),
       ViewCamera::from_horizontal_fov({a, 15}, 90, 160, 120), 160, 120},
      {"symmetric near a pole, rolled", RenderView::look_at(b, -40, 60, 64, 96),
       ViewCamera::from_horizontal_fov({b, -40}, 60, 64, 96), 64, 96},
      {"asymmetric eye, non-square pixels",
       RenderView::from_angles(view_rotation(b, 25), eye.angle_left, eye.angle_right,
                               eye.angle_down, eye.angle_up),
       ViewCamera::from_fov_angles({b, 25}, eye, 90, 50), 90, 50},
  };
}

TEST(RenderView, AgreesWithTheCpuCamera) {
  for (const Case& c : cases()) {
    const ViewCamera cam = c.view.camera(c.width, c.height);
    EXPECT_NEAR(cam.fx(), c.reference.fx(), 1e-9 * c.reference.fx()) << c.name;
    EXPECT_NEAR(cam.fy(), c.reference.fy(), 1e-9 * c.reference.fy()) << c.name;
    EXPECT_NEAR(cam.cx(), c.reference.cx(), 1e-9 * c.width) << c.name;
    EXPECT_NEAR(cam.cy(), c.reference.cy(), 1e-9 * c.height) << c.name;
    EXPECT_LE((cam.camera_to_world() - c.reference.camera_to_world()).norm(), 1e-12) << c.name;
    const double w = c.width, h = c.height;
    for (const double px : {0.0, 0.5, 0.37 * w, w - 0.5, w})
      for (const double py : {0.0, 0.5, 0.61 * h, h}) {
        // The documented formula (render_view.h), written out here.
        const double tx = c.view.tan_left + px / w * (c.view.tan_right - c.view.tan_left);
        const double ty = c.view.tan_up - py / h * (c.view.tan_up - c.view.tan_down);
        const Eigen::Vector2d t = c.view.tangent_at(px, py, c.width, c.height);
        EXPECT_NEAR(t.x(), tx, 1e-12) << c.name;
        EXPECT_NEAR(t.y(), ty, 1e-12) << c.name;
        const Eigen::Vector3d ray = c.view.world_ray(px, py, c.width, c.height);
        EXPECT_LE((ray - c.reference.ray(px, py)).norm(), 1e-12)
            << c.name << " " << px << "," << py;
        EXPECT_LE((ray - (c.view.orientation * Eigen::Vector3d(tx, ty, -1)).normalized()).norm(),
                  1e-12);
        // Round trips: tangent -> pixel, and the CPU projection of the ray.
        EXPECT_LE((c.view.pixel_at(t, c.width, c.height) - Eigen::Vector2d(px, py)).norm(), 1e-9);
        const auto back = c.reference.project(ray);
        ASSERT_TRUE(back) << c.name;
        EXPECT_LE((*back - Eigen::Vector2d(px, py)).norm(), 1e-9) << c.name;
      }
  }
}

TEST(RenderView, OneFovConversion) {
  const FovAngles eye{-0.9, 0.5, 0.7, -0.6};
  const effects::TanRect t = eye.tangents();
  EXPECT_DOUBLE_EQ(t.left, std::tan(-0.9));
  EXPECT_DOUBLE_EQ(t.up, std::tan(0.7));
  const RenderView v = RenderView::from_angles(Eigen::Matrix3d::Identity(), eye.angle_left,
                                               eye.angle_right, eye.angle_down, eye.angle_up);
  EXPECT_DOUBLE_EQ(v.tangents().right, t.right);
  EXPECT_DOUBLE_EQ(v.tangents().down, t.down);
  // An empty or beyond-90-degree FOV has no tangent rectangle.
  EXPECT_THROW((FovAngles{0.5, -0.5, 0.5, -0.5}.tangents()), std::invalid_argument);
  EXPECT_THROW((FovAngles{-1.6, 0.5, 0.5, -0.5}.tangents()), std::invalid_argument);
  EXPECT_THROW(ViewCamera::from_tangents(Eigen::Matrix3d::Identity(), {1, -1, 1, -1}, 8, 8),
               std::invalid_argument);
}

TEST(RenderView, ProjectionPutsWorldPointsOnTheirPixels) {
  // The GL path (quads, flare) projects world points with projection() * world_to_eye(); the
  // result must land on the pixel the camera's ray mapping gives, for any eye position.
  for (const Case& c : cases()) {
    RenderView v = c.view;
    v.position = Eigen::Vector3d(0.03, 1.6, -0.2);
    const ViewCamera cam = v.camera(c.width, c.height);
    for (const double n : {1e-3, 0.05}) {
      for (const double f : {100.0, 0.0 /* infinite */}) {
        const Eigen::Matrix4d m = v.projection(n, f) * v.world_to_eye();
        for (const auto& px :
             {Eigen::Vector2d(3.5, 7.25), Eigen::Vector2d(c.width - 1.0, c.height * 0.5)}) {
          for (const double dist : {0.05, 2.0, 90.0}) {
            const Eigen::Vector3d p = v.position + dist * cam.ray(px.x(), px.y());
            const Eigen::Vector4d clip = m * p.homogeneous();
            const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
            EXPECT_NEAR(0.5 * (ndc.x() + 1.0) * c.width, px.x(), 1e-9) << c.name;
            EXPECT_NEAR(0.5 * (1.0 - ndc.y()) * c.height, px.y(), 1e-9) << c.name;
            // Between the near and far planes a point is inside the depth range (never clipped).
            const double depth = -(v.world_to_eye() * p.homogeneous()).z();
            if (depth <= n || (f > n && depth >= f)) continue;
            const double z = clip.z() / clip.w();
            EXPECT_GT(z, -1.0) << c.name << " dist " << dist;
            EXPECT_LT(z, 1.0) << c.name << " dist " << dist;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace vdfx::xr
