#pragma once
// Natural frequency and damping ratio from a free decay (the pluck of experiments/jellyfish/frequency.toml):
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

struct DampedFit {
  double damped_hz = 0;        // f_d = ω / 2π; NaN when no oscillation fits
  double damping_ratio = 0;    // ζ = σ / sqrt(σ² + ω²)
  double natural_hz = 0;       // f_n = sqrt(σ² + ω²) / 2π
  double residual_fraction = 0;  // rms(residual) / rms(deviation − its mean), in [0, 1]
};

/// Least-squares fit of the whole free decay to one damped mode on a slow drift,
///   d(t) ≈ e^(−σ t) (a cos ω t + b sin ω t) + c + e t,
/// linear in (a, b, c, e) for given (ω, σ): the best (ω, σ) of a grid (f_d from 2/T to a fifth of
/// the sampling rate, ζ from 0 to 0.8), refined twice on finer grids about the best. Unlike the
/// zero crossings it uses every sample, so a higher mode beating in the tail or a crossing lost
/// below the hysteresis does not change the answer; the residual says how much of the decay is not
/// that one mode. NaN fields for fewer than 8 samples or a signal without variation.
DampedFit fitDampedOscillation(std::span<const double> time_s, std::span<const double> deviation);

}  // namespace creaturelab::jellyfish
