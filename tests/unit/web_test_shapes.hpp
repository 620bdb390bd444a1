#pragma once
// Attachment points for web tests.
#include <cmath>
#include <vector>

#include "web/web_params.hpp"

namespace creaturelab::test {

// A regular polygon of n points on a circle of radius r_m metres, turned 0.3 rad off the x axis.
inline std::vector<web::Point2> regularPolygon(int n, double r_m) {
  std::vector<web::Point2> pts;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n + 0.3;
    pts.emplace_back(r_m * std::cos(a), r_m * std::sin(a));
  }
  return pts;
}

}  // namespace creaturelab::test
