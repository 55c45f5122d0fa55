// Time step (F eq 5.1): dt = C_CFL min_i h_i / (c_i + |u_i|). Units: s.
#pragma once
#include "common/hd.hpp"

namespace impactsph {

// The limit one particle sets; the solver takes the minimum over particles.
template <class Real> IMPACTSPH_HD Real cfl_time_step(Real cfl, Real h, Real sound_speed, Real speed) {
  return cfl * h / (sound_speed + speed);
}

}  // namespace impactsph
