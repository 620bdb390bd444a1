#pragma once
// `creaturelab creature-glb`: a 3-D creature run's animation as .glb files from its point file alone
// (render/creature_gltf.hpp): the geoms' meshes moved by their recorded poses (/topology/geom_type,
// /lagrangian/geom_size_m, geom_position_m, geom_rotation, as control_fluid3d records them) into
// point_NNNNNN_creature.glb, and, when the run recorded its flesh (/lagrangian/flesh_position_m,
// /topology/flesh_triangles), the skin into point_NNNNNN_flesh.glb, beside the point file.
#include <string>

namespace CLI {
class App;
}

namespace creaturelab::cli {

struct CreatureGlbArgs {
  std::string source;  // a point file (.h5) or a run folder
  int point = 0;       // the point when source is a run folder
  std::string out_dir; // default: beside the point file
};

// Registers the subcommand on `app`, filling `args`; returns it.
CLI::App* addCreatureGlbCommand(CLI::App& app, CreatureGlbArgs& args);

// Writes the files and prints them; returns 0, or 3 when a write failed. Bad input (no such file,
// no recorded poses, a geom it cannot draw) is thrown as std::runtime_error (exit 2).
int creatureGlb(const CreatureGlbArgs& args);

}  // namespace creaturelab::cli
