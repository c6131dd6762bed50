#pragma once
// The controller model's numbered parameters: the system variables (#2001 offsets, #4001
// modal codes, #5001 positions, #5221 work offsets, ...) read and written by macro programs.
// They are views of lowering's one controller state (ControllerState, OffsetTables), laid out
// by the dialect's table (DialectTable::system_variables), not copies kept in step.
#include <vector>

#include "controller_state.h"
#include "ncc/eval/variables.h"
#include "ncc/ir/ir.h"

namespace ncc::passes {

struct LoweringCore;

class ControllerVariables final : public eval::SystemVariables {
 public:
  explicit ControllerVariables(LoweringCore& core) : core_(core) {}
  std::optional<eval::Value> read(int64_t number, SourceLocation loc,
                                  eval::Failure& failure) override;
  bool write(int64_t number, const eval::Value& value, SourceLocation loc,
             eval::Failure& failure) override;
  std::optional<eval::Value> readSystem(std::string_view name,
                                        std::span<const eval::SystemIndex> indices,
                                        SourceLocation loc, eval::Failure& failure) override;

 private:
  LoweringCore& core_;
};

// The system variables a G10 write changes, with their new values (after `tables` took the
// write), so that the IR records them for the VM (`ncc run --emit=vars`).
std::vector<ir::SetVariable> variablesOf(const TableWrite& write, const ControllerState& cs,
                                         const OffsetTables& tables, const DialectTable& table,
                                         int axis_count);

}  // namespace ncc::passes
