#include "kinds/strand.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "kinds/spring_run.hpp"
#include "springs/equilibrium.hpp"
#include "springs/network.hpp"
#include "springs/provot.hpp"
#include "springs/simulate.hpp"

namespace creaturelab::kinds {
namespace {

const char* kThesis = "A. Mehla, Modeling and Animation of Orb Webs, MSc thesis 2005,";

// The strand's geometry, derived once from the parameters (see the span_m / n_springs docs).
struct Layout {
  int n_springs;
  double placement_m;  // distance between neighbours as laid
  double span_m;       // anchor to anchor
};

Layout layoutOf(const StrandParams& q) {
  const double rest = q.rest_length_m;
  const double nominal = q.layout == "overextended" ? rest * (1.0 + q.overextension) : rest;
  const auto n = q.n_springs;
  const double span = q.span_m;
  if (span > 0) {
    const int count = std::max(2, int(std::lround(span / nominal)));
    return {count, span / count, span};
  }
  const int count = n > 0 ? int(n) : 50;
  return {count, nominal, nominal * count};
}

}  // namespace

StrandKind::StrandKind() {
  metrics_ = {
      {"particles", "", "particles in the strand, anchors included"},
      {"anchor_span_m", "m", "anchor separation, as set or derived"},
      {"mid_sag_m", "m", "depth of the middle of the strand below the anchors at the end"},
      {"static_mid_sag_m", "m", "the same from the static Newton equilibrium (no Provot)"},
      {"static_sag_rel_diff", "", "|mid_sag_m - static_mid_sag_m| / static_mid_sag_m"},
      {"max_strain", "", "largest (length - rest) / rest at the end"},
      {"provot_peak_strain", "", "largest strain left after any step's strain limiting (0 with provot off)"},
      {"provot_unconverged_steps", "", "steps whose Provot sweeps hit provot_passes with a spring still too long"},
      {"provot_mean_passes", "", "Provot sweeps per step, mean over the run (0 with provot off)"},
      {"settling_time_s", "s", "earliest time after which kinetic energy stays below settling_fraction of its peak"},
      {"final_kinetic_energy_j", "J", "kinetic energy at the end"},
      {"dt_used_s", "s", "the substep used"},
  };
}

std::string StrandKind::doc() const {
  return std::string("a web strand between two anchors under gravity and drag (") + kThesis + " §5.1)";
}

std::string StrandParams::validate() const {
  if (std::string problems = rangeProblems(*this); !problems.empty()) return problems;
  if (span_m > 0 && n_springs > 0)
    return "set span_m or n_springs, not both (the other follows from the placement length)";
  if (!dt_s.is_auto && dt_s.value > frame_interval_s)
    return "dt_s is longer than frame_interval_s; the frame is split into whole substeps";
  return "";
}

namespace {

// The strand as laid out before it is released: network, initial state and run options.
struct StrandSetup {
  springs::Network<2> net;
  springs::State<2> state;
  springs::SimulationOptions opt;
};

StrandSetup setupOf(const StrandParams& q) {
  const Layout lay = layoutOf(q);
  const double rest = q.rest_length_m, mass = q.mass_kg;

  springs::Network<2> net;
  for (int i = 0; i <= lay.n_springs; ++i) net.addParticle(mass, i == 0 || i == lay.n_springs);
  for (int i = 0; i < lay.n_springs; ++i)
    net.addSpring(i, i + 1, rest, q.spring_k_n_per_m, q.spring_damping_ns_per_m);
  net.gravity_m_per_s2 = springs::Vec<2>(0.0, -q.gravity_m_per_s2);
  net.drag_ns_per_m = q.drag_ns_per_m;

  const int n = lay.n_springs + 1;
  springs::State<2> state{springs::Points<2>::Zero(2, n), springs::Points<2>::Zero(2, n)};
  for (int i = 0; i < n; ++i) state.x_m(0, i) = lay.placement_m * i;

  springs::SimulationOptions opt;
  opt.integrator = parseIntegratorOrThrow(q.integrator);
  opt.frame_interval_s = q.frame_interval_s;
  opt.dt_s = q.dt_s.is_auto ? 0.0 : q.dt_s.value;
  opt.end_time_s = q.end_time_s;
  opt.settling_fraction = q.settling_fraction;
  opt.provot = q.provot;
  return {std::move(net), std::move(state), opt};
}

}  // namespace

CostEstimate StrandKind::estimateCost(const Params& p) const {
  try {
    const StrandParams q = readParams<StrandParams>(p);
    const StrandSetup setup = setupOf(q);
    return springRunCost(setup.net, setup.state, setup.opt, q.integrator);
  } catch (const std::exception&) {
    return {};  // the point itself will say what is wrong
  }
}

namespace {

// The depth of the strand's middle below the anchors: the middle particle, or the mean of the two.
double midSag(const springs::State<2>& s) {
  const int n = int(s.x_m.cols());
  const double y = (n % 2) ? s.x_m(1, n / 2) : 0.5 * (s.x_m(1, n / 2 - 1) + s.x_m(1, n / 2));
  return -y;
}

// Each frame: the middle's sag (a series in the Result as it grows, so a failed run keeps it) and,
// every frames_per_track frames, the particles' positions.
class StrandRecorder {
 public:
  StrandRecorder(int particles, int frames_per_track, Result& result)
      : sag_(result.timeseries["mid_sag_m"] = {{}, "m"}),
        tracks_(result.lagrangian["positions_m"]),
        frames_per_track_(frames_per_track) {
    tracks_.points = particles;
    tracks_.dim = 2;
  }
  void operator()(int frame, double t, const springs::State<2>& s) {
    sag_.values.push_back(midSag(s));
    if (frame % frames_per_track_ == 0) keep(t, s);
  }
  // The last frame is always kept.
  void finish(double t, const springs::State<2>& s) {
    if (tracks_.time_s.empty() || tracks_.time_s.back() < t) keep(t, s);
  }

