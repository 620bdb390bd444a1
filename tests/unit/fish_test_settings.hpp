#pragma once
// The settings the fish's unit tests were written for: a 1 m body of the [reimpl] soft units
// (c = 38, 30, 28 N/m) at its 0.055 s step in linear water (mu = 100), driven at alpha = 0.7. The
// structs' in-class defaults are the fish kind's (the calibrated 2 m body); these tests set their own.
#include "fish/fish_model.hpp"
#include "fish/fish_solver.hpp"
#include "fish/motor.hpp"

namespace creaturelab::fish {

inline FishGeometry testBody() {
  FishGeometry g;
  g.body_length_m = 1.0;
  return g;
}

inline UnitParams testUnits() {
  UnitParams u;
  u.stiffness_cross_n_per_m = 38.0;
  u.stiffness_other_n_per_m = 30.0;
  u.stiffness_muscle_n_per_m = 28.0;
  return u;
}

inline SolverParams testSolver() {
  SolverParams p;
  p.dt_s = 0.055;
  p.water.mu = 100.0;
  p.water.law = WaterLaw::linear;
  return p;
}

inline MotorParams testMotor() {
  MotorParams m;
  m.swim = {0.7, 0.004, 0.7, 0.004};
  m.turn_amplitude = 0.7;
  m.turn_rate = 0.016;
  return m;
}

inline FishModel testFish() { return buildFish(testBody(), testUnits()); }

}  // namespace creaturelab::fish
