#include "runner/render_run.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <toml++/toml.h>

#include "core/text.hpp"
#include "io/hdf5.hpp"
#include "io/xdmf.hpp"
#include "kinds/param_toml.hpp"
#include "kinds/render_params.hpp"
#include "render/jellyfish_renderer.hpp"
#include "render/mesh_export.hpp"
#include "render/pov_scene.hpp"
#include "runner/experiment.hpp"
#include "runner/store.hpp"

extern char** environ;

namespace creaturelab::runner {
namespace fs = std::filesystem;
using render::SliceFrame;
using render::TriangleMesh;

static_assert(sizeof(render::Vec3) == 3 * sizeof(double), "Vec3 rows are written to HDF5 as three doubles");

namespace {

// ---------------------------------------------------------------- the recorded swim

struct RecordedSwim {
  std::string point_file;
  int point_index = 0;
  std::string config_sha256;
  std::vector<double> time_s;        // per frame
  int markers = 0;
  std::vector<double> markers_xy;    // frames × markers × 2
  int muscles = 0;
  std::vector<double> activation;    // frames × muscles; empty when the run did not record it
  render::SliceTopology topology;
  double bell_thickness_m = 0.004, contraction_hz = 0;

  int frames() const { return int(time_s.size()); }
  SliceFrame frame(int k) const {
    SliceFrame f;
    f.time_s = time_s[k];
    f.markers_xy = std::span<const double>(markers_xy).subspan(std::size_t(k) * 2 * markers, 2 * std::size_t(markers));
    if (!activation.empty())
      f.muscle_activation = std::span<const double>(activation).subspan(std::size_t(k) * muscles, std::size_t(muscles));
    return f;
  }
};

std::string pointFilePath(const RenderRunOptions& o) {
  if (fs::is_directory(o.source)) {
    const std::string path = (fs::path(o.source) / pointFileName(o.point)).string();
    if (!fs::exists(path)) throw ExperimentError(o.source + ": the run folder has no " + pointFileName(o.point));
    return path;
  }
  if (!fs::exists(o.source)) throw ExperimentError(o.source + ": no such point file or run folder");
  return o.source;
}

RecordedSwim readSwim(const std::string& path) {
  RecordedSwim swim;
  swim.point_file = path;
  io::File file;
  try {
    file = io::File::openReadOnly(path);
  } catch (const std::exception& e) {
    throw ExperimentError(path + ": not a readable HDF5 point file (" + e.what() + ")");
  }
  const io::Group root = file.root();
  const std::string kind = io::hasAttr(root, "kind") ? io::getAttrString(root, "kind") : "";
  if (kind.empty()) throw ExperimentError(path + ": not a creaturelab point file (no 'kind' attribute)");
  if (kind != "jellyfish")
    throw ExperimentError(path + ": a run of kind '" + kind + "'; render needs a jellyfish run (kind 'jellyfish')");
  if (!root.isDataset("lagrangian/markers_m") || !root.isDataset("lagrangian/time_s"))
    throw ExperimentError(path + ": has no /lagrangian/markers_m and /lagrangian/time_s, the recorded bell to render");
  const auto shape = io::datasetShape(root, "lagrangian/markers_m");
  if (shape.size() != 3 || shape[2] != 2 || shape[0] == 0)
    throw ExperimentError(path + ": /lagrangian/markers_m must be (frames, markers, 2) with at least one frame");
  swim.markers = int(shape[1]);
  swim.markers_xy = io::readArrayDouble(root, "lagrangian/markers_m");
  swim.time_s = io::readVectorDouble(root, "lagrangian/time_s");
  if (swim.time_s.size() != shape[0])
    throw ExperimentError(path + ": /lagrangian/time_s has " + std::to_string(swim.time_s.size()) + " times for " +
                          std::to_string(shape[0]) + " frames of markers");
  for (const char* name : {"topology/bell_markers", "topology/springs"})
    if (!root.isDataset(name)) throw ExperimentError(path + ": has no /" + std::string(name));
  const auto bell = io::readVectorInt64(root, "topology/bell_markers");
  const auto springs = io::readVectorInt64(root, "topology/springs");
  const auto muscles =
      root.isDataset("topology/muscles") ? io::readVectorInt64(root, "topology/muscles") : std::vector<std::int64_t>{};
  swim.topology = render::sliceTopology(bell.empty() ? 0 : int(bell[0]), springs, muscles, swim.markers);
  swim.muscles = int(swim.topology.muscle_markers.size());
  // The muscle state the ridges follow; runs recorded before it was stored have none (no ridges).
  if (root.isDataset("lagrangian/muscle_activation")) {
    const auto a = io::datasetShape(root, "lagrangian/muscle_activation");
    if (a.size() != 3 || a[0] != shape[0] || int(a[1]) != swim.muscles || a[2] != 1)
      throw ExperimentError(path + ": /lagrangian/muscle_activation must be (frames, muscles, 1) like /topology/muscles");
    swim.activation = io::readArrayDouble(root, "lagrangian/muscle_activation");
  }
  if (std::string e = swim.topology.validate(swim.markers); !e.empty()) throw ExperimentError(path + ": " + e);
  if (io::hasAttr(root, "bell_thickness_m")) swim.bell_thickness_m = io::getAttrDouble(root, "bell_thickness_m");
  if (io::hasAttr(root, "contraction_hz")) swim.contraction_hz = io::getAttrDouble(root, "contraction_hz");
  if (io::hasAttr(root, "config_sha256")) swim.config_sha256 = io::getAttrString(root, "config_sha256");
  if (io::hasAttr(root, "point_index")) swim.point_index = int(io::getAttrInt64(root, "point_index"));
  return swim;
}

// ---------------------------------------------------------------- options

struct Settings {
  kinds::Params values;  // every render setting, resolved
  render::RenderParams params;
};

Settings resolveSettings(const std::vector<std::string>& overrides, double run_thickness_m) {
  Settings s;
  const auto& specs = kinds::renderParamSpecs();
  for (const auto& spec : specs) s.values[spec.name] = spec.default_value;
  std::vector<std::string> names;
  for (const auto& spec : specs) names.push_back(spec.name);
  for (const std::string& text : overrides) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
      throw ExperimentError("render setting '" + text + "': expected key=value, e.g. rings=48");
    std::string key = text.substr(0, eq);
    if (key.rfind("render.", 0) == 0) key = key.substr(7);
    const auto spec = std::find_if(specs.begin(), specs.end(), [&](const auto& p) { return p.name == key; });
    if (spec == specs.end())
      throw ExperimentError("render setting '" + key + "': unknown" + core::didYouMean(key, names) +
                            "; `creaturelab list render` shows every setting");
    kinds::Value value = std::string(text.substr(eq + 1));
    try {
      const toml::table t = toml::parse("v = " + text.substr(eq + 1));
      if (auto v = kinds::scalarValue(*t.get("v"))) value = *v;
    } catch (const toml::parse_error&) {
      // a bare word: structural_shape=sin
    }
    if (std::string problem = kinds::coerceValue(*spec, value); !problem.empty())
      throw ExperimentError("render setting '" + key + "': " + problem);
    s.values[key] = value;
  }
  s.params = kinds::renderParams(s.values, run_thickness_m);
  if (std::string e = s.params.validate(); !e.empty()) throw ExperimentError("render settings: " + e);
  return s;
}

std::vector<int> selectFrames(const std::string& text, int frames) {
  std::vector<int> out;
  if (text.empty()) {
    for (int k = 0; k < frames; ++k) out.push_back(k);
    return out;
  }
  const std::string range = "--frames " + text + ": the run has " + std::to_string(frames) + " frames (0.." +
                            std::to_string(frames - 1) + ")";
  long parts[3] = {0, frames, 1};
  bool given[3] = {false, false, false};
  int field = 0;
  std::string item;
  for (std::size_t k = 0; k <= text.size(); ++k) {
    if (k == text.size() || text[k] == ':') {
      if (field > 2) throw ExperimentError("--frames " + text + ": expected A:B or A:B:STEP");
      if (!item.empty()) {
        char* end = nullptr;
        parts[field] = std::strtol(item.c_str(), &end, 10);
        if (*end != '\0') throw ExperimentError("--frames " + text + ": '" + item + "' is not a whole number");
        given[field] = true;
      }
      item.clear();
      ++field;
    } else {
      item += text[k];
    }
  }
  if (field == 1) {  // a single frame index
    if (!given[0]) throw ExperimentError("--frames " + text + ": expected A:B or A:B:STEP");
    parts[1] = parts[0] + 1;
  }
  const long first = parts[0], end = parts[1], step = parts[2];
  if (step < 1) throw ExperimentError("--frames " + text + ": the step must be at least 1");
  if (first < 0 || end > frames || first >= end) throw ExperimentError(range);
  for (long k = first; k < end; k += step) out.push_back(int(k));
  return out;
}

std::string findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t start = 0; start <= dirs.size();) {
    const auto colon = dirs.find(':', start);
    const std::string dir = dirs.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/" + program;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  return "";
}

