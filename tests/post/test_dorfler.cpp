// Dörfler's marking (post/dorfler.hpp): the fewest largest indicators carrying theta of the
// estimate's square.
#include "core/error.hpp"
#include "post/dorfler.hpp"

#include <gtest/gtest.h>

namespace sig {
namespace {

TEST(Dorfler, FewestLargestIndicatorsCarryingTheta) {
  // Squares 16, 9, 1, 4: total 30. theta = 0.5 needs 15: 16 alone. 0.8 needs 24: 16 + 9.
  const std::vector<double> eta = {4, 3, 1, 2};
  EXPECT_EQ(dorfler_marking(eta, 0.5), std::vector<int>{0});
  EXPECT_EQ(dorfler_marking(eta, 0.8), (std::vector<int>{0, 1}));
  EXPECT_EQ(dorfler_marking(eta, 0.9), (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(dorfler_marking(eta, 1.0), (std::vector<int>{0, 1, 3, 2}));
}

TEST(Dorfler, TiesByTriangleNumberAndNothingWithoutError) {
  EXPECT_EQ(dorfler_marking({1, 1, 1, 1}, 0.5), (std::vector<int>{0, 1}));
  EXPECT_TRUE(dorfler_marking({0, 0}, 0.5).empty());
}

TEST(Dorfler, RefusesABadTheta) {
  EXPECT_THROW(dorfler_marking({1}, 0), Error);
  EXPECT_THROW(dorfler_marking({1}, 1.5), Error);
  EXPECT_THROW(dorfler_marking({-1}, 0.5), Error);
}

} // namespace
} // namespace sig
