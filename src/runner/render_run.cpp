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
#include <memory>
#include <optional>
#include <toml++/toml.h>

#include "core/text.hpp"
#include "io/hdf5.hpp"
#include "io/xdmf.hpp"
#include "kinds/kind.hpp"
#include "kinds/param_toml.hpp"
#include "kinds/render_hook.hpp"
#include "render/mesh_export.hpp"
#include "runner/experiment.hpp"
#include "runner/store.hpp"

extern char** environ;

namespace creaturelab::runner {
namespace fs = std::filesystem;
using render::TriangleMesh;

static_assert(sizeof(render::Vec3) == 3 * sizeof(double), "Vec3 rows are written to HDF5 as three doubles");

namespace {

// ---------------------------------------------------------------- the recorded run

// A point file as a render hook reads it (kinds/render_hook.hpp).
class PointFileRun : public kinds::RecordedRun {
 public:
  PointFileRun(const io::Group& root, const std::string& path) : root_(root), path_(path) {}
  bool has(const std::string& dataset) const override { return root_.isDataset(dataset); }
  std::vector<std::size_t> shape(const std::string& dataset) const override {
    const auto dims = io::datasetShape(root_, need(dataset));
    return {dims.begin(), dims.end()};
  }
  std::vector<double> reals(const std::string& dataset) const override {
    return io::readArrayDouble(root_, need(dataset));
  }
  std::vector<std::int64_t> integers(const std::string& dataset) const override {
    return io::readVectorInt64(root_, need(dataset));
  }
  std::optional<double> attribute(const std::string& name) const override {
    if (!io::hasAttr(root_, name)) return std::nullopt;
    return io::getAttrDouble(root_, name);
  }

