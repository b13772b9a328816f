/// @file
/// @brief HugeMatrix: a usable matrix of the asked size, 2 MiB-aligned where huge pages can map it.
#include "effects/huge_matrix.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace vdfx::effects {
namespace {

TEST(HugeMatrix, ALargeMatrixStartsOnA2MiBBoundaryAndHoldsItsValues) {
  HugeMatrix a(1000, 1000);  // 8 MB
  ASSERT_EQ(a.map().rows(), 1000);
  ASSERT_EQ(a.map().cols(), 1000);
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.map().data()) % (std::uintptr_t{2} << 20), 0u);
#endif
  a.map().setZero();
  a.map()(999, 999) = 7.0;
  a.map().col(3).setConstant(2.0);
  EXPECT_EQ(a.map().sum(), 7.0 + 2000.0);
  a.reset();
  EXPECT_EQ(a.map().size(), 0);
}

TEST(HugeMatrix, SmallAndEmptyMatricesAreOrdinaryAllocations) {
  HugeMatrix small(3, 4);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small.map().data()) % 64, 0u);
  small.map().setOnes();
  EXPECT_EQ(small.map().sum(), 12.0);
  const HugeMatrix empty(0, 5);
  EXPECT_EQ(empty.map().data(), nullptr);
  EXPECT_EQ(empty.map().size(), 0);
}

}  // namespace
}  // namespace vdfx::effects