// ---------------------------------------------------------------- writing

// CPU time of this thread: the render's own cost, whatever else the machine runs.
double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  if (!out.flush()) throw std::runtime_error(path.string() + ": cannot write");
}

// Runs `argv` in `cwd` with stdout and stderr to `log`; the exit status (or 128 + signal).
int runProgram(const std::vector<std::string>& argv, const fs::path& cwd, const fs::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0].c_str(), &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return 127;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// ---------------------------------------------------------------- figures (Figs. 7, 9, 10)

struct Figure {
  std::string name;  // file stem
  int width_px, height_px;
};

double apertureWidth(const RecordedSwim& swim, int k) {
  const SliceFrame f = swim.frame(k);
  const int right = 2 * (swim.topology.bell_markers - 1);
  return std::hypot(f.markers_xy[right] - f.markers_xy[0], f.markers_xy[right + 1] - f.markers_xy[1]);
}

// The frames of the last whole contraction-expansion cycle in the run (from a phase-0 start; a
// cycle counts as whole when the frames reach within one frame of its end), `count` of them evenly
// spaced; the recorded frames nearest those times.
std::vector<int> cycleFrames(const RecordedSwim& swim, int count) {
  const double t0 = swim.time_s.front(), t1 = swim.time_s.back();
  const double frame_s = swim.frames() > 1 ? swim.time_s[1] - t0 : 0.0;
  const double period = swim.contraction_hz > 0 ? 1.0 / swim.contraction_hz : t1 - t0 + frame_s;
  double start = std::floor((t1 - t0 + frame_s) / period + 1e-9) * period + t0 - period;
  if (start < t0) start = t0;
  std::vector<int> out;
  for (int m = 0; m < count; ++m) {
    const double t = start + period * m / count;
    int best = 0;
    for (int k = 1; k < swim.frames(); ++k)
      if (std::abs(swim.time_s[k] - t) < std::abs(swim.time_s[best] - t)) best = k;
    if (out.empty() || out.back() != best) out.push_back(best);
  }
  return out;
}

