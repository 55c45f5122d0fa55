// Damage model "fracture-energy": the crack-band regularisation of a work criterion (Bazant and Oh 1983,
// "Crack band theory for fracture of concrete", Materiaux et Constructions 16, 155-177). A criterion on a
// strain or a work density fails a band of material as wide as the discretisation localises it in, so the
// energy per unit crack area it dissipates scales with the spacing. Holding that energy at a material
// constant Gamma (J/m^2) fails a particle once its plastic work per unit initial volume reaches a critical
// work W_c = Gamma / L, L the width of the band the criterion assumes (m). Two ways to set L:
//   * local (band_width_factor k): L = k h0, the band as wide as k initial smoothing lengths (k measured,
//     not fitted). Production codes scale the failure measure with the element size in the same way
//     (LS-DYNA GISSMO and *MAT_ADD_EROSION with LCREGD, Radioss /FAIL element-size functions, Abaqus
//     damage evolution by plastic displacement). It holds Gamma only where the band is k h0 wide.
//   * non-local (nonlocal_radius R): the particle's own work density must reach W_c and so must its
//     average over the material within R of it in the initial configuration (common/nonlocal.hpp), with
//     L = 32 R / 35 the averaging's width across a plane. A band narrower than L then fails once its
//     work per unit area reaches Gamma, whatever its width, so the band's energy no longer follows the
//     spacing (an integral non-local model, Pijaudier-Cabot and Bazant 1987, J. Eng. Mech. 113, 1512-1533).
// D jumps from 0 to 1, as in F 4.9.
#pragma once
#include "common/models/model_base.hpp"
#include "common/nonlocal_weight.hpp"

namespace impactsph {

// The critical work W_c = Gamma / L (J/m^3) of a material's damage constants (`Damage` is DamageParams,
// material.hpp) at the initial smoothing length h0 (m): L = 32 R / 35 (nonlocal_band_width,
// common/nonlocal_weight.hpp) for a non-local radius R > 0, else k h0.
template <class Damage, class Real> IMPACTSPH_HD Real fracture_energy_critical_work(const Damage& d, Real h0) {
  const auto& f = d.fracture_energy;
  return f.gamma / (f.nonlocal_radius > 0 ? nonlocal_band_width(f.nonlocal_radius) : f.band_width_factor * h0);
}

struct FractureEnergyDamage : DamageModelDefaults {
  static constexpr const char* key = "fracture-energy";
  // Gamma (J/m^2); the band width in initial smoothing lengths k (dimensionless, 0 when non-local); the
  // non-local radius R (m, 0 when local); the critical work W_c (J/m^3), which the scene sets from its h0
  // (set_smoothing_length).
  template <class Real> struct Params {
    Real gamma = 0;
    Real band_width_factor = 0;
    Real nonlocal_radius = 0;
    Real critical_work = 0;
    template <class To> Params<To> to() const {
      return {To(gamma), To(band_width_factor), To(nonlocal_radius), To(critical_work)};
    }
  };
  // 1 on a plastic step once rho0 w_p after the step (w_p in J/kg, the particle's sum sigma_y d eps_p / rho)
  // reaches W_c and, for a non-local model, so does the non-local work density the solver formed
  // (DamageStep::nonlocal_work, J/m^3); never while W_c <= 0 (not yet set from the spacing).
  template <class Material, class Real>
  static IMPACTSPH_HD Real increment(const Material& m, const DamageStep<Real>& s) {
    if (!(s.d_eps_p > Real(0))) return Real(0);
    const auto& f = m.damage.fracture_energy;
    const Real w_c = f.critical_work;
    if (!(w_c > Real(0)) || m.eos.rho0 * s.w_p_after < w_c) return Real(0);
    return f.nonlocal_radius > Real(0) && s.nonlocal_work < w_c ? Real(0) : Real(1);
  }
  template <class Damage> static void set_smoothing_length(Damage& d, double h0) {
    d.fracture_energy.critical_work = fracture_energy_critical_work(d, h0);
  }
  static ModelKeys keys() { return {"fracture_energy", "band_width_factor", "nonlocal_radius"}; }
  // fracture_energy and exactly one of band_width_factor (local) and nonlocal_radius (non-local).
  template <class Reader, class Damage> static void read(const Reader& d, Damage& p) {
    Params<double>& f = p.fracture_energy;
    f.gamma = d.quantity("fracture_energy", Dimension::FractureEnergy);
    d.range("fracture_energy", f.gamma, 0, 1e8, Dimension::FractureEnergy, true, false,
            "Gamma, the plastic work per unit crack area at failure (damage_fracture_energy.hpp)");
    const bool local = d.has("band_width_factor"), nonlocal = d.has("nonlocal_radius");
    if (local == nonlocal)
      d.fail(local ? "nonlocal_radius" : "band_width_factor",
             std::string(local ? "given together with band_width_factor" : "missing") +
                 "; a fracture-energy damage sets its band width by exactly one of band_width_factor (a number of "
                 "initial smoothing lengths, such as 2.6) and nonlocal_radius (a length such as \"6 mm\")");
    if (local) {
      f.band_width_factor = d.number("band_width_factor");
      d.range("band_width_factor", f.band_width_factor, 0.5, 20, Dimension::Dimensionless, false, false,
              "the width of the failing band in initial smoothing lengths h0 = h_factor x spacing");
    } else {
      f.nonlocal_radius = d.quantity("nonlocal_radius", Dimension::Length);
      d.range("nonlocal_radius", f.nonlocal_radius, 0, 1, Dimension::Length, true, false,
              "the radius of the sphere over which the plastic work is averaged (common/nonlocal.hpp)");
    }
  }
};

}  // namespace impactsph
