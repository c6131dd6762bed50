#pragma once
// The state lowering shares between its concepts, and the entry points of each concept.
//
// Lowering is one modal-state machine, but its semantics fall into independent concepts;
// each lives in its own file and sees the block only through BlockContext:
//   lowering.cpp                   block driver: decode, modal groups, dispatch, unused
//                                  words, commit (and the public Lowering class)
//   lowering_motion.cpp            G00/G01/G02/G03 and F
//   lowering_coordinates.cpp       G54.. selection, G52, G53, G92, G92.1, G10 L2/L20
//   lowering_tool_offsets.cpp      H with G43/G44/G49, D, G10 L10-L13
//   lowering_reference.cpp         G27, G28, G30
//   lowering_skip.cpp              G31 skip, and the blocks after it that need where it stopped
//   lowering_machine_functions.cpp G04 dwell, S, T, M
//   lowering_cycles.cpp            G73-G89 hole cycles, G80, G98/G99, M29
//   lowering_position_offset.cpp   Mazak G45-G48
//   lowering_polar.cpp             G15/G16: radius and angle words into Cartesian ones
//   lowering_transforms.cpp        G68/G69, G51/G50, G51.1/G50.1, G92.5 into TransformState
//   lowering_transform_map.cpp     the transforms as one map; the tool under it
//   lowering_figure_rotation.cpp   Mazak's figure rotation (M98 I J K L)
//   lowering_frames.cpp            DIN programmable frame: TRANS, ROT, SCALE, MIRROR (A-forms)
//   lowering_cutter_comp.cpp       G40/G41/G42, D, G38/G39: the block's ir::CutterComp
//   lowering_recovery.cpp          after a rejected block: what is unknown, which later
//                                  blocks depend on it (skipped without a diagnostic)
//   lowering_context.cpp           the helpers below, shared by all of them
//
// A block is lowered on a copy of the controller state (BlockContext::next); the driver
// makes it LoweringCore::cs() only when no concept reported an error.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "block_words.h"
#include "controller_state.h"
#include "decimal_point_audit.h"
#include "lowering_settings.h"
#include "system_variables.h"
#include "ncc/passes/lowering.h"

namespace ncc::passes {

inline constexpr double kSamePoint = 1e-9;      // mm: "end equals start"
inline constexpr double kPositionCheck = 1e-6;  // mm: G27 reference position check

// A length in mm as diagnostics print it.
std::string mm(double v);

// The frame in force for a controller state (work offset + external, G92 + G52, tool length).
ir::Frame frameOf(const ControllerState& cs, const DialectBehaviour& b);
// The G52 shift that applies to the selected work system (shared or per work system).
AxisValues& localOf(ControllerState& cs, const DialectBehaviour& b);

// G16: a block's words on the plane's first axis (the radius) and second axis (the angle), as
// written; `first`/`second` are the axis indices (lowering_polar.cpp).
struct PolarWords {
  int first = -1, second = -1;
  std::optional<WordValue> radius, angle;
};

// Everything lowering keeps between blocks.
struct LoweringCore {
  LoweringOptions options;
  DiagnosticEngine& diags;
  ir::BlockSink& out;
  MachineConfig fallback_machine;
  const MachineConfig* machine = nullptr;
  // The table, address map and settings of the language of the block being lowered
  // (useLanguage); null table: the dialect is not lowered.
  const DialectTable* table = nullptr;
  const AddressMap* addresses = nullptr;
  LoweringSettings settings;
  // Each language the dialect reads (languageTables): its table, and what is built from it
  // once. One controller state serves both: a switch keeps tool, offsets and frames.
  struct LanguageLowering {
    const DialectTable* table = nullptr;
    std::optional<AddressMap> addresses;
    LoweringSettings settings;
  };
  std::array<LanguageLowering, 2> languages;
  frontend::Language language = frontend::Language::Iso;
  // Lowers the next blocks with `l`'s table; false (nothing changed) when the dialect has none.
  bool useLanguage(frontend::Language l);
  // table, addresses, settings and language from languages[l] (which has a table).
  void bindLanguage(frontend::Language l);
  // The controller state between blocks.
  ControllerState& cs() { return states_[current_]; }
  const ControllerState& cs() const { return states_[current_]; }
  // The state a block is lowered on (BlockContext::next): cs() copied into the other buffer.
  ControllerState& beginBlock() {
    states_[current_ ^ 1u] = states_[current_];
    return states_[current_ ^ 1u];
  }
  // beginBlock()'s state becomes cs(): the buffers swap roles, so a block costs one copy of
  // the state into storage it reuses, not a copy, a move and a destruction.
  void commitBlock() { current_ ^= 1u; }
  OffsetTables tables;
  DecimalPointAudit decimal_points;  // coordinate words without a point, over the file
  bool reported_dialect = false;
  ControllerVariables system_variables{*this};  // the system variables: views of cs, tables
  // Interface outputs #1100-#1131 (one bit each) and #1133-#1135 (words), as last written:
  // kept until power-off (Mazak §13-9-4 4. note 1). Not per block: not in ControllerState.
  std::array<double, 36> output_signals{};
  // Timers #3001/#3002: the value written last and the run's time then (0 and 0 at the start).
  struct TimerBase {
    double value = 0.0;
    double seconds = 0.0;
  };
  std::array<TimerBase, 2> timers{};
  std::array<int8_t, 3> xyz{-1, -1, -1};  // the machine indices of X, Y, Z (-1: none)

