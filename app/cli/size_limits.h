/// @file
/// @brief The largest images the command line may ask for, checked before anything is allocated
/// (docs/reliability.md, "Limits"). Input frames have their own limit (io/image_source.h).
#pragma once

#include <cstdint>

namespace vdfx::app {

/// Each side at most `max_side`, at most `max_pixels` in all.
struct SizeLimit {
  int max_side;
  std::int64_t max_pixels;
  const char* example;  //!< the largest 2:1 or square size within the limit, for messages
};

/// Rendered images and windows (`render --size`, `--window`): 2^26 pixels (8192x8192) take about
/// 2 GiB on the CPU path (measured: 2.1 GiB peak at 8192x8192).
inline constexpr SizeLimit kOutputSizeLimit{16384, std::int64_t{1} << 26, "8192x8192"};

/// `render --gpu`: the area the GPU renders, the blur's margin included, at most 2^25 pixels.
/// Mesa's llvmpipe keeps every float texture in main memory: 8.5 GiB peak measured at 8192x8192
/// without blur, about 128 bytes per pixel, so this stays near 4 GiB.
inline constexpr SizeLimit kGpuRenderLimit{16384, std::int64_t{1} << 25, "8192x4096"};

/// Per-pixel mode's parameter grid (`--bake`): 2^23 cells of about 110 bytes (baked parameters and
/// their float textures), under 1 GiB.
inline constexpr SizeLimit kBakeSizeLimit{4096, std::int64_t{1} << 23, "4096x2048"};

}  // namespace vdfx::app
