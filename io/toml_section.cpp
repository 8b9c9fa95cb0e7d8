// Typed, validated access to the sections of a TOML scene file: the shared helpers, the range grid
// { from, to, count, spacing }, the section check and reading the file (docs/scenes.md "Scene files").
#include "io/toml_section.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

namespace rotorsweep::io {

std::string join(const std::set<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string shortened(const std::string& s, std::size_t limit) {
  if (s.size() <= limit) return s;
  std::size_t cut = limit;
  while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;  // UTF-8 continuation
  return s.substr(0, cut) + "… (" + std::to_string(s.size()) + " bytes)";
}

namespace {

/// a·b as an unevaluated sum p + e, exactly (Dekker's product with Veltkamp's split; no fused
/// multiply-add, which the build does not contract to).
std::pair<double, double> exact_product(double a, double b) {
  const auto split = [](double x) {
    const double c = 134217729.0 * x;  // 2^27 + 1
    const double high = c - (c - x);
    return std::pair{high, x - high};
  };
  const double p = a * b;
  const auto [ah, al] = split(a);
  const auto [bh, bl] = split(b);
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}

/// a + b as an unevaluated sum s + e, exactly (Knuth's two-sum).
std::pair<double, double> exact_sum(double a, double b) {
  const double s = a + b, v = s - a;
  return {s, (a - (s - v)) + (b - v)};
}

/// Point i of the m + 1 equally spaced points from `from` to `to`: the double nearest to
/// (from (m − i) + to i) / m, its numerator summed exactly, so that a point the grid meets exactly
/// (6 in from 0.25 to 11 in 44 points) is that number, and both ends are `from` and `to`.
double linear_point(double from, double to, long long i, long long m) {
  const auto [p, dp] = exact_product(from, double(m - i));
  const auto [q, dq] = exact_product(to, double(i));
  const auto [s, ds] = exact_sum(p, q);
  const double low = dp + dq + ds;
  const double quotient = s / double(m);
  const auto [back, dback] = exact_product(quotient, double(m));
  return quotient + (((s - back) - dback) + low) / double(m);
}

}  // namespace

[[noreturn]] void fail(const std::string& key, const std::string& message) {
  throw SceneError("scene key '" + shortened(key) + "': " + message);
}

std::string describe(const toml::node& node) {
  std::ostringstream out;
  if (node.is_string())
    out << '"' << node.value<std::string>().value_or("") << '"';
  else if (node.is_table())
    out << "a table";
  else if (node.is_array())
    out << "an array";
  else
    node.visit([&](const auto& value) { out << value; });
  return shortened(out.str());
}

std::string number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

namespace {

/// The values of axis `key`, refused when one of them comes twice: each value is a point of the plan,
/// and two points with one coordinate would be one point twice.
std::vector<double> distinct(std::vector<double> values, const std::string& key) {
  std::vector<double> sorted(values);
  std::sort(sorted.begin(), sorted.end());
  if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
    fail(key, "has the value " + number_text(*twice) +
                  " more than once; the values of a sweep axis must differ (each is a point of the plan)");
  return values;
}

/// The grid's values before the check that they differ.
std::vector<double> grid_values(const Section& section, std::string_view k, const std::string& what,
                                bool (*valid)(double), const std::vector<double>& fallback) {
  const std::string key = section.key(k);
  const std::string shape =
      "a number, a list of numbers " + what + ", or { from, to, count, spacing = \"linear\"|\"log\" }";
  if (!fallback.empty() && !section.find(k)) return fallback;
  const toml::node& node = section.require(k, shape);
  if (node.is_floating_point() || node.is_integer()) return {Section::checked_number(node, key, what, valid)};
  std::vector<double> values;
  if (const auto* list = node.as_array()) {
    if (list->empty()) fail(key, "must not be empty; it must be " + shape);
    for (const auto& element : *list) values.push_back(Section::checked_number(element, key, what, valid));
    return values;
  }
  const auto* range = node.as_table();
  if (!range) fail(key, "must be " + shape + " (got " + describe(node) + ")");
  for (const auto& [name, value] : *range)
    if (name != "from" && name != "to" && name != "count" && name != "spacing")
      fail(key + "." + std::string(name.str()), "unknown key; a range has from, to, count, spacing");
  const Section r(range, key);
  const double from =
      Section::checked_number(r.require("from", "a number " + what), r.key("from"), what, valid);
  const double to = Section::checked_number(r.require("to", "a number " + what), r.key("to"), what, valid);
  r.require("count", "an integer >= 1");
  const long long count = r.integer("count", 1, "an integer from 1 to 10000000",
                                    [](long long c) { return c >= 1 && c <= 10000000; });
  const bool log = r.choice("spacing", "linear", {"linear", "log"}) == "log";
  if (to < from) fail(r.key("to"), "must be >= from (" + number_text(from) + ")");
  if (log && from <= 0) fail(r.key("from"), "must be > 0 with spacing = \"log\"");
  for (long long i = 0; i < count; ++i) {
    if (count == 1)
      values.push_back(from);
    else if (log)
      values.push_back(
          std::exp(std::log(from) + double(i) / double(count - 1) * (std::log(to) - std::log(from))));
    else
      values.push_back(linear_point(from, to, i, count - 1));
  }
  values.front() = from;  // exp(log(x)) need not give x back
  values.back() = to;
  return values;
}

}  // namespace

std::vector<double> grid(const Section& section, std::string_view k, const std::string& what,
                         bool (*valid)(double), const std::vector<double>& fallback) {
  return distinct(grid_values(section, k, what, valid, fallback), section.key(k));
}

void check_sections(const toml::table& root,
                    const std::map<std::string, std::set<std::string>>& allowed_keys) {
  std::set<std::string> sections;
  for (const auto& [name, keys] : allowed_keys) sections.insert(name);
  for (const auto& [name, node] : root) {
    const std::string section(name.str());
    const auto it = allowed_keys.find(section);
    if (it == allowed_keys.end()) fail(section, "unknown; the scene sections are " + join(sections));
    const auto* table = node.as_table();
    if (!table) fail(section, "must be a table [" + section + "]");
    for (const auto& [key, value] : *table)
      if (!it->second.count(std::string(key.str())))
        fail(section + "." + std::string(key.str()),
             "unknown key; [" + section + "] allows " + join(it->second));
  }
}

kernels::StepperId read_stepper(const Section& numerics, std::string_view fallback) {
  const std::set<std::string> names(kernels::stepper_names.begin(), kernels::stepper_names.end());
  return *kernels::parse_stepper(numerics.choice("stepper", std::string(fallback), names));
}

double read_max_steps(const Section& numerics) {
  return double(
      numerics.integer("max_steps", 100000000, "an integer >= 1", [](long long n) { return n >= 1; }));
}

toml::table parse_toml(std::string_view text, std::string_view source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream message;
    message << "scene file '" << source << "' line " << e.source().begin.line << ": " << e.description();
    throw SceneError(message.str());
  }
}

std::string read_scene_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  const std::string what = "cannot read scene file '" + shortened(path, 200) + "': ";
  if (!fs::exists(status)) throw SceneError(what + (error ? error.message() : "no such file"));
  if (fs::is_directory(status)) throw SceneError(what + "it is a directory");
  if (!fs::is_regular_file(status)) throw SceneError(what + "not a regular file (a FIFO, socket or device)");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw SceneError(what + std::strerror(errno));
  return text.str();
}

}  // namespace rotorsweep::io
