#pragma once
// The period of a sampled periodic signal, for profiles given without --period.
//
// Method: YIN (de Cheveigné & Kawahara 2002, J. Acoust. Soc. Am. 111, §II.B-E). The squared
// difference function d(τ) = mean_i (x(t_i + τ) - x(t_i))², over the samples whose shifted time
// is still inside the data, is zero at the period of a noiseless periodic signal. Dividing by
// its running mean, d'(τ_j) = d(τ_j) j / Σ_{m<=j} d(τ_m), removes the dip at τ = 0 and makes
// the threshold scale-free; the period is the first local minimum of d' below `threshold`
// (else the global minimum when below 0.5), refined by golden-section search on d(τ) between
// the neighbouring lags. x(t) between samples is linear, so uneven sampling is accepted.
// Rejected alternative: the first peak of the autocorrelation, which is biased toward short
// lags on a finite window and needs a taper.
#include <string>

#include "fit/profile.hpp"

namespace creaturelab::fit {

struct PeriodDetection {
  double period_s = 0;
  double mismatch = 0;  // d(period) / (2 variance): 0 for an exact repeat, about 1 for noise
  std::string error;    // "" on success: why no period was found
};

struct PeriodOptions {
  double threshold = 0.1;  // on d' (YIN's absolute threshold, §II.D)
};

/// Needs at least two periods of samples (lags up to half the span are tried).
PeriodDetection detectPeriod(const Profile& profile, const PeriodOptions& options = {});

}  // namespace creaturelab::fit
