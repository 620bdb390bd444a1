#include "springs/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "springs/settling.hpp"
#include "springs/stability.hpp"

namespace creaturelab::springs {

std::string SimulationOptions::validate() const {
  std::ostringstream msg;
  if (!(frame_interval_s > 0) || !std::isfinite(frame_interval_s)) {
    msg << "frame_interval_s is " << frame_interval_s << " s; it must be positive";
  } else if (!(dt_s >= 0) || !std::isfinite(dt_s)) {
    msg << "dt_s is " << dt_s << " s; give a positive step, or 0 to choose it from the stability limit";
  } else if (!(end_time_s >= 0) || !std::isfinite(end_time_s)) {
    msg << "end_time_s is " << end_time_s << " s; it must be zero or positive";
  } else if (!(settling_fraction > 0 && settling_fraction < 1)) {
    msg << "settling_fraction is " << settling_fraction << "; it must lie in (0, 1)";
  } else if (!(runaway_factor > 1) || !std::isfinite(runaway_factor)) {
    msg << "runaway_factor is " << runaway_factor << "; it must be a finite number above 1";
  } else if (!(auto_safety > 0 && auto_safety <= 1)) {
    msg << "auto_safety is " << auto_safety << "; it must lie in (0, 1]";
  } else {
    return provot.validate();
  }
  return msg.str();
}

namespace {

// Kinetic energy, the per-step divergence probe. Four partial sums in a fixed order: one serial
// sum is latency-bound (a quarter of a symplectic Euler step on the benchmark web). A non-finite
// velocity shows as a non-finite sum; positions cannot become non-finite without velocities
// doing so first (x += h v), and are checked per frame by allFinite().
template <int D> double kineticEnergyFast(const Network<D>& net, const State<D>& s) {
  const double* v = s.v_m_per_s.data();
  const double* m = net.mass_kg.data();
  const int n = net.particleCount();
  double acc[4] = {0, 0, 0, 0};
  int p = 0;
  for (; p + 4 <= n; p += 4) {
    for (int lane = 0; lane < 4; ++lane) {
      double v2 = 0;
      for (int d = 0; d < D; ++d) v2 += v[D * (p + lane) + d] * v[D * (p + lane) + d];
      acc[lane] += m[p + lane] * v2;
    }
  }
  for (; p < n; ++p) {
    double v2 = 0;
    for (int d = 0; d < D; ++d) v2 += v[D * p + d] * v[D * p + d];
    acc[0] += m[p] * v2;
  }
  return 0.5 * ((acc[0] + acc[1]) + (acc[2] + acc[3]));
}

// The reference energy of simulate.hpp's runaway test (0 when the initial state holds none).
template <int D> double referenceEnergyJ(const System<D>& system, const State<D>& s) {
  const Network<D>& net = system.network();
  double size_m = 0;
  if (net.particleCount() > 0) size_m = (s.x_m.rowwise().maxCoeff() - s.x_m.rowwise().minCoeff()).norm();
  for (double r : net.rest_length_m) size_m = std::max(size_m, r);
  double free_mass = 0;
  for (int p = 0; p < net.particleCount(); ++p)
    if (!net.pinned[p]) free_mass += net.mass_kg[p];
  return system.kineticEnergy(s) + system.elasticEnergy(s) + free_mass * net.gravity_m_per_s2.norm() * size_m;
}

std::string likelyCause(IntegratorKind kind, double omega_max, double dt_s, double bound) {
  std::ostringstream msg;
  if (kind == IntegratorKind::ImplicitEuler) {
    msg << "implicit Euler is unconditionally stable on springs, so look at the external force or at extreme "
           "parameters (omega_max = "
        << omega_max << " rad/s, dt = " << dt_s << " s)";
  } else {
    msg << "omega_max*dt = " << omega_max * dt_s << " against the stability bound " << bound << " of "
        << integratorName(kind) << " (omega_max = " << omega_max << " rad/s, dt = " << dt_s
        << " s); reduce dt_s, set dt_s = \"auto\" for a stable step, or use implicit_euler";
  }
  return msg.str();
}

struct StepPlan {
  double dt_s;             // frame_interval / substeps_per_frame
  int substeps_per_frame;
  double bound;            // stability limit of omega_max * dt for this integrator and damping
};

// The damping ratio of the top mode is only bounded, so the smaller stability limit of the two
// bounds is used (explicit Euler needs the lower one, symplectic Euler the upper one; RK4's limit
// is not monotonic in zeta). The step is then rounded down to fill each frame exactly.
template <int D> StepPlan planStep(const Network<D>& net, const SimulationOptions& options, double omega_max) {
  const DampingRatioBounds zeta = estimateDampingRatio(net, omega_max);
  const double bound =
      std::min(stabilityLimitOmegaDt(options.integrator, zeta.low), stabilityLimitOmegaDt(options.integrator, zeta.high));
  double dt_wanted = options.dt_s;
  if (dt_wanted == 0) {
    if (omega_max > 0 && bound == 0)
      throw std::invalid_argument(
          "explicit Euler gains energy on every undamped oscillation, so no stable step exists for this network "
          "(no drag); give dt_s or use symplectic_euler, rk4 or implicit_euler");
    dt_wanted = (std::isinf(bound) || omega_max == 0) ? options.frame_interval_s
                                                      : options.auto_safety * bound / omega_max;
  }
  // The 1e-12 keeps a step that divides the frame exactly (up to rounding) from gaining a substep.
  const double substeps = std::ceil(options.frame_interval_s / dt_wanted * (1 - 1e-12));
  if (!(substeps < 1e9))
    throw std::invalid_argument("the time step " + std::to_string(dt_wanted) + " s would need " +
                                std::to_string(substeps) + " substeps per frame");
  const int count = std::max(1, static_cast<int>(substeps));
  return {options.frame_interval_s / count, count, bound};
}

// Stage 3 of simulate(): frame 0, then the substeps of every frame, each followed by strain limiting
// and the divergence check.
template <int D>
void runFrames(const System<D>& system, State<D>& s, const SimulationOptions& options, const StepPlan& plan,
               double reference_j, const FrameObserver<D>& on_frame, SimulationSummary& summary) {
  const Network<D>& net = system.network();
  const double dt = plan.dt_s;
  const long frames = static_cast<long>(std::ceil(options.end_time_s / options.frame_interval_s * (1 - 1e-12)));
  double ke = kineticEnergyFast(net, s);
  SettlingTracker settling(options.settling_fraction);
  settling.add(0.0, ke);
  summary.time_s.push_back(0.0);
  summary.kinetic_energy_j.push_back(ke);
  if (on_frame) on_frame(0, 0.0, s);

  auto integrator = makeIntegrator<D>(options.integrator);
  Points<D> step_start_x_m;  // positions before the step, for Provot's velocities
  for (long frame = 1; frame <= frames; ++frame) {
    for (int sub = 0; sub < summary.substeps_per_frame; ++sub) {
      const long step = summary.steps;
      if (options.provot.enabled) step_start_x_m = s.x_m;
      integrator->step(system, s, StepContext{static_cast<double>(step) * dt, dt});
      if (options.provot.enabled) {  // strain limiting, velocities with the positions (provot.hpp)
        const ProvotResult limited = applyProvot(net, options.provot, s, &step_start_x_m, dt);
        summary.provot_peak_strain = std::max(summary.provot_peak_strain, limited.max_strain);
        summary.provot_unconverged_steps += !limited.converged;
        summary.provot_passes += limited.passes;
      }
      ++summary.steps;
      const double t_after = static_cast<double>(summary.steps) * dt;
      ke = kineticEnergyFast(net, s);
      const bool frame_end = sub + 1 == summary.substeps_per_frame;
      const bool finite = std::isfinite(ke) && (!frame_end || (s.x_m.allFinite() && s.v_m_per_s.allFinite()));
      if (!finite || (reference_j > 0 && ke > options.runaway_factor * reference_j)) {
        std::ostringstream msg;
        msg << "simulation diverged at step " << summary.steps << " (t = " << t_after << " s): ";
        if (!finite)
          msg << "the state became non-finite";
        else
          msg << "kinetic energy " << ke << " J exceeds " << options.runaway_factor << " x the reference energy "
              << reference_j << " J";
        msg << "; likely cause: " << likelyCause(options.integrator, summary.omega_max_rad_per_s, dt, plan.bound);
        throw DivergenceError(msg.str(), summary.steps, t_after);
      }
      settling.add(t_after, ke);
    }
    if (reference_j == 0) reference_j = settling.peak();
    const double t_frame = static_cast<double>(frame) * options.frame_interval_s;
    summary.time_s.push_back(t_frame);
    summary.kinetic_energy_j.push_back(ke);
    if (on_frame) on_frame(static_cast<int>(frame), t_frame, s);
  }
  summary.peak_kinetic_energy_j = settling.peak();
  summary.settling_time_s = settling.settlingTime();
}

// A 3D system that lies and stays in the plane z = 0: every particle at z = 0 and at rest along z, no
// force with a z component (gravity, constant force), no ExternalForce (its direction is unknown) and no
// bends (a 3D bend angle is unsigned, a 2D one signed). Then every z force, velocity and position stays
// exactly +0, and every x and y operation of the 3D step is the 2D step's operation (a sum over axes
// only gains "+ 0"), so the plane can be integrated in 2D with the same result bit for bit and a third
// fewer coordinates to move (thesis §5.2.1: the web hangs in the vertical plane). Explicit integrators only:
// implicit Euler's conjugate gradients sum dot products in SIMD packets whose grouping depends on the
// vector length, so its 2D and 3D results differ in the last bits.
bool planarInXY(const System<3>& system, const State<3>& s, IntegratorKind integrator) {
  const Network<3>& net = system.network();
  const Points<3>& fc = system.constantForce();
  return integrator != IntegratorKind::ImplicitEuler && !system.hasExternalForce() && net.bendCount() == 0 &&
         net.gravity_m_per_s2.z() == 0 && (s.x_m.row(2).array() == 0).all() &&
         (s.v_m_per_s.row(2).array() == 0).all() && (fc.size() == 0 || (fc.row(2).array() == 0).all());
}

Network<2> inPlane(const Network<3>& n) {
  Network<2> flat;
  flat.mass_kg = n.mass_kg;
  flat.pinned = n.pinned;
  flat.spring_a = n.spring_a;
  flat.spring_b = n.spring_b;
  flat.rest_length_m = n.rest_length_m;
  flat.stiffness_n_per_m = n.stiffness_n_per_m;
  flat.damping_ns_per_m = n.damping_ns_per_m;
  flat.gravity_m_per_s2 = n.gravity_m_per_s2.head<2>();
  flat.drag_ns_per_m = n.drag_ns_per_m;
  return flat;
}

// Runs a planar 3D system (planarInXY) in 2D, keeping s and every observed frame 3D.
void runFramesInPlane(const System<3>& system, State<3>& s, const SimulationOptions& options, const StepPlan& plan,
                      double reference_j, const FrameObserver<3>& on_frame, SimulationSummary& summary) {
  System<2> flat(inPlane(system.network()));
  if (system.constantForce().size() > 0) flat.setConstantForce(system.constantForce().topRows<2>());
  State<2> s2{s.x_m.topRows<2>(), s.v_m_per_s.topRows<2>()};
  auto copyBack = [&] {
    s.x_m.topRows<2>() = s2.x_m;
    s.v_m_per_s.topRows<2>() = s2.v_m_per_s;
  };
  FrameObserver<2> observe;
  if (on_frame)
    observe = [&](int frame, double t_s, const State<2>&) {
      copyBack();
      on_frame(frame, t_s, s);
    };
  try {
    runFrames<2>(flat, s2, options, plan, reference_j, observe, summary);
  } catch (const DivergenceError&) {
    copyBack();
    throw;
  }
  copyBack();
}

}  // namespace

template <int D>
SimulationSummary simulate(const System<D>& system, State<D>& s, const SimulationOptions& options,
                           const std::type_identity_t<FrameObserver<D>>& on_frame) {
  // Stage 0: check inputs.
  if (const std::string problem = options.validate(); !problem.empty())
    throw std::invalid_argument("simulation options: " + problem);
  const Network<D>& net = system.network();
  const int n = net.particleCount();
  if (s.x_m.cols() != n || s.v_m_per_s.cols() != n)
    throw std::invalid_argument("simulation state has " + std::to_string(s.x_m.cols()) + " positions and " +
                                std::to_string(s.v_m_per_s.cols()) + " velocities for " + std::to_string(n) +
                                " particles");

  // Stage 1: the time step.
  SimulationSummary summary;
  summary.settling_fraction = options.settling_fraction;
  summary.omega_max_rad_per_s = estimateOmegaMaxRadPerS(net, s);
  const StepPlan plan = planStep(net, options, summary.omega_max_rad_per_s);
  summary.substeps_per_frame = plan.substeps_per_frame;
  summary.dt_used_s = plan.dt_s;

  // Stage 2: reference energy for the runaway test (0: taken from the first frame with motion).
  const double reference_j = referenceEnergyJ(system, s);

  // Stage 3: the frames; in 2D when the system is planar (the same result, faster).
  if constexpr (D == 3) {
    if (planarInXY(system, s, options.integrator)) {
      runFramesInPlane(system, s, options, plan, reference_j, on_frame, summary);
      return summary;
    }
  }
  runFrames<D>(system, s, options, plan, reference_j, on_frame, summary);
  return summary;
}

template <int D> StepEstimate estimateSteps(const Network<D>& net, const State<D>& s, const SimulationOptions& options) {
  const StepPlan plan = planStep(net, options, estimateOmegaMaxRadPerS(net, s));
  const double frames = std::ceil(options.end_time_s / options.frame_interval_s * (1 - 1e-12));
  return {plan.dt_s, plan.substeps_per_frame, frames * plan.substeps_per_frame};
}

template StepEstimate estimateSteps<2>(const Network<2>&, const State<2>&, const SimulationOptions&);
template StepEstimate estimateSteps<3>(const Network<3>&, const State<3>&, const SimulationOptions&);
template SimulationSummary simulate<2>(const System<2>&, State<2>&, const SimulationOptions&, const FrameObserver<2>&);
template SimulationSummary simulate<3>(const System<3>&, State<3>&, const SimulationOptions&, const FrameObserver<3>&);

}  // namespace creaturelab::springs
