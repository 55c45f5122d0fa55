// Damage model "none": the material never fails. No constants.
#pragma once
#include "common/models/model_base.hpp"

namespace impactsph {

struct NoDamage : DamageModelDefaults {
  static constexpr const char* key = "none";
  static constexpr bool fails = false;
  static constexpr bool takes_crack_faces = false;
  static constexpr bool needs_ductile_strength = false;
  template <class Real> using Params = NoParams<Real>;
};

}  // namespace impactsph
