// Strength model "elastic": Hooke + Jaumann (F eqs 3.5-3.7), never yields (elastic projectile, the
// elastic-wave test). Its only constant is the shear modulus every deviatoric model shares.
#pragma once
#include "common/models/model_base.hpp"

namespace impactsph {

struct ElasticStrength : StrengthModelDefaults {
  static constexpr const char* key = "elastic";
  static constexpr bool plastic = false;
  template <class Real> using Params = NoParams<Real>;
};

}  // namespace impactsph
