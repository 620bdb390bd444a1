#pragma once
// Observables of a web state that the tests and the web kind share.
#include <initializer_list>

#include <Eigen/Core>

#include "web/web_model.hpp"

namespace creaturelab::web {

// Mean position of the hub particles, metres.
Eigen::Vector3d hubPositionM(const WebModel& model, const springs::State<3>& s);

// How far the hub has dropped from the laid web to s: y(laid) - y(s), metres (positive = down).
double hubSagM(const WebModel& model, const springs::State<3>& s);

// Mean strain (|l| - rest) / rest over the springs of one type at s; 0 if there are none.
double meanStrain(const WebModel& model, const springs::State<3>& s, StrandType type);

// Mean strain over the springs of several types at s, each type weighted by its spring count: how
// elongated a family of strands is (thesis Figs. 5.19-5.23 compare how "elongated" and "taut" each
// family looks); NaN if there are none.
double meanElongation(const WebModel& model, const springs::State<3>& s, std::initializer_list<StrandType> types);

// How much of the web the spiral spans, as laid: the annulus between the spiral's innermost and
// outermost particles (about the hub) over the disc of the inner frame's mean radius. The thesis
// describes its spiral variants by how much of the web they cover (§5.3.4, Figs. 5.24-5.27).
double spiralCoverage(const WebModel& model);

}  // namespace creaturelab::web
