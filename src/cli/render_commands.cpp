#include "cli/render_commands.hpp"

#include <cstdio>

#include "runner/experiment.hpp"

namespace creaturelab::cli {

int render(const runner::RenderRunOptions& options) {
  runner::RenderReport r;
  try {
    r = runner::renderRun(options);
  } catch (const runner::ExperimentError&) {
    throw;  // bad input: exit 2 (Commands::guard)
  } catch (const std::exception& e) {
    // Not the input: a write that failed, povray failing. The partial output is already removed.
    std::fprintf(stderr, "error: %s\n", e.what());
    return 3;
  }
  int obj = 0;
  std::string others;
  for (const auto& f : r.files) {
    if (f.rfind("obj/", 0) == 0) ++obj;
    else if (f.size() > 4 && f.compare(f.size() - 4, 4, ".inc") != 0) others += " " + f;
  }
  std::printf("render: %s -> %s\n", r.point_file.c_str(), r.out_dir.c_str());
  std::printf("  %d frame(s), %d vertices and %d triangles each; mesh %.3f ms CPU per frame (slice, discs, "
              "variation, normals)\n",
              r.frames, r.vertices, r.triangles, r.render_ms_per_frame);
  std::printf("  wrote%s%s\n", others.c_str(), obj ? (" and " + std::to_string(obj) + " OBJ frame(s) in obj/").c_str() : "");
  return 0;
}

}  // namespace creaturelab::cli
