#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "fish/fish_model.hpp"
#include "fish/fish_solver.hpp"
#include "fish/motor.hpp"
#include "fish/skin.hpp"
#include "kinds/describe_kind.hpp"

namespace creaturelab::kinds {

// What one fish run is built from: the body, the solver, the motor controllers and their schedule.
struct FishSetup {
  fish::SkinParams skin;
  fish::FishGeometry geometry;
  fish::UnitParams units;
  fish::SolverParams solver;
  fish::MotorParams motor;
  std::vector<fish::ScheduleItem> schedule;
};

// The fish kind's parameters: the fish structs' own (their in-class defaults are this kind's) and
// the run's (task, school, schedule, shape, swim-MC calibration, recording, skin output, stable step).
struct FishKindParams {
  std::string task = "simulate";
  std::int64_t school_size = 1;
  std::string schedule = "swim 30";
  std::string shape = "ours";
  fish::FishGeometry geometry;
  fish::UnitParams units;
  fish::MotorParams motor;
  fish::SolverParams solver;
  double swim_speed_body_lengths_per_s = 0.0;
  double swim_mc_slowest_knob = 0.5;
  std::int64_t swim_mc_levels = 5;
  double swim_mc_swim_s = 40.0;
  double warmup_s = 10.0;
  std::string on_blowup = "fail";
  std::int64_t frame_every_steps = 10;
  bool skin = false;
  fish::SkinParams skin_params;
  std::int64_t skin_samples_around = 32;
  std::int64_t skin_samples_along = 64;
  std::int64_t export_frames = 16;
  double export_start_s = 0.0;
  std::int64_t pov_frames = 4;
  double stable_lo_s = 1e-4;
  double stable_hi_s = 5.0;
  std::int64_t stable_iterations = 30;

  template <class V>
  void describe(V& v) {
    v.choice("task", task, {"simulate", "stable_step"},
             "simulate (run the schedule) | stable_step (bisect the largest step that survives the schedule)");
    v.integer("school_size", school_size, 1, 100000,
              "fish simulated (independent; fish k swims at amplitude x (1 - 0.05 (k mod 5))); the first is recorded, "
              "the rest counted");
    v.text("schedule", schedule, "", "controller schedule, \"NAME SECONDS; ...\" with NAME swim | left | right | glide (spec §3)");
    v.choice("shape", shape, {"ours", "reimplementation"},
             "node coordinates: ours (fish_model.hpp: fusiform, laterally compressed) | reimplementation (FishData.cs "
             "InitNodes, scaled to body_length_m)");
    geometry.describe(v);
    units.describe(v);
    motor.describeContraction(v);
    solver.describe(v);
    motor.swim.describe(v);
    v.real("swim_speed_body_lengths_per_s", swim_speed_body_lengths_per_s, "1/s", 0, 100,
           "if > 0: the swim-MC sets alpha = s and r = s r_max for this speed from its calibrated speed map "
           "(swim_mc.hpp), overriding swim_amplitude/rate; a speed outside the map's range fails the point");
    v.real("swim_mc_slowest_knob", swim_mc_slowest_knob, "", 1e-3, 0.999,
           "swim-MC calibration: the slowest knob s (ours: below s = 1/2 the fish swims under 0.15 body lengths/s and, "
           "the drag growing as the square of the speed, takes longer than a 40 s swim to settle)");
    v.integer("swim_mc_levels", swim_mc_levels, 2, 24, "swim-MC calibration: knobs spaced evenly in log s from the slowest to 1");
    v.real("swim_mc_swim_s", swim_mc_swim_s, "s", 1e-3, 1e6, "swim-MC calibration: each level swims this long from rest");
    motor.describeControllers(v);
    v.real("warmup_s", warmup_s, "s", 0, 1e6, "speed is measured from this time to the end (the gait settles first)");
    v.choice("on_blowup", on_blowup, {"fail", "record"},
             "fail: a blow-up fails the point (exit 3); record: the run stops there and the step is a metric (air experiment)");
    v.integer("frame_every_steps", frame_every_steps, 1, 1000000,
              "record a frame every this many steps (20 ms at the default step)");
    v.boolean("skin", skin,
              "NURBS skin (seed; spec §4): check it on every frame, store it on export_frames frames, write "
              ".glb/.obj/.pov artifacts");
    skin_params.describe(v);
    v.integer("skin_samples_around", skin_samples_around, 2, 1024, "mesh samples around each half body");
    v.integer("skin_samples_along", skin_samples_along, 2, 4096, "mesh samples along the body");
    v.integer("export_frames", export_frames, 1, 1000,
              "frames stored and exported (glb animation, OBJ), evenly spaced from export_start_s to the end");
    v.real("export_start_s", export_start_s, "s", 0, 1e6, "start of the exported window");
    v.integer("pov_frames", pov_frames, 0, 100, "POV-Ray scenes written, evenly spaced over the exported frames");
    v.real("stable_lo_s", stable_lo_s, "s", 1e-9, 100, "stable_step: the smallest step tried");
    v.real("stable_hi_s", stable_hi_s, "s", 1e-9, 1000, "stable_step: the largest step tried");
    v.integer("stable_iterations", stable_iterations, 1, 200, "stable_step: bisection steps (on a log scale)");
  }

  // The run's structs: the shape's geometry, one swim command for both segments, the parsed schedule.
  // Throws std::invalid_argument naming what is wrong (the structs' own validate()s, the schedule).
  FishSetup setup() const;
  // Ranges, setup()'s checks, then: stable_lo_s below stable_hi_s.
  std::string validate() const;
};

// Tu's artificial fish (X. Tu, Artificial Animals for Computer Animation, 1996; docs/fish-spec.md):
// a 23-node spring-mass body in water, stepped semi-implicitly, driven by swim and turn motor
// controllers through a schedule, optionally skinned with NURBS surfaces and exported.
class FishKind : public DescribedKind<FishKindParams> {
 public:
  FishKind();
  std::string name() const override { return "fish"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
  CostEstimate estimateCost(const Params& params) const override;
  // A recorded swim skinned on every frame (kinds/fish_render.cpp).
  const RenderHook* renderHook() const override;
};

}  // namespace creaturelab::kinds
