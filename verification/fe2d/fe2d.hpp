// An explicit 2D axisymmetric Lagrangian finite-element solver for a bar hitting a rigid, frictionless wall
// (a Taylor bar): a second method, beside the SPH, on the same case files and the same material models
// (README.md beside this file gives every equation and its source). Host only; nothing of it is built into
// the solvers of reference/ or gpu/.
//
// Frame: r is the distance from the bar's axis and z the height above the wall along the axis, both in m;
// the bar starts as 0 <= r <= R, 0 <= z <= L, moving at -v0 along z. The mesh is nr x nz quadrilaterals,
// node (i, j) at index j (nr + 1) + i (i radial, j axial), element (i, j) at index j nr + i.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "common/case_spec.hpp"
#include "common/tensor.hpp"
#include "verification/fe2d/element.hpp"

namespace impactsph::fe2d {

// A Taylor bar as a case file gives it (bar_from_case checks that the case is one).
struct Bar {
  std::string case_name, case_file;
  std::string body, material_name;
  MaterialParams<double> material;
  double radius = 0, length = 0;  // m
  double speed = 0;               // m/s, toward the wall
  // The plane at the impact end: a plane of symmetry ([[boundaries.symmetry]]) holds the end row of nodes on
  // it (they slide along it, as the SPH's mirror particles do); a wall ([[boundaries.wall]]) pushes and does
  // not pull, so the bar may leave it.
  bool plane_holds = true;
  double end_time = 0, output_interval = 0;  // s, the case's [time]
};

// The bar of a case: one body, a flat-ended cylinder moving along its axis toward a plane of symmetry or a
// wall at its end, normal to its axis; other planes only through its axis; a material without damage.
// Anything else throws CaseError naming the file, the line, the key and what would be valid.
Bar bar_from_case(const CaseSpec& spec);

// The numerics (README.md, "Numerics"; defaults there with their sources).
struct Options {
  int elements_across = 32;          // elements across the radius; along the length round(L/R x that)
  double cfl = 0.6;                  // the step is cfl x the least element's stable step
  double hourglass_stiffness = 0.05; // kappa of the Flanagan-Belytschko stiffness form
  double bulk_linear = 0.06;         // C_l of the bulk viscosity (LS-DYNA's default Q2)
  double bulk_quadratic = 1.5;       // C_q (LS-DYNA's default Q1)
  double end_time = 0;               // s; 0: the case's
  double output_interval = 0;        // s, history rows; 0: the case's
};

// The energies of the whole bar (J). kinetic + internal + hourglass + wall stays the initial kinetic energy
// up to the integrator's error (the drift); wall is what the wall took where it stopped nodes (their lumped
// masses meet it inelastically).
struct Energies {
  double kinetic = 0, internal = 0, hourglass = 0, wall = 0;
  double plastic_work = 0;  // part of internal
  double total() const { return kinetic + internal + hourglass + wall; }
};

struct HistoryRow {
  double time = 0;            // s
  double length = 0;          // m, highest node above the lowest
  double face_radius = 0;     // m, outermost node of the wall row (j = 0)
  double axial_velocity = 0;  // m/s, mass-weighted mean along +z (away from the wall)
  Energies energy;
};

struct Node {
  double r, z;  // m
  double u, w;  // m/s, radial and axial velocity at the last half step
  double mass;  // kg, lumped
};

struct Element {
  Sym3<double> S;            // deviatoric stress, Pa (x = r, y = theta, z = z)
  double pressure = 0;       // Pa, EOS
  double q = 0;              // Pa, bulk viscosity of the last step
  double energy = 0;         // J/kg, specific internal energy
  double rho = 0;            // kg/m^3
  double plastic_strain = 0; // equivalent plastic strain
  double plastic_work = 0;   // J/kg
  double temperature = 0;    // K
  double strain_rate = 0;    // 1/s, equivalent strain rate of the last step
  double sound_speed = 0;    // m/s, the EOS bulk sound speed
  double divergence = 0;     // 1/s, div v of the last step
  double volume = 0;         // m^3, now
  double length = 0;         // m, the time-step length now (QuadGeometry::length)
  double hourglass_r = 0, hourglass_z = 0;  // N, the hourglass generalised force (stiffness form)
  double volume0 = 0, mass = 0;              // m^3, kg
};

class Simulation {
 public:
  Simulation(const Bar& bar, const Options& options);

  // One central-difference step; false once the end time is reached. Throws DivergenceError when an element
  // turns inside out or a value is not finite.
  bool step();
  // Steps to the end; `each_step`, when given, is called after every step.
  void run(const std::function<void(const Simulation&)>& each_step = {});

  const Bar& bar() const { return bar_; }
  const Options& options() const { return opt_; }
  int nr() const { return nr_; }
  int nz() const { return nz_; }
  double time() const { return time_; }
  double end_time() const { return end_; }
  long steps() const { return steps_; }
  double last_dt() const { return dt_; }
  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Element>& elements() const { return elements_; }
  const std::vector<HistoryRow>& history() const { return history_; }
  double initial_energy() const { return initial_energy_; }
  // The state now (at the last whole step; velocities averaged over the half steps around it).
  HistoryRow now() const { return current_; }
  std::size_t node_index(int i, int j) const { return static_cast<std::size_t>(j) * (nr_ + 1) + i; }
  std::size_t element_index(int i, int j) const { return static_cast<std::size_t>(j) * nr_ + i; }
  // The nodes of element (i, j), counter-clockwise in (r, z): (i, j), (i+1, j), (i+1, j+1), (i, j+1).
  struct Corners {
    std::size_t node[4];
  };
  Corners corners(int i, int j) const {
    return {{node_index(i, j), node_index(i + 1, j), node_index(i + 1, j + 1), node_index(i, j + 1)}};
  }

 private:
  void internal_forces();
  double stable_time_step() const;
  void update_elements(double dt);

  Bar bar_;
  Options opt_;
  int nr_ = 0, nz_ = 0;
  std::vector<Node> nodes_;
  std::vector<Element> elements_;
  std::vector<QuadGeometry> geometry_;     // of each element at the current nodes
  std::vector<double> force_r_, force_z_;  // N, at the last whole step
  std::vector<double> u_old_, w_old_;      // m/s, the half step before
  double time_ = 0, end_ = 0, dt_ = 0, output_interval_ = 0, next_output_ = 0;
  long steps_ = 0;
  bool started_ = false, finished_ = false;
  double initial_energy_ = 0;
  Energies energy_;  // internal, hourglass, wall and plastic work as accumulated
  HistoryRow current_;
  std::vector<HistoryRow> history_;
};

// The observables `impactsph run` writes for a Taylor bar, measured on the mesh: the final length (the
// highest node above the lowest) and the impact-face diameter (2 x the outermost radius of the wall row).
struct Observables {
  double final_length = 0, impact_face_diameter = 0;  // m
};
Observables measure(const Simulation& s);

// The outer surface (nodes i = nr, j = 0..nz): (height, radius) pairs from the wall up, m.
std::vector<std::pair<double, double>> outer_profile(const Simulation& s);

}  // namespace impactsph::fe2d
