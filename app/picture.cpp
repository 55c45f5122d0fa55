#include "app/picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "app/gnuplot.hpp"
#include "common/damage.hpp"
#include "common/output.hpp"

namespace fs = std::filesystem;

namespace impactsph {

namespace {

constexpr double kInPlane = 1e-6;       // |direction component| below which an axis lies in the impact plane
constexpr const char* kFailedColour = "#1565ff";            // failed particles of the other bodies
constexpr const char* kFailedProjectileColour = "#2e9d3a";  // of the projectile
constexpr const char* kAxisNames = "xyz";

// The label of the colour bar, with the unit field_value gives.
const char* field_label(PictureField f) {
  switch (f) {
    case PictureField::Damage: return "damage D [-]";
    case PictureField::Speed: return "speed [m/s]";
    case PictureField::Pressure: return "pressure [GPa]";
    default: return "plastic strain [-]";
  }
}

double field_value(PictureField f, const ParticleSet& p, std::size_t i) {
  switch (f) {
    case PictureField::Damage: return p.damage[i];
    case PictureField::Speed: return norm(p.vel[i]);
    case PictureField::Pressure: return p.pressure[i] * 1e-9;
    default: return p.plastic_strain[i];
  }
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The body that moves: the case's projectile, else its Taylor bar, else the fastest body (the first of
// equals).
int moving_body(const CaseSpec& s) {
  if (s.observables.projectile_index >= 0) return s.observables.projectile_index;
  if (s.observables.taylor_bar_index >= 0) return s.observables.taylor_bar_index;
  int best = 0;
  for (std::size_t k = 1; k < s.bodies.size(); ++k)
    if (norm(s.bodies[k].velocity) > norm(s.bodies[best].velocity)) best = static_cast<int>(k);
  return best;
}

struct Cut {
  int normal = 0;
  double position = 0;  // m
  bool symmetry = false;
  int h = 1, v = 2;     // in-plane axes drawn across and up
  std::array<bool, 2> mirror{false, false};  // about a symmetry plane on h, v
  std::array<double, 2> mirror_at{0, 0};     // m
};

Cut choose_cut(const Scene& scene, const ParticleSet& p, int body) {
  const CaseSpec& s = scene.spec;
  const Vec3d u = s.bodies.empty() ? Vec3d{0, 0, 0} : s.bodies[body].velocity;
  const double speed = norm(u);
  const Vec3d d = speed > 0 ? (1.0 / speed) * u : Vec3d{0, 0, 0};
  Cut c;
  const auto plane = std::find_if(s.symmetry.begin(), s.symmetry.end(),
                                  [&](const SymmetryPlaneSpec& sp) { return std::abs(d[sp.axis]) < kInPlane; });
  if (plane != s.symmetry.end()) {
    c.normal = plane->axis;
    c.position = plane->position;
    c.symmetry = true;
  } else {
    for (int a = 1; a < 3; ++a)
      if (std::abs(d[a]) < std::abs(d[c.normal])) c.normal = a;
    double m = 0, mx = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.body[i] == body) {
        m += p.mass[i];
        mx += p.mass[i] * p.pos[i][c.normal];
      }
    c.position = m > 0 ? mx / m : 0.0;
  }
  c.h = c.normal == 0 ? 1 : 0;
  c.v = c.normal == 2 ? 1 : 2;
  for (int k = 0; k < 2; ++k) {
    const int a = k == 0 ? c.h : c.v;
    int planes = 0;
    for (const SymmetryPlaneSpec& sp : s.symmetry)
      if (sp.axis == a && !sp.wall) {  // a wall is no plane of symmetry: nothing is mirrored across it
        ++planes;
        c.mirror_at[k] = sp.position;
      }
    c.mirror[k] = planes == 1 && std::abs(d[a]) < kInPlane;
  }
  return c;
}

struct Square {
  double x, y, half_w, half_h, value;  // mm, mm, mm, mm, field unit
};

// The particles drawn, in the order drawn: intact ones of the bodies other than the projectile, intact ones
// of the projectile (outlined when there are other bodies), failed ones of the others, of the projectile.
enum Group { kIntact, kIntactProjectile, kFailed, kFailedProjectile, kGroups };

struct Groups {
  std::array<std::vector<Square>, kGroups> squares;
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();  // intact
};

Groups cut_particles(const Scene& scene, const ParticleSet& p, const Cut& c, int projectile, PictureField field) {
  const std::size_t bodies = scene.bodies.size();
  // A body at two resolutions has two lattices: its coarse particles (those of the coarse copy of its
  // material, Scene::materials) are drawn with their own cells, from their own layer.
  const std::size_t case_materials = scene.spec.materials.size();
  auto lattice_of = [&](std::size_t i) {
    return 2 * static_cast<std::size_t>(p.body[i]) + (static_cast<std::size_t>(p.material[i]) >= case_materials ? 1 : 0);
  };
  auto spacing_of = [&](std::size_t lattice) -> const Vec3d& {
    const BodyInfo& body = scene.bodies[lattice / 2];
    return lattice % 2 ? body.coarse_lattice_spacing : body.lattice_spacing;
  };
  // Of each lattice, the signed distance of its particle nearest the plane: its layer.
  std::vector<double> layer(2 * bodies, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double dist = p.pos[i][c.normal] - c.position;
    double& l = layer[lattice_of(i)];
    if (std::abs(dist) < std::abs(l)) l = dist;
  }
  const bool outline = bodies > 1;
  Groups g;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t b = static_cast<std::size_t>(p.body[i]);
    const Vec3d& ls = spacing_of(lattice_of(i));
    if (std::abs(p.pos[i][c.normal] - c.position - layer[lattice_of(i)]) >= 0.5 * ls[c.normal]) continue;
    const bool fails = can_fail(scene.materials[static_cast<std::size_t>(p.material[i])]);
    const bool failed = fails && p.damage[i] >= kFailedDamage;
    const int group = (failed ? kFailed : kIntact) + (outline && static_cast<int>(b) == projectile ? 1 : 0);
    const double value = field_value(field, p, i);
    if (!failed) {
      g.lo = std::min(g.lo, value);
      g.hi = std::max(g.hi, value);
    }
    const Square sq{p.pos[i][c.h] * 1e3, p.pos[i][c.v] * 1e3, 0.5e3 * ls[c.h], 0.5e3 * ls[c.v], value};
    g.squares[group].push_back(sq);
  }
  for (std::vector<Square>& list : g.squares)
    for (int k = 0; k < 2; ++k) {
      if (!c.mirror[k]) continue;
      const double at = c.mirror_at[k] * 1e3;
      for (std::size_t j = 0, m = list.size(); j < m; ++j) {
        Square q = list[j];
        (k == 0 ? q.x : q.y) = 2 * at - (k == 0 ? q.x : q.y);
        list.push_back(q);
      }
    }
  return g;
}

// The longest of 1, 2, 5 x 10^k mm that is at most a quarter of `width` mm.
double scale_bar_length(double width) {
  double best = 0.001;
  for (double decade = 1e-3; decade <= 1e4; decade *= 10)
    for (double f : {1.0, 2.0, 5.0})
      if (f * decade <= 0.25 * width) best = f * decade;
  return best;
}

std::string length_text(double mm) { return fmt("%g mm", mm); }

std::string picture_script(const std::string& stem, const Scene& scene, const Cut& c, const Groups& g, int projectile,
                           double time, PictureField field, const std::array<int, kGroups>& blocks) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const std::vector<Square>& list : g.squares)
    for (const Square& q : list) {
      x0 = std::min(x0, q.x - q.half_w);
      x1 = std::max(x1, q.x + q.half_w);
      y0 = std::min(y0, q.y - q.half_h);
      y1 = std::max(y1, q.y + q.half_h);
    }
  const double w = x1 - x0, h = y1 - y0;
  const double pad = 0.04 * std::max(w, h);
  const double bar_room = 0.1 * std::max(w, h);  // below the particles, for the scale bar
  x0 -= pad;
  x1 += pad;
  y1 += pad;
  y0 -= pad + bar_room;
  const double bar = scale_bar_length(w);
  const double bar_x = x0 + pad, bar_y = y0 + 0.45 * bar_room;

  double lo = std::isfinite(g.lo) ? g.lo : 0.0, hi = std::isfinite(g.hi) ? g.hi : 1.0;
  if (field == PictureField::Damage) lo = 0, hi = 1;
  if (field != PictureField::Pressure) lo = std::min(lo, 0.0);
  if (!(hi > lo)) hi = lo + 1;

  const bool flat = (y1 - y0) < 0.6 * (x1 - x0);  // room below, none above: the key goes below
  const int width_px = 1100;
  const int height_px = std::clamp(static_cast<int>(std::lround(780.0 * (y1 - y0) / (x1 - x0))) + 230, 450, 1500);

  const CaseSpec& s = scene.spec;
  const bool outline = scene.bodies.size() > 1;
  std::string names;  // of the bodies in the groups kIntact and kFailed
  for (std::size_t k = 0; k < scene.bodies.size(); ++k)
    if (static_cast<int>(k) != projectile || !outline) names += (names.empty() ? "" : ", ") + scene.bodies[k].name;
  const std::string failed = " failed (D >= " + fmt("%.2f", kFailedDamage) + ")";
  const std::string& projectile_name = scene.bodies[projectile].name;
  std::string where = std::string("cut ") + kAxisNames[c.normal] + " = " + fmt("%.4g", c.position * 1e3) + " mm (" +
                      (c.symmetry ? "symmetry plane" : "through the centre of mass of " + scene.bodies[projectile].name) +
                      ")";
  for (int k = 0; k < 2; ++k)
    if (c.mirror[k])
      where += ", mirrored about " + std::string(1, kAxisNames[k == 0 ? c.h : c.v]) + " = " +
               fmt("%.4g", c.mirror_at[k] * 1e3) + " mm";

  std::ostringstream o;
  o << "# Drawn by impactsph at the end of the run: `gnuplot " << stem << ".gp` in this folder redraws " << stem
    << ".png from " << stem << ".dat.\n"
    << "if (!exists(\"output\")) output = " << gp_quote(stem + ".png") << "\n"
    << "set terminal pngcairo size " << width_px << "," << height_px << " noenhanced font 'Sans,12'\n"
    << "set output output\n"
    << "set title " << gp_quote(s.name + " at t = " + fmt("%.4g", time * 1e6) + " µs, coloured by " + field_label(field))
    << ".\"\\n\"." << gp_quote(where + "; spacing " + fmt("%.4g", s.numerics.spacing * 1e3) + " mm") << "\n"
    << "set xlabel " << gp_quote(std::string(1, kAxisNames[c.h]) + " [mm]") << "\n"
    << "set ylabel " << gp_quote(std::string(1, kAxisNames[c.v]) + " [mm]") << "\n"
    << "set size ratio -1\n"
    << "set rmargin 12\n"
    << "set xrange [" << gp_number(x0) << ":" << gp_number(x1) << "]\n"
    << "set yrange [" << gp_number(y0) << ":" << gp_number(y1) << "]\n"
    << "set cbrange [" << gp_number(lo) << ":" << gp_number(hi) << "]\n"
    << "set cblabel " << gp_quote(field_label(field)) << "\n"
    << "set palette defined (0 '#f0f0f0', 0.2 '#fde08a', 0.45 '#f99b3e', 0.7 '#d9480f', 1 '#6b0f1a')\n"
    << (flat ? "set key below horizontal\n" : "set key top left inside opaque box\n")
    << "set tics out\n"
    << "set arrow 1 from " << gp_number(bar_x) << "," << gp_number(bar_y) << " to " << gp_number(bar_x + bar) << ","
    << gp_number(bar_y) << " heads size screen 0.006,90 lw 2.5 lc rgb 'black' front\n"
    << "set label 1 " << gp_quote(length_text(bar)) << " at " << gp_number(bar_x + 0.5 * bar) << ","
    << gp_number(bar_y + 0.3 * bar_room) << " center front\n";
  std::vector<std::string> plots;
  const std::string data = gp_quote(stem + ".dat");
  const std::string border = "border lc rgb '#505050'";
  const std::array<std::string, kGroups> style{
      "using 1:2:3:4:5 with boxxyerror fs solid 1.0 noborder lc palette title " + gp_quote(names),
      "using 1:2:3:4:5 with boxxyerror fs solid 1.0 " + border + " lc palette title " +
          gp_quote(projectile_name + " (outlined)"),
      "using 1:2:3:4 with boxxyerror fs solid 1.0 noborder lc rgb '" + std::string(kFailedColour) + "' title " +
          gp_quote(names + failed),
      "using 1:2:3:4 with boxxyerror fs solid 1.0 " + border + " lc rgb '" + kFailedProjectileColour + "' title " +
          gp_quote(projectile_name + failed)};
  for (int k = 0; k < kGroups; ++k)
    if (blocks[k] >= 0) plots.push_back(data + " index " + std::to_string(blocks[k]) + " " + style[k]);
  o << "plot ";
  for (std::size_t k = 0; k < plots.size(); ++k) o << (k ? ", \\\n     " : "") << plots[k];
  o << "\nunset output\n";
  return o.str();
}

}  // namespace

