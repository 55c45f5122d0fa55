// Case files: TOML -> validated CaseSpec in SI units (schema and examples: docs/case-files.md).
// Host only. Every problem throws impactsph::CaseError naming the file, the line (0 when the value came
// from an override or the key is missing from a table that has no line), the full key
// (`materials.steel.eos.c0`, `bodies[1].radius`, `boundaries.fixed[0].min[2]`; arrays count from 0) and
// what would be valid. The first problem found is reported; checking is in file order.
//
// Overrides ("KEY=VALUE", as a command line's --set would pass them) edit the TOML tree before it is
// validated, so an override is checked exactly like the file:
//   projectile.velocity=298 m/s    numerics.cfl=0.1    time.end=40us    steel.eos.c0=4600 m/s
// The first component names a top-level table (case, numerics, time, output), a body (by its name) or a
// material (by its name); `bodies.NAME.` and `materials.NAME.` spell the same out when a body and a
// material share a name. The rest is the key inside it, nested tables separated by '.'; missing tables
// and keys are created (and then validated). The value is read as TOML when it is one (0.1, true,
// "298 m/s", [0, 0, -1]) and as a string otherwise (298 m/s). Setting a body's velocity to a speed when
// the file gives it as a vector keeps the file's direction.
#pragma once
#include <string>
#include <vector>

#include "common/case_spec.hpp"

namespace impactsph {

// Reads, overrides and validates the case file at `path`. `spacing_override` (e.g. "0.5mm"), when not
// empty, replaces numerics.spacing after the other overrides.
CaseSpec load_case_file(const std::string& path, const std::vector<std::string>& set_overrides = {},
                        const std::string& spacing_override = "");

// The same for TOML text held in memory; `display_name` stands for the file in messages and in
// CaseSpec::source_file.
CaseSpec parse_case_string(const std::string& toml_text, const std::string& display_name,
                           const std::vector<std::string>& set_overrides = {},
                           const std::string& spacing_override = "");

// The material files the case file at `path` reads (`[materials.NAME] file = "PATH"`), resolved against
// its folder, in the order of the file; empty when there are none or the file is not valid TOML. For the
// fingerprints of runs, which must change when a material file does.
std::vector<std::string> case_material_files(const std::string& path);

// What the TOML file at `path` says, without its comments, blank lines and layout: the parsed tree written
// out with its keys in order, so that editing a comment does not change it and editing a value does. The
// file's raw text when it is not valid TOML; empty when it cannot be read. For the fingerprints of runs.
std::string toml_file_content(const std::string& path);

}  // namespace impactsph
