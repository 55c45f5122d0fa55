// The [materials] of a case file: EOS, strength and damage tables, checked against docs/case-files.md and
// read into MaterialSpec in SI units (common/case_reading.hpp).
#include "common/case_reading.hpp"

namespace impactsph::case_reading {
namespace {

// ---------------------------------------------------------------------------------------------------
// Materials

const Keys kEosKinds{"linear", "polynomial", "mie-gruneisen", "gruneisen-cubic"};
const Keys kStrengthKinds{"hydrodynamic", "elastic", "perfectly-plastic", "johnson-cook", "johnson-holmquist-2"};
// What the pairs of a failed particle carry (DamageParams::compressive_crack_faces).
const Keys kCrackFaces{"scaled", "compression"};
const Keys kDamageKinds{"none", "critical-plastic-strain", "fracture-energy", "johnson-cook", "johnson-holmquist-2"};

void read_eos(const View& e, EosParams<double>& p, bool& needs_bulk_modulus) {
  const std::string kind = e.choice("kind", kEosKinds);
  needs_bulk_modulus = false;
  if (e.has("min_pressure")) {
    p.min_pressure = e.quantity("min_pressure", Dimension::Pressure);
    e.range("min_pressure", p.min_pressure, -kMaxModulus, 0, Dimension::Pressure, false, false,
            "the pressure cutoff is the largest tension the material carries, a negative pressure such as "
            "\"-1.2 GPa\" (0: no tension)");
  }
  auto modulus = [&](const std::string& k) {
    const double v = e.quantity(k, Dimension::Pressure);
    e.range(k, v, kMinModulus, kMaxModulus, Dimension::Pressure, false, false, kModulusHint);
    return v;
  };
  auto coefficient = [&](const std::string& k) {
    const double v = e.quantity_or(k, Dimension::Pressure, 0.0);
    e.range(k, v, -kMaxModulus, kMaxModulus, Dimension::Pressure);
    return v;
  };
  auto c0 = [&]() {
    const double v = e.quantity("c0", Dimension::Velocity);
    e.range("c0", v, 0, 20000, Dimension::Velocity, true, false, "c0 is the bulk sound speed");
    return v;
  };
  auto gamma0 = [&]() {
    const double v = e.number("gamma0");
    e.range("gamma0", v, 0, 5, Dimension::Dimensionless);
    return v;
  };
  auto slope = [&](const std::string& k) {
    const double v = e.number(k);
    e.range(k, v, 0.5, 5, Dimension::Dimensionless, false, false, "the slope of the linear Us-up Hugoniot");
    return v;
  };
  if (kind == "linear") {
    e.allow({"kind", "bulk_modulus", "min_pressure"});
    p.kind = EosKind::Linear;
    if (e.has("bulk_modulus")) p.k1 = modulus("bulk_modulus");
    else needs_bulk_modulus = true;  // may come from youngs_modulus + poisson_ratio in the strength table
  } else if (kind == "polynomial") {
    e.allow({"kind", "k1", "k2", "k3", "min_pressure"});
    p.kind = EosKind::Polynomial;
    p.k1 = modulus("k1");
    p.k2 = coefficient("k2");
    p.k3 = coefficient("k3");
  } else if (kind == "mie-gruneisen") {
    e.allow({"kind", "c0", "s", "gamma0", "min_pressure"});
    p.kind = EosKind::MieGruneisen;
    p.c0 = c0();
    p.s1 = slope("s");
    p.gamma0 = gamma0();
  } else {
    e.allow({"kind", "c0", "s1", "s2", "s3", "gamma0", "a", "min_pressure"});
    p.kind = EosKind::GruneisenCubic;
    p.c0 = c0();
    p.s1 = slope("s1");
    p.s2 = e.number_or("s2", 0.0);
    e.range("s2", p.s2, -20, 20, Dimension::Dimensionless);
    p.s3 = e.number_or("s3", 0.0);
    e.range("s3", p.s3, -20, 20, Dimension::Dimensionless);
    p.gamma0 = gamma0();
    p.a = e.number_or("a", 0.0);
    e.range("a", p.a, -5, 5, Dimension::Dimensionless);
  }
}

// A stress that must be between kMinModulus and kMaxModulus (a bare number is in Pa).
double stress(const View& s, const std::string& k, const std::string& extra_hint = "") {
  const double v = s.quantity(k, Dimension::Pressure);
  s.range(k, v, kMinModulus, kMaxModulus, Dimension::Pressure, false, false, kModulusHint + extra_hint);
  return v;
}

// The Johnson-Cook flow stress constants (F 3.12-3.13) of a strength table of kind "johnson-cook".
void read_johnson_cook(const View& s, StrengthParams<double>& p) {
  p.jc_a = stress(s, "a", "; A is the yield stress at zero plastic strain");
  p.jc_b = s.quantity("b", Dimension::Pressure);
  if (p.jc_b != 0)  // B = 0 (no hardening) is valid; a small non-zero B is a bare number meant in MPa
    s.range("b", p.jc_b, kMinModulus, kMaxModulus, Dimension::Pressure, false, false,
            std::string(kModulusHint) + "; b = 0 means no strain hardening");
  p.jc_n = p.jc_b > 0 ? s.number("n") : s.number_or("n", 1.0);  // n is needed only with hardening
  s.range("n", p.jc_n, 0, 2, Dimension::Dimensionless, true);
  p.jc_c = s.number_or("c", 0.0);
  s.range("c", p.jc_c, 0, 1, Dimension::Dimensionless);
  p.jc_m = s.number_or("m", 1.0);
  s.range("m", p.jc_m, 0, 5, Dimension::Dimensionless, true);
  p.reference_strain_rate = s.quantity_or("reference_strain_rate", Dimension::StrainRate, 1.0);
  s.positive("reference_strain_rate", p.reference_strain_rate, Dimension::StrainRate);
  p.melt_temperature = 0;  // 0: no thermal softening; checked against room_temperature by read_material
  if (s.has("melt_temperature")) {
    p.melt_temperature = s.quantity("melt_temperature", Dimension::Temperature);
    s.positive("melt_temperature", p.melt_temperature, Dimension::Temperature);
  }
  p.taylor_quinney = s.number_or("taylor_quinney", 0.9);
  s.range("taylor_quinney", p.taylor_quinney, 0, 1, Dimension::Dimensionless, false, false,
          "the fraction of plastic work that heats the material");
}

// The JH-2 strength constants (X eqs 22-24, Table 1) of a strength table of kind "johnson-holmquist-2".
void read_jh2_strength(const View& s, StrengthParams<double>& p) {
  const std::string norm = "a normalised JH-2 constant (dimensionless; X Table 1)";
  p.jh_a = s.number("a");
  s.range("a", p.jh_a, 0, 5, Dimension::Dimensionless, true, false, norm);
  p.jh_b = s.number("b");
  s.range("b", p.jh_b, 0, 5, Dimension::Dimensionless, false, false, norm);
  p.jh_n = s.number("n");
  s.range("n", p.jh_n, 0, 2, Dimension::Dimensionless, true, false, norm);
  p.jh_m = s.number("m");
  s.range("m", p.jh_m, 0, 2, Dimension::Dimensionless, true, false, norm);
  p.jh_c = s.number_or("c", 0.0);
  s.range("c", p.jh_c, 0, 1, Dimension::Dimensionless, false, false, norm);
  p.hel = stress(s, "hel", "; the Hugoniot elastic limit, e.g. \"2.79 GPa\"");
  p.p_hel = stress(s, "p_hel", "; the pressure at the HEL, e.g. \"1.46 GPa\"");
  if (!(p.p_hel < p.hel))
    s.fail("p_hel", "must be less than hel = " + format_quantity(p.hel, Dimension::Pressure) + " (got " +
                        format_quantity(p.p_hel, Dimension::Pressure) + "): HEL = P_HEL + 2/3 sigma_HEL with sigma_HEL > 0");
  p.tensile_pressure = stress(s, "tensile_strength", "; T, the largest hydrostatic tension, e.g. \"0.2 GPa\"");
  p.sfmax = s.number_or("sfmax", 1e30);
  s.range("sfmax", p.sfmax, 0, 1e30, Dimension::Dimensionless, true, false,
          "the cap of the normalised fractured strength; leave it out for no cap");
  p.reference_strain_rate = s.quantity_or("reference_strain_rate", Dimension::StrainRate, 1.0);
  s.positive("reference_strain_rate", p.reference_strain_rate, Dimension::StrainRate);
}

// Returns the bulk modulus E/(3(1-2nu)) when the elastic constants were given as E and nu, else 0.
double read_strength(const View& s, StrengthParams<double>& p) {
  const std::string kind = s.choice("kind", kStrengthKinds);
  if (kind == "hydrodynamic") {
    s.allow({"kind"});
    p.kind = StrengthKind::Hydrodynamic;
    return 0;
  }
  if (kind == "elastic") {
    s.allow({"kind", "shear_modulus", "youngs_modulus", "poisson_ratio"});
    p.kind = StrengthKind::Elastic;
  } else if (kind == "perfectly-plastic") {
    s.allow({"kind", "shear_modulus", "youngs_modulus", "poisson_ratio", "yield_stress"});
    p.kind = StrengthKind::PerfectlyPlastic;
    p.yield_stress = stress(s, "yield_stress", "; a material without strength is kind = \"hydrodynamic\"");
  } else if (kind == "johnson-cook") {
    s.allow({"kind", "shear_modulus", "youngs_modulus", "poisson_ratio", "a", "b", "n", "c", "m",
             "reference_strain_rate", "melt_temperature", "taylor_quinney"});
    p.kind = StrengthKind::JohnsonCook;
  } else {
    s.allow({"kind", "shear_modulus", "youngs_modulus", "poisson_ratio", "a", "b", "c", "m", "n", "hel", "p_hel",
             "tensile_strength", "sfmax", "reference_strain_rate"});
    p.kind = StrengthKind::JohnsonHolmquist2;
  }
  const bool has_g = s.has("shear_modulus"), has_e = s.has("youngs_modulus"), has_nu = s.has("poisson_ratio");
  if (has_g && (has_e || has_nu))
    s.fail(has_e ? "youngs_modulus" : "poisson_ratio",
           "give either shear_modulus or youngs_modulus + poisson_ratio, not both");
  double derived_k = 0;
  if (has_g) {
    p.shear_modulus = stress(s, "shear_modulus");
  } else {
    if (!has_e && !has_nu)
      s.missing("shear_modulus", "expected shear_modulus = \"80 GPa\", or youngs_modulus = \"200 GPa\" with "
                                 "poisson_ratio = 0.3");
    if (!has_e) s.missing("youngs_modulus", "poisson_ratio needs youngs_modulus, e.g. \"200 GPa\"");
    if (!has_nu) s.missing("poisson_ratio", "youngs_modulus needs poisson_ratio, e.g. 0.3");
    const double E = stress(s, "youngs_modulus");
    const double nu = s.number("poisson_ratio");
    s.range("poisson_ratio", nu, -1, 0.5, Dimension::Dimensionless, true, true);
    p.shear_modulus = E / (2 * (1 + nu));
    derived_k = E / (3 * (1 - 2 * nu));
  }
  if (p.kind == StrengthKind::JohnsonCook) read_johnson_cook(s, p);
  if (p.kind == StrengthKind::JohnsonHolmquist2) read_jh2_strength(s, p);
  return derived_k;
}

// The damage table; `strength` is the strength table, named when damage needs plasticity it lacks.
void read_damage(const View& d, const StrengthParams<double>& strength, DamageParams<double>& p) {
  const std::string kind = d.choice("kind", kDamageKinds);
  if (kind == "none") {
    d.allow({"kind"});
    p.kind = DamageKind::None;
    return;
  }
  if (kind == "johnson-holmquist-2") {
    if (strength.kind != StrengthKind::JohnsonHolmquist2)
      d.fail("kind", "damage kind \"johnson-holmquist-2\" needs strength kind \"johnson-holmquist-2\" (its "
                     "failure strain uses the strength's p_hel and tensile_strength, X eq 26)");
    d.allow({"kind", "d1", "d2", "min_failure_strain", "bulking", "pair_factor"});
    p.kind = DamageKind::JohnsonHolmquist2;
    p.d1 = d.number("d1");
    d.range("d1", p.d1, 0, 1, Dimension::Dimensionless, true, false, "D1 of eps_f = D1 (P* + T*)^D2 (X eq 26)");
    p.d2 = d.number("d2");
    d.range("d2", p.d2, 0, 5, Dimension::Dimensionless, false, false, "D2 of eps_f = D1 (P* + T*)^D2 (X eq 26)");
    p.min_failure_strain = d.number_or("min_failure_strain", 0.0);
    d.range("min_failure_strain", p.min_failure_strain, 0, 10, Dimension::Dimensionless);
    p.bulking = d.number_or("bulking", 0.0);
    d.range("bulking", p.bulking, 0, 1, Dimension::Dimensionless, false, false,
            "beta, the fraction of lost elastic energy converted to pressure (X eq 28)");
    p.scale_pairs = d.boolean_or("pair_factor", false);  // JH-2 carries damage in its strength (X eq 22)
    return;
  }
  if (strength.kind != StrengthKind::JohnsonCook && strength.kind != StrengthKind::PerfectlyPlastic)
    d.fail("kind", "damage kind \"" + kind + "\" accumulates plastic strain, but the strength kind \"" +
                       (strength.kind == StrengthKind::Elastic ? "elastic" : strength.kind == StrengthKind::Hydrodynamic
                                                                              ? "hydrodynamic"
                                                                              : "johnson-holmquist-2") +
                       "\" has no plasticity of that kind; use strength kind \"johnson-cook\" or \"perfectly-plastic\", "
                       "or damage kind \"none\"");
  p.scale_pairs = d.boolean_or("pair_factor", true);
  p.compressive_crack_faces = d.choice("crack_faces", kCrackFaces, "scaled") == "compression";
  if (p.compressive_crack_faces && !p.scale_pairs)
    d.fail("crack_faces", "crack_faces = \"compression\" acts on the pairs of failed particles, which "
                          "pair_factor = false leaves unscaled and unfailed; set pair_factor = true or drop crack_faces");
  if (kind == "critical-plastic-strain") {
    d.allow({"kind", "critical_plastic_strain", "pair_factor", "crack_faces"});
    p.kind = DamageKind::CriticalPlasticStrain;
    p.critical_plastic_strain = d.number("critical_plastic_strain");
    d.range("critical_plastic_strain", p.critical_plastic_strain, 0, 10, Dimension::Dimensionless, true);
    return;
  }
  if (kind == "fracture-energy") {
    d.allow({"kind", "fracture_energy", "band_width_factor", "pair_factor", "crack_faces"});
    p.kind = DamageKind::FractureEnergy;
    p.fracture_energy = d.quantity("fracture_energy", Dimension::FractureEnergy);
    d.range("fracture_energy", p.fracture_energy, 0, 1e8, Dimension::FractureEnergy, true, false,
            "Gamma, the plastic work per unit crack area at failure (damage.hpp)");
    p.band_width_factor = d.number("band_width_factor");
    d.range("band_width_factor", p.band_width_factor, 0.5, 20, Dimension::Dimensionless, false, false,
            "the width of the failing band in initial smoothing lengths h0 = h_factor x spacing");
    return;
  }
  d.allow({"kind", "d1", "d2", "d3", "d4", "d5", "min_failure_strain", "pair_factor", "crack_faces"});
  p.kind = DamageKind::JohnsonCook;
  const std::string why = "the Johnson-Cook failure constants are at most 20 in magnitude";
  p.d1 = d.number("d1");
  d.range("d1", p.d1, -1, 20, Dimension::Dimensionless, false, false, why);
  p.d2 = d.number("d2");
  d.range("d2", p.d2, 0, 20, Dimension::Dimensionless, false, false, why);
  p.d3 = d.number("d3");
  d.range("d3", p.d3, -20, 20, Dimension::Dimensionless, false, false, why);
  p.d4 = d.number_or("d4", 0.0);
  d.range("d4", p.d4, -20, 20, Dimension::Dimensionless, false, false, why);
  p.d5 = d.number_or("d5", 0.0);
  d.range("d5", p.d5, -20, 20, Dimension::Dimensionless, false, false, why);
  p.min_failure_strain = d.number_or("min_failure_strain", 0.0);
  d.range("min_failure_strain", p.min_failure_strain, 0, 10, Dimension::Dimensionless);
}

MaterialSpec read_material(const View& m, const std::string& name) {
  m.allow({"density", "eos", "strength", "damage", "specific_heat", "room_temperature"});
  MaterialSpec out;
  out.name = name;
  out.line = line_of(&m.table());
  MaterialParams<double>& p = out.params;
  p.eos.rho0 = m.quantity("density", Dimension::Density);
  m.range("density", p.eos.rho0, 1, 30000, Dimension::Density);

  bool needs_bulk_modulus = false;
  const View eos = m.sub("eos", "the EOS of a material", "{ kind = \"linear\", bulk_modulus = \"160 GPa\" }");
  read_eos(eos, p.eos, needs_bulk_modulus);
  const View strength =
      m.sub("strength", "the strength model of a material", "{ kind = \"elastic\", shear_modulus = \"80 GPa\" }");
  const double derived_k = read_strength(strength, p.strength);
  if (needs_bulk_modulus) {
    if (derived_k <= 0)
      eos.missing("bulk_modulus", "a linear EOS needs bulk_modulus = \"160 GPa\" (or youngs_modulus and "
                                    "poisson_ratio in the strength table, from which K = E/(3(1-2nu)))");
    p.eos.k1 = derived_k;
    if (p.eos.k1 > kMaxModulus)
      strength.fail("poisson_ratio", "gives a bulk modulus E/(3(1-2nu)) of " + format_quantity(p.eos.k1, Dimension::Pressure) +
                                         ", above " + format_quantity(kMaxModulus, Dimension::Pressure) + "; give bulk_modulus");
  }

  if (m.has("damage")) {
    const View d = m.sub("damage", "the damage model of a material", "{ kind = \"none\" }");
    read_damage(d, p.strength, p.damage);
  }
  if (m.has("specific_heat")) {
    p.specific_heat = m.quantity("specific_heat", Dimension::SpecificHeat);
    m.range("specific_heat", p.specific_heat, 0, 1e5, Dimension::SpecificHeat, true);
  }
  p.room_temperature = m.quantity_or("room_temperature", Dimension::Temperature, 293.0);
  m.range("room_temperature", p.room_temperature, 0, 5000, Dimension::Temperature, true);
  if (p.strength.melt_temperature > 0) {
    if (!(p.strength.melt_temperature > p.room_temperature))
      strength.fail("melt_temperature", "must be above room_temperature = " +
                                            format_quantity(p.room_temperature, Dimension::Temperature) + " (got " +
                                            format_quantity(p.strength.melt_temperature, Dimension::Temperature) + ")");
    if (!(p.specific_heat > 0))
      m.missing("specific_heat", "Johnson-Cook thermal softening (strength.melt_temperature) needs the temperature, "
                                 "which plastic work raises by way of specific_heat = \"452 J/(kg K)\"; give it, or "
                                 "leave out melt_temperature to turn thermal softening off");
  }
  return out;
}

}  // namespace

std::vector<MaterialSpec> read_materials(const View& root) {
  const std::string example = "[materials.steel] with density, eos and strength";
  const toml::node* n = root.find("materials");
  if (!n) root.missing("materials", "expected one table per material, such as " + example);
  if (!n->is_table())
    root.fail("materials", "expected one table per material, such as " + example + ", not " + type_name(*n));
  const View all(root.values().reporter(), *n->as_table(), "materials", "materials");
  std::vector<MaterialSpec> out;
  for (const auto& [name, node] : in_file_order(all.table())) {
    check_name(root.values().reporter(), node, all.key(name), name);
    if (!node->is_table())
      all.fail(name, "expected a table of material constants such as " + example + ", not " + type_name(*node));
    out.push_back(read_material(View(root.values().reporter(), *node->as_table(), all.key(name), "a material"), name));
  }
  if (out.empty()) all.fail_here("no material is defined; expected " + example);
  return out;
}

}  // namespace impactsph::case_reading
