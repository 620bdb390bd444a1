#pragma once
// What the controller kinds (control: simple wind; control_fluid: the full fluid) read and measure
// the same way: the text parameters parsed into controller parameters (joint lists, objectives,
// weights, initial poses, the motion patterns of kinematic and PD-driven joints, Lentine et al. 2010
// §2.2; the flyer's stroke senses and flap period, §7.1), the model, and the copy of a run's measures
// (control/run_measures.hpp) into the Result (M. Lentine et al., "Creature Control in a Fluid
// Environment"). Every parse error throws std::invalid_argument naming the key.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "control/controller_params.hpp"
#include "control/run_measures.hpp"
#include "control/stroke_sense.hpp"
#include "kinds/params.hpp"
#include "kinds/result.hpp"

namespace creaturelab::kinds {

std::vector<std::string> splitList(const std::string& s, char sep);

// One initial pose: a hinge's angle (one value) or a ball joint's rotation vector (three), deg.
struct InitialPose {
  std::string joint;
  std::vector<double> deg;
};

// What both controller kinds let their user set the same way: the creature, its controlled and
// driven joints (as text: lists, objectives, weights, poses, the motion patterns of §2.2), the
// descent (§2.1) and the run's length and measures. Each kind sets its own defaults in-class where
// they differ (the fluid's objective and perturbation) and adds its own parameters.
struct ControllerSettings {
  std::string model_file = "experiments/control/models/block.xml";
  std::string controlled = "hinge";
  std::string kinematic;
  std::string kinematic_pattern;
  std::string pd_driven;
  std::string pd_pattern;
  double pd_kp_n_m_per_rad = 200;
  double pd_kd_n_m_s_per_rad = 10;
  std::string objectives = "effort";
  std::string senses = "min";
  std::string weights;
  std::string initial_deg;
  double drag_direction_x = 1;
  double drag_direction_y = 0;
  double drag_direction_z = 0;
  double gravity_m_per_s2 = 9.81;
  double frame_s = 1.0 / 60;
  std::int64_t substeps = 1;
  std::int64_t frames = 240;
  double strength_rad_per_s = 1.0;
  double delta_rad = 0.01;
  bool one_sided = false;
  std::int64_t search_every_frames = 1;
  bool rigidify_outboard = true;
  std::int64_t threads = 1;
  double convergence_tolerance_deg = 1.0;
  std::int64_t average_frames = 30;

