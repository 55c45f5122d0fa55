// Damage model "critical-plastic-strain" (F eq 4.9): D jumps from 0 to 1 once the equivalent plastic strain
// after a step reaches eps_c (eps_c > 0, or the material fails at once). Its answer moves with the spacing
// (it has no length of its own); "fracture-energy" is its regularised form.
#pragma once
#include "common/models/model_base.hpp"

namespace impactsph {

struct CriticalPlasticStrainDamage : DamageModelDefaults {
  static constexpr const char* key = "critical-plastic-strain";
  template <class Real> struct Params {
    Real strain = 0;  // eps_c, dimensionless
    template <class To> Params<To> to() const { return {To(strain)}; }
  };
  template <class Material, class Real>
  static IMPACTSPH_HD Real increment(const Material& m, const DamageStep<Real>& s) {
    return s.eps_p_after >= m.damage.critical_plastic_strain.strain ? Real(1) : Real(0);
  }
  static ModelKeys keys() { return {"critical_plastic_strain"}; }
  template <class Reader, class Damage> static void read(const Reader& d, Damage& p) {
    p.critical_plastic_strain.strain = d.number("critical_plastic_strain");
    d.range("critical_plastic_strain", p.critical_plastic_strain.strain, 0, 10, Dimension::Dimensionless, true);
  }
};

}  // namespace impactsph
