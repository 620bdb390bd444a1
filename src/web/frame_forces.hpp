#pragma once
// Stage 4 of the web: the inward radial force on the inner frame (thesis
// Mehla 2005 §5.2, Fig. 5.8; Fig. 5.10 step 8: "apply inward radial force on inner
// frame segments"), which bows the straight frame sides inward like a real frame (Figs. 3.2, 3.4).
#include <vector>

#include "springs/network.hpp"
#include "web/geometry2.hpp"

namespace creaturelab::web {

// Force on each mass of the closed chain (3 x particle_count, zero elsewhere): magnitude
// q * (|x_i - x_{i-1}| + |x_{i+1} - x_i|) / 2 (a line load of q newtons per metre shared between
// neighbours), direction toward centre_m, in the plane z = 0.
springs::Points<3> inwardFrameForces(const std::vector<int>& chain, const springs::Points<3>& x_m,
                                     const Point2& centre_m, double q_n_per_m, int particle_count);

}  // namespace creaturelab::web
