// Unit tests of common/verlet.hpp (the reach of the neighbour search and the Verlet-list criterion, shared
// by the reference and the gpu port) and of contact_touch_distance (common/contact.hpp, X eqs 18, 20).
#include <gtest/gtest.h>

#include "common/contact.hpp"
#include "common/verlet.hpp"

namespace {

using namespace impactsph;

// The reach is the largest of the kernel support, the fixed contact distance and SRAD h_max.
TEST(Verlet, SearchReachIsTheLargestOfItsThreeParts) {
  EXPECT_DOUBLE_EQ(search_reach(2.4e-3, 0.0, 0.0, 1.2e-3), 2.4e-3);     // kernel support
  EXPECT_DOUBLE_EQ(search_reach(2.4e-3, 3.0e-3, 0.0, 1.2e-3), 3.0e-3);  // fixed contact distance
  EXPECT_DOUBLE_EQ(search_reach(2.4e-3, 1.0e-3, 2.5, 1.2e-3), 3.0e-3);  // SRAD 2.5 x 1.2 mm
  EXPECT_DOUBLE_EQ(search_reach(2.4e-3, 3.5e-3, 2.5, 1.2e-3), 3.5e-3);
}

// Kept while moved + 1.01 dt vmax + growth/2 < skin/2; rebuilt at the boundary and beyond.
TEST(Verlet, ListHoldsUntilHalfTheSkinIsUsed) {
  const double skin = 1e-4, dt = 1e-7, vmax = 100;  // dt vmax = 1e-5 m
  EXPECT_TRUE(verlet_list_holds(0.0, dt, vmax, 0.0, skin));
  EXPECT_TRUE(verlet_list_holds(3.9e-5, dt, vmax, 0.0, skin));   // 3.9e-5 + 1.01e-5 = 4.91e-5 < 5e-5
  EXPECT_FALSE(verlet_list_holds(4.0e-5, dt, vmax, 0.0, skin));  // 5.01e-5
  EXPECT_FALSE(verlet_list_holds(0.0, dt, vmax, 8.0e-5, skin));  // growth 8e-5 uses 4e-5 of the 5e-5
  EXPECT_TRUE(verlet_list_holds(0.0, dt, vmax, 7.0e-5, skin));
  EXPECT_FALSE(verlet_list_holds(0.0, dt, vmax, 0.0, 0.0));      // no skin: rebuild every step
}

TEST(Contact, TouchDistanceIsSradTimesMeanSmoothingLengthOrTheFixedDistance) {
  EXPECT_DOUBLE_EQ(contact_touch_distance(1.2, 9.9e-3, 1.0e-3, 2.0e-3), 1.2 * 1.5e-3);  // X eq 20
  EXPECT_DOUBLE_EQ(contact_touch_distance(0.0, 2.0e-3, 1.0e-3, 2.0e-3), 2.0e-3);
  EXPECT_FLOAT_EQ(contact_touch_distance(1.2f, 0.0f, 1.0e-3f, 2.0e-3f), 1.8e-3f);
}

}  // namespace
