/// @file
/// @brief HugeMatrix's allocation.
#include "effects/huge_matrix.h"

#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <sys/mman.h>
#define VDFX_HUGE_PAGES 1
#endif

namespace vdfx::effects {

namespace {

#if defined(VDFX_HUGE_PAGES)
constexpr std::size_t kHuge = std::size_t{2} << 20;
#endif

double* allocate(std::size_t bytes) {
#if defined(VDFX_HUGE_PAGES)
  // Small matrices gain nothing from a huge page and would waste most of one.
  if (bytes >= kHuge) {
    const std::size_t whole = (bytes + kHuge - 1) / kHuge * kHuge;
    void* p = std::aligned_alloc(kHuge, whole);
    if (!p) throw std::bad_alloc();
    madvise(p, whole, MADV_HUGEPAGE);  // advice only: without it, ordinary pages
    return static_cast<double*>(p);
  }
#endif
  void* p = std::aligned_alloc(64, (bytes + 63) / 64 * 64);
  if (!p) throw std::bad_alloc();
  return static_cast<double*>(p);
}

}  // namespace

void HugeMatrix::Free::operator()(double* p) const {
  std::free(p);
}

HugeMatrix::HugeMatrix(Eigen::Index rows, Eigen::Index cols)
    : data_(rows * cols > 0 ? allocate(static_cast<std::size_t>(rows * cols) * sizeof(double))
                            : nullptr),
      map_(data_.get(), rows, cols) {}

void HugeMatrix::reset() {
  new (&map_) Eigen::Map<Eigen::MatrixXd>(nullptr, 0, 0);
  data_.reset();
}

}  // namespace vdfx::effects