void write_picture_files(const fs::path& dir, const std::string& stem, const Scene& scene, const ParticleSet& p,
                         double time, PictureField field) {
  const int projectile = moving_body(scene.spec);
  const Cut cut = choose_cut(scene, p, projectile);
  const Groups g = cut_particles(scene, p, cut, projectile, field);
  const char* what[kGroups] = {"intact particles of the other bodies", "intact particles of the projectile",
                               "failed particles (D >= 0.99) of the other bodies",
                               "failed particles (D >= 0.99) of the projectile"};
  std::ostringstream d;
  d << "# The particles of the cut drawn by " << stem << ".gp; blocks (gnuplot index) of the groups that have any:\n"
    << "# columns: " << kAxisNames[cut.h] << " [mm], " << kAxisNames[cut.v] << " [mm], half width [mm], half height [mm], "
    << field_label(field) << "\n";
  std::array<int, kGroups> blocks{-1, -1, -1, -1};
  int next = 0;
  for (int k = 0; k < kGroups; ++k) {
    if (g.squares[k].empty()) continue;
    blocks[k] = next++;
    d << (blocks[k] > 0 ? "\n\n" : "") << "# " << what[k] << "\n";
    for (const Square& q : g.squares[k]) {
      char line[160];
      std::snprintf(line, sizeof line, "%.6g %.6g %.6g %.6g %.6g\n", q.x, q.y, q.half_w, q.half_h, q.value);
      d << line;
    }
  }
  if (next == 0)
    throw std::runtime_error("no particle lies in the cut " + std::string(1, kAxisNames[cut.normal]) + " = " +
                             fmt("%.4g", cut.position * 1e3) + " mm");
  write_text_atomic(dir / (stem + ".dat"), d.str());
  write_text_atomic(dir / (stem + ".gp"), picture_script(stem, scene, cut, g, projectile, time, field, blocks));
}

std::string draw_picture(const fs::path& dir, const std::string& stem) {
  if (!fs::exists(dir / (stem + ".gp")))
    return (dir / (stem + ".gp")).string() + " is missing, so " + stem + ".png was not drawn";
  return run_gnuplot(dir / (stem + ".png"), [&](const fs::path& target) {
    return "output = " + gp_quote(target.string()) + "\nload " + gp_quote(stem + ".gp") + "\n";
  });
}

std::string write_and_draw_picture(const fs::path& dir, const std::string& stem, const Scene& scene,
                                   const ParticleSet& p, double time, PictureField field) {
  std::error_code ec;
  fs::remove(dir / (stem + ".png"), ec);  // an earlier run's would not match the new script
  try {
    write_picture_files(dir, stem, scene, p, time, field);
    const std::string error = draw_picture(dir, stem);
    if (error.empty()) return "";
    return stem + ".png not drawn: " + error + "; redraw it with `gnuplot " + stem + ".gp` in " + dir.string();
  } catch (const std::exception& e) {
    return stem + ".png not drawn: " + e.what();
  }
}

std::string picture_field_label(PictureField field) { return field_label(field); }

}  // namespace impactsph
