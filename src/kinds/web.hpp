#pragma once
#include <string>

#include "kinds/describe_kind.hpp"
#include "springs/simulate.hpp"
#include "web/web_params.hpp"

namespace creaturelab::kinds {

// The web kind's parameters: the frame's points, the construction (web::WebParams, whose in-class
// defaults are this kind's), the rest-length override, and the run (start, integrator, step, span,
// recording, wind).
struct WebKindParams {
  std::string frame_shape = "default";
  std::string attachment_points_m;  // "x1,y1; x2,y2; ..."; "" = frame_shape
  double frame_scale = 1.0;
  web::WebParams web;
  double overextension = 0.0;  // 0 = the per-type rest lengths
  std::string start = "laid";
  std::string integrator = "rk4";
  RealOrAuto dt_s;  // "auto": auto_safety times the stability limit
  double auto_safety = web::kAutoStepSafety;
  double frame_interval_s = 0.02;
  double end_time_s = 10.0;
  double settling_fraction = 1e-4;
  double lagrangian_interval_s = 1.0;
  double wind_scale = 0.0;

  template <class V>
  void describe(V& v) {
    v.choice("frame_shape", frame_shape, {"default", "triangle", "square", "hexagon", "decagon"},
             "attachment points: an irregular 7-point frame 1.07 m across, or a regular polygon 1 m across (Fig. 5.18)");
    v.text("attachment_points_m", attachment_points_m, "m",
           "custom attachment points \"x1,y1; x2,y2; ...\" (3 to 10); overrides frame_shape");
    v.real("frame_scale", frame_scale, "", 0.05, 20, "scales the attachment points (web size, thesis Fig. 5.17)");
    web.describe(v);
    v.real("overextension", overextension, "", 0, 10, "if > 0, every rest length = placement / (1 + this) (§5.1: 0.75-2.5)");
    v.choice("start", start, {"laid", "static"}, "start from the web as laid, or from its static equilibrium (for wind)");
    v.choice("integrator", integrator, {"euler", "symplectic_euler", "rk4", "implicit_euler"}, "time integrator (thesis: rk4)");
    v.realOrAuto("dt_s", dt_s, "s", 1e-9, 1, "substep; \"auto\" = auto_safety times the stability limit");
    v.real("auto_safety", auto_safety, "", 1e-3, 1,
           "fraction of the stability limit (from an upper bound on omega_max) that dt_s = \"auto\" uses");
    v.real("frame_interval_s", frame_interval_s, "s", 1e-6, 10, "output frame (thesis §5.2.1 'time step' 0.02 s)");
    v.real("end_time_s", end_time_s, "s", 0, 1e5, "simulated time; 0 = build and solve the statics only");
    v.real("settling_fraction", settling_fraction, "", 1e-12, 1,
           "settled when kinetic energy stays below this fraction of its peak");
    v.real("lagrangian_interval_s", lagrangian_interval_s, "s", 1e-6, 1e5, "interval between stored particle positions");
    v.real("wind_scale", wind_scale, "", 0, 1e6, "wind of Fig. 5.45 times this (1 = WIND = m g 10); 0 = no wind");
  }

  // The web to build: `web` with the frame's points (attachment_points_m, else frame_shape; times
  // frame_scale) and the overextension. Throws std::invalid_argument naming attachment_points_m.
  web::WebParams webParams() const;
  springs::SimulationOptions simulationOptions() const;
  // Ranges, the points, then the web's own validate().
  std::string validate() const;
};

// An orb web built strand by strand (Mehla 2005 thesis §5.2) and settled under gravity and drag,
// optionally swaying in the thesis's wind (§5.3.9, Fig. 5.45).
class WebKind : public DescribedKind<WebKindParams> {
 public:
  WebKind();
  std::string name() const override { return "web"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
};

}  // namespace creaturelab::kinds
