#pragma once
// The thesis's wind (Mehla 2005 §5.3.9, Fig. 5.45 "windgen"), in SI.
//   WIND = MASS * GRAVITY * 10; every 50 calls a new random factor in [-3, 3];
//   wind = (r WIND sin(degree), r WIND sin(degree), -WIND sin(degree)); degree += 1 per call;
//   each mass gets exp(distance to the hub / alpha) * wind, alpha = web radius * 50.
// Choices where the figure is silent: windgen is called once per output frame (50 frames/s, the
// thesis's 20 s animation); sin takes degrees (an integer count read as radians would jump
// pseudo-randomly, against the text's "predictable pattern"); the force is held between frames;
// `scale` multiplies WIND (1 = the thesis's). The random factor comes from core::rng.
#include <cmath>
#include <cstdint>

#include "core/rng.hpp"

namespace creaturelab::kinds {

struct WindGen {
  double wind_n;  // MASS * GRAVITY * 10 * scale
  std::uint64_t seed;
  long degree = 0;
  double random = 1.0;
  double x = 0, y = 0, z = 0;  // the wind vector, newtons

  void next() {
    if (degree % 50 == 0) random = -3.0 + 6.0 * core::uniform01(seed, core::purposeId("web.wind"), std::uint64_t(degree / 50));
    const double s = std::sin(double(degree) * M_PI / 180.0);
    x = random * wind_n * s;
    y = random * wind_n * s;
    z = -wind_n * s;
    ++degree;
  }
};

}  // namespace creaturelab::kinds
