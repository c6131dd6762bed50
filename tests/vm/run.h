#pragma once
// Helpers for executor tests: a three-axis header and a "run to the end" loop.
#include <vector>

#include "gtest/gtest.h"
#include "ncc/bytecode/assembler.h"
#include "ncc/bytecode/verifier.h"
#include "ncc/vm/executor.h"

namespace ncc::test {

inline bytecode::Header xyzHeader() {
  bytecode::Header header;
  header.axes = {{"X", AxisKind::Linear}, {"Y", AxisKind::Linear}, {"Z", AxisKind::Linear}};
  return header;
}

// Every event of a run; the program must pass the verifier first.
inline std::vector<vm::Event> runAll(vm::Executor& executor, const bytecode::Program& program) {
  std::optional<bytecode::Error> error = bytecode::verify(program);
  EXPECT_FALSE(error) << error->code << ": " << error->message;
  std::vector<vm::Event> events;
  vm::Event event;
  while (executor.next(event)) events.push_back(event);
  return events;
}

}  // namespace ncc::test