class FigureMaker {
 public:
  FigureMaker(const RecordedSwim& swim, const render::RenderParams& params, fs::path dir, double scale)
      : swim_(swim), params_(params), dir_(fs::absolute(dir)), scale_(scale) {}

  // The frames the figures draw (all checked before anything is written).
  std::vector<int> frames() const {
    std::vector<int> out = cycleFrames(swim_, 8);
    out.push_back(0);
    out.push_back(contracted());
    return out;
  }

  void make(std::vector<std::string>& files) {
    fs::create_directories(dir_);
    fig07(files);
    fig09(files);
    fig10(files);
  }

 private:
  int contracted() const {
    int best = 0;
    for (int k = 1; k < swim_.frames(); ++k)
      if (apertureWidth(swim_, k) < apertureWidth(swim_, best)) best = k;
    return best;
  }

  // Renders frame k with `params`, writes its mesh include NAME.inc, returns the placement.
  render::PovPlacement place(const render::RenderParams& params, int k, const std::string& name,
                             const std::string& caption, std::vector<std::string>& files) {
    render::JellyfishRenderer renderer(params, swim_.topology, swim_.markers);
    const TriangleMesh& mesh = renderer.render(swim_.frame(k));
    writeFile(dir_ / (name + ".inc"), render::povMeshInclude(mesh, name));
    files.push_back("figures/" + name + ".inc");
    render::PovPlacement p{name + ".inc", name, caption, render::boundsOf(mesh), {}};
    p.offset = -1.0 * render::Vec3{p.bounds.centre().x, p.bounds.centre().y, p.bounds.centre().z};
    return p;
  }

