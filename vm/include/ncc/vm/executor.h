#pragma once
// Runs verified bytecode (bytecode::verify) and yields its events one at a time. Pulling
// events is the seam to the planner: a caller (the CLI, a controller's real-time loop, a later
// planner stage) asks for the next primitive when it has room for it.
//
// Real-time discipline: everything is sized at construction (variable table, value stack);
// next() allocates nothing and never throws. The executor re-checks what it relies on, so an
// unverified or corrupted program stops with an alarm instead of crashing.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ncc/bytecode/code_view.h"
#include "ncc/bytecode/program.h"
#include "ncc/machine/machine_config.h"
#include "ncc/machine/travel.h"
#include "ncc/vm/events.h"

namespace ncc::vm {

// An ARC instruction's operands on `m` (kind, plane, axes, centre, direction, turns): how the
// executor reads it, and the compiler's run budget (driver/src/run_budget.h). The axes must be
// checked against the machine first.
void setArcOperands(const bytecode::Instruction& in, MotionPrimitive& m);

class BlockPreparation;
struct PreparedInstruction;

// G27: a position within this distance (mm or deg) of the reference point counts as on it;
// half the 0.001 least input increment.
inline constexpr double kReferenceTolerance = 0.0005;

class Executor {
 public:
  // `program` must outlive the executor. Starts at machine.start_position. A paged program
  // (bytecode::Program::paged) is read through a bounded window (bytecode::CodeView).
  // A program with a block store (bytecode 2.2) goes on, at its PREPARE, with the blocks
  // prepared while it runs (docs/runtime.md); the blocks the compiler prepared before it are
  // replayed here, and a store that does not decode or replay is alarm NCC7212.
  Executor(const bytecode::Program& program, const MachineConfig& machine);
  ~Executor();

  // Runs to the next event and stores it in `out`. A SKIP (G31) is a LINE that ends where the
  // machine's probe (MachineConfig::probe) turns the skip signal on, with an exact stop; the
  // point it stopped at, minus the instruction's origin, goes to its result variables
  // (#5061..), and the next move starts there. Returns false at the end of the program
  // (END, or the call after M02/M30 was returned) or on an alarm (see alarm()). A move that
  // would leave an axis' travel range (its end point, or any point of an arc) is not emitted:
  // the dialect's stored-stroke-limit alarm instead (travelAlarmCodes(): FANUC OT0500/OT0501,
  // Sinumerik 10720, Mazak NCC7210), naming the axis and the block.
  bool next(Event& out);

  bool finished() const { return finished_; }
  const std::optional<Alarm>& alarm() const { return alarm_; }
  // Commanded machine position after the last motion.
  const AxisValues& position() const { return position_; }

  // Stops the run with alarm NCC7204 after this many instructions (0: no limit). Guards
  // callers that must stay bounded (fuzzing, a run without a cycle-time budget).
  // Also bounds the blocks prepared at run time without motion (BlockPreparation).
  void setStepLimit(uint64_t limit);
  // The run's time, s: what blocks prepared from now on read as the timers (#3001, #3002).
  // The controller sets its IPO time before it asks for events; 0 unless set.
  void setClock(double seconds) { clock_ = seconds; }
  uint64_t steps() const { return steps_; }

  // Value of #n, or nullopt when vacant or beyond the program's variable table.
  std::optional<double> variable(uint32_t number) const;
  // Every non-vacant variable in increasing number: ("#100", 3.0), ...
  std::vector<std::pair<std::string, double>> variables() const;

 private:
  struct Value {
    double number = 0.0;
    bool vacant = true;
  };

  bool raise(const char* code, const char* message, uint32_t offset);
  bool raiseRefCheck(int axis, double reference, uint32_t offset);
  // The dialect's stored-stroke-limit alarm for a move that would leave the travel range.
  bool raiseTravel(const TravelViolation& violation, uint32_t offset);
  // An arc whose end point is not on its circle (beyond arc_radius_tolerance): no compiled
  // program holds one, and an edited file could make it a spiral of hours.
  bool raiseArcRadius(double start_radius, double end_radius, uint32_t offset);
  SourcePosition where(uint32_t offset);
  // SKIP: where the move stops on the probe, and the skip position into its result variables.
  bool skip(const bytecode::Instruction& in, MotionPrimitive& m, uint32_t offset);
  bool pop(Value& out, uint32_t offset);
  bool push(Value v, uint32_t offset);
  // The next instruction: decoded at pc_, or after PREPARE the next prepared one. False
  // (with finished_ set) at the end of the prepared program or on an alarm.
  bool fetch(bytecode::Instruction& in, uint32_t& at);

  const bytecode::Program& program_;
  bytecode::CodeView code_;             // the program's code and line table
  std::size_t line_hint_ = 0;  // the line entry where() found last (program order)
  const int axis_count_;
  const std::vector<AxisConfig> axes_;   // travel limits (a copy, sized once)
  const TravelAlarmCodes travel_alarms_;  // of the program's dialect
  const double arc_radius_tolerance_;     // [machine.params] arc_radius_tolerance, as compiled
  const ProbeConfig probe_;               // the simulated skip signal (SKIP, G31)
  AxisValues position_{};
  std::vector<Value> variables_;  // sized once: header.variable_count
  std::array<Value, bytecode::kMaxStackDepth> stack_{};
  int stack_size_ = 0;
  uint32_t pc_ = 0;
  // After PREPARE: the instructions of the blocks prepared at run time, and where the one
  // being run comes from.
  std::unique_ptr<BlockPreparation> preparation_;
  bool preparing_ = false;
  std::vector<PreparedInstruction> prepared_;
  std::size_t prepared_next_ = 0;
  SourcePosition prepared_where_;
  uint64_t steps_ = 0;
  uint64_t step_limit_ = 0;
  double clock_ = 0.0;
  bool finished_ = false;
  std::optional<Alarm> alarm_;
};

}  // namespace ncc::vm