  // model_file to initial_deg and drag_direction_*: the creature and its joints.
  template <class V>
  void describeCreature(V& v) {
    v.text("model_file", model_file, "", "MJCF creature (path from the working folder); 2-D creatures live in the x-z plane");
    v.text("controlled", controlled, "",
           "controlled joints, comma-separated: hinges (one DOF) or ball joints (three, about the body's axes; not in "
           "the 2-D fluid)");
    v.text("kinematic", kinematic, "",
           "joints that follow kinematic_pattern exactly whatever the load (hinges; ball joints hold), comma-separated");
    v.text("kinematic_pattern", kinematic_pattern, "",
           "'joint = pattern; ...' (§2.2): hold | sine(mean_deg, amplitude_deg, frequency_hz, phase_deg) | "
           "table(t_s angle_deg, ...) (linear, held past its ends); others hold");
    v.text("pd_driven", pd_driven, "",
           "hinges PD-driven to pd_pattern (§2.2: pre-specified PD targets; §7.1: the flyer's inner wing joints), "
           "comma-separated");
    v.text("pd_pattern", pd_pattern, "", "'joint = pattern; ...' for pd_driven hinges, as kinematic_pattern (default hold)");
    v.real("pd_kp_n_m_per_rad", pd_kp_n_m_per_rad, "N m/rad", 0, 1e7,
           "PD stiffness of pd_driven joints (the paper gives none; explicit at each step, keep kp h^2 / I small)");
    v.real("pd_kd_n_m_s_per_rad", pd_kd_n_m_s_per_rad, "N m s/rad", 0, 1e6, "PD damping of pd_driven joints");
    v.text("objectives", objectives, "",
           "per controlled joint: effort (Eq. 1, |torque| x frame_s, N m s) | drag (|F|, N) | drag_along (F . w, "
           "Eq. 4 and Eq. 10, N); F the wind's or the fluid's force on the bodies the joint moves");
    v.text("senses", senses, "", "per controlled joint: min | max");
    v.text("weights", weights, "",
           "rows 'w11,w12,..; w21,..': joint i descends sum_j w_ij F_j (§5), weights carrying unit conversion; one "
           "row per controlled joint; empty = each its own");
    v.text("initial_deg", initial_deg, "",
           "initial poses 'hinge=degrees, ball=x y z, ...' (ball: rotation vector in degrees; hinges only in the "
           "2-D fluid; default: the model's reference)");
    v.real("drag_direction_x", drag_direction_x, "", -1e9, 1e9, "w of Eq. 4 and Eq. 10 (normalised); lift = drag along up");
    v.real("drag_direction_y", drag_direction_y, "", -1e9, 1e9, "w of Eq. 4 and Eq. 10");
    v.real("drag_direction_z", drag_direction_z, "", -1e9, 1e9, "w of Eq. 4 and Eq. 10");
  }
  // gravity_m_per_s2 to frames: the world and the run's length.
  template <class V>
  void describeRun(V& v) {
    v.real("gravity_m_per_s2", gravity_m_per_s2, "m/s^2", 0, 1e3,
           "gravity along -z on the bodies (a fluid has none of its own; 0: the wind alone, Fig. 6)");
    v.real("frame_s", frame_s, "s", 1e-5, 1, "one controller step (a frame; Fig. 2 counts frames)");
    v.integer("substeps", substeps, 1, 1000,
              "MuJoCo steps, or coupled fluid-solid steps, per frame (the servo reaches its targets at each)");
    v.integer("frames", frames, 1, 10000000, "controlled frames to run");
  }
  // strength_rad_per_s to threads: the descent (§2.1, §5).
  template <class V>
  void describeDescent(V& v) {
    v.real("strength_rad_per_s", strength_rad_per_s, "rad/s", 0, 1e4,
           "the creature's strength: largest joint angle change per second, the fixed descent step (§2.1)");
    v.real("delta_rad", delta_rad, "rad", 1e-9, 1,
           "central-difference perturbation (§2.1; not given: large against round-off and, in a fluid, against its "
           "noise, §4.3; small against the objectives' curvature)");
    v.boolean("one_sided", one_sided, "forward differences (§2.1: biased, off in the paper)");
    v.integer("search_every_frames", search_every_frames, 1, 100000, "re-determine the direction every k frames (§2.1)");
    v.boolean("rigidify_outboard", rigidify_outboard, "§5: hold the bodies outboard of a perturbed joint rigid with it");
    v.integer("threads", threads, 1, 16, "threads for the per-DOF evaluations (§5, Fig. 10); results do not depend on it");
  }
  // convergence_tolerance_deg and average_frames: the measures.
  template <class V>
  void describeMeasures(V& v) {
    v.real("convergence_tolerance_deg", convergence_tolerance_deg, "deg", 1e-6, 90,
           "converged frame: from it every controlled angle stays this close to its final mean");
    v.integer("average_frames", average_frames, 1, 100000, "frames at the end over which final values are averaged");
  }

  // model_file with gravity_m_per_s2 (along -z) and the step frame_s / substeps.
  rigid::RigidModel loadModel() const;
  // Every controller parameter but steady_state and servo_projection (the wind kind's own).
  control::ControllerParams controllerParams() const;
  // A fluid run's coupled steps per frame, for the cost estimate: the frame's substeps, and every
  // search_every_frames frames two evaluations per controlled joint of steps_per_evaluation each (none at
  // strength 0, where the controller does not search).
  double coupledStepsPerFrame(double steps_per_evaluation) const;
  // "joint=deg, ball=x y z"
  std::vector<InitialPose> initialPoses() const;
  // The initial poses checked against the model: each joint in it, not free, with as many angles as it
  // has rotations (hinges only: `hinges_only`); "" or what is wrong, naming initial_deg.
  std::string checkInitialPoses(const rigid::RigidModel& model, bool hinges_only) const;
};

// "hold" | "sine(mean_deg, amplitude_deg, frequency_hz, phase_deg)" |
// "table(t_s angle_deg, t_s angle_deg, ...)"; `key` names the parameter in errors.
control::Pattern parsePattern(const std::string& text, const std::string& key);

// "outer=inner, outer2=-inner2" (the driven flyer, Lentine et al. 2010 §7.1): per controlled joint (in
// `controlled` order) the inboard joint whose pattern's stroke flips its sense; "+" (default) = the
// given sense while that joint's angle increases, "-" = while it decreases. Joints not named keep their
// sense; "" = none. Throws std::invalid_argument naming stroke_sense for a malformed entry or a joint
// not controlled.
std::vector<control::StrokeFollow> parseStrokeSense(const std::string& text, const std::vector<std::string>& controlled);

// Frames in one flap period: period_s / frame_s rounded; throws std::invalid_argument naming
// flap_period_s when that is not within 1e-6 of a whole number of frames (cycles would drift).
int framesPerCycle(double period_s, double frame_s);

// Copies a controller run's series (each the length of time_s) and measures into the Result.
void addSeries(Result& result, const control::SeriesSet& series);
void addMetrics(Result& result, const std::vector<control::NamedValue>& values);

}  // namespace creaturelab::kinds
