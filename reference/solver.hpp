// The double-precision OpenMP reference solver: readable first (design.md, "One step").
//
// One step of the explicit midpoint (second-order Runge-Kutta) integrator:
//   y_1/2 = y_n + dt/2 f(y_n),   y_n+1 = y_n + dt f(y_1/2),
// where y holds position, velocity, density, specific internal energy and deviatoric stress, and one
// evaluation of f is: mirror ghosts, EOS, pass 1 (correction matrix, velocity and density gradients),
// the deviatoric stress rate, pass 2 (continuity with delta-SPH, momentum, energy with viscosity).
// The plastic return follows each stress update. Fixed particles keep zero velocity.
//
// Pair forces use the symmetrised corrected gradient (L_i^-1 + L_j^-1)/2 grad_i W_ij, which is
// antisymmetric in i and j, so momentum and energy are conserved to round-off; the velocity gradient
// uses L_i^-1 grad W, which is exact for linear fields (patch test).
#pragma once
#include <vector>

#include "common/nonlocal.hpp"
#include "common/scene.hpp"
#include "common/stage_setup.hpp"
#include "common/stages.hpp"
#include "common/stepper.hpp"
#include "reference/neighbours.hpp"

namespace impactsph::reference {

class ReferenceSolver final : public Stepper {
 public:
  explicit ReferenceSolver(const Scene& scene);
  std::string name() const override { return "reference (double, OpenMP)"; }
  double stable_time_step(const ParticleSet& p) override;
  void step(ParticleSet& p, double dt) override;
  StepStats last_stats() const override { return stats_; }

  // Pass 1 alone on the current state: the corrected velocity gradient grad_v(a,b) = d v_a / d x_b of
  // every particle (verification: patch test, objectivity). Returns the number of fallbacks.
  std::size_t velocity_gradients(const ParticleSet& p, std::vector<Mat3d>& grad_v);

 private:
  // Per-axis affine map x' = sign x + shift taking a real particle to its mirror image; walls: bit k set
  // when the image was mirrored through plane k and that plane is a wall (lets_go_of_wall,
  // common/integration.hpp).
  struct Ghost {
    std::int32_t source;
    Vec3d sign;
    Vec3d shift;
    unsigned walls;
  };
  struct State {
    std::vector<Vec3d> pos, vel;
    std::vector<double> rho, energy;
    std::vector<Sym3d> dev_stress;
  };
  struct Rates {
    std::vector<Vec3d> vel, acc;
    std::vector<double> drho, drho_diffusion, denergy;  // drho_diffusion: the delta-SPH share of drho
    std::vector<Sym3d> dstress;
    std::vector<double> strain_rate;    // equivalent strain rate sqrt(2/3 d':d'), 1/s (Johnson-Cook, damage)
    std::vector<double> contact_power;  // power particle i's penalty pairs take from the motion, W
  };
  // What the final stage of a step does to the history variables of each particle.
  struct History {
    std::vector<double> d_eps_p, d_plastic_work, d_temperature, strain_rate;
  };

  void load_constants(const ParticleSet& p);
  void find_ghosts(const std::vector<Vec3d>& pos, double margin);
  // Search radius without the skin: the kernel support or the contact reach at the largest h (m).
  double search_reach() const;
  void build_neighbours(const std::vector<Vec3d>& pos, double skin);
  // Rebuilds the Verlet list (and the ghosts) when a pair that is not in it could come within reach
  // before the step ends.
  void update_neighbours(const ParticleSet& p, double dt);
  void evaluate(const State& y, Rates& f, double dt);
  // A row's candidates (pass 1): their indices, r and kernel gradient factor, in the scratch of the thread
  // that takes the row, so that they stay in its cache.
  struct RowCandidates {
    std::vector<std::int32_t> j;
    std::vector<double> r, factor;  // m, 1/m^5
  };
  template <class Kernel>
  void candidate_kernel(Kernel kernel, Vec3d x_i, double h_i, std::int64_t count, RowCandidates& c) const;
  void advance(const State& y0, const Rates& f, double dt, State& out, History* history) const;
  void gather(const State& y);
  void gradient_pass();
  void rate_pass(Rates& f, double dt);
  void restress(const State& y);
  void midpoint_step(ParticleSet& p, double dt);
  void leapfrog_step(ParticleSet& p, double dt);
  void evaluate_carried_rates(ParticleSet& p, double dt);
  void carry_rates(ParticleSet& p);
  void finish_history(ParticleSet& p, double dt);
  void resize_history(std::size_t n);
  static void resize_state(State& y, std::size_t n);
  Vec3d drift_velocity(const ParticleSet& p, std::int64_t i, double dt) const;
  StepHistory<double> step_history(std::int64_t i) const;
  void check_state(const State& y, double dt) const;
  // The work arrays as the stages (common/stages.hpp) read them.
  StagePoints<double> points();

