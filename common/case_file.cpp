// Case file reader: parse TOML with toml++, apply overrides to the tree, then walk the tree once,
// checking every key against the schema of docs/case-files.md and filling a CaseSpec in SI units.
// Tables are read through View (common/case_reading.hpp), which knows the full key of what it reads so
// every CaseError names it. Here: the case, numerics, time, observables and output sections, the
// overrides and material files; the materials are read in case_materials.cpp, the bodies, boundaries
// and contacts in case_geometry.cpp.
#include "common/case_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <toml++/toml.h>

#include "common/case_reading.hpp"
#include "common/errors.hpp"
#include "common/mesh_solid.hpp"
#include "common/units.hpp"

namespace impactsph {
namespace {

using namespace case_reading;


// ---------------------------------------------------------------------------------------------------
// Case, numerics, time, output

// output.picture_field, in the order of enum PictureField.
const Keys kPictureFields{"plastic_strain", "damage", "speed", "pressure"};

void read_numerics(const View& root, NumericsSpec& num) {
  const View n = root.sub("numerics", "[numerics]", "[numerics] with spacing = \"0.5 mm\"");
  n.allow({"spacing", "kernel", "h_factor", "viscosity_linear", "viscosity_quadratic", "viscosity_balsara",
           "viscosity_limiter", "viscosity_limiter_close_approach",
           "bulk_viscosity_linear", "bulk_viscosity_quadratic", "artificial_stress", "artificial_stress_exponent", "artificial_stress_of",
           "delta",
           "cfl", "integrator", "correction_max_condition"});
  num.spacing = n.quantity("spacing", Dimension::Length);
  num.spacing_line = line_of(n.find("spacing"));
  n.positive("spacing", num.spacing, Dimension::Length);
  const std::string kernel = n.choice("kernel", {"wendland-c2", "cubic-spline"}, "wendland-c2");
  num.kernel = kernel == "wendland-c2" ? KernelKind::WendlandC2 : KernelKind::CubicSpline;
  num.h_factor = n.number_or("h_factor", 1.2);
  n.range("h_factor", num.h_factor, 1.0, 2.0, Dimension::Dimensionless);
  num.viscosity.linear = n.number_or("viscosity_linear", 1.0);
  n.non_negative("viscosity_linear", num.viscosity.linear, Dimension::Dimensionless);
  num.viscosity.quadratic = n.number_or("viscosity_quadratic", 1.0);
  n.non_negative("viscosity_quadratic", num.viscosity.quadratic, Dimension::Dimensionless);
  num.viscosity_balsara = n.boolean_or("viscosity_balsara", false);
  const bool limited = n.choice("viscosity_limiter", {"none", "van-leer"}, "none") == "van-leer";
  const double close = n.number_or("viscosity_limiter_close_approach", kViscosityCloseApproachSpacings);
  n.range("viscosity_limiter_close_approach", close, 0, 1, Dimension::Dimensionless);
  if (!limited && n.has("viscosity_limiter_close_approach"))
    n.fail("viscosity_limiter_close_approach", "only acts with viscosity_limiter = \"van-leer\"; set that, or remove this key");
  num.viscosity = limited_viscosity_params(num.viscosity.linear, num.viscosity.quadratic, limited, num.h_factor, close);
  num.bulk_viscosity.linear = n.number_or("bulk_viscosity_linear", 0.0);
  n.range("bulk_viscosity_linear", num.bulk_viscosity.linear, 0, 5, Dimension::Dimensionless);
  num.bulk_viscosity.quadratic = n.number_or("bulk_viscosity_quadratic", 0.0);
  n.range("bulk_viscosity_quadratic", num.bulk_viscosity.quadratic, 0, 5, Dimension::Dimensionless);
  num.artificial_stress = n.number_or("artificial_stress", 0.0);
  n.range("artificial_stress", num.artificial_stress, 0, 1, Dimension::Dimensionless);
  const double exponent = n.number_or("artificial_stress_exponent", 4.0);
  n.range("artificial_stress_exponent", exponent, 1, 8, Dimension::Dimensionless);
  if (exponent != std::floor(exponent))
    n.fail("artificial_stress_exponent", "must be a whole number such as 4 (Gray, Monaghan and Swift 2001), got " +
                                             format_quantity(exponent, Dimension::Dimensionless));
  num.artificial_stress_exponent = static_cast<int>(exponent);
  const std::string of = n.choice("artificial_stress_of", {"deviatoric", "total", "total-bounded"}, "deviatoric");
  num.artificial_stress_of = of == "total"           ? ArtificialStressOf::Total
                             : of == "total-bounded" ? ArtificialStressOf::TotalBounded
                                                     : ArtificialStressOf::Deviatoric;
  num.delta = n.number_or("delta", 0.1);
  n.range("delta", num.delta, 0, 1, Dimension::Dimensionless);
  num.cfl = n.number_or("cfl", 0.2);
  n.range("cfl", num.cfl, 0, 1, Dimension::Dimensionless, true);
  num.integrator = n.choice("integrator", {"leapfrog", "midpoint"}, "leapfrog") == "leapfrog" ? Integrator::Leapfrog
                                                                                            : Integrator::Midpoint;
  num.correction.max_condition = n.number_or("correction_max_condition", 1e3);
  if (!(num.correction.max_condition > 3))
    n.fail("correction_max_condition", "must be greater than 3, the condition number of the identity (got " +
                                           format_quantity(num.correction.max_condition, Dimension::Dimensionless) + ")");
}

void read_time(const View& root, TimeSpec& time) {
  const View t = root.sub("time", "[time]", "[time] with end = \"20 us\" and output_interval = \"1 us\"");
  t.allow({"end", "output_interval", "frame_interval", "checkpoint_interval"});
  time.end = t.quantity("end", Dimension::Time);
  t.positive("end", time.end, Dimension::Time);
  auto interval = [&](const std::string& k, double v) {
    if (v > time.end)
      t.fail(k, "is longer than time.end = " + format_quantity(time.end, Dimension::Time) + " (got " +
                    format_quantity(v, Dimension::Time) + "); an interval must be at most the end time");
  };
  time.output_interval = t.quantity("output_interval", Dimension::Time);
  t.positive("output_interval", time.output_interval, Dimension::Time);
  interval("output_interval", time.output_interval);
  time.frame_interval = t.quantity_or("frame_interval", Dimension::Time, time.output_interval);
  t.positive("frame_interval", time.frame_interval, Dimension::Time);
  interval("frame_interval", time.frame_interval);
  time.checkpoint_interval = t.quantity_or("checkpoint_interval", Dimension::Time, 0.0);
  t.non_negative("checkpoint_interval", time.checkpoint_interval, Dimension::Time);
  interval("checkpoint_interval", time.checkpoint_interval);
}

void read_observables(const Reporter& r, const View& root, CaseSpec& spec) {
  const toml::node* n = root.find("observables");
  if (!n) return;
  if (!n->is_table())
    root.fail("observables", "expected a table such as [observables] with projectile = \"projectile\", not " + type_name(*n));
  const View o(r, *n->as_table(), "observables", "[observables]");
  o.allow({"taylor_bar", "projectile", "target", "stop_when_settled", "settle_window", "settle_tolerance"});
  ObservablesSpec& obs = spec.observables;
  auto body = [&](const std::string& k, std::string& name, int& index) {
    if (!o.has(k)) return;
    name = o.string(k, "\"projectile\"");
    Keys names;
    for (std::size_t b = 0; b < spec.bodies.size(); ++b) {
      names.push_back(spec.bodies[b].name);
      if (spec.bodies[b].name == name) index = static_cast<int>(b);
    }
    if (index < 0) o.fail(k, "names no body: \"" + name + "\"; the bodies are " + join_quoted(names));
  };
  body("taylor_bar", obs.taylor_bar, obs.taylor_bar_index);
  if (obs.taylor_bar_index >= 0 && spec.bodies[static_cast<std::size_t>(obs.taylor_bar_index)].shape == Shape::Sphere)
    o.fail("taylor_bar", "\"" + obs.taylor_bar + "\" is a sphere; the Taylor-bar observables (final length, impact-face "
                         "diameter) measure a bar: a cylinder, or a box along z");
  body("projectile", obs.projectile, obs.projectile_index);
  body("target", obs.target, obs.target_index);
  if (obs.target_index >= 0 && obs.projectile_index < 0)
    o.fail("target", "needs projectile = \"...\" too: the plug is the part of the target that leaves with the projectile");
  obs.stop_when_settled = o.boolean_or("stop_when_settled", false);
  if (obs.stop_when_settled && obs.projectile_index < 0)
    o.fail("stop_when_settled", "needs projectile = \"...\": the run settles when the projectile's velocity is steady");
  obs.settle_window = o.quantity_or("settle_window", Dimension::Time, obs.settle_window);
  o.positive("settle_window", obs.settle_window, Dimension::Time);
  obs.settle_tolerance = o.quantity_or("settle_tolerance", Dimension::Velocity, obs.settle_tolerance);
  o.positive("settle_tolerance", obs.settle_tolerance, Dimension::Velocity);
}

CaseSpec read_case(const toml::table& tree, const Reporter& r) {
  const View root(r, tree, "", "the case file");
  root.allow({"case", "materials", "bodies", "boundaries", "contacts", "numerics", "time", "observables", "output"});
  CaseSpec spec;
  spec.source_file = r.file();

  const View c = root.sub("case", "[case]", "[case] with name = \"elastic-wave\"");
  c.allow({"name", "description"});
  spec.name = c.string("name", "\"elastic-wave\"");
  if (spec.name.empty()) c.fail("name", "must not be empty");
  spec.description = c.string_or("description", "");

  spec.materials = read_materials(root);
  spec.bodies = read_bodies(root, spec.materials);
  read_boundaries(root, spec);
  read_contacts(root, spec);
  read_numerics(root, spec.numerics);
  // A coarse region with a largest spacing ([bodies.coarse] max_spacing) is not built above it.
  for (BodySpec& b : spec.bodies)
    if (b.coarse_ratio > 1 && b.coarse_max_spacing > 0 && spec.numerics.spacing > b.coarse_max_spacing * (1 + 1e-9)) {
      b.coarse_ratio = 1;
      b.coarse_off_above = b.coarse_max_spacing;
    }
  read_time(root, spec.time);
  read_observables(r, root, spec);
  if (const toml::node* n = root.find("output")) {
    if (!n->is_table()) root.fail("output", "expected a table such as [output] with vtu = true, not " + type_name(*n));
    const View o(r, *n->as_table(), "output", "[output]");
    o.allow({"vtu", "csv", "picture", "picture_field"});
    spec.output.vtu = o.boolean_or("vtu", true);
    spec.output.csv = o.boolean_or("csv", true);
    spec.output.picture = o.boolean_or("picture", true);
    const std::string field = o.choice("picture_field", kPictureFields, "plastic_strain");
    spec.output.picture_field = static_cast<PictureField>(
        std::find(kPictureFields.begin(), kPictureFields.end(), field) - kPictureFields.begin());
    if (spec.output.picture_field == PictureField::Damage &&
        std::none_of(spec.materials.begin(), spec.materials.end(),
                     [](const MaterialSpec& m) { return can_fail(m.params); }))
      o.fail("picture_field", "\"damage\" needs a material with a damage model ([materials.NAME] damage = { kind = "
                              "... }) and no material of this case has one; valid here: \"plastic_strain\", "
                              "\"speed\", \"pressure\"");
  }
  return spec;
}

// ---------------------------------------------------------------------------------------------------
// Overrides

// The value of an override as a TOML node: `0.1`, `true`, `"298 m/s"`, `[0, 0, -1]` are TOML; anything
// that does not parse as one TOML value (`298 m/s`, `40us`) is taken as a string.
toml::table value_holder(const std::string& value) {
  if (value.find('\n') == std::string::npos) {
    try {
      toml::table t = toml::parse("v = " + value);
      if (t.size() == 1 && t.contains("v")) return t;
    } catch (const toml::parse_error&) {
      // Not a TOML value: fall through to a plain string.
    }
  }
  toml::table t;
  t.insert("v", value);
  return t;
}

// Puts a copy of the value held by `holder` under `key` in `t` and returns the new node. A copy, not a
// move: toml++ copies drop the source region, so the node reports line 0 instead of line 1 of "v = ...".
const toml::node* put(toml::table& t, const std::string& key, const toml::table& holder) {
  const toml::node* out = nullptr;
  holder.get("v")->visit([&](const auto& v) { out = &t.insert_or_assign(key, v).first->second; });
  return out;
}

// A body's velocity given as a vector in the file and overridden by a speed keeps its direction: the
// direction of the old vector is written as `direction`, unless the body already has one.
void keep_direction(toml::table& body, Reporter& r, const std::string& origin) {
  if (body.contains("direction")) return;
  const toml::array* old = body.get_as<toml::array>("velocity");
  if (!old || old->size() != 3) return;
  Vec3d v{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const toml::node* c = old->get(i);
    if (const auto* s = c->as_string()) {
      try {
        v[i] = parse_quantity(s->get(), Dimension::Velocity);
      } catch (const std::invalid_argument&) {
        return;  // the vector was invalid anyway; validation reports the missing direction
      }
    } else if (c->is_number()) {
      v[i] = c->value<double>().value_or(0.0);
    } else {
      return;
    }
  }
  const double len = norm(v);
  if (!(len > 0)) return;
  toml::array dir{v.x / len, v.y / len, v.z / len};
  r.mark(&body.insert_or_assign("direction", std::move(dir)).first->second, origin + ", keeping the file's direction");
}

void apply_override(toml::table& root, const std::string& text, Reporter& r) {
  const std::string file = r.file();
  const auto eq = text.find('=');
  if (eq == std::string::npos)
    throw CaseError(file, 0, text, "an override is KEY=VALUE, such as projectile.velocity=298 m/s or numerics.cfl=0.1");
  const std::string path = trim(text.substr(0, eq));
  const std::string value = trim(text.substr(eq + 1));
  Keys parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(trim(p));
  if (!path.empty() && path.back() == '.') parts.push_back("");
  if (parts.size() < 2 || std::any_of(parts.begin(), parts.end(), [](const std::string& p) { return p.empty(); }))
    throw CaseError(file, 0, text, "the key of an override is TABLE.key, BODY.key or MATERIAL.key, such as "
                                   "numerics.cfl, projectile.velocity or steel.eos.c0");
  if (value.empty()) throw CaseError(file, 0, text, "the override has no value after '='");

  // Names that exist in the file, for resolving the first component and for the error listing them.
  std::map<std::string, toml::table*> bodies, materials;
  if (toml::array* a = root.get_as<toml::array>("bodies"))
    for (toml::node& b : *a)
      if (toml::table* t = b.as_table())
        if (const auto* name = t->get_as<std::string>("name")) bodies.emplace(name->get(), t);
  if (toml::table* m = root.get_as<toml::table>("materials"))
    for (auto&& [k, v] : *m)
      if (toml::table* t = v.as_table()) materials.emplace(std::string(k.str()), t);

  const Keys tables{"case", "numerics", "time", "observables", "output"};
  toml::table* target = nullptr;
  std::size_t first_key = 1;
  const std::string& head = parts[0];
  auto named = [&](const std::map<std::string, toml::table*>& from, const std::string& what) -> toml::table* {
    const auto it = from.find(parts[1]);
    if (it != from.end()) return it->second;
    Keys names;
    for (const auto& [k, v] : from) names.push_back(k);
    throw CaseError(file, 0, text, "no " + what + " named \"" + parts[1] + "\";" + did_you_mean(parts[1], names) +
                                       " defined: " + (names.empty() ? std::string("none") : join_quoted(names)));
  };
  if (std::find(tables.begin(), tables.end(), head) != tables.end()) {
    toml::node* n = root.get(head);
    if (!n) n = &root.insert_or_assign(head, toml::table{}).first->second;
    target = n->as_table();
    if (!target) throw CaseError(file, 0, text, "\"" + head + "\" in the case file is not a table");
  } else if ((head == "bodies" || head == "materials") && parts.size() >= 3) {
    target = named(head == "bodies" ? bodies : materials, head == "bodies" ? "body" : "material");
    first_key = 2;
  } else {
    const bool is_body = bodies.count(head) > 0, is_material = materials.count(head) > 0;
    if (is_body && is_material)
      throw CaseError(file, 0, text, "\"" + head + "\" names both a body and a material; write bodies." + head +
                                         "." + parts[1] + " or materials." + head + "." + parts[1]);
    if (!is_body && !is_material) {
      Keys all = tables;
      std::string listing = "tables: " + join_quoted(tables);
      Keys names;
      for (const auto& [k, v] : bodies) names.push_back(k), all.push_back(k);
      listing += "; bodies: " + (names.empty() ? std::string("none") : join_quoted(names));
      names.clear();
      for (const auto& [k, v] : materials) names.push_back(k), all.push_back(k);
      listing += "; materials: " + (names.empty() ? std::string("none") : join_quoted(names));
      throw CaseError(file, 0, text, "no table, body or material named \"" + head + "\";" + did_you_mean(head, all) +
                                         " valid: " + listing);
    }
    target = is_body ? bodies[head] : materials[head];
  }

  const std::string origin = "override \"" + text + "\"";
  for (std::size_t i = first_key; i + 1 < parts.size(); ++i) {
    toml::node* n = target->get(parts[i]);
    if (!n) {
      n = &target->insert_or_assign(parts[i], toml::table{}).first->second;
      r.mark(n, origin);
    }
    if (!n->is_table())
      throw CaseError(file, line_of(n), text, "\"" + parts[i] + "\" is " + type_name(*n) + ", not a table");
    target = n->as_table();
  }
  toml::table holder = value_holder(value);
  const std::string& leaf = parts.back();
  const bool is_body_table = std::any_of(bodies.begin(), bodies.end(), [&](const auto& b) { return b.second == target; });
  if (is_body_table && leaf == "velocity" && !holder.get("v")->is_array()) keep_direction(*target, r, origin);
  r.mark(put(*target, leaf, holder), origin);
}

// Material files: a material given as `[materials.NAME]` with the single key `file = "PATH"` (PATH relative
// to the case file's folder) takes its constants from that TOML file, whose top level holds the keys of
// a material table (density, eos, strength, ...). Read before the overrides, so NAME.key overrides work on
// the file's values; errors in the file name the file and its line (the nodes keep their source).
void resolve_material_files(toml::table& tree, const Reporter& r) {
  toml::table* materials = tree.get_as<toml::table>("materials");
  if (!materials) return;
  const std::filesystem::path base = std::filesystem::path(r.file()).parent_path();
  for (auto&& [k, v] : *materials) {
    toml::table* m = v.as_table();
    if (!m || !m->contains("file")) continue;
    const std::string key = "materials." + std::string(k.str()) + ".file";
    const toml::node* f = m->get("file");
    const auto* path = f->as_string();
    if (!path) r.fail(f, key, "expected the path of a material file such as \"../materials/alumina-ad995.toml\", not " + type_name(*f));
    for (auto&& [other, node] : *m)
      if (other.str() != "file")
        r.fail(&node, "materials." + std::string(k.str()) + "." + std::string(other.str()),
               "a material read from a file takes all its constants from the file; give only file = \"...\" here "
               "(change a constant with an override, NAME.key=VALUE)");
    const std::filesystem::path full = base / path->get();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(full, ec))
      r.fail(f, key, "no material file \"" + full.string() + "\" (the path is relative to the case file's folder)");
    std::ifstream in(full, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    toml::table loaded;
    try {
      loaded = toml::parse(text.str(), full.string());
    } catch (const toml::parse_error& e) {
      throw CaseError(full.string(), static_cast<int>(e.source().begin.line), "", "not valid TOML: " + std::string(e.description()));
    }
    *m = std::move(loaded);
  }
}

CaseSpec parse_tree(toml::table& tree, Reporter& r, const std::vector<std::string>& set_overrides,
                    const std::string& spacing_override) {
  resolve_material_files(tree, r);
  for (const std::string& o : set_overrides) apply_override(tree, o, r);
  if (!spacing_override.empty()) {
    toml::node* n = tree.get("numerics");
    if (!n) n = &tree.insert_or_assign("numerics", toml::table{}).first->second;
    toml::table* numerics = n->as_table();
    if (!numerics) throw CaseError(r.file(), line_of(n), "numerics", "expected a table [numerics], not " + type_name(*n));
    toml::table holder = value_holder(trim(spacing_override));
    r.mark(put(*numerics, "spacing", holder), "the spacing override \"" + spacing_override + "\"");
  }
  return read_case(tree, r);
}

}  // namespace

CaseSpec parse_case_string(const std::string& toml_text, const std::string& display_name,
                           const std::vector<std::string>& set_overrides, const std::string& spacing_override) {
  Reporter r(display_name);
  toml::table tree;
  try {
    tree = toml::parse(toml_text, display_name);
  } catch (const toml::parse_error& e) {
    throw CaseError(display_name, static_cast<int>(e.source().begin.line), "",
                    "not valid TOML: " + std::string(e.description()));
  }
  return parse_tree(tree, r, set_overrides, spacing_override);
}

std::vector<std::string> case_material_files(const std::string& path) {
  std::vector<std::string> files;
  toml::table tree;
  try {
    tree = toml::parse_file(path);
  } catch (const toml::parse_error&) {
    return files;
  }
  const toml::table* materials = tree.get_as<toml::table>("materials");
  if (!materials) return files;
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  for (auto&& [k, v] : *materials) {
    const toml::table* m = v.as_table();
    const toml::node* f = m ? m->get("file") : nullptr;
    if (f && f->as_string()) files.push_back((base / f->as_string()->get()).string());
  }
  return files;
}

std::string toml_file_content(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::ostringstream text;
  text << in.rdbuf();
  try {
    const toml::table tree = toml::parse(text.str(), path);
    std::ostringstream out;
    out << toml::toml_formatter(tree);  // keys in order, no comments: the same tree prints the same text
    return out.str();
  } catch (const toml::parse_error&) {
    return text.str();
  }
}

CaseSpec load_case_file(const std::string& path, const std::vector<std::string>& set_overrides,
                        const std::string& spacing_override) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw CaseError(path, 0, "", "no such case file");
  if (std::filesystem::is_directory(path, ec))
    throw CaseError(path, 0, "", "is a directory; expected a case file such as " + path + "/case.toml");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(path, 0, "", "cannot open the case file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_case_string(text.str(), path, set_overrides, spacing_override);
}

}  // namespace impactsph