  void draw(const Figure& figure, const std::string& scene, std::vector<std::string>& files) {
    writeFile(dir_ / (figure.name + ".pov"), scene);
    const int w = std::max(64, int(std::lround(figure.width_px * scale_)));
    const int h = std::max(64, int(std::lround(figure.height_px * scale_)));
    const std::vector<std::string> argv = {
        findOnPath("povray"), "+I" + figure.name + ".pov", "+O" + figure.name + ".png", "+W" + std::to_string(w),
        "+H" + std::to_string(h), "-D", "+A0.2", "+FN", "-GA", "+L/usr/share/povray-3.7/include"};
    const fs::path log = dir_ / (figure.name + ".log");
    const int status = runProgram(argv, dir_, log);
    if (status != 0 || !fs::exists(dir_ / (figure.name + ".png"))) {
      // The folder is removed with the failed render: the message carries the end of povray's output.
      std::ifstream in(log);
      std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      if (text.size() > 1500) text = "..." + text.substr(text.size() - 1500);
      throw std::runtime_error("povray failed on " + figure.name + ".pov (exit " + std::to_string(status) + "): " + text);
    }
    fs::remove(dir_ / (figure.name + ".log"));
    files.push_back("figures/" + figure.name + ".pov");
    files.push_back("figures/" + figure.name + ".png");
  }

  static std::string timeCaption(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "t = %.2f s", t);
    return buf;
  }

  // Fig. 7: the contracted frame's slice with example pairs and their discs.
  void fig07(std::vector<std::string>& files) {
    render::JellyfishRenderer renderer(params_, swim_.topology, swim_.markers);
    renderer.render(swim_.frame(contracted()));
    const render::Slice2& slice = renderer.slice();
    std::vector<int> rings;
    for (double f : {0.0, 0.2, 0.4, 0.6, 0.8}) rings.push_back(int(std::lround(f * (params_.rings - 2))));
    const render::PovView view{1200, 900, 20, 28, 0.06};
    draw({"fig07_disc_extrapolation", view.width_px, view.height_px},
         render::povSliceDiscsScene(slice, rings, view,
                                    "Rudolf & Mould 2009 Fig. 7: point pairs of the 2-D slice extrapolated to 3-D discs"),
         files);
  }

  // Fig. 9: naive extrapolation expanded and contracted, each variation alone, all combined.
  void fig09(std::vector<std::string>& files) {
    render::RenderParams plain = params_;
    plain.tentacles = 0;  // the figure is about the umbrella
    plain.structural = plain.ridges = plain.noise = false;
    const auto only = [&](bool structural, bool ridges, bool noise) {
      render::RenderParams p = plain;
      p.structural = structural;
      p.ridges = ridges;
      p.noise = noise;
      return p;
    };
    const int expanded = 0, closed = contracted();
    std::vector<render::PovPlacement> items = {
        place(plain, expanded, "fig09_naive_expanded", "naive, expanded", files),
        place(plain, closed, "fig09_naive_contracted", "naive, contracted", files),
        place(only(true, false, false), expanded, "fig09_structural", "structural", files),
        place(only(false, true, false), closed, "fig09_ridges", "compression ridges", files),
        place(only(false, false, true), expanded, "fig09_noise", "noise (Eq. 2)", files),
        place(only(true, true, true), closed, "fig09_combined", "combined", files),
    };
    double w = 0, h = 0;
    for (const auto& it : items) {
      w = std::max(w, it.bounds.hi.x - it.bounds.lo.x);
      h = std::max(h, it.bounds.hi.y - it.bounds.lo.y);
    }
    for (std::size_t k = 0; k < items.size(); ++k)
      items[k].offset = items[k].offset + render::Vec3{1.25 * w * double(k % 3), -1.6 * h * double(k / 3), 0};
    const render::PovView view{1500, 1000, 20, 0, 0.05};
    draw({"fig09_variation", view.width_px, view.height_px},
         render::povGalleryScene(items, view, "Rudolf & Mould 2009 Fig. 9: naive extrapolation and variation"), files);
  }

  // Fig. 10: one contraction-expansion cycle, Lambertian shading; each frame at its height
  // relative to the first (the bell swims up).
  void fig10(std::vector<std::string>& files) {
    const std::vector<int> cycle = cycleFrames(swim_, 8);
    std::vector<render::PovPlacement> items;
    for (std::size_t m = 0; m < cycle.size(); ++m)
      items.push_back(place(params_, cycle[m], "fig10_frame" + std::to_string(m), timeCaption(swim_.time_s[cycle[m]]),
                            files));
    double w = 0;
    for (const auto& it : items) w = std::max(w, it.bounds.hi.x - it.bounds.lo.x);
    const double y0 = items.front().bounds.centre().y;
    for (std::size_t m = 0; m < items.size(); ++m)
      items[m].offset = items[m].offset + render::Vec3{1.15 * w * double(m), items[m].bounds.centre().y - y0, 0};
    const render::PovView view{2000, 650, 12, 0, 0.04};
    draw({"fig10_contraction_cycle", view.width_px, view.height_px},
         render::povGalleryScene(items, view, "Rudolf & Mould 2009 Fig. 10: a contraction-expansion cycle"), files);
  }

  const RecordedSwim& swim_;
  render::RenderParams params_;
  fs::path dir_;
  double scale_;
};

