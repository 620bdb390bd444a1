#pragma once
// The muscle activation curve of Rudolf & Mould 2009,
// §3.3 and Fig. 4: each circumferential-muscle spring's rest length is its relaxed length times a
// periodic curve "based on Hermite splines", normalised between 1 (relaxed) and 0.56 (the bell
// contracts to 56% of its diameter, Fig. 3).
//
// The curve is a periodic cubic Hermite spline through K knots (phase in [0, 1), value, tangent
// d value / d phase). Its values are the rest-length factor itself, so knot values live in
// [0.56, 1]. It is a template in the value type so that Ceres' autodiff (issue "Fitting with
// Ceres") can differentiate it with respect to knot values and tangents; phases stay doubles.
//
// Staggered expansion (§3.3, Fig. 4 right): springs nearer the aperture expand more slowly
// than those near the apex. The expansion is the part of the period from the knot of smallest
// value to the knot of largest value (cyclically). A spring at position a in [0, 1] (0 apex,
// 1 aperture) replays it at speed 1 / (1 - stagger (1 - a)), finishing early and holding the
// largest value until the curve's own expansion ends; the aperture spring follows the curve as
// written, and the contraction is the same for every spring. stagger = 0 is the paper's "unison"
// expansion. The paper gives no numbers for either curve; defaults are in jellyfish_params.hpp.
#include <algorithm>
#include <cmath>
#include <span>

namespace creaturelab::jellyfish {

struct Knot {
  double phase = 0;    // in [0, 1), strictly increasing along the knot list
  double value = 1;    // rest-length factor
  double tangent = 0;  // d value / d phase
};

/// Position in the period, in [0, 1).
inline double wrapPhase(double phase) {
  const double p = phase - std::floor(phase);
  return p < 1.0 ? p : 0.0;  // floor rounding can give exactly 1 for tiny negative phases
}

/// Index of the knot that starts the segment holding `phase` (in [0, 1)): the last knot with
/// knot_phase <= phase, or the last knot when phase precedes the first (the wrapped segment).
inline int segmentOf(std::span<const double> knot_phases, double phase) {
  const int count = static_cast<int>(knot_phases.size());
  int k = count - 1;
  for (int i = 0; i < count; ++i)
    if (knot_phases[i] <= phase) k = i;
  return k;
}

/// The periodic cubic Hermite curve at `phase` (any real; wrapped). Values and tangents have
/// type T (double or a Ceres Jet); knot phases are constants.
template <typename T>
T hermiteCurve(std::span<const double> knot_phases, const T* values, const T* tangents, double phase) {
  const int count = static_cast<int>(knot_phases.size());
  const double p = wrapPhase(phase);
  const int k0 = segmentOf(knot_phases, p);
  const int k1 = (k0 + 1) % count;
  const double start = knot_phases[k0];
  double end = knot_phases[k1];
  if (k1 <= k0) end += 1.0;  // the segment wrapping across phase 1 (also the single-knot case)
  double offset = p - start;
  if (offset < 0) offset += 1.0;
  const double width = end - start;
  const double s = offset / width;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s;
  const double h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  return h00 * values[k0] + (h10 * width) * tangents[k0] + h01 * values[k1] + (h11 * width) * tangents[k1];
}

/// Phases where the expansion starts and ends: those of the knots of smallest and largest value.
struct ExpansionWindow {
  double start_phase = 0;  // contracted
  double end_phase = 0;    // relaxed
};

inline ExpansionWindow expansionWindow(std::span<const Knot> knots) {
  int low = 0, high = 0;
  for (int i = 1; i < static_cast<int>(knots.size()); ++i) {
    if (knots[i].value < knots[low].value) low = i;
    if (knots[i].value > knots[high].value) high = i;
  }
  return knots.empty() ? ExpansionWindow{} : ExpansionWindow{knots[low].phase, knots[high].phase};
}

/// The curve of one muscle spring, with the staggered expansion described above.
inline double muscleFactor(std::span<const Knot> knots, double phase, ExpansionWindow window, double stagger,
                           double aperture_position) {
  double p = wrapPhase(phase);
  const double width = wrapPhase(window.end_phase - window.start_phase);
  const double since = wrapPhase(p - window.start_phase);
  if (since < width && stagger > 0) {
    const double speed = 1.0 / (1.0 - stagger * (1.0 - aperture_position));
    p = wrapPhase(window.start_phase + std::min(since * speed, width));
  }
  constexpr int kMax = 16;
  double phases[kMax], values[kMax], tangents[kMax];
  const int count = static_cast<int>(knots.size());
  if (count < 1 || count > kMax) return 1.0;  // validate() rejects these counts before any run
  for (int i = 0; i < count; ++i) {
    phases[i] = knots[i].phase;
    values[i] = knots[i].value;
    tangents[i] = knots[i].tangent;
  }
  return hermiteCurve<double>(std::span<const double>(phases, count), values, tangents, p);
}

}  // namespace creaturelab::jellyfish
