#pragma once
// Observables of a web state that the tests and the web kind share.
#include <Eigen/Core>

#include "web/web_model.hpp"

namespace creaturelab::web {

// Mean position of the hub particles, metres.
Eigen::Vector3d hubPositionM(const WebModel& model, const springs::State<3>& s);

// How far the hub has dropped from the laid web to s: y(laid) - y(s), metres (positive = down).
double hubSagM(const WebModel& model, const springs::State<3>& s);

// Mean strain (|l| - rest) / rest over the springs of one type at s; 0 if there are none.
double meanStrain(const WebModel& model, const springs::State<3>& s, StrandType type);

}  // namespace creaturelab::web
