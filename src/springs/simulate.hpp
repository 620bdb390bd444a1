#pragma once
// A fixed-step run with substeps per output frame, divergence detection and settling time.
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "springs/integrator.hpp"
#include "springs/provot.hpp"
#include "springs/system.hpp"

namespace creaturelab::springs {

struct SimulationOptions {
  IntegratorKind integrator = IntegratorKind::RK4;
  double frame_interval_s = 0.02;   // output interval, seconds, > 0
  double dt_s = 0;                  // requested step, seconds; 0 = auto (autoStepS at the initial state)
  double end_time_s = 10;           // seconds, >= 0; the run covers ceil(end/frame) frames
  double settling_fraction = 1e-4;  // settled when kinetic energy stays below this * its peak
  double runaway_factor = 1e8;      // diverged when kinetic energy exceeds this * reference energy
  double auto_safety = 0.5;         // auto dt = safety * stability limit / omega_max, in (0, 1]
  ProvotOptions provot;             // strain limiting after every step (thesis §5.1)
  std::string validate() const;
};

struct SimulationSummary {
  std::vector<double> time_s, kinetic_energy_j;  // per frame, including t = 0
  double dt_used_s = 0;                          // frame_interval_s / substeps_per_frame
  int substeps_per_frame = 0;
  double omega_max_rad_per_s = 0;                // estimateOmegaMaxRadPerS at the initial state
  double peak_kinetic_energy_j = 0;              // over every substep
  std::optional<double> settling_time_s;         // over every substep, see settling.hpp
  double settling_fraction = 0;
  long steps = 0;
  // Provot's strain limiting (options.provot), over every step; all 0 when it is off.
  double provot_peak_strain = 0;       // largest strain left after any step's limiting
  long provot_unconverged_steps = 0;   // steps whose sweeps hit the pass cap with a spring still too long
  long provot_passes = 0;              // sweeps over all steps
};

// Thrown when the state becomes non-finite or kinetic energy runs away. what() names the step,
// the time and, for explicit integrators, omega_max*dt against the integrator's stability bound.
class DivergenceError : public std::runtime_error {
 public:
  DivergenceError(const std::string& message, long step, double time_s)
      : std::runtime_error(message), step_(step), time_s_(time_s) {}
  long step() const { return step_; }
  double timeS() const { return time_s_; }

 private:
  long step_;
  double time_s_;
};

// The step simulate() would take, found the same way but without running, so that a caller can
// refuse a run that would take hours before it starts (explicit Euler at dt_s = auto can pick a
// step far below the frame). Throws std::invalid_argument where simulate() would.
struct StepEstimate {
  double dt_s = 0;             // the substep simulate() would use
  int substeps_per_frame = 0;
  double steps = 0;            // substeps over the whole run
};
template <int D> StepEstimate estimateSteps(const Network<D>& net, const State<D>& s, const SimulationOptions& options);

template <int D> using FrameObserver = std::function<void(int frame, double t_s, const State<D>& s)>;

// Runs from t = 0 to the end of the last frame, in place on s. on_frame (if set) is called at
// t = 0 (frame 0) and after every frame. dt is rounded DOWN so an integer number of substeps fills
// each frame: dt_used = frame_interval / ceil(frame_interval / dt).
// Divergence (checked after every step, O(particles)): any non-finite position or velocity, or
//   kinetic energy > runaway_factor * E_ref. The reference energy is what the initial state can
//   release: E_ref = KE(0) + elastic energy(0) + sum over free particles of m |g| L, with
//   L = max(diagonal of the initial bounding box, longest rest length). A run that starts with no
//   energy at all (at rest, unstretched, no gravity: driven only by its external force) takes the
//   peak kinetic energy of its first frame with motion instead, and is checked only for
//   non-finite values until then. This catches the exponential growth of an explicit integrator
//   beyond its stability bound; a blow-up that saturates (springs flipping through their ends)
//   below the threshold is not caught: compare omega_max * dt with the bound for that.
//   Throws DivergenceError.
// A 3D system that lies in the plane z = 0 with no force out of it (no ExternalForce, no bends, gravity
//   and constant force in the plane, every particle at z = 0 and at rest along z) is integrated in 2D
//   when the integrator is explicit: the result is the 3D one bit for bit, a third cheaper (simulate.cpp).
// Throws std::invalid_argument for bad options, a state of the wrong size, or an auto step that
// cannot exist (explicit Euler without damping).
// (on_frame is a non-deduced parameter so that a lambda can be passed directly.)
template <int D>
SimulationSummary simulate(const System<D>& system, State<D>& s, const SimulationOptions& options,
                           const std::type_identity_t<FrameObserver<D>>& on_frame = {});

}  // namespace creaturelab::springs
