/// @file
/// @brief The area-average mip chain (see mip_chain.h).
#include "effects/mip_chain.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vdfx::effects {
namespace {

struct Tap {
  int index = 0;
  double weight = 0.0;
};

/// For each of the m texels of a reduced side of n: the level-l texels under it and the share of
/// each (the overlap of [i, i + 1) with [k n / m, (k + 1) n / m), over the span's length).
std::vector<std::vector<Tap>> area_taps(int n, int m) {
  const double span = static_cast<double>(n) / m;
  std::vector<std::vector<Tap>> taps(static_cast<std::size_t>(m));
  for (int k = 0; k < m; ++k) {
    const double start = k * span, end = (k + 1) * span;
    for (int i = static_cast<int>(std::floor(start)); i < static_cast<int>(std::ceil(end)); ++i) {
      const double w = (std::min(end, i + 1.0) - std::max(start, static_cast<double>(i))) / span;
      if (w > 0.0) taps[static_cast<std::size_t>(k)].push_back({std::min(i, n - 1), w});
    }
  }
  return taps;
}

}  // namespace

int mip_level_count(int width, int height) {
  int levels = 1;
  while (width > 1 || height > 1) {
    width = std::max(1, width / 2);
    height = std::max(1, height / 2);
    ++levels;
  }
  return levels;
}

cv::Mat mip_reduce(const cv::Mat& level) {
  if (level.empty() || level.depth() != CV_32F)
    throw std::invalid_argument("mip_reduce: need a non-empty float image");
  const int n_x = level.cols, n_y = level.rows, ch = level.channels();
  const int m_x = std::max(1, n_x / 2), m_y = std::max(1, n_y / 2);
  const auto tx = area_taps(n_x, m_x), ty = area_taps(n_y, m_y);
  cv::Mat out(m_y, m_x, level.type());
  cv::parallel_for_(cv::Range(0, m_y), [&](const cv::Range& rows) {
    std::vector<double> acc(static_cast<std::size_t>(m_x) * ch);
    for (int k = rows.start; k < rows.end; ++k) {
      std::fill(acc.begin(), acc.end(), 0.0);
      for (const Tap& r : ty[static_cast<std::size_t>(k)]) {
        const float* in = level.ptr<float>(r.index);
        for (int x = 0; x < m_x; ++x)
          for (const Tap& c : tx[static_cast<std::size_t>(x)])
            for (int q = 0; q < ch; ++q)
              acc[static_cast<std::size_t>(x * ch + q)] +=
                  r.weight * c.weight * in[c.index * ch + q];
      }
      float* o = out.ptr<float>(k);
      for (std::size_t i = 0; i < acc.size(); ++i) o[i] = static_cast<float>(acc[i]);
    }
  });
  return out;
}

std::vector<cv::Mat> build_mip_chain(const cv::Mat& image) {
  if (image.empty() || image.depth() != CV_32F)
    throw std::invalid_argument("build_mip_chain: need a non-empty float image");
  std::vector<cv::Mat> levels{image};
  const int count = mip_level_count(image.cols, image.rows);
  while (static_cast<int>(levels.size()) < count) levels.push_back(mip_reduce(levels.back()));
  return levels;
}

}  // namespace vdfx::effects
