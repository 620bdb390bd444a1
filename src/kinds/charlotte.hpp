#pragma once
#include <cstdint>
#include <initializer_list>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "charlotte/inscribe.hpp"
#include "charlotte/resettle.hpp"
#include "charlotte/text_target.hpp"
#include "kinds/describe_kind.hpp"
#include "web/web_params.hpp"

namespace creaturelab::kinds {

// A visitor that passes on to V only the named fields of a description and skips the rest: a kind
// that lets its user set a few of a solver struct's fields describes those through it.
template <class V>
class OnlyVisitor {
 public:
  OnlyVisitor(V& v, std::initializer_list<const char*> names) : v_(v), names_(names.begin(), names.end()) {}

  void real(const std::string& n, double& f, const std::string& unit, double lo, double hi, const std::string& doc) {
    if (has(n)) v_.real(n, f, unit, lo, hi, doc);
  }
  template <class I>
  void integer(const std::string& n, I& f, std::int64_t lo, std::int64_t hi, const std::string& doc) {
    if (has(n)) v_.integer(n, f, lo, hi, doc);
  }
  void boolean(const std::string& n, bool& f, const std::string& doc) {
    if (has(n)) v_.boolean(n, f, doc);
  }
  void text(const std::string& n, std::string& f, const std::string& unit, const std::string& doc) {
    if (has(n)) v_.text(n, f, unit, doc);
  }
  void choice(const std::string& n, std::string& f, const std::vector<std::string>& choices, const std::string& doc) {
    if (has(n)) v_.choice(n, f, choices, doc);
  }
  template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  void choice(const std::string& n, E& f, std::initializer_list<std::pair<const char*, E>> named, const std::string& doc) {
    if (has(n)) v_.choice(n, f, named, doc);
  }
  template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  void choice(const std::string& n, E& f, std::initializer_list<E> values, const std::string& doc) {
    if (has(n)) v_.choice(n, f, values, doc);
  }
  void realOrAuto(const std::string& n, RealOrAuto& f, const std::string& unit, double lo, double hi,
                  const std::string& doc) {
    if (has(n)) v_.realOrAuto(n, f, unit, lo, hi, doc);
  }

 private:
  bool has(const std::string& n) const {
    for (const std::string& m : names_)
      if (m == n) return true;
    return false;
  }
  V& v_;
  std::vector<std::string> names_;
};

// The web charlotte inscribes: the web kind's, with a secondary spoke from every second inner-frame
// mass (~80 radii: spiral segments short enough for letters).
inline web::WebParams charlotteWeb() {
  web::WebParams w;
  w.secondary_spoke_stride = 2;
  return w;
}

// The charlotte kind's parameters: the web (a few of web::WebParams' fields; the rest are the web
// kind's defaults), the target, the procedure (charlotte::InscribeParams) and the resettle.
struct CharlotteParams {
  double frame_scale = 1.0;
  web::WebParams web = charlotteWeb();
  std::string target = "text";
  std::string text = "PIG";
  std::string font = std::string(charlotte::kDefaultFont);
  std::string image_file;
  double target_width_m = 0.85;
  double target_max_height_m = 0.5;
  double target_offset_x_m = 0.0;
  double target_offset_y_m = 0.0;
  std::int64_t gap_count = 12;
  double gap_radius_m = 0.035;
  double gaps_region_radius_m = 0.33;
  std::int64_t canvas_px = 600;
  charlotte::InscribeParams inscribe;
  std::string resettle = "dynamic";
  double resettle_time_s = 12.0;
  double settling_fraction = 1e-4;
  bool renders = true;

  template <class V>
  void describe(V& v) {
    // the web (src/web, thesis §5.2)
    v.real("frame_scale", frame_scale, "", 0.05, 20, "scales the default 7-point frame (1.07 m across)");
    OnlyVisitor<V> some(v, {"secondary_spoke_stride", "spiral_density", "spiral_jitter", "spiral_k_n_per_m",
                            "spoke_k_n_per_m", "drag_ns_per_m", "seed"});
    web.describe(some);
    // the target (§6, Figs. 6.1, 6.6, 6.16, 6.18)
    v.choice("target", target, {"text", "image", "random_gaps"},
             "inscribe text (set in `font`), a PBM/PGM image, or random gaps (Fig. 6.18)");
    v.text("text", text, "", "the text, UTF-8; \\n breaks a line (Fig. 6.11: P, I, G)");
    v.text("font", font, "",
           "pango font description of the text, installed (fc-list); heavy capitals as in Fig. 6.10 (thesis names none)");
    v.text("image_file", image_file, "", "PBM/PGM target image (P1/P2/P4/P5; dark = target), path from the working folder");
    v.real("target_width_m", target_width_m, "m", 1e-3, 100,
           "width of the target on the web, the height following its aspect (the default inner frame is ~0.85 m wide)");
    v.real("target_max_height_m", target_max_height_m, "m", 1e-3, 100, "largest height of the target on the web");
    v.real("target_offset_x_m", target_offset_x_m, "m", -100, 100, "target centre right of the hub");
    v.real("target_offset_y_m", target_offset_y_m, "m", -100, 100, "target centre above the hub");
    v.integer("gap_count", gap_count, 1, 10000, "random gaps: how many discs (Fig. 6.18; thesis gives none)");
    v.real("gap_radius_m", gap_radius_m, "m", 1e-4, 10, "random gaps: disc radius");
    v.real("gaps_region_radius_m", gaps_region_radius_m, "m", 0, 100,
           "random gaps: centres within this distance of the target centre");
    // the procedure (§6, Fig. 6.9)
    v.integer("canvas_px", canvas_px, 64, 4096, "canvas side, pixels (§5.3.1: 600 x 600)");
    inscribe.describe(v);
    // settling (§6: "allow the web simulation to settle down"; after removal, so it stays physical)
    v.choice("resettle", resettle, {"dynamic", "static"},
             "after removal: RK4 run from the old rest state (gives the settling time), or the static equilibrium");
    v.real("resettle_time_s", resettle_time_s, "s", 0.02, 1e4,
           "dynamic resettle: simulated time (the web settles in 5-10 s, §5.1)");
    v.real("settling_fraction", settling_fraction, "", 1e-12, 1,
           "settled when kinetic energy stays below this fraction of its peak");
    v.boolean("renders", renders, "return PNG renders (web, overlay, cut, result) for the run folder");
  }

  // The web with its frame scaled; the procedure with the web's seed; the resettle.
  web::WebParams webParams() const;
  charlotte::InscribeParams inscribeParams() const;
  charlotte::ResettleParams resettleParams() const { return {resettle == "dynamic", resettle_time_s, settling_fraction}; }
  // Ranges, the web's and the procedure's validate(), then the text's font or the image file.
  std::string validate() const;
};

// Charlotte's web (Mehla 2005 thesis ch. 6): a settled orb web with a text or an image inscribed by
// removing the spiral segments that match the dilated target, the three emphasis variants of
// Figs. 6.12-6.14, an image target (Fig. 6.16) and random gaps (Fig. 6.18); the web settles again
// afterwards. Renders (web, overlay, result) come back as Result::artifacts.
class CharlotteKind : public DescribedKind<CharlotteParams> {
 public:
  CharlotteKind();
  std::string name() const override { return "charlotte"; }
  std::string doc() const override;
  Result run(const Params& params) const override;
};

}  // namespace creaturelab::kinds
