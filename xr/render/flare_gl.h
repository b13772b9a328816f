/// @file
/// @brief The flare layer on the GPU: this frame's flare layouts (effects/flare_layout.h, computed
/// once from the head pose) drawn into an eye as world-space quads in the flare plane, additively,
/// each from that eye's own pose and FOV. Tested against effects::add_flares (the CPU reference).
#pragma once

#include <memory>
#include <vector>

#include "effects/flare_layout.h"
#include "xr/render/eye_layer.h"

namespace vdfx::xr {

class FlareGl final : public EyeLayer {
 public:
  /// Needs a current GL 4.3 context.
  FlareGl();
  ~FlareGl() override;
  FlareGl(const FlareGl&) = delete;
  FlareGl& operator=(const FlareGl&) = delete;

  /// This frame's flares (both eyes draw them); empty draws nothing.
  void set_layouts(std::vector<effects::FlareLayout> layouts);
  const std::vector<effects::FlareLayout>& layouts() const;

  const char* name() const override { return "flare"; }
  void draw(const RenderView& view, int eye, int width, int height) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vdfx::xr
