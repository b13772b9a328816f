/// @file
/// @brief The blocked Cholesky factorisation on the solve's threads (effects/cholesky.h): the
/// factor Eigen's LLT gives, the same bits on one thread as on two, indefinite matrices refused
/// on both, solves and the condition estimate as Eigen's.
#include "effects/cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <functional>
#include <limits>
#include <random>

#include "effects/solve_threads.h"

namespace vdfx::effects {
namespace {

/// Restores one thread when a test ends, whatever it set.
struct ThreadsScope {
  explicit ThreadsScope(int n) { set_solve_threads(n); }
  ~ThreadsScope() { set_solve_threads(1); }
};

/// A random symmetric positive definite n x n matrix, condition about 1e4.
Eigen::MatrixXd spd(Eigen::Index n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  Eigen::MatrixXd b(n, n);
  for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = g(rng);
  Eigen::MatrixXd a = b * b.transpose() / static_cast<double>(n);
  a.diagonal().array() += 1e-2;
  return a;
}

/// The lower triangle of `a` factorised by cholesky_in_place, the strict upper one NaN (it must
/// be neither read nor written).
Eigen::MatrixXd factor(const Eigen::MatrixXd& a, bool* definite = nullptr) {
  Eigen::MatrixXd l = a;
  l.triangularView<Eigen::StrictlyUpper>().setConstant(std::numeric_limits<double>::quiet_NaN());
  const bool ok = cholesky_in_place(l);
  if (definite) *definite = ok;
  return l;
}

TEST(Cholesky, GivesEigensFactorAtEverySizeAndLeavesTheUpperTriangle) {
  // Below kParallelSolveMin it is Eigen's LLT itself; from there the blocked one, with a last
  // block column narrower than kCholeskyBlock (500 = 5 x 96 + 20) or not (960).
  for (const Eigen::Index n :
       {Eigen::Index{1}, Eigen::Index{7}, Eigen::Index{100}, kParallelSolveMin - 1,
        kParallelSolveMin, Eigen::Index{500}, Eigen::Index{960}}) {
    const Eigen::MatrixXd a = spd(n, static_cast<unsigned>(n));
    bool definite = false;
    const Eigen::MatrixXd l = factor(a, &definite);
    ASSERT_TRUE(definite) << n;
    EXPECT_TRUE(l.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().array().isNaN().count() ==
                n * (n - 1) / 2)
        << n;
    const Eigen::MatrixXd lower = l.triangularView<Eigen::Lower>();
    const Eigen::MatrixXd eigen = Eigen::LLT<Eigen::MatrixXd>(a).matrixL();
    if (n < kParallelSolveMin) {
      EXPECT_EQ(lower, eigen) << n;
    } else {
      EXPECT_LT((lower - eigen).cwiseAbs().maxCoeff(), 1e-12 * eigen.cwiseAbs().maxCoeff()) << n;
    }
    EXPECT_LT((lower * lower.transpose() - a).cwiseAbs().maxCoeff(),
              1e-13 * a.cwiseAbs().maxCoeff())
        << n;
  }
}

TEST(Cholesky, TwoThreadsGiveTheSameFactorBitForBit) {
  for (const Eigen::Index n : {kParallelSolveMin, Eigen::Index{701}, Eigen::Index{1000}}) {
    const Eigen::MatrixXd a = spd(n, 11);
    const Eigen::MatrixXd one = factor(a);
    Eigen::MatrixXd two;
    {
      const ThreadsScope scope(2);
      two = factor(a);
    }
    const Eigen::MatrixXd l1 = one.triangularView<Eigen::Lower>();
    const Eigen::MatrixXd l2 = two.triangularView<Eigen::Lower>();
    EXPECT_EQ(l1, l2) << n;
  }
}

TEST(Cholesky, WhereTheHelpersAreTakenItFactorsInTurnToTheSameBits) {
  // Inside a task the helpers are held by its caller: the two parts, each waiting for the other
  // between the phases, must not be started one after the other; the factor comes in turn.
  const Eigen::MatrixXd a = spd(600, 13);
  const ThreadsScope scope(2);
  const Eigen::MatrixXd alone = factor(a);
  Eigen::MatrixXd inside;
  const std::function<void()> tasks[] = {[&] { inside = factor(a); }, [] {}};
  ASSERT_TRUE(try_run_on_helpers(tasks));
  EXPECT_EQ(Eigen::MatrixXd(inside.triangularView<Eigen::Lower>()),
            Eigen::MatrixXd(alone.triangularView<Eigen::Lower>()));
}

TEST(Cholesky, RefusesAnIndefiniteMatrixOnOneThreadAndOnTwo) {
  // A negative pivot in the first block column, in a later one, and in the last row.
  for (const Eigen::Index bad : {Eigen::Index{3}, Eigen::Index{450}, Eigen::Index{599}}) {
    Eigen::MatrixXd a = spd(600, 5);
    a(bad, bad) = -1.0;
    bool definite = true;
    factor(a, &definite);
    EXPECT_FALSE(definite) << bad;
    const ThreadsScope scope(2);
    definite = true;
    factor(a, &definite);
    EXPECT_FALSE(definite) << bad;
  }
}

TEST(Cholesky, FactorsABlockOfALargerMatrixInPlace) {
  // The solve factorises through an Eigen::Ref; here one with an outer stride.
  const Eigen::MatrixXd a = spd(450, 8);
  Eigen::MatrixXd big = Eigen::MatrixXd::Constant(460, 455, 7.0);
  big.block(5, 3, 450, 450) = a;
  const ThreadsScope scope(2);
  ASSERT_TRUE(cholesky_in_place(big.block(5, 3, 450, 450)));
  EXPECT_EQ(Eigen::MatrixXd(big.block(5, 3, 450, 450).triangularView<Eigen::Lower>()),
            Eigen::MatrixXd(factor(a).triangularView<Eigen::Lower>()));
  EXPECT_EQ(big.topRows(5).cwiseEqual(7.0).count(), 5 * 455);  // nothing outside the block
  EXPECT_EQ(big.leftCols(3).cwiseEqual(7.0).count(), 460 * 3);
}

TEST(Cholesky, SolvesAndEstimatesTheConditionAsEigensLlt) {
  for (const Eigen::Index n : {50, 700}) {
    Eigen::MatrixXd a = spd(n, 21);
    a(0, 0) *= 1e4;  // a condition estimate not near 1
    const double norm1 = symmetric_norm1_lower(a);
    EXPECT_DOUBLE_EQ(norm1, a.cwiseAbs().colwise().sum().maxCoeff()) << n;
    Eigen::MatrixXd l = a;
    ASSERT_TRUE(cholesky_in_place(l));
    const CholeskyFactor f(l, norm1);
    const Eigen::LLT<Eigen::MatrixXd> llt(a);
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const Eigen::Index cols : {1, 6}) {  // a column at a time, and as one matrix
      Eigen::MatrixXd b(n, cols);
      for (Eigen::Index i = 0; i < b.size(); ++i) b.data()[i] = u(rng);
      const Eigen::MatrixXd x = f.solve(b);
      EXPECT_LT((a * x - b).cwiseAbs().maxCoeff(), 1e-10) << n << " " << cols;
      EXPECT_LT((x - llt.solve(b)).cwiseAbs().maxCoeff(), 1e-9 * x.cwiseAbs().maxCoeff());
    }
    EXPECT_NEAR(f.rcond(), llt.rcond(), 1e-9 * llt.rcond()) << n;
    EXPECT_LT(f.rcond(), 1e-3) << n;
  }
}

}  // namespace
}  // namespace vdfx::effects
