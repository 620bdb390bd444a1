#pragma once
// What a controller run in the 3-D coupled fluid measures (M. Lentine et al., "Creature Control in a
// Fluid Environment", 2010 §7.1, the driven flyer): per frame the controller's record (frame_series.hpp),
// the controlled and PD-driven angles, the senses followed and the fluid's force on all bodies; at the
// end the mean upward force over whole flap cycles with its standard error. For renders (Figs. 11, 13)
// also every geom's pose per frame and, every few frames, the fluid's cell-centred fields on a plane or
// the whole box. No I/O: the kind copies them into its Result.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "control/fluid_controller.hpp"
#include "control/frame_series.hpp"
#include "control/run_measures.hpp"
#include "core/named_measure.hpp"
#include "fluid3d/vorticity3.hpp"

namespace creaturelab::control {

// Which of the fluid a run stores: nothing, the centre plane normal to y (the x-z plane through the
// chord's middle), or the whole box.
enum class StoredFields3 { none, plane, volume };

struct FluidRecording3 {
  StoredFields3 stored = StoredFields3::none;
  int field_every = 10;  // frames between stored fields (the first after frame 0)
};

// The model's geoms (MuJoCo's order) and their world poses after each frame.
struct GeomPoses3 {
  std::vector<std::int64_t> type;  // MuJoCo's geom type (2 sphere, 3 capsule, 4 ellipsoid, 5 cylinder, 6 box, 7 mesh)
  std::vector<std::int64_t> body;  // the geom's body index (0: world)
  std::vector<double> size_m;      // MuJoCo's geom_size, 3 per geom (half-sizes, radii, half-lengths)
  std::vector<double> time_s;      // one per frame
  std::vector<double> position_m;  // frames x geoms x 3, world
  std::vector<double> rotation;    // frames x geoms x 9, row-major, columns the geom's axes (MuJoCo's xmat)
  int geoms() const { return int(type.size()); }
};

// Cell-centred fields of the stored frames: (frames, nz, ny, nx) for the volume, (frames, nz, nx) for the
// plane (its rows along z); x fastest. u_m_per_s, v_m_per_s, w_m_per_s, pressure_pa,
// vorticity_magnitude_per_s, q_per_s2 (fluid3d/vorticity3.hpp), as the fluid3d kind names them.
struct FluidFrames3 {
  std::vector<double> time_s;
  std::array<int, 3> n{0, 0, 0};  // cells along x, y, z of the box
  int plane_layer = -1;           // the plane's cell layer along y; -1: the volume
  double dx_m = 0;
  std::vector<core::NamedSeries> fields;
};

class FluidRunRecorder3 {
 public:
  FluidRunRecorder3(const rigid::RigidModel& model, const ControllerParams& p, FluidRecording3 recording = {});
  // After each frame: its record and the controller's state.
  void record(const FrameRecord& fr, FluidController& controller);

  const SeriesSet& series() const { return series_; }
  const GeomPoses3& geoms() const { return geoms_; }
  const FluidFrames3& fluid() const { return fluid_; }
  // mean_up_force_n (+ _stderr) over the last `force_cycles` flaps of `frames_per_cycle` frames, the first
  // controlled joint's objective over the same flaps' maximising and minimising frames (+ _stderr);
  // `markers` and `forcing_iterations_most` as the kind reports them.
  std::vector<NamedValue> measure(int frames_per_cycle, int force_cycles, int markers,
                                  int forcing_iterations_most) const;

 private:
  void recordGeoms(double time_s, const rigid::RigidData& data);
  void recordFluid(double time_s, const FluidController& controller);

  std::vector<int> pd_qpos_;
  SeriesSet series_;
  FrameSeries common_;  // after series_, which holds its series
  std::vector<double> *body_fx_, *body_fy_, *body_fz_;
  std::vector<std::vector<double>*> angle_, target_, derivative_, sense_, pd_angle_;
  FluidRecording3 recording_;
  GeomPoses3 geoms_;
  FluidFrames3 fluid_;
  fluid3d::FlowObservables3 observables_;
};

}  // namespace creaturelab::control
