// Damage model "fracture-energy": the crack-band regularisation of a work criterion (Bazant and Oh 1983,
// "Crack band theory for fracture of concrete", Materiaux et Constructions 16, 155-177). A criterion on a
// strain or a work density fails a band of material as wide as the discretisation localises it in, so the
// energy per unit crack area it dissipates scales with the spacing. Holding that energy at a material
// constant Gamma (J/m^2) over a band of width w = k h0 (k the band width in initial smoothing lengths,
// measured, not fitted) fails a particle once its plastic work per unit initial volume reaches
//   W_c = Gamma / (k h0)   (J/m^3).
// Production codes scale the failure measure with the element size in the same way (LS-DYNA GISSMO and
// *MAT_ADD_EROSION with LCREGD, Radioss /FAIL element-size functions, Abaqus damage evolution by plastic
// displacement). D jumps from 0 to 1, as in F 4.9.
#pragma once
#include "common/models/model_base.hpp"

namespace impactsph {

// The critical work W_c = Gamma / (k h0) (J/m^3) of a material's damage constants (`Damage` is
// DamageParams, material.hpp) at the initial smoothing length h0 (m).
template <class Damage, class Real> IMPACTSPH_HD Real fracture_energy_critical_work(const Damage& d, Real h0) {
  return d.fracture_energy.gamma / (d.fracture_energy.band_width_factor * h0);
}

struct FractureEnergyDamage : DamageModelDefaults {
  static constexpr const char* key = "fracture-energy";
  // Gamma (J/m^2), the band width in initial smoothing lengths k (dimensionless), and the critical work
  // W_c (J/m^3), which the scene sets from its h0 (set_smoothing_length).
  template <class Real> struct Params {
    Real gamma = 0;
    Real band_width_factor = 0;
    Real critical_work = 0;
    template <class To> Params<To> to() const {
      return {To(gamma), To(band_width_factor), To(critical_work)};
    }
  };
  // 1 once rho0 w_p after the step (w_p in J/kg, the particle's sum sigma_y d eps_p / rho) reaches W_c on a
  // plastic step; never while W_c <= 0 (not yet set from the spacing).
  template <class Material, class Real>
  static IMPACTSPH_HD Real increment(const Material& m, const DamageStep<Real>& s) {
    if (!(s.d_eps_p > Real(0))) return Real(0);
    const Real w_c = m.damage.fracture_energy.critical_work;
    return w_c > Real(0) && m.eos.rho0 * s.w_p_after >= w_c ? Real(1) : Real(0);
  }
  template <class Damage> static void set_smoothing_length(Damage& d, double h0) {
    d.fracture_energy.critical_work = fracture_energy_critical_work(d, h0);
  }
  static ModelKeys keys() { return {"fracture_energy", "band_width_factor"}; }
  template <class Reader, class Damage> static void read(const Reader& d, Damage& p) {
    Params<double>& f = p.fracture_energy;
    f.gamma = d.quantity("fracture_energy", Dimension::FractureEnergy);
    d.range("fracture_energy", f.gamma, 0, 1e8, Dimension::FractureEnergy, true, false,
            "Gamma, the plastic work per unit crack area at failure (damage_fracture_energy.hpp)");
    f.band_width_factor = d.number("band_width_factor");
    d.range("band_width_factor", f.band_width_factor, 0.5, 20, Dimension::Dimensionless, false, false,
            "the width of the failing band in initial smoothing lengths h0 = h_factor x spacing");
  }
};

}  // namespace impactsph