 private:
  const std::string& need(const std::string& dataset) const {
    if (!root_.isDataset(dataset)) throw ExperimentError(path_ + ": has no /" + dataset);
    return dataset;
  }
  const io::Group& root_;
  const std::string& path_;
};

// What the render needs of the point file: the kind's hook made ready to draw, and the run's identity.
struct Recording {
  kinds::Registry registry;  // owns the kind whose hook this is
  const kinds::RenderHook* hook = nullptr;
  std::unique_ptr<kinds::RunRender> run;
  int point_index = 0;
  std::string config_sha256;
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

// ---------------------------------------------------------------- options

// Every render setting of the hook, resolved: its default unless an override (key=value) sets it.
kinds::Params resolveSettings(const std::vector<kinds::ParamSpec>& specs, const std::vector<std::string>& overrides) {
  kinds::Params values;
  for (const auto& spec : specs) values[spec.name] = spec.default_value;
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
    values[key] = value;
  }
  return values;
}

// Opens the point file, finds its kind's render hook and makes the run ready to draw.
Recording openRecording(const std::string& path, const std::vector<std::string>& overrides) {
  io::File file;
  try {
    file = io::File::openReadOnly(path);
  } catch (const std::exception& e) {
    throw ExperimentError(path + ": not a readable HDF5 point file (" + e.what() + ")");
  }
  const io::Group root = file.root();
  const std::string kind = io::hasAttr(root, "kind") ? io::getAttrString(root, "kind") : "";
  if (kind.empty()) throw ExperimentError(path + ": not a creaturelab point file (no 'kind' attribute)");
  Recording r;
  r.registry = kinds::defaultRegistry();
  const kinds::Registry& registry = r.registry;
  const kinds::Kind* k = registry.find(kind);
  r.hook = k ? k->renderHook() : nullptr;
  if (!r.hook) {
    std::string rendered;
    for (const auto& other : registry.all())
      if (other->renderHook()) rendered += std::string(rendered.empty() ? "" : ", ") + "'" + other->name() + "'";
    throw ExperimentError(path + ": a run of kind '" + kind + "', whose runs do not render; render takes a run of kind " +
                          rendered);
  }
  const kinds::Params settings = resolveSettings(r.hook->settings(), overrides);
  const PointFileRun run(root, path);
  try {
    r.run = r.hook->open(run, settings);
  } catch (const std::invalid_argument& e) {
    throw ExperimentError(path + ": " + e.what());
  }
  if (io::hasAttr(root, "config_sha256")) r.config_sha256 = io::getAttrString(root, "config_sha256");
  if (io::hasAttr(root, "point_index")) r.point_index = int(io::getAttrInt64(root, "point_index"));
  return r;
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

// ---------------------------------------------------------------- figures

// Writes the figure's include files and scene into `dir` and runs povray headless on it (pixel
// sizes times `scale`); adds the files written to `files` (relative to the render's folder).
void drawFigure(const render::PovFigure& figure, const fs::path& dir, double scale, std::vector<std::string>& files) {
  for (const auto& [name, text] : figure.includes) {
    writeFile(dir / name, text);
    files.push_back("figures/" + name);
  }
  writeFile(dir / (figure.name + ".pov"), figure.scene);
  const int w = std::max(64, int(std::lround(figure.width_px * scale)));
  const int h = std::max(64, int(std::lround(figure.height_px * scale)));
  const std::vector<std::string> argv = {
      findOnPath("povray"), "+I" + figure.name + ".pov", "+O" + figure.name + ".png", "+W" + std::to_string(w),
      "+H" + std::to_string(h), "-D", "+A0.2", "+FN", "-GA", "+L/usr/share/povray-3.7/include"};
  const fs::path log = dir / (figure.name + ".log");
  const int status = runProgram(argv, dir, log);
  if (status != 0 || !fs::exists(dir / (figure.name + ".png"))) {
    // The folder is removed with the failed render: the message carries the end of povray's output.
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.size() > 1500) text = "..." + text.substr(text.size() - 1500);
    throw std::runtime_error("povray failed on " + figure.name + ".pov (exit " + std::to_string(status) + "): " + text);
  }
  fs::remove(dir / (figure.name + ".log"));
  files.push_back("figures/" + figure.name + ".pov");
  files.push_back("figures/" + figure.name + ".png");
}

void writeRenderAttributes(const io::Group& group, const Recording& r) {
  for (const auto& spec : r.hook->settings()) {
    io::setAttr(group, spec.name, r.run->settings().at(spec.name));
    io::setAttr(group, spec.name + ".unit", spec.unit);
  }
}

}  // namespace

RenderReport renderRun(const RenderRunOptions& o) {
  // --- everything that can be refused, before anything is written
  const std::string path = pointFilePath(o);
  const Recording recording = openRecording(path, o.overrides);
  kinds::RunRender& run = *recording.run;
  const std::vector<int> frames = selectFrames(o.frames, run.frames());
  if (!(o.figure_scale > 0 && o.figure_scale <= 10)) throw ExperimentError("--figure-scale must be in (0, 10]");
  if (o.figures && findOnPath("povray").empty())
    throw ExperimentError("--figures needs POV-Ray (the Debian package povray) on the PATH");
  const fs::path out = o.out_dir.empty()
                           ? fs::path(path).parent_path() / ("render_point_" + [&] {
                               char buf[16];
                               std::snprintf(buf, sizeof buf, "%06d", recording.point_index);
                               return std::string(buf);
                             }())
                           : fs::path(o.out_dir);
  fs::path tmp = out;
  tmp += ".tmp";
  std::vector<int> checked = frames;
  if (o.figures)
    for (int k : run.figureFrames()) checked.push_back(k);
  for (int k : checked)
    if (std::string problem = run.check(k); !problem.empty())
      throw ExperimentError(path + ": frame " + std::to_string(k) + ", " + problem);
  if (fs::exists(out) && !o.force)
    throw ExperimentError(out.string() + " already exists: pass --force to replace it, or -o DIR");
  if (fs::exists(out) && !fs::is_directory(out)) throw ExperimentError(out.string() + " exists and is not a folder");

  // --- the render, into OUT.tmp
  RenderReport report;
  report.out_dir = out.string();
  report.point_file = path;
  report.frames = int(frames.size());
  const TriangleMesh& layout = run.layout();
  report.vertices = int(layout.positions.size());
  report.triangles = int(layout.triangles.size());
  std::error_code ec;
  fs::remove_all(tmp, ec);  // a stale one from an interrupted render
  try {
    fs::create_directories(tmp);
    render::GltfAnimation animation(recording.hook->look());
    double render_s = 0;
    {
      io::File file = io::File::create(tmp / "render.h5");
      {
        const io::Group root = file.root();
        io::setAttr(root, "kind", recording.hook->name());
        io::setAttr(root, "title", recording.hook->title());
        io::setAttr(root, "source_point_file", path);
        io::setAttr(root, "source_config_sha256", recording.config_sha256);
        for (const auto& [k, v] : collectProvenance()) io::setAttr(root, k, v);
        const io::Group group = root.requireGroup("render");
        writeRenderAttributes(group, recording);
        std::vector<double> times;
        std::vector<std::int64_t> indices;
        for (int k : frames) {
          times.push_back(run.timeS(k));
          indices.push_back(k);
        }
        io::setAttr(io::writeVector(group, "time_s", times), "unit", "s");
        io::writeVector(group, "frame_index", indices);
        std::vector<std::int64_t> triangles, parts;
        for (const auto& t : layout.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
        for (auto part : layout.parts) parts.push_back(std::int64_t(part));
        const hsize_t nt = frames.size(), nv = hsize_t(report.vertices);
        io::writeArray(group, "triangles", triangles.data(), {layout.triangles.size(), 3});
        io::setAttr(io::writeVector(group, "part", parts), "meaning", recording.hook->partMeaning());
        const io::Dataset positions = io::createArray(group, "positions_m", {nt, nv, 3}, std::vector<hsize_t>{1, nv, 3});
        io::setAttr(positions, "unit", "m");
        const io::Dataset normals = io::createArray(group, "normals", {nt, nv, 3}, std::vector<hsize_t>{1, nv, 3});
        io::setAttr(normals, "unit", "");
        if (o.obj) fs::create_directories(tmp / "obj");
        for (std::size_t f = 0; f < frames.size(); ++f) {
          const int k = frames[f];
          const double t0 = threadCpuSeconds();
          const TriangleMesh& mesh = run.render(k);
          render_s += threadCpuSeconds() - t0;
          io::writeSlab(positions, f, 1, reinterpret_cast<const double*>(mesh.positions.data()));
          io::writeSlab(normals, f, 1, reinterpret_cast<const double*>(mesh.normals.data()));
          if (o.glb) animation.addFrame(run.timeS(k), mesh);
          if (o.obj) {
            char name[32];
            std::snprintf(name, sizeof name, "frame_%06d.obj", k);
            char comment[160];
            std::snprintf(comment, sizeof comment, "creaturelab render of %s, frame %d, t = %.6f s", path.c_str(), k,
                          run.timeS(k));
            writeFile(tmp / "obj" / name, render::objText(mesh, recording.hook->meshName(), comment));
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
    for (int k : frames) x.time_s.push_back(run.timeS(k));
    x.vertices = report.vertices;
    x.triangles = report.triangles;
    x.vectors = {"normals"};
    x.fixed_scalars = {"part"};
    writeFile(tmp / "render.xdmf", io::xdmfMeshText(x));
    report.files.push_back("render.xdmf");
    if (o.glb) {
      const std::string name = recording.hook->meshName();
      const auto bytes = animation.glb(name);
      writeFile(tmp / (name + ".glb"), std::string(bytes.begin(), bytes.end()));
      report.files.push_back(name + ".glb");
    }
    if (o.figures) {
      const fs::path dir = fs::absolute(tmp / "figures");
      fs::create_directories(dir);
      for (const render::PovFigure& figure : run.figures()) drawFigure(figure, dir, o.figure_scale, report.files);
    }
    if (fs::exists(out)) fs::remove_all(out);
    fs::rename(tmp, out);
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
  return report;
}

}  // namespace creaturelab::runner
