/// @file
/// @brief create_gl_panel_textures: panel images as mipmapped GL textures.
#include <epoxy/gl.h>

#include <stdexcept>

#include "app/window/editor_client.h"

namespace vdfx::app {

namespace {

class GlPanelTextures : public PanelTextures {
 public:
  unsigned upload(std::size_t slot, const cv::Mat& image,
                  const std::vector<cv::Rect>& regions) override {
    if (image.type() != CV_8UC4 || !image.isContinuous())
      throw std::invalid_argument("GlPanelTextures::upload: continuous RGBA8 image expected");
    if (names_.size() <= slot) names_.resize(slot + 1, 0u);
    unsigned& name = names_[slot];
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (!name || regions.empty()) {
      if (!name) glGenTextures(1, &name);
      glBindTexture(GL_TEXTURE_2D, name);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.cols, image.rows, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   image.data);
      // A 1000-2000 px panel covers a few hundred eye pixels: without mipmaps text aliases.
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    } else {
      glBindTexture(GL_TEXTURE_2D, name);
      glPixelStorei(GL_UNPACK_ROW_LENGTH, image.cols);
      for (const cv::Rect& r : regions) {
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, r.x);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, r.y);
        glTexSubImage2D(GL_TEXTURE_2D, 0, r.x, r.y, r.width, r.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.data);
      }
      glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
      glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
      glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    }
    glGenerateMipmap(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    return name;
  }

  void release() override {
    for (unsigned& n : names_)
      if (n) glDeleteTextures(1, &n);
    names_.clear();
  }

 private:
  std::vector<unsigned> names_;
};

}  // namespace

std::unique_ptr<PanelTextures> create_gl_panel_textures() {
  return std::make_unique<GlPanelTextures>();
}

}  // namespace vdfx::app
