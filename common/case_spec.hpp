// CaseSpec: a case file after parsing and validation, every value in SI units. Built by case_file.cpp
// from TOML (see docs/case-files.md for the schema), turned into particles by scene.cpp.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "common/artificial_stress.hpp"
#include "common/correction.hpp"
#include "common/kernels.hpp"
#include "common/material.hpp"
#include "common/particle_set.hpp"
#include "common/viscosity.hpp"

namespace impactsph {

struct MaterialSpec {
  std::string name;
  MaterialParams<double> params;
  int line = 0;            // line of [materials.NAME] in the case file, for messages (0: unknown)
};

enum class Shape { Box, Cylinder, Sphere, Mesh };

class MeshSolid;  // common/mesh_solid.hpp

// The end of a cylinder (a projectile's nose). Flat: the plain cylinder. The others are solids of
// revolution of radius r(x) at the distance x from the shank (0 <= x <= nose_length): hemispherical
// r = sqrt(R^2 - x^2), nose_length = R; conical r = R (1 - x / nose_length), a sharp tip; ogival the
// tangent ogive of radius S = 2 crh R (crh: calibre-radius-head, S over the diameter),
// r = sqrt(S^2 - x^2) - (S - R), nose_length = R sqrt(4 crh - 1).
enum class Nose { Flat, Hemispherical, Conical, Ogival };

// Particles inside the region are clamped (velocity held at zero).
struct FixedRegionSpec {
  enum class Kind { Box, OutsideCylinder } kind = Kind::Box;
  std::string body;        // restrict to this body; empty: any body
  Vec3d box_min{0, 0, 0}, box_max{0, 0, 0};  // Box
  Vec3d axis_point{0, 0, 0};  // OutsideCylinder: a point on the axis
  int axis = 2;               // OutsideCylinder: axis direction
  double radius = 0;          // OutsideCylinder: particles farther than this from the axis are fixed
  int line = 0;               // line of its [[boundaries.fixed]] header, for messages (0: unknown)
};

struct BodySpec {
  std::string name;
  std::string material;    // name of a MaterialSpec
  int material_index = -1; // index into CaseSpec::materials
  Shape shape = Shape::Box;
  Vec3d box_min{0, 0, 0}, box_max{0, 0, 0};  // Box
  Vec3d base{0, 0, 0};     // Cylinder: centre of the base face, m
  int axis = 2;            // Cylinder: 0, 1, 2 for x, y, z
  double radius = 0;       // Cylinder, Sphere, m
  Vec3d center{0, 0, 0};   // Sphere: centre, m
  std::string mesh_file;   // Mesh: the file as the case names it (relative to the case file's folder)
  std::shared_ptr<const MeshSolid> mesh;  // Mesh: the closed surface, read and checked, in m in the case frame
  double length = 0;       // Cylinder: extent along +axis from the base, m, the nose included
  Nose nose = Nose::Flat;  // Cylinder: the shape of one end
  bool nose_at_base = true;  // Cylinder: the nose ends the cylinder at its base (true) or at base + length
  double nose_length = 0;  // Cylinder: m, the nose's extent along the axis (0 for a flat end)
  double nose_crh = 0;     // Cylinder, ogival nose: calibre-radius-head, the ogive's radius over 2 radius
  Vec3d velocity{0, 0, 0}; // initial velocity, m/s
  // Variable smoothing length (X eqs 9-10): dh/dt = (1/3) h div v, kept within
  // [h_min_factor, h_max_factor] x h0 (h0 = numerics.h_factor x spacing). Off by default.
  bool variable_h = false;
  double h_min_factor = 0.2, h_max_factor = 2.0;  // X: HMIN = 0.2, HMAX = 2.0 (LS-DYNA defaults)
  // Two resolutions in one body ([bodies.coarse]): the body's lattice at the spacing, with every complete
  // block of coarse_ratio^3 cells whose centre lies inside coarse_region merged into one cell, so the body is
  // coarse_ratio times coarser inside the region and the case's lattice elsewhere (scene.cpp).
  // coarse_ratio 1: one resolution; the case reader accepts 2 (the verified ratio); the scene builder takes
  // any whole number. The region takes the kinds of [[boundaries.fixed]] (its body unused).
  int coarse_ratio = 1;
  FixedRegionSpec coarse_region;
  // The largest numerics.spacing at which the coarse region is built (m; 0: at every spacing). Above it the
  // body is built at one resolution (coarse_ratio 1) and coarse_off_above keeps the bound for `check`.
  double coarse_max_spacing = 0;
  double coarse_off_above = 0;
  int line = 0;            // line of its [[bodies]] header in the case file, for messages (0: unknown)
};

// Mirror plane x_axis = position; the model lies on one side of it (build_scene decides which from the
// bodies and clips bodies that reach across it to that side). A wall ([[boundaries.wall]]) is a mirror
// plane that pushes but does not pull (presses_on_wall, common/integration.hpp); no body may reach across it.
struct SymmetryPlaneSpec {
  int axis = 0;
  double position = 0;
  bool wall = false;
  int line = 0;  // line of its [[boundaries.symmetry]] or [[boundaries.wall]] header, for messages (0: unknown)
  std::string key;  // its table in the case file, e.g. "boundaries.wall[0]", for messages (empty: unknown)
};

// How two bodies interact. Pairs not listed share the SPH sums (particle approximation across bodies,
// X section 2.2 "PAM"); a listed pair can instead use the penalty contact of F eqs 4.1-4.6.
struct ContactSpec {
  enum class Kind { Shared, Penalty } kind = Kind::Penalty;
  std::string body_a, body_b;
  int index_a = -1, index_b = -1;   // indices into CaseSpec::bodies
  double penalty_scale = 0.3;       // K_p (F Table 3)
  double contact_distance = 1.0;    // particles of the two bodies touch at this many spacings
  // X eqs 18, 20: when > 0, particles touch at srad (h_i + h_j)/2 instead (SRAD; X uses 1.2), so the
  // contact follows a variable smoothing length. 0: use contact_distance.
  double srad = 0;
  int line = 0;                     // line of its [[contacts]] header, for messages (0: unknown)
};

// How a step advances the state (common/stages.hpp, "Advance"): kick-drift-kick leapfrog, one evaluation of the
// rates per step; or the explicit midpoint rule, two.
enum class Integrator { Leapfrog, Midpoint };

struct NumericsSpec {
  double spacing = 0;          // particle spacing dx, m
  int spacing_line = 0;        // line of numerics.spacing in the case file (0: unknown or overridden)
  KernelKind kernel = KernelKind::WendlandC2;
  double h_factor = 1.2;       // h = h_factor * dx (X: CSLH = 1.2)
  ViscosityParams<double> viscosity{1.0, 1.0};
  bool viscosity_balsara = false;  // scale the viscosity by the Balsara shear limiter (viscosity.hpp)
  BulkViscosityParams<double> bulk_viscosity{};  // volumetric viscosity in compression (viscosity.hpp); 0, 0: off
  double artificial_stress = 0;        // epsilon of the artificial stress (artificial_stress.hpp); 0: off
  int artificial_stress_exponent = 4;  // its n
  ArtificialStressOf artificial_stress_of = ArtificialStressOf::Deviatoric;  // which stress R is built from
  double delta = 0.1;          // delta-SPH coefficient (F Table 3)
  double cfl = 0.2;            // C_CFL of F eq 5.1, the step factor: every measured case holds at 0.2 with
                               // the leapfrog (docs/time-integration.md); each case file sets its own
  Integrator integrator = Integrator::Leapfrog;
  CorrectionParams<double> correction{};
};

struct TimeSpec {
  double end = 0;                  // s
  double output_interval = 0;      // observables (CSV) every this, s
  double frame_interval = 0;       // VTU frames every this, s (0: same as output_interval)
  double checkpoint_interval = 0;  // s (0: only at the end and when interrupted)
};

// What a case measures besides the per-body histories (observables.cpp). Names are body names.
struct ObservablesSpec {
  std::string taylor_bar;           // body: final_length, impact_face_diameter against the plane it rests on
  std::string projectile;           // body: residual_velocity, residual_mass
  std::string target;               // body: plug_mass, plug_velocity, perforated
  int taylor_bar_index = -1, projectile_index = -1, target_index = -1;
  bool stop_when_settled = false;   // end the run once the residual velocity is steady
  double settle_window = 20e-6;     // s: steady when the residual velocity moved less than
  double settle_tolerance = 1.0;    // m/s over the last settle_window
};

// What the picture at the end of a run (app/picture.hpp) is coloured by.
enum class PictureField { PlasticStrain, Damage, Speed, Pressure };

struct OutputSpec {
  bool vtu = true;
  bool csv = true;
  bool picture = true;  // picture.png of a cut through the model after the last frame
  PictureField picture_field = PictureField::PlasticStrain;
};

struct CaseSpec {
  std::string source_file;  // path of the case file, for messages
  std::string name;
  std::string description;
  std::vector<MaterialSpec> materials;
  std::vector<BodySpec> bodies;
  std::vector<FixedRegionSpec> fixed;
  std::vector<SymmetryPlaneSpec> symmetry;
  std::vector<ContactSpec> contacts;
  NumericsSpec numerics;
  TimeSpec time;
  ObservablesSpec observables;
  OutputSpec output;
};

}  // namespace impactsph
