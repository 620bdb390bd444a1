#pragma once
// Motor controllers (spec §3; thesis ch. 5). A muscle acts only through its rest length l (spec §2).
// Its contraction is c = l_rest - l, between 0 (rest) and l_rest - l_contracted (fully contracted).
//
// Amplitude alpha in (0, 1]: the fraction of the full contraction a controller reaches,
//   c_max = alpha (l_rest - l_contracted).
// (Ours. The spec words it as "0 the fully contracted length, 1 the rest length", which read
// literally would make alpha = 1 no contraction; it also says speed grows with amplitude, which
// fixes the direction we take.)
// Rate r in (0, r_max]: the rest-length change per time step as a fraction of the rest length
// (r_max = 0.075 [reimpl]), per *reference* step dt_ref = 0.055 s, so that the motion is the same
// in time whatever step the solver takes (the stability experiment changes it). Two readings
// (MotorParams::rate_reading):
//   full_stroke (default): r is the ramp of the full stroke (alpha = 1); a weaker stroke keeps its
//     period and ramps at alpha r, dc/dt = alpha r l_rest / dt_ref. r then sets the stroke frequency
//     and alpha its amplitude, as in the public reimplementation (its swim parameters "amplitude" in
//     [0, 1] and "frequency" in [0, 0.075]) and as the thesis's claim that speed grows with both reads.
//   rest_length (the spec's literal reading): every stroke ramps at dc/dt = r l_rest / dt_ref, so a
//     weaker stroke beats faster (its period is alpha times the full stroke's) and the tail's lateral
//     speed, hence the swimming speed, depends on r alone.
// Rest lengths ramp at that constant rate: a triangle wave of period 2 c_max / (dc/dt).
//
// swim-MC: the middle and posterior muscle segments (spec §1: the two posterior segments swim);
// left and right exactly out of phase (the right side starts half a period later); the posterior
// segment lags the anterior one by posterior_lag_rad of its period (ours: pi/2, a travelling wave).
// turn-MCs: the left (or right) muscles of the anterior and middle segments contract at turn_rate
// to turn_amplitude, hold while the turn item lasts and then relax more slowly
// (turn_relax_fraction); the fish bends and turns towards that side. The swim-MC keeps driving the
// middle and posterior segments during a turn (swim_during_turn; spec §1: the middle segment both
// swims and turns), its wave running on from the swim before; the middle segment's muscles take the
// sum of both contractions, clamped to the full one.
// Between controllers every muscle's contraction moves towards its new target at no more than the
// fastest rate (r_max), so switching never jerks a rest length.
#include <array>
#include <string>
#include <vector>

#include "fish/fish_model.hpp"

namespace creaturelab::fish {

enum class Action { swim, left, right, glide };

struct ScheduleItem {
  Action action;
  double duration_s;
  double start_s;  // filled by parseSchedule: the sum of the durations before
};

// "swim 10; left 3; glide 2" -> items. Names: swim, left, right, glide; durations in seconds, > 0.
// Throws std::invalid_argument naming the item that is wrong (unknown controller, bad duration).
std::vector<ScheduleItem> parseSchedule(const std::string& text);
std::string actionName(Action a);
double scheduleDurationS(const std::vector<ScheduleItem>& schedule);

// The parameter structs' in-class defaults are the fish kind's (kinds/fish.hpp); each describes its
// fields for it (kinds/describe.hpp: name, unit, range, one-line doc).
struct SwimCommand {
  double amplitude_anterior = 1.0, rate_anterior = 0.0375;  // ours: the full stroke at r_max / 2 cruises
  double amplitude_posterior = 1.0, rate_posterior = 0.0375;

  // One amplitude and one rate for both segments: read into the anterior's, then bothAsAnterior().
  template <class V>
  void describe(V& v) {
    v.real("swim_amplitude", amplitude_anterior, "", 0, 1,
           "swim-MC amplitude alpha in (0, 1]: the fraction of full contraction reached (spec §3)");
    v.real("swim_rate", rate_anterior, "", 0, 1,
           "swim-MC rate r in (0, r_max]: rest-length change per reference step as a fraction of the rest length "
           "(spec §3; see rate_reading); the default r_max / 2 cruises");
  }
  void bothAsAnterior() {
    amplitude_posterior = amplitude_anterior;
    rate_posterior = rate_anterior;
  }
};


// What the rate r is a fraction of (see the header comment).
enum class RateReading { full_stroke, rest_length };

// How a swim segment's rest lengths move (spec §3 fixes neither; see MotorParams::stroke).
enum class Stroke { contract, antagonistic };

struct MotorParams {
  double contracted_fraction = 0.7;  // fully contracted length / rest length (ours: thesis value not in text)
  template <class V>
  void describeContraction(V& v) {
    v.real("contracted_fraction", contracted_fraction, "", 1e-6, 1 - 1e-6,
           "fully contracted length / rest length of a muscle (ours: the thesis value is not in text; 0.7 keeps the "
           "tail from folding at alpha = 1)");
  }
  // contract (ours, the spec's wording "0 the fully contracted length, 1 the rest length"): each
  //   muscle moves between its rest length l0 and l0 - alpha (l0 - lc); the pair's length
  //   difference spans +-alpha (l0 - lc).
  // antagonistic ([reimpl] FishData.cs Spring(): rest length lerp(1.3 l0, 0.7 l0, a), left a and
  //   right 1 - a, a = 0.5 at rest): each muscle moves between l0 + alpha (l0 - lc) and
  //   l0 - alpha (l0 - lc), its partner the opposite way; twice the bend of `contract`, and no
  //   mean shortening of the segment.
  Stroke stroke = Stroke::contract;
  RateReading rate_reading = RateReading::full_stroke;
  // Swap left and right in every controller (the swim's starting side and the turns): the mirror
  // image of a run, for the left/right symmetry checks from a swimming start.
  bool mirror = false;
  SwimCommand swim;
  double posterior_lag_rad = 1.5707963267948966;  // pi/2 (spec §3 [choose])
  double turn_amplitude = 1.0;  // ours: a 90-degree turn in 3 s
  double turn_rate = 0.0375;
  // A turn contracts at turn_rate and relaxes at turn_rate x this (ours: 0.25). A symmetric pulse
  // bends the body and unbends it along the same path, and the water gives back most of the turn;
  // a slow release lets the bent body glide round (the thesis's turns: a quick bend, a slow return).
  double turn_relax_fraction = 0.25;
  // contract: only the inner side's muscles shorten; antagonistic (ours, after the [reimpl] pair
  // above): the outer side's lengthen as much, twice the bend.
  Stroke turn_stroke = Stroke::antagonistic;
  bool swim_during_turn = true;  // ours: the tail beats on through a turn, which carries the fish round
  double r_max = 0.075;             // [reimpl]
  double reference_step_s = 0.055;  // the step r is defined per ([reimpl] dt)

