#pragma once
// The thesis's wind (Mehla 2005 §5.3.9, Fig. 5.45 "windgen"), in SI.
//   WIND = MASS * GRAVITY * 10; every 50 calls a new random factor in [-3, 3];
//   wind = (r WIND sin(degree), r WIND sin(degree), -WIND sin(degree)); degree += 1 per call;
//   each mass gets exp(distance to the hub / alpha) * wind, alpha = web radius * 50.
// Choices where the figure is silent: windgen is called once per output frame (50 frames/s, the
// thesis's 20 s animation); sin takes degrees (an integer count read as radians would jump
// pseudo-randomly, against the text's "predictable pattern"); the force is held between frames;
// `scale` multiplies WIND (1 = the thesis's). The random factor comes from core::rng.
#include <cstdint>

#include <Eigen/Core>

#include "web/web_model.hpp"

namespace creaturelab::web {

struct WindGen {
  double wind_n;  // MASS * GRAVITY * 10 * scale
  std::uint64_t seed;
  long degree = 0;
  double random = 1.0;
  double x = 0, y = 0, z = 0;  // the wind vector, newtons

  void next();
};

// Windgen's force on every particle of a web, held from one call of next() to the next (zero
// before the first).
class WebWind {
 public:
  // Weights exp(|x_i - hub| / alpha) from the particles' positions in `start`, alpha = 50 x the
  // laid web's radius (largest distance from the hub to an attachment particle).
  WebWind(const WebModel& model, const springs::State<3>& start, WindGen gen);
  void next();  // windgen once (once per frame, Fig. 5.45)
  const springs::Points<3>& force_n() const { return force_n_; }

 private:
  WindGen gen_;
  Eigen::VectorXd weight_;
  springs::Points<3> force_n_;
};

}  // namespace creaturelab::web
