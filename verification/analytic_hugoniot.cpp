// Hugoniot (issue 2): symmetric plate impact of 4340 steel, hydrodynamic, cases/hugoniot-4340.
// Rankine-Hugoniot with Us = c0 + s up, up = V/2 (the jump conditions; 4340 constants of Steinberg's LLNL equation-of-state compilation): shock pressure rho0 Us up
// and shock speed Us within 3 %. The shocked material is at rest in the laboratory, so the front in the
// target runs at Us - up; its half-pressure point is fitted over time.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "verification/harness.hpp"
#include "verification/measures.hpp"

namespace impactsph::verification {
namespace {

void check_hugoniot(double impact_speed, const std::vector<std::string>& sets = {}, const char* form = "") {
  const HugoniotMeasure r = measure_hugoniot(case_path("hugoniot-4340"), "", impact_speed, {}, sets);
  std::printf("Hugoniot at %.0f m/s%s: %zu particles, %ld steps: Us %.1f m/s (RH %.1f, %+.2f %%), P %.3f GPa (RH %.3f, "
              "%+.2f %%), momentum %.3g of sum m|v|, energy drift %.3g\n",
              impact_speed, form, r.cost.particles, r.cost.steps, r.us, HugoniotExact::us(impact_speed), 100 * r.us_error(),
              r.pressure / 1e9, HugoniotExact::pressure(impact_speed) / 1e9, 100 * r.pressure_error(),
              r.momentum_ratio, r.energy_drift);
  EXPECT_NEAR(r.us_error(), 0.0, 0.03);
  EXPECT_NEAR(r.pressure_error(), 0.0, 0.03);
  EXPECT_LT(r.momentum_ratio, 1e-12) << "total momentum of the symmetric impact is not zero";
  EXPECT_LT(std::abs(r.energy_drift), 0.005);
}

TEST(Hugoniot, Steel4340At500MetresPerSecond) { check_hugoniot(500); }
TEST(Hugoniot, Steel4340At1000MetresPerSecond) { check_hugoniot(1000); }

// The limited viscosity (issue 19, numerics.viscosity_limiter) must still capture the shock: across the
// front the velocity jump is not linear, so the limiter keeps the Monaghan term there. Also with the
// larger smoothing length the Taylor bars were run with.
const std::vector<std::string> kLimited = {"numerics.viscosity_limiter=van-leer"};
TEST(Hugoniot, Steel4340At1000MetresPerSecondLimitedViscosity) {
  check_hugoniot(1000, kLimited, ", limited viscosity");
}
TEST(Hugoniot, Steel4340At1000MetresPerSecondLimitedViscosityTwoSpacingSmoothingLength) {
  check_hugoniot(1000, {kLimited[0], "numerics.h_factor=2.0"}, ", limited viscosity, h = 2 dx");
}

}  // namespace
}  // namespace impactsph::verification
