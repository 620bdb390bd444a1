#pragma once
// Small MJCF creatures for the control tests, written to a scratch folder.
#include <fstream>
#include <string>

#include "scratch_dir_test.hpp"

namespace creaturelab::testing {

// The block of experiments/control/models/block.xml: hinge "hinge" about y at the origin, a
// 1 x 1 x thickness box of mass 24 kg whose centre is 0.5 m along +x at angle 0.
inline std::string blockXml(double thickness_m, double gravity) {
  return "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.016666666666666666\" gravity=\"0 0 " +
         std::to_string(-gravity) + "\"/><default><geom contype=\"0\" conaffinity=\"0\"/></default><worldbody>"
         "<body name=\"block\"><joint name=\"hinge\" type=\"hinge\" axis=\"0 1 0\"/>"
         "<geom type=\"box\" size=\"0.5 0.5 " + std::to_string(thickness_m / 2) + "\" pos=\"0.5 0 0\" mass=\"24\"/>"
         "</body></worldbody></mujoco>";
}

// A planar chain of `links` capsules 0.4 m long, hinges j0, j1, ... about y (damped: MuJoCo's Euler
// step takes the damping implicitly, which the servo's Jacobian must include), hanging along +x.
inline std::string chainXml(int links) {
  std::string body;
  for (int k = links - 1; k >= 0; --k) {
    const std::string pos = k == 0 ? "0 0 0" : "0.4 0 0";
    body = "<body name=\"b" + std::to_string(k) + "\" pos=\"" + pos + "\"><joint name=\"j" + std::to_string(k) +
           "\" type=\"hinge\" axis=\"0 1 0\" damping=\"0.5\"/><geom type=\"capsule\" fromto=\"0 0 0 0.4 0 0\" size=\"0.04\" mass=\"2\"/>" +
           body + "</body>";
  }
  return "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.01\"/><default><geom contype=\"0\" "
         "conaffinity=\"0\"/></default><worldbody>" + body + "</worldbody></mujoco>";
}

// A free-floating creature (no gravity, no contacts): a torso box on a free joint, an arm on a
// hinge about x, a leg on a hinge about z, a head on a ball joint, and a sliding "tail" block on a
// slide joint along x carrying a hinged fin (hinge "fin" about y). Masses 10 / 2 / 3 / 1.5 / 4 / 1 kg.
inline std::string freeCreatureXml() {
  return "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.01\" gravity=\"0 0 0\"/><default><geom "
         "contype=\"0\" conaffinity=\"0\"/></default><worldbody>"
         "<body name=\"torso\" pos=\"0 0 1\"><freejoint name=\"root\"/>"
         "<geom type=\"box\" size=\"0.3 0.2 0.1\" mass=\"10\"/>"
         "<body name=\"arm\" pos=\"0 0.2 0\"><joint name=\"shoulder\" type=\"hinge\" axis=\"1 0 0\"/>"
         "<geom type=\"capsule\" fromto=\"0 0 0 0 0.4 0\" size=\"0.04\" mass=\"2\"/></body>"
         "<body name=\"leg\" pos=\"0.3 0 0\"><joint name=\"hip\" type=\"hinge\" axis=\"0 0 1\"/>"
         "<geom type=\"capsule\" fromto=\"0 0 0 0.3 0.1 -0.2\" size=\"0.05\" mass=\"3\"/></body>"
         "<body name=\"head\" pos=\"0 0 0.1\"><joint name=\"neck\" type=\"ball\"/>"
         "<geom type=\"box\" size=\"0.1 0.05 0.08\" pos=\"0.02 0 0.1\" mass=\"1.5\"/></body>"
         "<body name=\"tail\" pos=\"-0.3 0 0\"><joint name=\"slide\" type=\"slide\" axis=\"1 0 0\"/>"
         "<geom type=\"box\" size=\"0.1 0.1 0.1\" pos=\"-0.1 0 0\" mass=\"4\"/>"
         "<body name=\"finbody\" pos=\"-0.2 0 0\"><joint name=\"fin\" type=\"hinge\" axis=\"0 1 0\"/>"
         "<geom type=\"box\" size=\"0.2 0.1 0.01\" pos=\"-0.2 0 0\" mass=\"1\"/></body></body>"
         "</body></worldbody></mujoco>";
}

// The block of blockXml on a ball joint "ball" at the origin (centre 0.5 m along +x at rest):
// 24 kg, 1 x 1 x 0.1 m.
inline std::string ballBlockXml(double gravity) {
  return "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.016666666666666666\" gravity=\"0 0 " +
         std::to_string(-gravity) + "\"/><default><geom contype=\"0\" conaffinity=\"0\"/></default><worldbody>"
         "<body name=\"block\"><joint name=\"ball\" type=\"ball\"/>"
         "<geom type=\"box\" size=\"0.5 0.5 0.05\" pos=\"0.5 0 0\" mass=\"24\"/>"
         "</body></worldbody></mujoco>";
}

// A hinge j0 about y carrying a capsule, then a ball joint "wrist" carrying a second capsule
// (damped, 2 kg each, 0.4 m), hanging along +x.
inline std::string wristXml() {
  return "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.01\"/><default><geom contype=\"0\" "
         "conaffinity=\"0\"/></default><worldbody><body name=\"b0\"><joint name=\"j0\" type=\"hinge\" "
         "axis=\"0 1 0\" damping=\"0.5\"/><geom type=\"capsule\" fromto=\"0 0 0 0.4 0 0\" size=\"0.04\" mass=\"2\"/>"
         "<body name=\"hand\" pos=\"0.4 0 0\"><joint name=\"wrist\" type=\"ball\" damping=\"0.2\"/>"
         "<geom type=\"capsule\" fromto=\"0 0 0 0.4 0.05 0\" size=\"0.04\" mass=\"2\"/></body></body>"
         "</worldbody></mujoco>";
}

inline std::string writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace creaturelab::testing
