#pragma once
// What a controller run measures the same way in wind and in the fluid (M. Lentine et al.,
// "Creature Control in a Fluid Environment", 2010): named per-frame series, means over a run's
// last frames, angles between lines, and the converged frame of Fig. 2. No I/O: the kind copies the
// series and values into its Result.
#include <deque>
#include <string>
#include <vector>

#include "control/controller_params.hpp"
#include "core/named_measure.hpp"

namespace creaturelab::control {

using core::NamedSeries;
using core::NamedValue;

// Named series whose values stay where they are while more are added (a deque).
class SeriesSet {
 public:
  std::vector<double>& add(const std::string& name, const std::string& unit);
  const std::deque<NamedSeries>& all() const { return series_; }

 private:
  std::deque<NamedSeries> series_;
};

// Mean of the last `tail` values of v (each divided by tail before summing).
double tailMean(const std::vector<double>& v, int tail);

// Angle (deg) between two lines (not directions): in [0, 90].
double lineAngleDeg(const Vec3& a, const Vec3& b);

// The mean of lines (not directions) as axial data: the principal axis of the orientation tensor
// sum u u^T of their unit vectors (Mardia & Jupp 2000 §9.2.3), returned as its angle (deg, in
// [0, 90]) to the line `reference`. Unlike the mean of folded angles it is not biased when the lines
// wander across the perpendicular or across the reference (a flat optimum at 90 or 0 degrees).
double meanLineAngleDeg(const std::vector<Vec3>& lines, const Vec3& reference);

// The frame from which every controlled angle stays within tol of its mean over the last `tail`
// frames; frames + 1 if the last frame is not yet settled (frames count from 1).
double convergedFrame(const std::vector<std::vector<double>>& angles_deg, double tol_deg, int tail);

// The driven flyer's means over whole flap cycles (§7.1, Figs. 11-13): a mean over a part of a cycle
// would weigh up- and down-stroke unequally.
// Mean of the last `cycles` x `frames_per_cycle` values of v; NaN when v is shorter.
double lastCyclesMean(const std::vector<double>& v, int frames_per_cycle, int cycles);

// Standard error of lastCyclesMean from its cycles' means m_k: sqrt(sum (m_k - mean)^2 / (cycles - 1)) /
// sqrt(cycles), cycles taken as independent samples; NaN with fewer than two cycles or v shorter.
double lastCyclesStandardError(const std::vector<double>& v, int frames_per_cycle, int cycles);

// The same over one phase of the flap: v's mean over the frames of each of the last `cycles` cycles whose
// `sense` has the sign of `sign` (the frames the controller maximises, sign > 0, or minimises, sign < 0),
// those cycles' means averaged; the standard error as lastCyclesStandardError's from those means. NaN when
// a cycle has no frame of the phase, sense and v differ in length, or (the error) with fewer than two cycles.
struct PhaseMean {
  double mean = 0, standard_error = 0;
};
PhaseMean lastCyclesPhaseMean(const std::vector<double>& v, const std::vector<double>& sense, double sign,
                              int frames_per_cycle, int cycles);

}  // namespace creaturelab::control