void writeRenderAttributes(const io::Group& group, const Settings& s) {
  for (const auto& spec : kinds::renderParamSpecs()) {
    kinds::Value v = s.values.at(spec.name);
    if (spec.name == "thickness_m") v = s.params.thickness.apex_m;  // "auto" resolved
    io::setAttr(group, spec.name, v);
    io::setAttr(group, spec.name + ".unit", spec.unit);
  }
}

}  // namespace

RenderReport renderRun(const RenderRunOptions& o) {
  // --- everything that can be refused, before anything is written
  const std::string path = pointFilePath(o);
  const RecordedSwim swim = readSwim(path);
  const Settings settings = resolveSettings(o.overrides, swim.bell_thickness_m);
  const std::vector<int> frames = selectFrames(o.frames, swim.frames());
  if (!(o.figure_scale > 0 && o.figure_scale <= 10)) throw ExperimentError("--figure-scale must be in (0, 10]");
  if (o.figures && findOnPath("povray").empty())
    throw ExperimentError("--figures needs POV-Ray (the Debian package povray) on the PATH");
  std::unique_ptr<render::JellyfishRenderer> renderer;
  try {
    renderer = std::make_unique<render::JellyfishRenderer>(settings.params, swim.topology, swim.markers);
  } catch (const std::invalid_argument& e) {
    throw ExperimentError(path + ": " + e.what());
  }
  const fs::path out = o.out_dir.empty()
                           ? fs::path(path).parent_path() / ("render_point_" + [&] {
                               char buf[16];
                               std::snprintf(buf, sizeof buf, "%06d", swim.point_index);
                               return std::string(buf);
                             }())
                           : fs::path(o.out_dir);
  fs::path tmp = out;
  tmp += ".tmp";
  FigureMaker figures(swim, settings.params, tmp / "figures", o.figure_scale);
  std::vector<int> checked = frames;
  if (o.figures)
    for (int k : figures.frames()) checked.push_back(k);
  for (int k : checked)
    if (std::string problem = renderer->check(swim.frame(k)); !problem.empty())
      throw ExperimentError(path + ": frame " + std::to_string(k) + ", " + problem);
  if (fs::exists(out) && !o.force)
    throw ExperimentError(out.string() + " already exists: pass --force to replace it, or -o DIR");
  if (fs::exists(out) && !fs::is_directory(out)) throw ExperimentError(out.string() + " exists and is not a folder");

  // --- the render, into OUT.tmp
  RenderReport report;
  report.out_dir = out.string();
  report.point_file = path;
  report.frames = int(frames.size());
  const render::MeshLayout& layout = renderer->layout();
  report.vertices = layout.vertices();
  report.triangles = layout.triangles();
  std::error_code ec;
  fs::remove_all(tmp, ec);  // a stale one from an interrupted render
  try {
    fs::create_directories(tmp);
    render::GltfAnimation animation;
    double render_s = 0;
    {
      io::File file = io::File::create(tmp / "render.h5");
      {
        const io::Group root = file.root();
        io::setAttr(root, "kind", "jellyfish_render");
        io::setAttr(root, "title", "3-D jellyfish from a recorded swim (Rudolf & Mould 2009 §3.4-3.5)");
        io::setAttr(root, "source_point_file", path);
        io::setAttr(root, "source_config_sha256", swim.config_sha256);
        for (const auto& [k, v] : collectProvenance()) io::setAttr(root, k, v);
        const io::Group group = root.requireGroup("render");
        writeRenderAttributes(group, settings);
        std::vector<double> times;
        std::vector<std::int64_t> indices;
        for (int k : frames) {
          times.push_back(swim.time_s[k]);
          indices.push_back(k);
        }
        io::setAttr(io::writeVector(group, "time_s", times), "unit", "s");
        io::writeVector(group, "frame_index", indices);
        const TriangleMesh& first = renderer->mesh();
        std::vector<std::int64_t> triangles, parts;
        for (const auto& t : first.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
        for (auto part : first.parts) parts.push_back(std::int64_t(part));
        const hsize_t nt = frames.size(), nv = hsize_t(layout.vertices());
        io::writeArray(group, "triangles", triangles.data(), {first.triangles.size(), 3});
        io::setAttr(io::writeVector(group, "part", parts), "meaning", "0 exumbrella, 1 subumbrella, 2 tentacle");
        const io::Dataset positions = io::createArray(group, "positions_m", {nt, nv, 3}, std::vector<hsize_t>{1, nv, 3});
        io::setAttr(positions, "unit", "m");
        const io::Dataset normals = io::createArray(group, "normals", {nt, nv, 3}, std::vector<hsize_t>{1, nv, 3});
        io::setAttr(normals, "unit", "");
        if (o.obj) fs::create_directories(tmp / "obj");
        for (std::size_t f = 0; f < frames.size(); ++f) {
          const int k = frames[f];
          const double t0 = threadCpuSeconds();
          const TriangleMesh& mesh = renderer->render(swim.frame(k));
          render_s += threadCpuSeconds() - t0;
          io::writeSlab(positions, f, 1, reinterpret_cast<const double*>(mesh.positions.data()));
          io::writeSlab(normals, f, 1, reinterpret_cast<const double*>(mesh.normals.data()));
          if (o.glb) animation.addFrame(swim.time_s[k], mesh);
          if (o.obj) {
            char name[32];
            std::snprintf(name, sizeof name, "frame_%06d.obj", k);
            char comment[160];
            std::snprintf(comment, sizeof comment, "creaturelab render of %s, frame %d, t = %.6f s", path.c_str(), k,
                          swim.time_s[k]);
            writeFile(tmp / "obj" / name, render::objText(mesh, comment));
            report.files.push_back(std::string("obj/") + name);
          }
        }
        // Per-frame views of the moving arrays for render.xdmf (io/xdmf.hpp).
        io::writeFrameViews(group, "positions_m");
        io::writeFrameViews(group, "normals");
      }
      file.close();
    }
    report.files.push_back("render.h5");
    report.render_ms_per_frame = 1e3 * render_s / double(frames.size());
    io::XdmfTriangleMesh x;
    x.h5_file = "render.h5";
    x.group = "/render";
    for (int k : frames) x.time_s.push_back(swim.time_s[k]);
    x.vertices = layout.vertices();
    x.triangles = layout.triangles();
    x.vectors = {"normals"};
    x.fixed_scalars = {"part"};
    writeFile(tmp / "render.xdmf", io::xdmfMeshText(x));
    report.files.push_back("render.xdmf");
    if (o.glb) {
      const auto bytes = animation.glb("jellyfish");
      writeFile(tmp / "jellyfish.glb", std::string(bytes.begin(), bytes.end()));
      report.files.push_back("jellyfish.glb");
    }
    if (o.figures) figures.make(report.files);
    if (fs::exists(out)) fs::remove_all(out);
    fs::rename(tmp, out);
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
  return report;
}

}  // namespace creaturelab::runner
