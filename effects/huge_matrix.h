/// @file
/// @brief A large dense matrix in memory that the kernel maps with 2 MiB pages.
///
/// A fresh m x m matrix is first touched page by page: at m = 1000 (8 MB) that is 2000 page
/// faults of 4 KiB, a few microseconds each on a virtual machine, about a fifth of a whole
/// `vdfx eval` process at that size. Allocated 2 MiB-aligned in whole 2 MiB units with
/// MADV_HUGEPAGE asked for (Linux's "madvise" mode, Debian's default, gives huge pages only to
/// regions that ask), its first touch takes one fault per 2 MiB. Elsewhere (and in the web
/// module) it is an ordinary aligned allocation.
#pragma once

#include <Eigen/Core>
#include <memory>

namespace vdfx::effects {

class HugeMatrix {
 public:
  HugeMatrix() = default;
  /// Uninitialised, as an Eigen::MatrixXd of that size is.
  HugeMatrix(Eigen::Index rows, Eigen::Index cols);
  // The map's assignment copies coefficients, not where it points: no copies, no moves.
  HugeMatrix(const HugeMatrix&) = delete;
  HugeMatrix& operator=(const HugeMatrix&) = delete;

  Eigen::Map<Eigen::MatrixXd>& map() { return map_; }
  const Eigen::Map<Eigen::MatrixXd>& map() const { return map_; }
  /// Frees the memory; the map becomes 0 x 0.
  void reset();

 private:
  struct Free {
    void operator()(double* p) const;
  };
  std::unique_ptr<double[], Free> data_;
  Eigen::Map<Eigen::MatrixXd> map_{nullptr, 0, 0};
};

}  // namespace vdfx::effects
