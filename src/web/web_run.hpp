#pragma once
// What a web run measures (A. Mehla, Modeling and Animation of Orb Webs, MSc thesis 2005, §5.3):
// per frame the hub's sag and its displacement from where the run started, the positions every k
// frames; at the end the web's counts, sags, strains and elongations. No I/O: the kind copies them
// into its Result.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/named_measure.hpp"
#include "springs/equilibrium.hpp"
#include "web/web_model.hpp"

namespace creaturelab::web {

// All particles' positions (m) at the recorded frames: frames x particles x 3.
struct PositionFrames {
  std::vector<double> time_s;
  std::vector<double> data;
  int points = 0;
};

class WebRunRecorder {
 public:
  // `hub_start_m`: the hub's position the displacement counts from; positions every
  // `frames_per_track` frames (frame 0 included).
  WebRunRecorder(const WebModel& model, const Eigen::Vector3d& hub_start_m, int frames_per_track);
  void record(int frame, double t_s, const springs::State<3>& s);

  const std::vector<double>& hubSag_m() const { return hub_sag_m_; }
  const PositionFrames& positions() const { return positions_; }
  // Root mean square of the hub's displacement from hub_start_m over the recorded frames; NaN if none.
  double hubRmsDisplacement_m() const;

 private:
  const WebModel& model_;
  Eigen::Vector3d hub_start_m_;
  int frames_per_track_;
  std::vector<double> hub_sag_m_;
  PositionFrames positions_;
  double sum_d2_ = 0;
  int frames_ = 0;
};

// How the run ended, for webMeasures.
struct WebRunEnd {
  const springs::State<3>& state;          // the last frame
  const springs::State<3>& statics;        // the static equilibrium
  const springs::EquilibriumResult& eq;    // its solve
  std::optional<double> settling_time_s;   // none: not settled (or no dynamics)
  double dt_used_s;                        // NaN without dynamics
  double hub_rms_displacement_m;
};

// The web's counts, silk and mass, the hub's sag at the end and in statics, their relative
// difference, the largest strain, the settling time, the strand families' elongations and the hub's
// rms displacement (the web kind's metrics). `net` is the network the run stepped.
std::vector<core::NamedValue> webMeasures(const WebModel& model, const springs::Network<3>& net, const WebRunEnd& end);

// Which particles each spring joins and its strand type (StrandType order), the attachment and hub
// particles: tables for figures to draw and colour the web.
std::map<std::string, std::vector<std::int64_t>> webTopology(const WebModel& model);

}  // namespace creaturelab::web
