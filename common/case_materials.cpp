// The [materials] of a case file: EOS, strength and damage tables, checked against docs/case-files.md and
// read into MaterialSpec in SI units (common/case_reading.hpp). Each strength and damage model reads its own
// constants (common/models/); what every model shares is read here.
#include <stdexcept>

#include "common/case_reading.hpp"

namespace impactsph::case_reading {
namespace {

// ---------------------------------------------------------------------------------------------------
// Materials

const Keys kEosKinds{"linear", "polynomial", "mie-gruneisen", "gruneisen-cubic"};
// What the pairs of a failed particle carry (DamageParams::compressive_crack_faces).
const Keys kCrackFaces{"scaled", "compression"};

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

// The registered kind of a case key that choice() has checked against strength_keys() / damage_keys().
StrengthKind strength_kind_of(const std::string& key) {
#define IMPACTSPH_MODEL_MATCH(k, member, Model) \
  if (key == Model::key) return StrengthKind::k;
  IMPACTSPH_STRENGTH_MODELS(IMPACTSPH_MODEL_MATCH)
#undef IMPACTSPH_MODEL_MATCH
  throw std::logic_error("no strength model has the key \"" + key + "\"");
}
DamageKind damage_kind_of(const std::string& key) {
#define IMPACTSPH_MODEL_MATCH(k, member, Model) \
  if (key == Model::key) return DamageKind::k;
  IMPACTSPH_DAMAGE_MODELS(IMPACTSPH_MODEL_MATCH)
#undef IMPACTSPH_MODEL_MATCH
  throw std::logic_error("no damage model has the key \"" + key + "\"");
}

// Returns the bulk modulus E/(3(1-2nu)) when the elastic constants were given as E and nu, else 0. The
// elastic constants are read here for every model with a deviatoric stress; the model reads the rest.
double read_strength(const View& s, StrengthParams<double>& p) {
  p.kind = strength_kind_of(s.choice("kind", strength_keys()));
  return with_strength_model(p.kind, [&](auto model) {
    using Model = decltype(model);
    Keys allowed{"kind"};
    if (Model::deviatoric) allowed.insert(allowed.end(), {"shear_modulus", "youngs_modulus", "poisson_ratio"});
    const Keys own = Model::keys();
    allowed.insert(allowed.end(), own.begin(), own.end());
    s.allow(allowed);
    if (!Model::deviatoric) return 0.0;
    const bool has_g = s.has("shear_modulus"), has_e = s.has("youngs_modulus"), has_nu = s.has("poisson_ratio");
    if (has_g && (has_e || has_nu))
      s.fail(has_e ? "youngs_modulus" : "poisson_ratio",
             "give either shear_modulus or youngs_modulus + poisson_ratio, not both");
    double derived_k = 0;
    if (has_g) {
      p.shear_modulus = s.stress("shear_modulus");
    } else {
      if (!has_e && !has_nu)
        s.missing("shear_modulus", "expected shear_modulus = \"80 GPa\", or youngs_modulus = \"200 GPa\" with "
                                   "poisson_ratio = 0.3");
      if (!has_e) s.missing("youngs_modulus", "poisson_ratio needs youngs_modulus, e.g. \"200 GPa\"");
      if (!has_nu) s.missing("poisson_ratio", "youngs_modulus needs poisson_ratio, e.g. 0.3");
      const double E = s.stress("youngs_modulus");
      const double nu = s.number("poisson_ratio");
      s.range("poisson_ratio", nu, -1, 0.5, Dimension::Dimensionless, true, true);
      p.shear_modulus = E / (2 * (1 + nu));
      derived_k = E / (3 * (1 - 2 * nu));
    }
    Model::read(s, p);
    return derived_k;
  });
}

// The strength kinds whose plasticity the metal damage models count, quoted and joined with "or".
std::string ductile_strength_keys() {
  std::string out;
  for (const std::string& key : strength_keys()) {
    if (!with_strength_model(strength_kind_of(key), [](auto model) { return decltype(model)::ductile; })) continue;
    out += (out.empty() ? "\"" : " or \"") + key + "\"";
  }
  return out;
}

// The damage table; `strength` is the strength table, named when the damage model needs a strength it lacks.
// The pair options (pair_factor, crack_faces) are read here for every failing model; the model reads the rest.
void read_damage(const View& d, const StrengthParams<double>& strength, DamageParams<double>& p) {
  const std::string kind = d.choice("kind", damage_keys());
  p.kind = damage_kind_of(kind);
  with_damage_model(p.kind, [&](auto model) {
    using Model = decltype(model);
    const std::string strength_kind = strength_key(strength.kind);
    if (Model::required_strength && strength_kind != Model::required_strength)
      d.fail("kind", "damage kind \"" + kind + "\" needs strength kind \"" + Model::required_strength + "\" (" +
                         Model::required_strength_because + ")");
    const bool ductile = with_strength_model(strength.kind, [](auto s) { return decltype(s)::ductile; });
    if (Model::needs_ductile_strength && !ductile)
      d.fail("kind", "damage kind \"" + kind + "\" accumulates plastic strain, but the strength kind \"" + strength_kind +
                         "\" has no plasticity of that kind; use strength kind " + ductile_strength_keys() +
                         ", or damage kind \"none\"");
    Keys allowed{"kind"};
    const Keys own = Model::keys();
    allowed.insert(allowed.end(), own.begin(), own.end());
    if (Model::fails) allowed.push_back("pair_factor");
    if (Model::takes_crack_faces) allowed.push_back("crack_faces");
    d.allow(allowed);
    if (!Model::fails) return;
    p.scale_pairs = d.boolean_or("pair_factor", Model::default_pair_factor);
    if (Model::takes_crack_faces) {
      p.compressive_crack_faces = d.choice("crack_faces", kCrackFaces, "scaled") == "compression";
      if (p.compressive_crack_faces && !p.scale_pairs)
        d.fail("crack_faces", "crack_faces = \"compression\" acts on the pairs of failed particles, which "
                              "pair_factor = false leaves unscaled and unfailed; set pair_factor = true or drop crack_faces");
    }
    Model::read(d, p);
  });
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
