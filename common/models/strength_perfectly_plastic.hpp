// Strength model "perfectly-plastic": Hooke + Jaumann + von Mises at a constant yield stress sigma_y (Pa).
#pragma once
#include "common/models/model_base.hpp"

namespace impactsph {

struct PerfectlyPlasticStrength : StrengthModelDefaults {
  static constexpr const char* key = "perfectly-plastic";
  static constexpr bool ductile = true;
  template <class Real> struct Params {
    Real yield_stress = 0;  // sigma_y, Pa
    template <class To> Params<To> to() const { return {To(yield_stress)}; }
  };
  template <class Material, class Real>
  static IMPACTSPH_HD Real flow_stress(const Material& m, const FlowState<Real>&) {
    return m.strength.perfectly_plastic.yield_stress;
  }
  static ModelKeys keys() { return {"yield_stress"}; }
  template <class Reader, class Strength> static void read(const Reader& s, Strength& p) {
    p.perfectly_plastic.yield_stress =
        s.stress("yield_stress", "; a material without strength is kind = \"hydrodynamic\"");
  }
};

}  // namespace impactsph
