#pragma once
// Each parameter declared once, beside the field it sets (DESIGN.md). A parameter struct
// describes its fields through one visitor, and its in-class initialisers are the user's defaults:
//
//   struct StepParams {
//     double end_time_s = 10.0;
//     template <class V> void describe(V& v) {
//       v.real("end_time_s", end_time_s, "s", 1e-6, 1e5, "simulated time");
//     }
//   };
//
// The visitors here derive from that one description the kind's schema (`list`, docs/kinds.md, the
// TOML checks, the units of the HDF5 attributes), the reading of resolved Params into the struct, the
// way back, and the range check. Cross-field rules go in the struct's member validate(). A solver's
// struct needs no include for this: describe() is a template over any visitor with these members
//   real(name, double&, unit, min, max, doc)        integer(name, int-like&, min, max, doc)
//   boolean(name, bool&, doc)                       text(name, std::string&, unit, doc)
//   choice(name, std::string&, {"a", "b"}, doc)     choice(name, Enum&, {Enum::a, Enum::b}, doc)
//   choice(name, Enum&, {{"a", Enum::a}, ...}, doc) realOrAuto(name, RealOrAuto&, unit, min, max, doc)
// (the enum form without names spells each value by `to_string(value)`, found beside the enum).
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "kinds/params.hpp"

namespace creaturelab::kinds {

// A number, or "auto": the solver picks it (e.g. a stable step).
struct RealOrAuto {
  bool is_auto = true;
  double value = 0;  // meaningful when !is_auto
};

// What every visitor shares: enum and integer fields travel as the string and 64-bit forms that
// Params holds, so each visitor writes one member per ParamType.
template <class Derived>
class FieldVisitor {
 public:
  template <class I, std::enable_if_t<std::is_integral_v<I> && !std::is_same_v<I, bool>, int> = 0>
  void integer(const std::string& name, I& field, std::int64_t min, std::int64_t max, const std::string& doc) {
    std::int64_t wide = field;
    self().integer64(name, wide, min, max, doc);
    field = I(wide);
  }

  template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  void choice(const std::string& name, E& field, std::initializer_list<std::pair<const char*, E>> named,
              const std::string& doc) {
    std::vector<std::string> names;
    std::string current;
    for (const auto& [n, e] : named) {
      names.emplace_back(n);
      if (e == field) current = n;
    }
    self().choice(name, current, names, doc);
    for (const auto& [n, e] : named)
      if (current == n) field = e;
  }

  template <class E, std::enable_if_t<std::is_enum_v<E>, int> = 0>
  void choice(const std::string& name, E& field, std::initializer_list<E> values, const std::string& doc) {
    std::vector<std::string> names;
    std::string current;
    for (E e : values) {
      names.emplace_back(to_string(e));
      if (e == field) current = names.back();
    }
    self().choice(name, current, names, doc);
    for (E e : values)
      if (current == to_string(e)) field = e;
  }

 private:
  Derived& self() { return static_cast<Derived&>(*this); }
};

// The schema: one ParamSpec per field, the field's value as its default.
class SchemaVisitor : public FieldVisitor<SchemaVisitor> {
 public:
  using FieldVisitor::choice;
  using FieldVisitor::integer;
  std::vector<ParamSpec> specs;

  void real(const std::string& name, double& field, const std::string& unit, double min, double max,
            const std::string& doc) {
    specs.push_back(kinds::real(name, field, unit, min, max, doc));
  }
  void integer64(const std::string& name, std::int64_t& field, std::int64_t min, std::int64_t max,
                 const std::string& doc) {
    specs.push_back(kinds::integer(name, field, min, max, doc));
  }
  void boolean(const std::string& name, bool& field, const std::string& doc) {
    specs.push_back(kinds::boolean(name, field, doc));
  }
  void choice(const std::string& name, std::string& field, const std::vector<std::string>& choices,
              const std::string& doc) {
    specs.push_back(kinds::choice(name, field, choices, doc));
  }
  void text(const std::string& name, std::string& field, const std::string& unit, const std::string& doc) {
    specs.push_back(kinds::text(name, field, unit, doc));
  }
  void realOrAuto(const std::string& name, RealOrAuto& field, const std::string& unit, double min, double max,
                  const std::string& doc) {
    ParamSpec spec = kinds::realOrAuto(name, unit, min, max, doc);
    if (!field.is_auto) spec.default_value = field.value;
    specs.push_back(std::move(spec));
  }
};

// Resolved Params (every declared name present, types and ranges checked) into the fields. A name
// missing or of the wrong type is a programming error: std::logic_error, as ParamReader.
class ReadVisitor : public FieldVisitor<ReadVisitor> {
 public:
  using FieldVisitor::choice;
  using FieldVisitor::integer;
  explicit ReadVisitor(const Params& params) : r_(params) {}

