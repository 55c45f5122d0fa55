#include "common/expected.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <toml++/toml.h>

#include "common/errors.hpp"

namespace impactsph {

namespace {

int line_of(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

std::string known_figures(const std::map<std::string, ExpectedFigure>& figures) {
  std::string s;
  for (const auto& [name, f] : figures) s += (s.empty() ? "" : ", ") + name;
  return s.empty() ? "none" : s;
}

}  // namespace

const ExpectedFigure& ExpectedAnswers::figure(const std::string& name) const {
  const auto it = figures_.find(name);
  if (it == figures_.end())
    throw CaseError(file_, 0, name, "no such expected figure; this file has: " + known_figures(figures_));
  return it->second;
}

double ExpectedAnswers::value(const std::string& name, Dimension dimension) const {
  const ExpectedFigure& f = figure(name);
  try {
    return parse_quantity(f.value, dimension);
  } catch (const std::invalid_argument& e) {
    throw CaseError(file_, f.line, name + ".value", e.what());
  }
}

double ExpectedAnswers::tolerance(const std::string& name) const {
  const ExpectedFigure& f = figure(name);
  if (f.tolerance <= 0)
    throw CaseError(file_, f.line, name + ".tolerance", "missing: the target as a relative tolerance, e.g. 0.05 for 5 %");
  return f.tolerance;
}

ExpectedAnswers read_expected(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw CaseError(path, 0, "", "no such expected-answers file");
  toml::table tree;
  try {
    tree = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw CaseError(path, static_cast<int>(e.source().begin.line), "", "not valid TOML: " + std::string(e.description()));
  }
  std::map<std::string, ExpectedFigure> figures;
  for (auto&& [key, node] : tree) {
    const std::string name(key.str());
    const toml::table* t = node.as_table();
    if (!t)
      throw CaseError(path, line_of(node), name,
                      "expected a table [" + name + "] with value, tolerance and source");
    ExpectedFigure f;
    f.name = name;
    f.line = line_of(node);
    bool has_value = false, has_source = false;
    for (auto&& [k, v] : *t) {
      const std::string field(k.str());
      const std::string where = name + "." + field;
      if (field == "value") {
        if (!v.as_string()) throw CaseError(path, line_of(v), where, "expected a quantity with its unit, e.g. \"16.21 mm\"");
        f.value = v.as_string()->get();
        f.line = line_of(v);
        has_value = true;
      } else if (field == "tolerance") {
        const std::optional<double> x = v.value<double>();
        if (!x || !(*x > 0 && *x < 1))
          throw CaseError(path, line_of(v), where, "expected a relative tolerance in (0, 1), e.g. 0.05 for 5 %");
        f.tolerance = *x;
      } else if (field == "source") {
        if (!v.as_string() || v.as_string()->get().empty())
          throw CaseError(path, line_of(v), where, "expected the figure's source as a string (paper, table or figure)");
        f.source = v.as_string()->get();
        has_source = true;
      } else {
        throw CaseError(path, line_of(v), where, "unknown key; valid keys are value, tolerance and source");
      }
    }
    if (!has_value) throw CaseError(path, f.line, name + ".value", "missing: the figure with its unit, e.g. \"16.21 mm\"");
    if (!has_source) throw CaseError(path, f.line, name + ".source", "missing: where the figure comes from");
    figures.emplace(name, std::move(f));
  }
  return ExpectedAnswers(path, std::move(figures));
}

}  // namespace impactsph
