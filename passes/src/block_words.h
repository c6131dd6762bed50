#pragma once
// First step of lowering a block: sort its words by meaning. G codes are looked up in the
// dialect table and checked against the same-group policy; every other word is classified
// (axis, centre, feed, ...), checked for repeats and macro expressions, and tagged with the
// G90/G91 mode that applies to it. Nothing here changes the controller state.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "ncc/frontend/ast.h"
#include "ncc/ir/ir.h"
#include "ncc/machine/machine_config.h"
#include "ncc/passes/dialect_table.h"
#include "ncc/support/diagnostics.h"

namespace ncc::passes {

enum class SameGroupPolicy : uint8_t { Error, LastWins, PerWord };

struct WordValue {
  double value = 0.0;
  bool point = false;
  SourceLocation loc;
  ir::DistanceMode mode = ir::DistanceMode::Absolute;  // G90/G91 in force for this word
  // The address as written (the syntax tree's word, or a machine axis name): both outlive the
  // block's lowering, the only time a WordValue lives.
  std::string_view address;
  int order = 0;  // position among the block's words (Mazak reads `X5. G04` differently)
};

struct GWord {
  const GCodeEntry* entry = nullptr;
  SourceLocation loc;
  int order = 0;
};

struct DecodedBlock {
  // Modal G codes by group (the effective one after the same-group policy), one-shot code.
  std::array<std::optional<GWord>, static_cast<size_t>(GGroup::Other) + 1> modal;
  std::optional<GWord> one_shot;  // G04 G10 G27 G28 G30 G52 G53 G92 G92.1
  std::optional<GWord> exact_stop;  // G09
  // G38 / G39 (cutter compensation, one-shot): the block's move (G38) or its lack (G39) is
  // lowered as usual, so they are kept apart from `one_shot`.
  std::optional<GWord> comp_special;
  std::array<std::optional<WordValue>, kMaxAxes> axes;
  std::optional<WordValue> i, j, k, r, f, s, h, d, p, l, q;
  std::vector<WordValue> t, m;
  std::optional<WordValue> corner;  // ,C (chamfer) or ,R (rounding)
  std::optional<WordValue> line_angle;  // Mazak A (not an axis): the angle of a G01 line
  // DIN frame instruction (TRANS ...; lowering_frames.cpp) and its angle in the plane (RPL=).
  const FrameCommand* frame = nullptr;
  std::optional<WordValue> rpl;
  std::string_view corner_kind() const { return corner ? corner->address : std::string_view(); }
  std::optional<SourceLocation> first_axis_loc;

  const std::optional<GWord>& group(GGroup g) const { return modal[static_cast<size_t>(g)]; }
  bool anyAxis() const {
    for (const auto& a : axes)
      if (a) return true;
    return false;
  }
  // The axis whose word is a time in this block, not a position (G04 X), or -1: the format
  // checks and the decimal-point audit read it alike.
  int timeAxis(const MachineConfig& machine) const {
    return one_shot && one_shot->entry->action == GAction::Dwell ? machine.axisIndex("X") : -1;
  }
};

// Where each one-letter address goes in a DecodedBlock, for one dialect and machine: built
// once, so that sorting a word is an index, not a row of name comparisons.
class AddressMap {
 public:
  enum class Slot : uint8_t { Other, Axis, I, J, K, R, F, S, P, L, Q, H, D, M, T, LineAngle };
  AddressMap(const DialectTable& table, const MachineConfig& machine);
  // Slot::Other for an address that is not one letter or that no slot takes (it is then
  // reported by name).
  Slot slot(std::string_view address) const {
    if (address.size() != 1) return Slot::Other;
    const unsigned i = static_cast<unsigned>(address[0] - 'A');
    return i < 26 ? slots_[i] : Slot::Other;
  }
  int axis(std::string_view address) const { return axes_[static_cast<unsigned>(address[0] - 'A')]; }

 private:
  std::array<Slot, 26> slots_{};
  std::array<int8_t, 26> axes_{};
};

struct DecodeContext {
  const DialectTable& table;
  const MachineConfig& machine;
  const AddressMap& addresses;
  SameGroupPolicy policy;
  ir::DistanceMode modal_distance;  // G90/G91 before the block
  DiagnosticEngine& diags;
  bool cycle_in_force = false;      // a hole cycle is in force: Q is cycle data
  // A block that will be lowered only at run time (after a value known then): only what holds
  // whatever the values and the state are is checked (addresses, literal G codes, repeated
  // words); a word with an expression, the statements and Q's context are left to run time.
  bool statically = false;
};

// Returns nullopt (after reporting) when the block has an error.
std::optional<DecodedBlock> decodeBlock(const ast::Block& block, const DecodeContext& ctx);
// The same into `out` (default-constructed): false (after reporting) on an error. Lowering
// decodes every block this way, without moving the large DecodedBlock.
bool decodeBlock(const ast::Block& block, const DecodeContext& ctx, DecodedBlock& out);

}  // namespace ncc::passes
