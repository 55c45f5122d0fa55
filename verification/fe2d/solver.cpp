// The explicit axisymmetric finite-element solver (fe2d.hpp; the equations in README.md beside this file).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "common/errors.hpp"
#include "common/viscosity.hpp"
#include "verification/fe2d/constitutive.hpp"
#include "verification/fe2d/element.hpp"
#include "verification/fe2d/fe2d.hpp"

namespace impactsph::fe2d {

Simulation::Simulation(const Bar& bar, const Options& opt) : bar_(bar), opt_(opt) {
  if (opt.elements_across < 1) throw std::invalid_argument("elements across the radius must be 1 or more");
  if (!(opt.cfl > 0 && opt.cfl <= 1)) throw std::invalid_argument("the CFL number must lie in (0, 1]");
  if (!has_deviatoric_stress(bar.material))
    throw std::invalid_argument("the material " + bar.material_name + " has no shear modulus, which the hourglass "
                                "control of the finite-element bar needs");
  nr_ = opt.elements_across;
  nz_ = std::max(1, static_cast<int>(std::lround(bar.length / bar.radius * nr_)));
  end_ = opt.end_time > 0 ? opt.end_time : bar.end_time;
  const double interval = opt.output_interval > 0 ? opt.output_interval : bar.output_interval;
  output_interval_ = interval > 0 ? interval : end_ / 100;
  next_output_ = output_interval_;

  nodes_.resize(static_cast<std::size_t>(nr_ + 1) * (nz_ + 1));
  for (int j = 0; j <= nz_; ++j)
    for (int i = 0; i <= nr_; ++i)
      nodes_[node_index(i, j)] = Node{bar.radius * i / nr_, bar.length * j / nz_, 0.0, -bar.speed, 0.0};
  elements_.resize(static_cast<std::size_t>(nr_) * nz_);
  geometry_.resize(elements_.size());
  const MaterialParams<double>& mat = bar.material;
  for (int j = 0; j < nz_; ++j)
    for (int i = 0; i < nr_; ++i) {
      const Corners corner = corners(i, j);
      double r[4], z[4], m[4];
      for (int k = 0; k < 4; ++k) r[k] = nodes_[corner.node[k]].r, z[k] = nodes_[corner.node[k]].z;
      lumped_masses(r, z, mat.eos.rho0, m);
      for (int k = 0; k < 4; ++k) nodes_[corner.node[k]].mass += m[k];
      const QuadGeometry g = quad_geometry(r, z);
      geometry_[element_index(i, j)] = g;
      Element& e = elements_[element_index(i, j)];
      e.S = Sym3<double>::zero();
      e.rho = mat.eos.rho0;
      e.volume0 = e.volume = g.volume;
      e.mass = mat.eos.rho0 * g.volume;
      e.length = g.length;
      e.temperature = mat.room_temperature;
      e.pressure = material_pressure(mat, e.rho, 0.0, 0.0, e.sound_speed);
    }
  force_r_.assign(nodes_.size(), 0.0);
  force_z_.assign(nodes_.size(), 0.0);
  internal_forces();
  for (const Node& n : nodes_) initial_energy_ += 0.5 * n.mass * (n.u * n.u + n.w * n.w);
  current_.time = 0;
  current_.length = bar.length;
  current_.face_radius = bar.radius;
  current_.axial_velocity = -bar.speed;
  current_.energy.kinetic = initial_energy_;
  current_.energy.internal = 0;
  for (const Element& e : elements_) current_.energy.internal += e.mass * e.energy;
  history_.push_back(current_);
}

// f_I = -V (sigma_rr b_r + sigma_rz b_z + sigma_tt hoop, sigma_rz b_r + sigma_zz b_z)_I - gamma_I Q (N): the
// element's stress against its volume-averaged gradient operator at the current nodes, and the hourglass
// force (README.md, "Nodal forces").
void Simulation::internal_forces() {
  std::fill(force_r_.begin(), force_r_.end(), 0.0);
  std::fill(force_z_.begin(), force_z_.end(), 0.0);
  for (int j = 0; j < nz_; ++j)
    for (int i = 0; i < nr_; ++i) {
      const Corners corner = corners(i, j);
      const std::size_t k_e = element_index(i, j);
      const QuadGeometry& g = geometry_[k_e];
      const Element& e = elements_[k_e];
      const double p = e.pressure + e.q;
      const double s_rr = e.S.xx - p, s_tt = e.S.yy - p, s_zz = e.S.zz - p, s_rz = e.S.zx;
      for (int k = 0; k < 4; ++k) {
        force_r_[corner.node[k]] -=
            g.volume * (s_rr * g.b_r[k] + s_rz * g.b_z[k] + s_tt * g.hoop[k]) + g.gamma[k] * e.hourglass_r;
        force_z_[corner.node[k]] -= g.volume * (s_rz * g.b_r[k] + s_zz * g.b_z[k]) + g.gamma[k] * e.hourglass_z;
      }
    }
}

// The least stable step of the elements (s), dt_e = l / (Q + sqrt(Q^2 + c^2)) with c the longitudinal
// signal speed and Q = C_l c + C_q l |div v| in compression (README.md, "Time step").
double Simulation::stable_time_step() const {
  double dt = std::numeric_limits<double>::infinity();
  for (const Element& e : elements_) {
    const double c = signal_speed(bar_.material, e.sound_speed, e.rho);
    const double q = e.divergence < 0 ? opt_.bulk_linear * c - opt_.bulk_quadratic * e.length * e.divergence : 0.0;
    dt = std::min(dt, e.length / (q + std::sqrt(q * q + c * c)));
  }
  return dt;
}

void Simulation::update_elements(double dt) {
  const MaterialParams<double>& mat = bar_.material;
  const BulkViscosityParams<double> bulk{opt_.bulk_linear, opt_.bulk_quadratic};
  for (int j = 0; j < nz_; ++j)
    for (int i = 0; i < nr_; ++i) {
      const Corners corner = corners(i, j);
      double r[4], z[4], r_half[4], z_half[4], u[4], w[4];
      for (int k = 0; k < 4; ++k) {
        const Node& n = nodes_[corner.node[k]];
        r[k] = n.r, z[k] = n.z, u[k] = n.u, w[k] = n.w;
        r_half[k] = n.r - 0.5 * dt * n.u;
        z_half[k] = n.z - 0.5 * dt * n.w;
      }
      const QuadGeometry half = quad_geometry(r_half, z_half);
      QuadGeometry& now = geometry_[element_index(i, j)];
      now = quad_geometry(r, z);
      Element& e = elements_[element_index(i, j)];
      if (!(now.area > 0 && now.volume > 0) || !(half.area > 0)) {
        std::ostringstream msg;
        msg.precision(6);
        msg << "the finite-element solution failed at t = " << time_ * 1e6 << " us (step " << steps_
            << "): the element of ring " << i + 1 << " of " << nr_ << " from the axis, layer " << j + 1 << " of " << nz_
            << " from the wall, turned inside out (area " << now.area * 1e6
            << " mm^2). Try more elements across (--elements-across) or a smaller --cfl.";
        throw DivergenceError(msg.str());
      }
      // The velocity gradient of the step's midpoint (1/s).
      double dvr_dr = 0, dvr_dz = 0, dvz_dr = 0, dvz_dz = 0, vr_over_r = 0, hg_r = 0, hg_z = 0;
      for (int k = 0; k < 4; ++k) {
        dvr_dr += half.b_r[k] * u[k];
        dvr_dz += half.b_z[k] * u[k];
        dvz_dr += half.b_r[k] * w[k];
        dvz_dz += half.b_z[k] * w[k];
        vr_over_r += half.hoop[k] * u[k];
        hg_r += half.gamma[k] * u[k];
        hg_z += half.gamma[k] * w[k];
      }
      const Mat3<double> grad_v = axisymmetric_velocity_gradient(dvr_dr, dvr_dz, dvz_dr, dvz_dz, vr_over_r);
      const double div = grad_v.trace();
      const double volume_change = now.volume - e.volume;  // m^3
      const double rho = e.mass / now.volume;

      // Bulk viscosity (Pa) at the midpoint, with the length sqrt(A).
      e.q = bulk_viscosity(bulk, div, rho, e.sound_speed, std::sqrt(half.area));
      // Deviatoric stress, its return and heating.
      const Sym3<double> s_old = e.S;
      const DeviatoricStep<double> step =
          update_deviatoric_stress(mat, e.S, grad_v, dt, e.plastic_strain, e.temperature, rho, e.pressure);
      // Energy (J/kg): the deviatoric work at the midpoint, the bulk viscosity's and the pressure's on the volume
      // change, the pressure time-centred (P_old + P_new)/2 by fixed-point iteration on the EOS.
      const double deviatoric_work = dt * half.volume * 0.5 * ddot((s_old + e.S).full(), grad_v);
      const double e_base = e.energy + (deviatoric_work - (0.5 * e.pressure + e.q) * volume_change) / e.mass;
      double p = e.pressure, energy = e.energy, c = e.sound_speed;
      for (int it = 0; it < 3; ++it) {
        energy = e_base - 0.5 * p * volume_change / e.mass;
        p = material_pressure(mat, rho, energy, 0.0, c);
      }
      e.energy = energy;
      e.pressure = p;
      e.sound_speed = c;
      e.rho = rho;
      e.volume = now.volume;
      e.length = now.length;
      e.divergence = div;
      e.strain_rate = step.strain_rate;
      e.plastic_strain += step.plastic.d_eps_p;
      e.plastic_work += step.plastic.plastic_work;
      e.temperature += step.plastic.d_T;

      // Hourglass (README.md, "Hourglass control"): the generalised force turns with the element's r-z spin
      // and grows with the hourglass rate at the stiffness kappa G V sum(b_A^2) (N/m).
      double area_b2 = 0;
      for (int k = 0; k < 4; ++k) area_b2 += half.area_b_r[k] * half.area_b_r[k] + half.area_b_z[k] * half.area_b_z[k];
      const double stiffness = opt_.hourglass_stiffness * mat.strength.shear_modulus * half.volume * area_b2;
      const double angle = 0.5 * (dvr_dz - dvz_dr) * dt;
      const double cs = std::cos(angle), sn = std::sin(angle);
      const double q_r = cs * e.hourglass_r + sn * e.hourglass_z, q_z = -sn * e.hourglass_r + cs * e.hourglass_z;
      e.hourglass_r = q_r + dt * stiffness * hg_r;
      e.hourglass_z = q_z + dt * stiffness * hg_z;
      energy_.hourglass += dt * 0.5 * ((q_r + e.hourglass_r) * hg_r + (q_z + e.hourglass_z) * hg_z);

      if (!std::isfinite(e.energy) || !std::isfinite(e.pressure) || !std::isfinite(von_mises(e.S))) {
        std::ostringstream msg;
        msg << "the finite-element solution diverged at t = " << time_ * 1e6 << " us (step " << steps_
            << "): the element of ring " << i + 1 << " of " << nr_ << " from the axis, layer " << j + 1 << " of " << nz_
            << " from the wall, has energy " << e.energy << " J/kg, pressure " << e.pressure
            << " Pa. Try more elements across (--elements-across) or a smaller --cfl.";
        throw DivergenceError(msg.str());
      }
    }
}

bool Simulation::step() {
  if (finished_) return false;
  const double dt_stable = time_ >= end_ ? 0.0 : opt_.cfl * stable_time_step();
  const bool last = dt_stable >= end_ - time_;
  const double dt_new = std::min(dt_stable, end_ - time_);
  // The kick from v(n - 1/2) to v(n + 1/2) spans (dt_old + dt_new)/2; the first from v(0) spans dt_new/2; with
  // dt_new = 0 (the end) it brings the velocities to the whole step n.
  const double kick = started_ ? 0.5 * (dt_ + dt_new) : 0.5 * dt_new;
  double kinetic_old = 0, kinetic_new = 0, wall = 0, mass = 0, momentum = 0;
  for (std::size_t n = 0; n < nodes_.size(); ++n) {
    Node& d = nodes_[n];
    const double u_old = d.u, w_old = d.w;
    d.u += kick * force_r_[n] / d.mass;
    const double w_free = d.w + kick * force_z_[n] / d.mass;
    d.w = w_free;
    if (n % static_cast<std::size_t>(nr_ + 1) == 0) d.u = 0;  // the axis: r stays 0
    // The wall: the end row of a plane of symmetry stays on it; any other node is stopped where it would
    // cross the plane (README.md, "The wall").
    if (bar_.plane_holds && n <= static_cast<std::size_t>(nr_)) d.w = 0;
    else if (dt_new > 0 && d.z + dt_new * d.w < 0) d.w = -d.z / dt_new;
    else if (dt_new == 0 && d.z <= 0 && d.w < 0) d.w = 0;
    // What the wall took out of this kick's kinetic energy (J): the change of (1/2) m w^2 less the work of the
    // node's force over it.
    wall -= 0.5 * d.mass * (w_old + d.w) * (d.w - w_free);
    kinetic_old += 0.5 * d.mass * (u_old * u_old + w_old * w_old);
    kinetic_new += 0.5 * d.mass * (d.u * d.u + d.w * d.w);
    mass += d.mass;
    momentum += d.mass * (dt_new > 0 ? 0.5 * (w_old + d.w) : d.w);
  }
  // The state at the whole step n: kinetic energy and the wall's share of this kick halved, except at the
  // end, where the kick was the half step itself.
  const double share = dt_new > 0 ? 0.5 : 1.0;
  current_.time = time_;
  current_.energy.kinetic = dt_new > 0 ? 0.5 * (kinetic_old + kinetic_new) : kinetic_new;
  current_.energy.wall = energy_.wall + share * wall;
  energy_.wall += wall;
  current_.energy.hourglass = energy_.hourglass;
  current_.energy.internal = 0;
  current_.energy.plastic_work = 0;
  for (const Element& e : elements_) {
    current_.energy.internal += e.mass * e.energy;
    current_.energy.plastic_work += e.mass * e.plastic_work;
  }
  current_.axial_velocity = momentum / mass;
  double z_lo = std::numeric_limits<double>::infinity(), z_hi = -z_lo, face = 0;
  for (const Node& d : nodes_) z_lo = std::min(z_lo, d.z), z_hi = std::max(z_hi, d.z);
  for (int i = 0; i <= nr_; ++i) face = std::max(face, nodes_[node_index(i, 0)].r);
  current_.length = z_hi - z_lo;
  current_.face_radius = face;
  if (dt_new == 0) {
    history_.push_back(current_);
    finished_ = true;
    return false;
  }
  if (started_ && time_ >= next_output_ * (1 - 1e-12)) {
    history_.push_back(current_);
    next_output_ += output_interval_;
  }

  for (Node& d : nodes_) {
    d.r += dt_new * d.u;
    d.z += dt_new * d.w;
  }
  update_elements(dt_new);
  internal_forces();
  time_ = last ? end_ : time_ + dt_new;
  dt_ = dt_new;
  ++steps_;
  started_ = true;
  return true;
}

void Simulation::run(const std::function<void(const Simulation&)>& each_step) {
  while (step())
    if (each_step) each_step(*this);
}

Observables measure(const Simulation& s) {
  const HistoryRow& now = s.now();
  return {now.length, 2 * now.face_radius};
}

std::vector<std::pair<double, double>> outer_profile(const Simulation& s) {
  std::vector<std::pair<double, double>> p;
  for (int j = 0; j <= s.nz(); ++j) {
    const Node& n = s.nodes()[s.node_index(s.nr(), j)];
    p.emplace_back(n.z, n.r);
  }
  return p;
}

}  // namespace impactsph::fe2d
