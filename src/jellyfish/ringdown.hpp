#pragma once
// Natural frequency and damping ratio from a free decay (issue 13 §2, natural_frequency.toml):
// after a pluck the bell's diameter rings down about its rest value. With deviation d(t) from the
// rest value, the damped frequency comes from the zero crossings of d (half a period apart), the
// damping from the logarithmic decrement of successive extrema (one per half period):
//   δ = 2 ln(|d_k| / |d_k+1|) per period,  ζ = δ / sqrt(4π² + δ²),  f_n = f_d / sqrt(1 − ζ²)
// (any vibrations text, e.g. Rao, Mechanical Vibrations §2.6). Pure numerics: no simulation here.
#include <span>

namespace creaturelab::jellyfish {

struct Ringdown {
  int half_periods = 0;        // zero crossings found minus one; < 2 means no oscillation measured
  double damped_hz = 0;        // f_d; NaN when half_periods < 2
  double damping_ratio = 0;    // ζ; NaN when fewer than two extrema above the noise floor
  double natural_hz = 0;       // f_n = f_d / sqrt(1 − ζ²); NaN when either is
};

/// `time_s` increasing, `deviation` the signal minus its rest value. A zero crossing counts only
/// once the signal passes ±h on its far side, h = `relative_floor` × the previous half period's
/// extremum (the starting deviation at first): beats of higher modes about zero and the flow's
/// slow drifts then add no crossings, while the decaying ring still does.
/// Only the first `max_half_periods` half periods count: after a pluck the breathing mode
/// dominates the first two periods, and higher shape modes beat with it later.
Ringdown measureRingdown(std::span<const double> time_s, std::span<const double> deviation, double relative_floor,
                         int max_half_periods);

}  // namespace creaturelab::jellyfish
