#include "cli/creature_glb_command.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "render/creature_gltf.hpp"
#include "render/flesh_gltf.hpp"
#include "runner/store.hpp"

namespace creaturelab::cli {
namespace fs = std::filesystem;

namespace {

// The frames x points x dim array /lagrangian/<name>, checked against its expected shape.
std::vector<double> track(const io::Group& root, const std::string& name, hsize_t frames, hsize_t points, hsize_t dim) {
  const std::string path = "lagrangian/" + name;
  if (!root.has(path)) throw std::runtime_error("no /" + path + " in the point file");
  const std::vector<hsize_t> shape = io::datasetShape(root.openGroup("lagrangian"), name);
  if (shape != std::vector<hsize_t>{frames, points, dim})
    throw std::runtime_error("/" + path + " is not (" + std::to_string(frames) + ", " + std::to_string(points) + ", " +
                             std::to_string(dim) + ")");
  return io::readArrayDouble(root.openGroup("lagrangian"), name);
}

std::vector<std::uint8_t> creatureBytes(const io::Group& root, const std::string& name) {
  if (!root.has("topology/geom_type") || !root.has("lagrangian/geom_position_m"))
    throw std::runtime_error("the point file has no recorded geom poses (/topology/geom_type, "
                             "/lagrangian/geom_position_m: a control_fluid3d run records them)");
  const std::vector<std::int64_t> types = io::readVectorInt64(root.openGroup("topology"), "geom_type");
  const std::vector<double> times = io::readVectorDouble(root.openGroup("lagrangian"), "time_s");
  const hsize_t nf = times.size(), ng = types.size();
  const std::vector<double> size = track(root, "geom_size_m", nf, ng, 3);
  const std::vector<double> position = track(root, "geom_position_m", nf, ng, 3);
  const std::vector<double> rotation = track(root, "geom_rotation", nf, ng, 9);
  std::vector<render::CreatureGeom> geoms;
  for (hsize_t g = 0; g < ng; ++g) geoms.push_back({int(types[g]), {size[3 * g], size[3 * g + 1], size[3 * g + 2]}});
  render::CreatureAnimation animation(geoms);
  for (hsize_t f = 0; f < nf; ++f)
    animation.addFrame(times[f], {position.begin() + 3 * f * ng, position.begin() + 3 * (f + 1) * ng},
                       {rotation.begin() + 9 * f * ng, rotation.begin() + 9 * (f + 1) * ng});
  return animation.glb(name);
}

std::vector<std::uint8_t> fleshBytes(const io::Group& root, const std::string& name) {
  const std::vector<std::int64_t> flat = io::readVectorInt64(root.openGroup("topology"), "flesh_triangles");
  if (flat.size() % 3 != 0) throw std::runtime_error("/topology/flesh_triangles does not hold 3 indices per triangle");
  std::vector<std::array<std::int32_t, 3>> triangles;
  for (std::size_t t = 0; t < flat.size(); t += 3)
    triangles.push_back({std::int32_t(flat[t]), std::int32_t(flat[t + 1]), std::int32_t(flat[t + 2])});
  const std::vector<double> times = io::readVectorDouble(root.openGroup("lagrangian"), "time_s");
  const std::vector<hsize_t> shape = io::datasetShape(root.openGroup("lagrangian"), "flesh_position_m");
  if (shape.size() != 3 || shape[0] != times.size() || shape[2] != 3)
    throw std::runtime_error("/lagrangian/flesh_position_m is not (frames, vertices, 3)");
  const std::vector<double> xyz = io::readArrayDouble(root.openGroup("lagrangian"), "flesh_position_m");
  render::SkinAnimation skin(std::move(triangles));
  const std::size_t per = std::size_t(shape[1]) * 3;
  for (std::size_t f = 0; f < times.size(); ++f)
    skin.addFrame(times[f], {xyz.begin() + f * per, xyz.begin() + (f + 1) * per});
  return skin.glb(name);
}

}  // namespace

CLI::App* addCreatureGlbCommand(CLI::App& app, CreatureGlbArgs& args) {
  auto* c = app.add_subcommand("creature-glb", "a 3-D creature run's geoms (and flesh) animated as .glb, from its "
                                               "point file (control_fluid3d)");
  c->add_option("source", args.source, "a point file (.h5) or run folder")->required();
  c->add_option("--point", args.point, "point index when SOURCE is a run folder")->capture_default_str();
  c->add_option("-o,--out", args.out_dir, "output folder (default: beside the point file)");
  return c;
}

int creatureGlb(const CreatureGlbArgs& args) {
  if (args.point < 0) throw std::runtime_error("--point " + std::to_string(args.point) + " is negative");
  const fs::path file = fs::is_directory(args.source) ? fs::path(args.source) / runner::pointFileName(args.point)
                                                      : fs::path(args.source);
  if (!fs::is_regular_file(file)) throw std::runtime_error(file.string() + ": no such point file");
  std::vector<std::pair<std::string, std::vector<std::uint8_t>>> outputs;
  const std::string stem = file.stem().string();
  {
    const io::File h5 = io::File::openReadOnly(file);
    const io::Group root = h5.root();
    try {
      outputs.push_back({stem + "_creature.glb", creatureBytes(root, stem)});
      if (root.has("lagrangian/flesh_position_m") && root.has("topology/flesh_triangles"))
        outputs.push_back({stem + "_flesh.glb", fleshBytes(root, stem + " flesh")});
    } catch (const std::exception& e) {
      throw std::runtime_error(file.string() + ": " + e.what());
    }
  }
  const fs::path dir = args.out_dir.empty() ? file.parent_path() : fs::path(args.out_dir);
  try {
    if (!args.out_dir.empty()) fs::create_directories(dir);
    for (const auto& [name, bytes] : outputs) {
      io::writeFileAtomically(dir / name, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
      std::printf("wrote %s (%zu bytes)\n", (dir / name).string().c_str(), bytes.size());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 3;
  }
  return 0;
}

}  // namespace creaturelab::cli
