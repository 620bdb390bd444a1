#include "fluid/tracers2.hpp"

#include <algorithm>

namespace creaturelab::fluid {

void advectTracersRk2(std::vector<Vec2>& positions_m, const VelocitySampler2& velocity, double dt_s, double width_m,
                        double height_m) {
  auto clamp_x = [width_m](double x) { return x > 0.0 ? (x < width_m ? x : width_m) : 0.0; };
  auto clamp_y = [height_m](double y) { return y > 0.0 ? (y < height_m ? y : height_m) : 0.0; };
  for (Vec2& p : positions_m) {
    const Vec2 u0 = velocity.velocityAt_m_per_s(p);
    const Vec2 mid{p.x + 0.5 * dt_s * u0.x, p.y + 0.5 * dt_s * u0.y};
    const Vec2 u1 = velocity.velocityAt_m_per_s(mid);
    p = {clamp_x(p.x + dt_s * u1.x), clamp_y(p.y + dt_s * u1.y)};
  }
}

}  // namespace creaturelab::fluid
