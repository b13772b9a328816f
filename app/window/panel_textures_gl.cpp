/// @file
/// @brief create_gl_panel_textures: panel images as mipmapped GL textures (xr::GlTexture).
#include <stdexcept>
#include <vector>

#include "app/window/editor_client.h"
#include "xr/render/gl_texture.h"

namespace vdfx::app {

namespace {

class GlPanelTextures : public PanelTextures {
 public:
  /// Frees nothing: the window's context may be gone (release() frees them while it is not).
  ~GlPanelTextures() override {
    for (xr::GlTexture& t : textures_) t.disown();
  }

  unsigned upload(std::size_t slot, const cv::Mat& image,
                  const std::vector<cv::Rect>& regions) override {
    if (image.type() != CV_8UC4 || !image.isContinuous())
      throw std::invalid_argument("GlPanelTextures::upload: continuous RGBA8 image expected");
    if (textures_.size() <= slot) textures_.resize(slot + 1);
    xr::GlTexture& t = textures_[slot];
    const cv::Rect whole(0, 0, image.cols, image.rows);
    if (!t || t.width() != image.cols || t.height() != image.rows) {
      // A 1000-2000 px panel covers a few hundred eye pixels: without mipmaps text aliases
      // (the texture samples trilinearly, clamped at the edges).
      t = xr::GlTexture(image.cols, image.rows, xr::TexFormat::RGBA8,
                        xr::full_mip_levels(image.cols, image.rows));
      t.upload_rgba_region(image, whole);
    } else if (regions.empty()) {
      t.upload_rgba_region(image, whole);
    } else {
      for (const cv::Rect& r : regions) t.upload_rgba_region(image, r);
    }
    t.generate_mipmaps();
    return t.id();
  }

  void release() override { textures_.clear(); }

 private:
  std::vector<xr::GlTexture> textures_;
};

}  // namespace

std::unique_ptr<PanelTextures> create_gl_panel_textures() {
  return std::make_unique<GlPanelTextures>();
}

}  // namespace vdfx::app
