#include "fish/fish_run.hpp"

#include <cmath>

namespace creaturelab::fish {

double headingRad(const NodeMatrix& x) {
  const Eigen::RowVector3d mid = 0.25 * (x.row(5) + x.row(6) + x.row(7) + x.row(8));  // ring 2
  const Eigen::RowVector3d d = x.row(0) - mid;
  return std::atan2(d.y(), d.x());
}

Eigen::Vector3d centreOfMass(const FishModel& fish, const NodeMatrix& x) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int i = 0; i < kNodes; ++i) c += fish.network.mass_kg[i] * x.row(i).transpose();
  return c / fish.totalMassKg();
}

namespace {
void recordFrame(const FishModel& fish, const FishState& s, FishRecord& rec) {
  rec.time_s.push_back(s.time_s);
  const Eigen::Vector3d c = centreOfMass(fish, s.x_m);
  rec.com_m.insert(rec.com_m.end(), {c.x(), c.y(), c.z()});
  double h = headingRad(s.x_m);
  if (!rec.heading_rad.empty()) {  // unwrap: the nearest branch to the previous frame
    const double prev = rec.heading_rad.back();
    h += 2 * M_PI * std::round((prev - h) / (2 * M_PI));
  }
  rec.heading_rad.push_back(h);
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int i = 0; i < kNodes; ++i) p += fish.network.mass_kg[i] * s.v_m_per_s.row(i).transpose();
  rec.momentum_kg_m_per_s.insert(rec.momentum_kg_m_per_s.end(), {p.x(), p.y(), p.z()});
  for (int i = 0; i < kNodes; ++i)
    for (int d = 0; d < 3; ++d) rec.nodes_m.push_back(s.x_m(i, d));
  for (const Muscle& m : fish.muscles) rec.muscle_rest_m.push_back(s.rest_m[m.unit]);
}
}  // namespace

FishRecord runSchedule(const FishModel& fish, const SolverParams& solver_params, const MotorParams& motor_params,
                       const std::vector<ScheduleItem>& schedule, const RunOptions& options) {
  FishSolver solver(fish, solver_params);
  MotorController motor(fish, motor_params, schedule);
  FishState s = restState(fish);
  FishRecord rec;
  const double dt = solver_params.dt_s, end = scheduleDurationS(schedule);
  const long steps = std::lround(std::ceil(end / dt - 1e-9));
  Eigen::Vector3d p0 = Eigen::Vector3d::Zero();
  double drift = 0, scale = 0;
  recordFrame(fish, s, rec);
  for (long n = 0; n < steps; ++n) {
    motor.apply(s.time_s, dt, s.rest_m);
    const StepReport report = solver.step(s);
    if (report.status != StepStatus::ok) {
      rec.blew_up = true;
      rec.blowup_step = n + 1;
      rec.blowup_time_s = double(n + 1) * dt;
      rec.blowup_cause = report.cause;
      break;
    }
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    double sum_abs = 0;
    for (int i = 0; i < kNodes; ++i) {
      p += fish.network.mass_kg[i] * s.v_m_per_s.row(i).transpose();
      sum_abs += fish.network.mass_kg[i] * s.v_m_per_s.row(i).norm();
    }
    drift = std::max(drift, (p - p0).norm());
    scale = std::max(scale, sum_abs);
    if ((n + 1) % options.frame_every_steps == 0 || n + 1 == steps) recordFrame(fish, s, rec);
  }
  rec.steps = s.step;
  rec.momentum_scale_kg_m_per_s = scale;
  rec.momentum_drift_rel = scale > 0 ? drift / scale : 0.0;
  if (rec.blew_up && rec.time_s.back() < s.time_s) recordFrame(fish, s, rec);  // the last good state
  return rec;
}

StableStep largestStableStep(const FishModel& fish, SolverParams solver, const MotorParams& motor,
                             const std::vector<ScheduleItem>& schedule, double lo, double hi, int iterations) {
  RunOptions opt;
  opt.frame_every_steps = 1 << 30;
  auto failure = [&](double dt) {
    solver.dt_s = dt;
    const FishRecord r = runSchedule(fish, solver, motor, schedule, opt);
    return r.blew_up ? r.blowup_cause + " at step " + std::to_string(r.blowup_step) : std::string();
  };
  StableStep out;
  if (auto f = failure(hi); f.empty()) return {hi, ""};
  else out.first_failure = f;
  if (auto f = failure(lo); !f.empty()) return {lo, f};
  for (int k = 0; k < iterations; ++k) {
    const double mid = std::sqrt(lo * hi);
    if (auto f = failure(mid); f.empty()) lo = mid;
    else hi = mid, out.first_failure = f;
  }
  out.dt_s = lo;
  return out;
}

}  // namespace creaturelab::fish
