#pragma once
// The golden cases of cutter radius compensation (tests/compensation/golden_test.cpp): each a
// program built by hand, the moves the pass must emit, worked out by hand (the derivation is in
// the comment beside each case, never by calling the pass's geometry), and the diagnostics it
// must give. The docs' drawings (docs/compensation/*.svg) are drawn from the same cases.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "compensation_harness.h"

namespace ncc::passes::testing {

struct GoldenCase {
  std::string name;      // also the drawing's file name: docs/compensation/<name>.svg
  std::string title;     // one line, for the drawing
  std::function<CompProgram()> build;
  std::string expected;  // CompProgram::run()'s text
  std::vector<std::string> errors, warnings;  // diagnostic codes, in order
};

const std::vector<GoldenCase>& goldenCases();

// GoogleTest prints a case by its name.
inline void PrintTo(const GoldenCase& g, std::ostream* os) { *os << g.name; }

}  // namespace ncc::passes::testing