  void real(const std::string& name, double& field, const std::string&, double, double, const std::string&) {
    field = r_.real(name);
  }
  void integer64(const std::string& name, std::int64_t& field, std::int64_t, std::int64_t, const std::string&) {
    field = r_.integer(name);
  }
  void boolean(const std::string& name, bool& field, const std::string&) { field = r_.boolean(name); }
  void choice(const std::string& name, std::string& field, const std::vector<std::string>&, const std::string&) {
    field = r_.text(name);
  }
  void text(const std::string& name, std::string& field, const std::string&, const std::string&) {
    field = r_.text(name);
  }
  void realOrAuto(const std::string& name, RealOrAuto& field, const std::string&, double, double, const std::string&) {
    field.is_auto = r_.isAuto(name);
    if (!field.is_auto) field.value = r_.real(name);
  }

 private:
  ParamReader r_;
};

// The fields as Params (what a run with this struct resolves to).
class WriteVisitor : public FieldVisitor<WriteVisitor> {
 public:
  using FieldVisitor::choice;
  using FieldVisitor::integer;
  Params params;

  void real(const std::string& name, double& field, const std::string&, double, double, const std::string&) {
    params[name] = field;
  }
  void integer64(const std::string& name, std::int64_t& field, std::int64_t, std::int64_t, const std::string&) {
    params[name] = field;
  }
  void boolean(const std::string& name, bool& field, const std::string&) { params[name] = field; }
  void choice(const std::string& name, std::string& field, const std::vector<std::string>&, const std::string&) {
    params[name] = field;
  }
  void text(const std::string& name, std::string& field, const std::string&, const std::string&) {
    params[name] = field;
  }
  void realOrAuto(const std::string& name, RealOrAuto& field, const std::string&, double, double, const std::string&) {
    params[name] = field.is_auto ? Value(std::string("auto")) : Value(field.value);
  }
};

template <class P>
std::vector<ParamSpec> schemaOf(P described) {
  SchemaVisitor v;
  described.describe(v);
  return std::move(v.specs);
}

// The schema with P's in-class defaults (a named P, not a defaulted argument: gcc 12 warns
// -Wmaybe-uninitialized on destroying such a temporary when P holds a std::vector).
template <class P>
std::vector<ParamSpec> schemaOf() {
  P described;
  SchemaVisitor v;
  described.describe(v);
  return std::move(v.specs);
}

// `params` read into a P; a name P describes but `params` lacks is a std::logic_error.
template <class P>
P readParams(const Params& params) {
  P p;
  ReadVisitor v(params);
  p.describe(v);
  return p;
}

template <class P>
Params paramsOf(P described) {
  WriteVisitor v;
  described.describe(v);
  return std::move(v.params);
}

// Each field against its described type and range: "" when all hold, else "<name>: got <value>,
// expected <what>" per field, joined by "; " (a struct filled in code, not read from a checked file).
template <class P>
std::string rangeProblems(const P& p) {
  const std::vector<ParamSpec> specs = schemaOf<P>();
  const Params values = paramsOf(p);
  std::string out;
  for (const ParamSpec& spec : specs) {
    const Value& value = values.at(spec.name);
    if (std::string expected = checkValue(spec, value); !expected.empty())
      out += (out.empty() ? "" : "; ") + spec.name + ": got " + describeValue(value) + ", expected " + expected;
  }
  return out;
}

}  // namespace creaturelab::kinds