  NumericsSpec numerics_;
  bool leapfrog_;                              // numerics.integrator: leapfrog (else the midpoint rule)
  StageParams<double> params_;                 // numerics and planes (common/stage_setup.hpp)
  std::vector<PairContact<double>> contacts_;  // how each pair of bodies interacts
  std::vector<BodySmoothing<double>> smoothing_;  // variable smoothing length per body
  ContactReach contact_reach_;                 // how far the penalty contacts reach
  std::vector<MaterialParams<double>> materials_;
  // The initial configuration of the particles that average their plastic work (common/nonlocal.hpp),
  // built from the scene before any checkpoint replaces its particles; per particle, the plastic work per
  // unit initial volume after the step and its non-local average (J/m^3).
  NonlocalGridData nonlocal_grid_;
  std::vector<double> work_density_, nonlocal_work_;
  // Constant per particle (copied from the scene at each step).
  std::vector<double> mass_, h_;
  std::vector<std::int32_t> material_;
  std::vector<std::uint8_t> fixed_;
  std::vector<std::int32_t> body_;
  std::vector<std::string> body_names_;
  double h_max_ = 0, h_min_ = 0;  // m, the largest and smallest smoothing length now
  bool variable_h_ = false;      // some body has a variable smoothing length
  std::vector<double> point_radius_;  // search radius of each point (reals, then ghosts) when reach_per_pair

  std::vector<Ghost> ghosts_;
  // Walls: per point the walls it let go of (ghosts 0) and the walls of its image (reals 0); bit k for
  // plane k. A pair takes no part when image_walls_[j] & let_go_[i] (lets_go_of_wall).
  std::vector<unsigned> let_go_, image_walls_;
  NeighbourList neighbours_;  // Verlet list: each row in index order (reals, then ghosts)
  bool list_valid_ = false;
  std::vector<Vec3d> pos_at_build_;  // positions when the list was built
  double reach_at_build_ = 0, skin_ = 0;  // m
  // Work arrays over real particles followed by ghosts.
  std::vector<Vec3d> x_, v_, grad_rho_;
  std::vector<double> rho_, pressure_, sound_speed_, m_, hh_, volume_, av_factor_;
  std::vector<std::int32_t> mat_;
  std::vector<Sym3d> s_over_rho2_;  // (S - P I) / rho^2 stored as a symmetric tensor
  std::vector<Sym3d> artificial_stress_;  // R of common/artificial_stress.hpp, units of s_over_rho2_ (empty: off)
  std::vector<Mat3d> l_inverse_;
  std::vector<Mat3d> grad_v_;       // reals; ghosts mirror theirs only for the limited viscosity
  std::vector<double> damage_, plastic_strain_, temperature_, bulking_;  // history variables at the step start
  std::vector<std::int32_t> bb_;    // body of reals and ghosts
  std::vector<double> damage_all_;  // damage of reals and ghosts
  std::vector<double> pair_damage_; // damage each particle brings into the pair factor (reals and ghosts)
  std::vector<std::int32_t> row_neighbours_, fell_back_;  // pass 1 per real: neighbours, 1 if it fell back
  // The pairs of this evaluation, in the slots of the list's rows: pass 1 writes each row's SPH pairs (those
  // that share sums, within the support) from the front of its slots, with their kernel gradient factor,
  // and its penalty contact pairs from the back; pass 2 reads them back rather than test and take the
  // kernel of every list entry again (it takes r = |x_ij| again, as pass 1 did: the same bits).
  std::vector<std::int32_t> pair_j_;
  std::vector<double> pair_grad_factor_;  // 1/m^5
  std::vector<std::int64_t> sph_end_, contact_begin_;  // per real: its SPH pairs end, its contact pairs begin
  std::vector<Sym3d> stress_;       // deviatoric stress of reals and ghosts
  // Stage states and rates, kept between steps so that a step allocates nothing.
  State y0_, y_half_, y1_;
  Rates rates_;
  History history_;
  StepStats stats_;
};

}  // namespace impactsph::reference