  LoweringCore(LoweringOptions o, DiagnosticEngine& d, ir::BlockSink& s);

  // The power-on state: the table's '*' codes, overridden by the reset_* parameters.
  void powerOn();
  // At run time: the axes a G31 moved take the position where it stopped (ahead of time
  // they stay unknown, ControllerState::skip_axes).
  void resolveSkip();
  // The running machine, or null (the compiler, or the VM replaying what the compiler did).
  const RunTimeState* running() const {
    return options.run_time && options.run_time->running() ? options.run_time : nullptr;
  }

 private:
  std::array<ControllerState, 2> states_;
  unsigned current_ = 0;
};

// One block being lowered: its decoded words, the state it produces, the IR it emits and the
// offset-table writes it will commit. Also the small helpers every concept needs.
struct BlockContext {
  BlockContext(LoweringCore& st, const ast::Block& b)
      : core(st),
        block(b),
        table(*st.table),
        behaviour(table.behaviour),
        settings(st.settings),
        next(st.beginBlock()) {}

  LoweringCore& core;
  const ast::Block& block;
  const DialectTable& table;
  const DialectBehaviour& behaviour;
  const LoweringSettings& settings;
  ControllerState& next;  // the controller state after the block (LoweringCore::beginBlock)
  DecodedBlock words;
  ir::Operations ops;
  std::vector<TableWrite> table_writes;
  // A length-offset change not yet traversed on the length axis: axis and amount. It moves
  // the axis when the axis is programmed incrementally or, unless `length_delta_deferred`
  // (Siemens: only when the axis is programmed), when it is not programmed at all.
  int length_delta_axis = -1;
  double length_delta = 0.0;
  bool length_delta_deferred = false;
  // Words some code of the block has read; the rest are reported as having no meaning.
  bool used_ijk = false, used_r = false, used_p = false, used_l = false, used_angle = false;
  // ,C / ,R of a G01-G03 move: recorded on the IR block for the corners pass.
  std::optional<ir::CornerRequest> corner;
  // G45-G48: the signed amount (+-1 or 2 x the D offset, mm) each move lengthens by.
  double position_offset = 0.0;
  bool used_k = false, used_q = false;  // K as a cycle's repeat count, Q as cycle data
  // The axes a G31 in this block moves: where they stop is known only at run time.
  AxisMask skip_moved = 0;
  // G16: the block's plane words as written, before convertPolarWords made them Cartesian.
  std::optional<PolarWords> polar;
  // Cutter compensation: the block's record for the compensation pass (lowering_cutter_comp.cpp).
  std::optional<ir::CutterComp> comp;
  bool failed = false;
  // The block depends on unknown state (lowering_recovery.cpp): it is lowered for its effects
  // on the state only, and its errors are not reported (they would be consequences).
  bool silent = false;

  // ---- diagnostics and values ----
  // Reports an error with the dialect's alarm number (unless `silent`); the block then
  // produces no IR.
  void fail(Alarm a, SourceLocation loc, std::string message);
  // The block needs a value known only when the program runs: no IR, no diagnostic, no state
  // change; the compiler leaves the rest to the VM (LowerResult::needs_run_time).
  void needRunTime(SourceLocation loc, std::string why);
  std::optional<eval::Failure> needs_run_time;
  // The integer value of an address such as H, D, P, L, M (nullopt after reporting).
  std::optional<int64_t> integer(const WordValue& w);
  // Every word of the block against its format (format_digits): integer addresses by their
  // digits, values by their least input increments. F is checked by applyFeed.
  void checkFormats();
  // Reports (TooManyDigits) an integer word with more digits than the format allows.
  bool integerFits(const WordValue& w);

