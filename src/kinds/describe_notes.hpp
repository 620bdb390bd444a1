#pragma once
// A kind's own reason for its default of a shared struct's field (kinds/describe.hpp). The struct
// declares the field once (name, unit, range, doc); a kind that composes it with another default
// says why beside that default, and the note is appended to the field's doc:
//
//   DefaultNotes noted(v, {{"kinematic_viscosity_m2_per_s", "1e-2 damps the relaxation in seconds"}});
//   fluid.describeFluid(noted);  // doc: "nu (...); default 1e-2 damps the relaxation in seconds"
//
// Every other call passes through unchanged, so any visitor can be wrapped.
#include <cstdint>
#include <initializer_list>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "kinds/describe.hpp"

namespace creaturelab::kinds {

template <class V>
class DefaultNotes {
 public:
  DefaultNotes(V& v, std::initializer_list<std::pair<const std::string, std::string>> notes) : v_(v), notes_(notes) {}

  void real(const std::string& name, double& field, const std::string& unit, double min, double max,
            const std::string& doc) {
    v_.real(name, field, unit, min, max, noted(name, doc));
  }
  template <class I, std::enable_if_t<std::is_integral_v<I> && !std::is_same_v<I, bool>, int> = 0>
  void integer(const std::string& name, I& field, std::int64_t min, std::int64_t max, const std::string& doc) {
    v_.integer(name, field, min, max, noted(name, doc));
  }
  void boolean(const std::string& name, bool& field, const std::string& doc) { v_.boolean(name, field, noted(name, doc)); }
  void text(const std::string& name, std::string& field, const std::string& unit, const std::string& doc) {
    v_.text(name, field, unit, noted(name, doc));
  }
  void choice(const std::string& name, std::string& field, const std::vector<std::string>& choices,
              const std::string& doc) {
    v_.choice(name, field, choices, noted(name, doc));
  }
  template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  void choice(const std::string& name, E& field, std::initializer_list<E> values, const std::string& doc) {
    v_.choice(name, field, values, noted(name, doc));
  }
  template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  void choice(const std::string& name, E& field, std::initializer_list<std::pair<const char*, E>> named,
              const std::string& doc) {
    v_.choice(name, field, named, noted(name, doc));
  }
  void realOrAuto(const std::string& name, RealOrAuto& field, const std::string& unit, double min, double max,
                  const std::string& doc) {
    v_.realOrAuto(name, field, unit, min, max, noted(name, doc));
  }

 private:
  std::string noted(const std::string& name, const std::string& doc) const {
    const auto it = notes_.find(name);
    return it == notes_.end() ? doc : doc + "; default " + it->second;
  }

  V& v_;
  std::map<std::string, std::string> notes_;
};

}  // namespace creaturelab::kinds
