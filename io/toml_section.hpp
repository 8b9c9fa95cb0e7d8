// Typed, validated access to the sections of a TOML scene file (toml++): every message names the
// key ("section.key") and what it must be; shared by the readers of every kind of scene.
#pragma once

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "io/scene_parser.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::io {

/// The names, comma-separated.
std::string join(const std::set<std::string>& names);
/// s cut to about `limit` bytes at a character boundary, saying how long it was.
std::string shortened(const std::string& s, std::size_t limit = 80);
/// Throws SceneError "scene key 'key': message".
[[noreturn]] void fail(const std::string& key, const std::string& message);
/// A value as the user wrote it, for messages.
std::string describe(const toml::node& node);
/// A number for messages, to 6 significant digits ("%g": 1.6e+301, not 301 digits).
std::string number_text(double x);

/// Typed access to one section of the scene, keys named "section.key" in messages.
class Section {
 public:
  Section(const toml::table* table, std::string name) : table_(table), name_(std::move(name)) {}

  std::string key(std::string_view k) const { return name_ + "." + std::string(k); }
  const toml::node* find(std::string_view k) const { return table_ ? table_->get(k) : nullptr; }
  const toml::node& require(std::string_view k, const std::string& what) const {
    const toml::node* node = find(k);
    if (!node) fail(key(k), "is missing; it must be " + what);
    return *node;
  }

  double number(std::string_view k, double fallback, const std::string& what, bool (*valid)(double)) const {
    const toml::node* node = find(k);
    return node ? checked_number(*node, key(k), what, valid) : fallback;
  }

  long long integer(std::string_view k, long long fallback, const std::string& what,
                    bool (*valid)(long long)) const {
    const toml::node* node = find(k);
    if (!node) return fallback;
    const auto v = node->value_exact<long long>();
    if (!node->is_integer() || !v || !valid(*v))
      fail(key(k), "must be " + what + " (got " + describe(*node) + ")");
    return *v;
  }

  /// A number, or a non-empty list of numbers, each valid.
  std::vector<double> numbers(std::string_view k, std::vector<double> fallback, const std::string& what,
                              bool (*valid)(double)) const {
    const toml::node* node = find(k);
    if (!node) return fallback;
    const auto* list = node->as_array();
    if (!list) return {checked_number(*node, key(k), what + ", or a list of them", valid)};
    if (list->empty()) fail(key(k), "must be " + what + ", or a non-empty list of them");
    std::vector<double> values;
    for (const auto& element : *list) values.push_back(checked_number(element, key(k), what, valid));
    return values;
  }

  /// An integer, or a non-empty list of distinct integers, each valid.
  std::vector<long long> integers(std::string_view k, const std::string& what,
                                  bool (*valid)(long long)) const {
    const toml::node& node = require(k, what + ", or a list of them");
    const auto* list = node.as_array();
    std::vector<long long> values;
    const auto check = [&](const toml::node& n) {
      const auto v = n.value_exact<long long>();
      if (!n.is_integer() || !v || !valid(*v) || std::count(values.begin(), values.end(), *v))
        fail(key(k), "must be " + what + ", or a list of distinct ones (got " + describe(n) + ")");
      values.push_back(*v);
    };
    if (!list)
      check(node);
    else if (list->empty())
      fail(key(k), "must be " + what + ", or a non-empty list of them");
    else
      for (const auto& element : *list) check(element);
    return values;
  }

  bool boolean(std::string_view k, bool fallback) const {
    const toml::node* node = find(k);
    if (!node) return fallback;
    if (!node->is_boolean()) fail(key(k), "must be true or false (got " + describe(*node) + ")");
    return *node->value<bool>();
  }

  /// A non-empty string.
  std::string text(std::string_view k, std::string fallback) const {
    const toml::node* node = find(k);
    if (!node) return fallback;
    const auto v = node->value_exact<std::string>();
    if (!v || v->empty()) fail(key(k), "must be a non-empty string (got " + describe(*node) + ")");
    return *v;
  }

  std::string choice(std::string_view k, std::string fallback, const std::set<std::string>& allowed) const {
    const toml::node* node = find(k);
    if (!node) return fallback;
    const auto v = node->value_exact<std::string>();
    if (!v || !allowed.count(*v))
      fail(key(k), "must be one of " + join(allowed) + " (got " + describe(*node) + ")");
    return *v;
  }

  static double checked_number(const toml::node& node, const std::string& key, const std::string& what,
                               bool (*valid)(double)) {
    std::optional<double> v;
    if (node.is_floating_point() || node.is_integer()) v = node.value<double>();
    if (v && !std::isfinite(*v))
      fail(key, "must be a finite number: " + what + " (got " + describe(node) + ")");
    if (!v || !valid(*v)) fail(key, "must be " + what + " (got " + describe(node) + ")");
    return *v;
  }

 private:
  const toml::table* table_;
  std::string name_;
};

/// The section `name` of the scene (absent: a section without keys).
inline Section section(const toml::table& root, const std::string& name) {
  return Section(root[name].as_table(), name);
}

/// A number, a list of numbers, or { from, to, count, spacing = "linear" | "log" }, its values distinct
/// (each is a point of the plan's axis); with a `fallback`, the fallback when the key is absent.
std::vector<double> grid(const Section& section, std::string_view k, const std::string& what,
                         bool (*valid)(double), const std::vector<double>& fallback = {});

/// numerics.stepper: a name from the stepper list (`fallback` where the scene names none).
kernels::StepperId read_stepper(const Section& numerics,
                                std::string_view fallback = kernels::default_stepper_name);
/// The tolerances every scene allows, with the words its messages use.
inline constexpr const char* rtol_range = "a number from 1e-14 to 1e-2";
inline constexpr const char* atol_range = "a number from 1e-16 to 1e-2";
inline bool valid_rtol(double x) { return x >= 1e-14 && x <= 1e-2; }
inline bool valid_atol(double x) { return x >= 1e-16 && x <= 1e-2; }
/// numerics.max_steps: attempted steps per member (default 1e8).
double read_max_steps(const Section& numerics);

/// Every top-level entry is a table named in `allowed`, and every key in it is allowed there.
void check_sections(const toml::table& root, const std::map<std::string, std::set<std::string>>& allowed);

/// The scene text parsed; a syntax error is a SceneError naming the source and line.
toml::table parse_toml(std::string_view text, std::string_view source);

/// The text of the scene file at `path`; a SceneError says why it cannot be read.
std::string read_scene_file(const std::string& path);

}  // namespace rotorsweep::io
