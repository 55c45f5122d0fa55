// Strength model "hydrodynamic": no deviatoric stress (Hugoniot tests, fluids). No constants.
#pragma once
#include "common/models/model_base.hpp"

namespace impactsph {

struct HydrodynamicStrength : StrengthModelDefaults {
  static constexpr const char* key = "hydrodynamic";
  static constexpr bool deviatoric = false;
  static constexpr bool plastic = false;
  template <class Real> using Params = NoParams<Real>;
};

}  // namespace impactsph
