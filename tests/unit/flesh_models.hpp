#pragma once
// Small MJCF skeletons for the flesh tests (no gravity, no contacts), written to a scratch folder.
#include <string>

namespace creaturelab::testing {

// A sphere of radius r (m) welded to the world (no joint): a skeleton held still.
inline std::string heldSphereXml(double r) {
  return "<mujoco><option timestep=\"0.01\" gravity=\"0 0 0\"/><worldbody><body name=\"bone\">"
         "<geom type=\"sphere\" size=\"" + std::to_string(r) + "\" contype=\"0\" conaffinity=\"0\"/>"
         "</body></worldbody></mujoco>";
}

// A free sphere of radius r and mass m (its centre of mass at its frame's origin) plus a capsule
// hinged to it: a skeleton free to move, with one joint.
inline std::string freeCreatureXml(double r, double m) {
  return "<mujoco><option timestep=\"0.01\" gravity=\"0 0 0\"/><worldbody><body name=\"bone\">"
         "<freejoint/><geom type=\"sphere\" size=\"" + std::to_string(r) + "\" mass=\"" + std::to_string(m) +
         "\" contype=\"0\" conaffinity=\"0\"/>"
         "<body name=\"leg\" pos=\"" + std::to_string(r) + " 0 0\"><joint name=\"knee\" type=\"hinge\" axis=\"0 1 0\"/>"
         "<geom type=\"capsule\" fromto=\"0.02 0 0 0.3 0 0\" size=\"0.03\" mass=\"" + std::to_string(m / 4) +
         "\" contype=\"0\" conaffinity=\"0\"/></body></body></worldbody></mujoco>";
}

// A free sphere of radius r and mass m, its centre of mass at its frame's origin (so MuJoCo's
// Euler step changes its linear momentum by exactly h times the applied force).
inline std::string freeSphereXml(double r, double m) {
  return "<mujoco><option timestep=\"0.01\" gravity=\"0 0 0\"/><worldbody><body name=\"bone\">"
         "<freejoint/><geom type=\"sphere\" size=\"" + std::to_string(r) + "\" mass=\"" + std::to_string(m) +
         "\" contype=\"0\" conaffinity=\"0\"/></body></worldbody></mujoco>";
}

// A capsule 0.4 m long along +x, radius 0.04 m, mass 50 kg, on a hinge about z at the origin.
inline std::string spinnerXml() {
  return "<mujoco><option timestep=\"0.002\" gravity=\"0 0 0\"/><worldbody><body name=\"arm\">"
         "<joint name=\"spin\" type=\"hinge\" axis=\"0 0 1\"/>"
         "<geom type=\"capsule\" fromto=\"0 0 0 0.4 0 0\" size=\"0.04\" mass=\"50\" contype=\"0\" conaffinity=\"0\"/>"
         "</body></worldbody></mujoco>";
}

// A box of half-sizes 0.1 x 0.05 x 0.02 m on a slide joint along x.
inline std::string boxXml() {
  return "<mujoco><option gravity=\"0 0 0\"/><worldbody><body name=\"box\" pos=\"0 0 1\">"
         "<joint type=\"slide\" axis=\"1 0 0\"/>"
         "<geom type=\"box\" size=\"0.1 0.05 0.02\" mass=\"1\" contype=\"0\" conaffinity=\"0\"/>"
         "</body></worldbody></mujoco>";
}

}  // namespace creaturelab::testing