 private:
  void keep(double t, const springs::State<2>& s) {
    tracks_.time_s.push_back(t);
    tracks_.data.insert(tracks_.data.end(), s.x_m.data(), s.x_m.data() + s.x_m.size());
  }
  Series& sag_;
  Tracks& tracks_;
  int frames_per_track_;
};

// The run's and the static solve's measures.
void addStrandMetrics(const Layout& lay, const springs::System<2>& system, const springs::State<2>& state,
                      const springs::SimulationSummary& summary, const springs::State<2>& settled, bool static_converged,
                      Result& result) {
  const double nan = std::nan("");
  const double static_sag = static_converged ? midSag(settled) : nan;
  auto& m = result.metrics;
  m["particles"] = {double(state.x_m.cols()), ""};
  m["anchor_span_m"] = {lay.span_m, "m"};
  m["mid_sag_m"] = {midSag(state), "m"};
  m["static_mid_sag_m"] = {static_sag, "m"};
  m["static_sag_rel_diff"] = {std::fabs(midSag(state) - static_sag) / static_sag, ""};
  m["max_strain"] = {springs::maxStrain(system.network(), state), ""};
  m["provot_peak_strain"] = {summary.provot_peak_strain, ""};
  m["provot_unconverged_steps"] = {double(summary.provot_unconverged_steps), ""};
  m["provot_mean_passes"] = {summary.steps ? double(summary.provot_passes) / double(summary.steps) : 0.0, ""};
  m["settling_time_s"] = {summary.settling_time_s.value_or(nan), "s"};
  m["final_kinetic_energy_j"] = {summary.kinetic_energy_j.back(), "J"};
  m["dt_used_s"] = {summary.dt_used_s, "s"};
}

}  // namespace

Result StrandKind::run(const Params& p) const {
  const StrandParams q = readParams<StrandParams>(p);
  StrandSetup setup = setupOf(q);
  springs::State<2>& state = setup.state;
  Result result;
  StrandRecorder recorder(int(state.x_m.cols()),
                          std::max(1, int(std::lround(q.lagrangian_interval_s / setup.opt.frame_interval_s))), result);
  springs::System<2> system(std::move(setup.net));
  springs::State<2> settled = state;  // the static solve starts from the same layout
  const auto summary = runOrFail(system, state, setup.opt, std::ref(recorder), result);
  recorder.finish(summary.time_s.back(), state);
  result.timeseries["time_s"] = {summary.time_s, "s"};
  result.timeseries["kinetic_energy_j"] = {summary.kinetic_energy_j, "J"};
  const auto eq = springs::solveStaticEquilibrium(system, settled);
  addStrandMetrics(layoutOf(q), system, state, summary, settled, eq.converged, result);
  return result;
}

}  // namespace creaturelab::kinds
