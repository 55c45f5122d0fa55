// A case's expected answers (host only): cases/NAME/expected.toml holds the figures a case is checked
// against, each with its unit, its target as a relative tolerance and its source, so that the validation
// tests and `impactsph verify` read them from beside the case instead of typing them in. Format
// (docs/case-files.md, "Expected answers"):
//
//   [final_length]
//   value = "16.21 mm"     # a quantity with its unit (common/units.hpp)
//   tolerance = 0.03       # the target, relative (0.03: within 3 %); optional
//   source = "Johnson and Cook 1983, as reported by Zerilli and Armstrong 1987"
//
// Every problem throws CaseError naming the file, the line and the key.
#pragma once
#include <map>
#include <string>
#include <utility>

#include "common/units.hpp"

namespace impactsph {

struct ExpectedFigure {
  std::string name;     // the table's key, e.g. "final_length"
  std::string value;    // as written, e.g. "16.21 mm"; parsed by ExpectedAnswers::value
  double tolerance = 0; // relative target; 0 when the file gives none
  std::string source;   // where the figure comes from
  int line = 0;         // of the figure's value in the file
};

class ExpectedAnswers {
 public:
  ExpectedAnswers() = default;
  ExpectedAnswers(std::string file, std::map<std::string, ExpectedFigure> figures)
      : file_(std::move(file)), figures_(std::move(figures)) {}
  const std::string& file() const { return file_; }
  // The figure `name`; throws CaseError listing the figures the file has when it lacks it.
  const ExpectedFigure& figure(const std::string& name) const;
  // Its value in SI, checked to be a `dimension`.
  double value(const std::string& name, Dimension dimension) const;
  // Its tolerance; throws CaseError when the file gives none for it.
  double tolerance(const std::string& name) const;

 private:
  std::string file_;
  std::map<std::string, ExpectedFigure> figures_;
};

// Reads and checks an expected-answers file: every top-level entry a table with value (a string, required),
// tolerance (a number in (0, 1), optional) and source (a string, required), and nothing else.
ExpectedAnswers read_expected(const std::string& path);

}  // namespace impactsph