  bool isRotary(int axis) const;
  // An axis word normalised for its axis kind (mm or degrees).
  double axisValue(int axis, const WordValue& w) const;
  // A length (R, I/J/K) normalised to mm.
  double lengthValue(const WordValue& w) const;
  int axisCount() const;
  int axisNamed(const char* name) const;
  AxisMask namedAxes() const;
  // Where to report a motion error: the G code, else the first axis word, else the block.
  SourceLocation motionLoc() const;
  bool samePosition(const AxisValues& a, const AxisValues& b) const;
  AxisValues toMachine(const AxisValues& work, const ir::Frame& f) const;
  // The work position the block's axis words start from, under the block's new frame. On the
  // length axis an untraversed length change is added (the start point in the old frame)
  // when the change moves now: the axis not programmed (G43 H alone) or programmed
  // incrementally (Mazak §12-2: move = ±z + (new length − old length)).
  AxisValues baseWork() const;
  AxisValues baseWork(const ir::Frame& frame) const;  // frame: frameOf(next), already at hand
  // The block programs the length axis of a pending length change: it is taken up.
  void lengthChangeTraversed();
  // Work-space targets: programmed axes absolute or incremental per word, others unchanged.
  AxisValues workTargets(const AxisValues& base) const;
};

// ---- lowering_motion.cpp ----
// F: feed rate (or F1-digit preset) into the modal state.
void applyFeed(BlockContext& ctx);
// The move of a block without a one-shot code, in the group 01 mode in force.
void lowerMotion(BlockContext& ctx);
// A cutting move's feed: reports FeedMissing when none is in force (G93: when the block has
// none); `inverse_time_needs_f`: G93 needs an F in the block itself.
bool checkFeed(BlockContext& ctx, bool inverse_time_needs_f);

// ---- lowering_position_offset.cpp ----
// G45-G48: the block's move in the group 01 mode, each named axis's move lengthened by the
// signed offset amount (Mazak §12-3).
void positionOffsetMove(BlockContext& ctx, const GWord& g);
// Under G45-G48: `target` with each named axis's move from `start` lengthened; an arc's centre
// offset or radius (`length`, non-zero) likewise. Unchanged without G45-G48.
void applyPositionOffset(const BlockContext& ctx, const AxisValues& start, AxisValues& target);
double positionOffsetLength(const BlockContext& ctx, double length);

// ---- lowering_skip.cpp ----
// G31: the skip move; the axes it moves are known only at run time afterwards.
void skipMove(BlockContext& ctx, const GWord& g);
// A block that needs the position where an earlier G31 stopped (an incremental word on such
// an axis, G92 naming it, a move that leaves it where it is) needs the run time
// (BlockContext::needRunTime); an absolute word makes the axis known again.
void checkSkipDependence(BlockContext& ctx);

// ---- lowering_coordinates.cpp ----
// G54-G59, G54.1 P / G54 P: selects the work system named by the group's code.
void selectWorkOffset(BlockContext& ctx, const GWord& w);
void machineCoordinateMove(BlockContext& ctx, const GWord& g);  // G53
void localShift(BlockContext& ctx, const GWord& g);             // G52
void setShift(BlockContext& ctx);                               // G92
void resetShift(BlockContext& ctx, const GWord& g);             // G92.1
// G10 L2 / L20: writes a work offset (or the external offset, L2 P0).
void dataSetWork(BlockContext& ctx, const GWord& g, int l, bool add);

// ---- lowering_tool_offsets.cpp ----
// H with G43/G44/G49: the tool length applied on the length axis.
void applyLengthOffset(BlockContext& ctx);
// D: selects the radius offset number.
void applyRadiusOffsetNumber(BlockContext& ctx);
// G10 L10-L13: writes a tool length/radius (wear) register.
void dataSetRegister(BlockContext& ctx, const GWord& g, int l, bool add);

// ---- lowering_reference.cpp ----
void referenceCheck(BlockContext& ctx, const GWord& g);  // G27
// G28 (n = 1) / G30 (the P number).
void referenceReturn(BlockContext& ctx, const GWord& g, int n);
// G30 / G27 P: the reference point number, `fallback` without P or after an error.
int referenceNumber(BlockContext& ctx, const GWord& g, int fallback);

// ---- lowering_recovery.cpp ----
// A block rejected with a diagnostic: what it would have written becomes unknown in `cs`
// (the axes it names, the modal groups of its G codes, F). Read from the AST, since the
// block may not have decoded.
void forgetRejected(ControllerState& cs, const ast::Block& block, const DialectTable& table,
                    const MachineConfig& machine);
// A block that could not be read at all (a syntax error): anything may have changed.
void forgetEverything(ControllerState& cs);
// Whether judging the block (decoded, its modal codes applied to `next`) needs state that
// is unknown; such parts are lowered `silent`. `words`: its words themselves (formats, F, H:
// units or the motion mode unknown); `motion`: its motion or one-shot code (start point,
// G90/G91, plane, feed). Faults of words that do not depend are still reported.
struct Dependence {
  bool words = false;
  bool motion = false;
};
Dependence dependsOnUnknown(const BlockContext& ctx);
// After a block is lowered (reported or silent): the unknowns it determines again. A modal
// code re-knows its group, F the feed, an absolute axis word its axis (`next.position` is
// set from the word when the block itself did not get to it); an axis the block named on an
// unknown base stays unknown.
void relearn(BlockContext& ctx);

// ---- lowering_cycles.cpp ----
// G73-G89, G80, G98/G99 and a group-01 code into the cycle state; M03/M04/M05 into the
// spindle direction the cycles read. Before the block's motion.
void applyCycleCodes(BlockContext& ctx);
// Whether the block is a cycle block (a cycle in force and no one-shot code).
bool inCycle(const BlockContext& ctx);
// A cycle block of a dialect whose repeat count is K (K is then no length).
bool repeatCountIsK(const BlockContext& ctx);
// A block in cycle mode: its cycle words into the cycle state, one ir::HoleCycle per hole
// (repeats K/L), the position at the end of the last one.
void lowerCycle(BlockContext& ctx);

// ---- lowering_transforms.cpp, lowering_transform_map.cpp, lowering_figure_rotation.cpp ----
// Whether the block's axis words belong to G68, G51, G51.1 or G50.1 (centres, mirrored axes)
// rather than to a move: the block then moves nothing.
bool transformTakesAxisWords(const BlockContext& ctx);
// G68/G69, G51/G50, G51.1/G50.1 into the transform state. Before the block's motion.
void applyTransformCodes(BlockContext& ctx);
// Mazak's G50 without a move of its own: every axis goes back to its unscaled point.
void scalingCancelMove(BlockContext& ctx);
// G27/G28/G30 end scaling where the manual says so (Mazak §13-10 5.4-5.5).
void cancelScalingAfterReference(BlockContext& ctx);
void workRotation(BlockContext& ctx, const GWord& g);  // Mazak G92.5
// The transforms in force after the block, for its IR block (or in a given state).
ir::Transform transformOf(const BlockContext& ctx);
ir::Transform transformOf(const BlockContext& ctx, const ControllerState& cs);
ir::Transform transformOf(const LoweringCore& core, const ControllerState& cs);
// The machine point the tool goes to for the programmed point `position` (machine coordinates
// of the programmed point, as ControllerState::position) under the state's transforms.
AxisValues imageOf(const LoweringCore& core, const ControllerState& cs, const AxisValues& position);
// Whether the tool moves on the way to the work-space `target`: `moves` (the programmed point
// changes) unless a transform is or was in force, then whether the point it maps to changes.
bool movesUnderTransforms(const BlockContext& ctx, const AxisValues& target, bool moves);
// An arc (work space, as programmed) under the transforms in force: false after reporting
// when its image is no circle from where the tool is (unequal scaling in its plane, a plane
// tilted out of the principal ones, or a start off the circle because a transform changed
// since the last move). The controls scale and turn the end point and the centre and cut a
// circle: it is one only when the radii at both ends agree (arc_radius_tolerance).
bool arcUnderTransforms(BlockContext& ctx, const ir::Arc& arc);
// After a block that moved: where the tool now is, if not at the commanded point.
void trackTool(BlockContext& ctx);
// Mazak figure rotation (Lowering::figureRotationBegin/Run/End).
bool figureRotationBegin(LoweringCore& core, const std::array<std::optional<double>, 3>& ijk);
void figureRotationRun(LoweringCore& core, int64_t run);
void figureRotationEnd(LoweringCore& core);
// The machine coordinates of the programmed point that the transforms in force take to
// `machine` (after a move given in machine coordinates: G53, a reference return).
AxisValues programmedAt(const BlockContext& ctx, const AxisValues& machine);
AxisValues programmedAt(const LoweringCore& core, const ControllerState& cs, const AxisValues& machine);

// ---- lowering_frames.cpp ----
// Whether the block is a DIN frame instruction (TRANS X.. ...): its axis words are the
// frame's values, and it moves nothing.
bool frameTakesAxisWords(const BlockContext& ctx);
// The frame instruction into TransformState::programmable; the tool stays where it is.
void applyFrameInstruction(BlockContext& ctx);

// ---- lowering_polar.cpp ----
// G15/G16 into the state; G16 (or a plane chosen under it) in a plane whose axes the machine
// lacks is AxisMissing.
void applyPolarCode(BlockContext& ctx);
// In G16: the block's radius and angle words (the plane's first and second axis) rewritten as
// Cartesian words on both plane axes, so that every move, hole cycle and G31 reads them as
// usual: absolute where the point follows from the words alone, else incremental from the
// block's start (baseWork), so that recovery and the G31 dependence see that it rests on the
// current position. Codes whose words are no positions (G04 G10 G52 G53 G92 G92.1) keep them;
// G27/G28/G30/G45-G48 with plane words, and arcs and corners the dialect's PolarRules refuse,
// are PolarNotAllowed. The original words stay in BlockContext::polar.
void convertPolarWords(BlockContext& ctx);
// The axis whose word is an angle in this block (G16 in force, a code that reads positions),
// else -1: the decimal-point audit counts it in degrees.
int polarAngleAxis(const BlockContext& ctx);
// A hole cycle's repeat (K/L) in G16: the plane coordinates of `hole` from the block's polar
// words taken from `from` (the previous hole), as the control repeats them (`G91 Y45. K7`
// drills round a bolt circle). Unchanged without polar words.
void polarHole(const BlockContext& ctx, const AxisValues& from, AxisValues& hole);

// ---- lowering_cutter_comp.cpp ----
// G40/G41/G42 (and Mazak's D00), G38/G39 and the I J K vectors: the block checked against the
// compensation in force (start-up/cancel in an arc, plane change, G31, G28/G30, an early side
// change, a G39 move), the new state in `next.comp` and the block's record in `ctx.comp`.
// After the modal codes and D, before the block's motion.
void applyCutterComp(BlockContext& ctx);
// A G39 block: the corner arc is the compensation pass's; the block moves nothing itself.
bool cornerArcBlock(const BlockContext& ctx);
// After the block's motion and M codes: the radius (with the block's G10 writes), `suspended`
// on a hole cycle's block (Mazak 901 in 3-D), the count of compensated blocks; M02/M30
// (`program_end`) put G40 back.
void finishCutterComp(BlockContext& ctx, bool program_end);
// The record of a block lowering emits outside lowerBlock (variable writes, at `loc`) while
// compensation is in force; nullopt when it is not.
std::optional<ir::CutterComp> compensationInForce(const LoweringCore& core,
                                                  const ControllerState& cs, SourceLocation loc);

// ---- lowering_machine_functions.cpp ----
void dwell(BlockContext& ctx, const GWord& g);  // G04
// DIN G4 F (seconds) / G4 S (spindle revolutions): F and S are the dwell's, not the feed or
// the spindle speed.
void dwellFeedOrSpindle(BlockContext& ctx, const GWord& g);
inline bool isDwell(GAction a) { return a == GAction::Dwell || a == GAction::DwellFeedOrSpindle; }
// The block's F and S belong to a DIN dwell (G4 F / G4 S).
inline bool dwellTakesFeedAndSpindle(const DecodedBlock& w) {
  return w.one_shot && w.one_shot->entry->action == GAction::DwellFeedOrSpindle;
}
// S and T: spindle speed and tool number into the modal state.
void applySpindleAndToolWords(BlockContext& ctx);
// S, T and M as IR machine functions, ordered around the block's motion.
void machineFunctions(BlockContext& ctx, LowerResult& result);

}  // namespace ncc::passes