  // Every field but contracted_fraction and swim (describeContraction, SwimCommand::describe).
  template <class V>
  void describeControllers(V& v) {
    v.real("posterior_lag_rad", posterior_lag_rad, "rad", -100, 100,
           "phase lag of the posterior swim segment (spec §3 [choose]: pi/2)");
    v.real("turn_amplitude", turn_amplitude, "", 0, 1, "turn-MC amplitude alpha in (0, 1]");
    v.real("turn_rate", turn_rate, "", 0, 1, "turn-MC rate r in (0, r_max] of the contraction");
    v.choice("muscle_stroke", stroke, {{"contract", Stroke::contract}, {"antagonistic", Stroke::antagonistic}},
             "swim-MC stroke: contract (rest length to alpha of the way to the contracted one; ours) | antagonistic "
             "([reimpl]: l0 -+ alpha (l0 - lc), the partner opposite)");
    v.choice("rate_reading", rate_reading,
             {{"full_stroke", RateReading::full_stroke}, {"rest_length", RateReading::rest_length}},
             "what a motor controller's rate r is a fraction of (motor.hpp): full_stroke (ours: r l0 per reference step "
             "is the alpha = 1 stroke's ramp, a weaker stroke keeps the period; r sets the frequency, alpha the "
             "amplitude, as in the reimplementation) | rest_length (the spec's literal reading: every stroke ramps at "
             "r l0 per step, a weaker one beats faster)");
    v.boolean("mirror", mirror, "swap left and right in every controller (the mirror image of the run; symmetry checks)");
    v.real("turn_relax_fraction", turn_relax_fraction, "", 0, 1,
           "turn-MC: relaxation rate / contraction rate (ours: a quick bend, a slow return)");
    v.choice("turn_stroke", turn_stroke, {{"contract", Stroke::contract}, {"antagonistic", Stroke::antagonistic}},
             "turn-MC stroke: antagonistic (ours, after the [reimpl] pair: the outer side's muscles lengthen as much "
             "as the inner side's shorten, twice the bend; a 90-degree turn needs it) | contract (the inner side only)");
    v.boolean("swim_during_turn", swim_during_turn,
              "the swim-MC keeps driving the middle and posterior segments through a turn item (spec §1: the middle "
              "segment swims and turns); false: the fish glides bent");
    v.real("r_max", r_max, "", 1e-9, 1, "the largest rate ([reimpl] 0.075)");
    v.real("reference_step_s", reference_step_s, "s", 1e-9, 100, "the step the rates are defined per (the [reimpl] step)");
  }

  // "" or what is wrong, naming the parameter (alpha outside (0, 1], r outside (0, r_max], ...).
  std::string validate() const;
};

// The period of the swim-MC's anterior segment (seconds): 2 x its triangle's height / its slope.
double swimPeriodS(const MotorParams& p);

class MotorController {
 public:
  // Keeps a reference to `fish`, which must outlive it. Throws std::invalid_argument (validate()).
  MotorController(const FishModel& fish, MotorParams params, std::vector<ScheduleItem> schedule);
  // Sets the muscles' rest lengths for the step that starts at time t_s, moving from their current
  // values over one step of dt_s.
  void apply(double t_s, double dt_s, std::array<double, kUnits>& rest_m);
  // The contraction each muscle aims at, at time t_s (before the rate limit).
  std::array<double, kMuscles> targetContraction(double t_s) const;
  const std::vector<ScheduleItem>& schedule() const { return schedule_; }
  // The schedule item active at t_s (the last one after the end).
  const ScheduleItem& itemAt(double t_s) const;

 private:
  double swimClockStart(const ScheduleItem& item) const;
  double turnContraction(int muscle, int side, double t_s) const;

  const FishModel& fish_;
  MotorParams params_;
  std::vector<ScheduleItem> schedule_;
  std::array<double, kMuscles> rest_m_{};         // each muscle's rest length
  std::array<double, kMuscles> contraction_m_{};  // current contraction
};

}  // namespace creaturelab::fish
