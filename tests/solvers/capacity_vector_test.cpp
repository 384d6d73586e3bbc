// CapacityVector keeps its storage while its size stays within the largest it has held, takes
// its size and values from what is assigned as a VectorXd does, copies deeply, swaps storage,
// and gives Eigen's sums and products the bits they have on a VectorXd.
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solvers/common/capacity_vector.hpp"
#include "tests/support/lib/double_bits.hpp"

namespace impactbench::solvers {
namespace {

Eigen::VectorXd random_vector(Eigen::Index size, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::VectorXd v(size);
  for (Eigen::Index i = 0; i < size; ++i) v(i) = value(generator);
  return v;
}

using test_support::bits;

TEST(CapacityVector, ResizeWithinTheCapacityKeepsTheStorage) {
  CapacityVector v(100);
  const double* storage = v.data();
  EXPECT_EQ(v.size(), 100);
  EXPECT_EQ(v.capacity(), 100);
  v.resize(40);
  EXPECT_EQ(v.size(), 40);
  EXPECT_EQ(v.data(), storage);
  v.setZero(73);
  EXPECT_EQ(v.size(), 73);
  EXPECT_EQ(v.data(), storage);
  EXPECT_TRUE(v.isZero(0.0));
  v.resize(0);
  EXPECT_EQ(v.size(), 0);
  v.resize(100);
  EXPECT_EQ(v.data(), storage);
  EXPECT_EQ(v.capacity(), 100);
  v.resize(101);  // beyond: new storage, at least twice as large (a count rising slowly
                  // reallocates O(log count) times)
  EXPECT_EQ(v.size(), 101);
  EXPECT_EQ(v.capacity(), 200);
  v.conservativeResize(450);  // beyond twice: what is asked for
  EXPECT_EQ(v.size(), 450);
  EXPECT_EQ(v.capacity(), 450);
  const double* grown = v.data();
  v.resize(300);
  EXPECT_EQ(v.data(), grown);
}

TEST(CapacityVector, AssignmentTakesTheSizeAndTheValues) {
  CapacityVector v;
  EXPECT_EQ(v.size(), 0);
  const Eigen::VectorXd seven = Eigen::VectorXd::LinSpaced(7, 1.0, 7.0);
  v = seven;
  ASSERT_EQ(v.size(), 7);
  EXPECT_EQ(v, seven);
  const double* storage = v.data();
  const Eigen::VectorXd three = 2.0 * seven.head(3);
  v = three;
  ASSERT_EQ(v.size(), 3);
  EXPECT_EQ(v, three);
  EXPECT_EQ(v.data(), storage);
  v = Eigen::VectorXd::Constant(5, -1.5);
  EXPECT_EQ(v, Eigen::VectorXd::Constant(5, -1.5));
  const CapacityVector made_from_expression = seven.tail(2);
  EXPECT_EQ(made_from_expression, seven.tail(2));
}

TEST(CapacityVector, ACopyHasItsOwnStorage) {
  CapacityVector original = Eigen::VectorXd::LinSpaced(4, 1.0, 4.0);
  CapacityVector copy = original;
  EXPECT_NE(copy.data(), original.data());
  copy(0) = 99.0;
  EXPECT_EQ(original(0), 1.0);
  CapacityVector assigned;
  assigned = original;
  assigned(3) = -1.0;
  EXPECT_EQ(original(3), 4.0);
  EXPECT_EQ(assigned.head(3), original.head(3));
}

TEST(CapacityVector, SwapAndMoveExchangeTheStorage) {
  CapacityVector five = Eigen::VectorXd::Constant(5, 5.0);
  CapacityVector two = Eigen::VectorXd::Constant(2, 2.0);
  const double* five_storage = five.data();
  const double* two_storage = two.data();
  five.swap(two);
  EXPECT_EQ(five.size(), 2);
  EXPECT_EQ(five.data(), two_storage);
  EXPECT_EQ(five, Eigen::VectorXd::Constant(2, 2.0));
  EXPECT_EQ(two.size(), 5);
  EXPECT_EQ(two.data(), five_storage);
  EXPECT_EQ(two, Eigen::VectorXd::Constant(5, 5.0));
  const CapacityVector moved = std::move(two);
  EXPECT_EQ(moved.data(), five_storage);
  EXPECT_EQ(moved.size(), 5);
}

TEST(CapacityVector, ConservativeResizeKeepsTheLeadingValues) {
  CapacityVector v = Eigen::VectorXd::LinSpaced(6, 1.0, 6.0);
  const double* storage = v.data();
  v.conservativeResize(4);
  EXPECT_EQ(v, Eigen::VectorXd::LinSpaced(4, 1.0, 4.0));
  EXPECT_EQ(v.data(), storage);
  v.conservativeResize(9);  // beyond the capacity: the four values move to new storage
  ASSERT_EQ(v.size(), 9);
  EXPECT_EQ(v.head(4), Eigen::VectorXd::LinSpaced(4, 1.0, 4.0));
}

TEST(CapacityVector, ReserveKeepsTheSizeAndTheValues) {
  CapacityVector v = Eigen::VectorXd::LinSpaced(3, 1.0, 3.0);
  v.reserve(40);
  EXPECT_EQ(v, Eigen::VectorXd::LinSpaced(3, 1.0, 3.0));
  EXPECT_GE(v.capacity(), 40);
  const double* storage = v.data();
  v.resize(40);  // within the reserved storage
  EXPECT_EQ(v.data(), storage);
  v.reserve(10);  // below the capacity: nothing changes
  EXPECT_EQ(v.size(), 40);
  EXPECT_EQ(v.data(), storage);
}

TEST(CapacityVector, AssignNoaliasSizesItToTheProduct) {
  Eigen::SparseMatrix<double, Eigen::RowMajor> J(5, 3);
  J.insert(0, 0) = 0.3;
  J.insert(1, 2) = -1.7;
  J.insert(3, 1) = 2.9;
  J.insert(4, 0) = 1.1;
  J.insert(4, 2) = 0.123456789;
  J.makeCompressed();
  const Eigen::VectorXd x = random_vector(3, 7);
  Eigen::VectorXd expected;
  expected.noalias() = J * x;
  CapacityVector v(2);
  v.assign_noalias(J * x);
  ASSERT_EQ(v.size(), 5);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(bits(v(i)), bits(expected(i))) << i;
}

TEST(CapacityVector, SumsAndProductsHaveTheBitsTheyHaveOnAVectorXd) {
  // Eigen sums in SIMD pairs from the first aligned entry: a vector read at another alignment
  // would sum in another order. Every size up to 33, in storage that held more before.
  CapacityVector v(64);
  for (int size = 1; size <= 33; ++size) {
    const Eigen::VectorXd plain = random_vector(size, static_cast<unsigned>(size));
    const Eigen::VectorXd other = random_vector(size, static_cast<unsigned>(100 + size));
    const Eigen::MatrixXd matrix = Eigen::MatrixXd::Random(5, size);
    v = plain;
    ASSERT_EQ(v.size(), size);
    EXPECT_EQ(bits(v.sum()), bits(plain.sum())) << size;
    EXPECT_EQ(bits(v.squaredNorm()), bits(plain.squaredNorm())) << size;
    EXPECT_EQ(bits(v.dot(other)), bits(plain.dot(other))) << size;
    EXPECT_EQ(bits(other.dot(v)), bits(other.dot(plain))) << size;
    EXPECT_EQ(bits(v.cwiseAbs().maxCoeff()), bits(plain.cwiseAbs().maxCoeff())) << size;
    const Eigen::VectorXd product = matrix * v;
    const Eigen::VectorXd plain_product = matrix * plain;
    for (int i = 0; i < 5; ++i) EXPECT_EQ(bits(product(i)), bits(plain_product(i))) << size;
  }
}

}  // namespace
}  // namespace impactbench::solvers
