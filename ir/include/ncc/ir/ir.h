#pragma once
// The IR: a stream of canonical blocks. Every block says everything explicitly (the modal
// state in force, the frame of offsets, its operations with absolute targets in normalised
// units: mm, degrees, seconds, mm/min) so no pass re-derives modal state. Blocks flow through
// the passes one at a time (streaming); no pass needs the whole program.
//
// Coordinates: lowering emits targets in the *work* space (program coordinates after unit
// normalisation and G90/G91 resolution; G53 and reference returns are already machine space).
// The coordinate-transform pass adds the block's frame and marks them Machine. The backend
// accepts machine-space operations only (the verifier checks this).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "absl/container/inlined_vector.h"
#include "ncc/machine/axes.h"
#include "ncc/support/inline_string.h"
#include "ncc/support/source_location.h"

namespace ncc::ir {

enum class Space : uint8_t { Work, Machine };
enum class Plane : uint8_t { XY, ZX, YZ };              // G17, G18, G19
enum class DistanceMode : uint8_t { Absolute, Incremental };  // G90, G91
enum class Units : uint8_t { Millimetre, Inch };          // G21, G20 (input unit)
enum class FeedMode : uint8_t { PerMinute, PerRevolution, InverseTime };  // G94, G95, G93
enum class PathControl : uint8_t { Continuous, ExactStop, Tapping, CornerOverride };  // G64 G61 G63 G62
enum class RapidType : uint8_t { Linear, PerAxis };  // G00 interpolation type (parameter)

// Modal state in force for the block (after its own G codes took effect).
// A work offset's name, "G54" or "G54.1P300": inline, as every block carries it. The machine
// file's names are at most 9 characters (G54.1P<n>, n <= 300).
using WorkOffsetName = InlineString<15>;

struct Modal {
  Plane plane = Plane::XY;
  DistanceMode distance = DistanceMode::Absolute;
  Units units = Units::Millimetre;
  FeedMode feed_mode = FeedMode::PerMinute;
  PathControl path = PathControl::Continuous;
  WorkOffsetName work_offset = "G54";  // name as in MachineConfig::work_offsets
  int length_offset_h = 0;          // H register in force (0 = none)
  int length_offset_sign = 0;       // +1 G43, -1 G44, 0 G49
  double feed = 0.0;                // modal F, normalised (mm/min, or mm/rev in G95)
  double spindle_speed = 0.0;       // modal S, rev/min
  int tool = 0;                     // T selected
  friend bool operator==(const Modal&, const Modal&) = default;
};

// The translation from work to machine coordinates in force for the block, per axis:
// machine = work + work_offset + shift + tool_length.
struct Frame {
  AxisValues work_offset{};   // G54..G59 / G54.1 Pn (possibly rewritten by G10)
  AxisValues shift{};         // G92 / G52 combined
  AxisValues tool_length{};   // G43/G44 H: the tool-length vector
  AxisValues total() const {
    AxisValues t{};
    for (int i = 0; i < kMaxAxes; ++i) t[i] = work_offset[i] + shift[i] + tool_length[i];
    return t;
  }
  friend bool operator==(const Frame&, const Frame&) = default;
};

// A map of programmed points onto the points the tool goes to, on the X, Y and Z axes (their
// machine indices in `axes`, -1 where the machine has none): p' = m p + t, m row-major. The
// lowering composes it from the modes in force (G68 rotation, G51 scaling, G51.1 mirror, Mazak
// figure rotation) in the order the dialect's manual states (passes/src/affine.h builds and
// composes them; docs/transforms.md).
struct Affine {
  std::array<double, 9> m{1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::array<double, 3> t{};
  std::array<int8_t, 3> axes{0, 1, 2};
  friend bool operator==(const Affine&, const Affine&) = default;
};

// The transforms in force for the block; the `transform` pass applies them to its work-space
// targets and clears them. `work` acts in work coordinates; `machine` (Mazak G92.5 work
// coordinate rotation) about a point given in machine coordinates: it acts on work + frame.
struct Transform {
  std::optional<Affine> work;
  std::optional<Affine> machine;
  bool any() const { return work.has_value() || machine.has_value(); }
  friend bool operator==(const Transform&, const Transform&) = default;
};

struct Rapid {
  AxisValues to{};  // every configured axis, absolute
  Space space = Space::Work;
  RapidType type = RapidType::Linear;
};

struct Linear {
  AxisValues to{};
  Space space = Space::Work;
  double feed = 0.0;          // mm/min, or mm/rev when feed_per_rev
  bool feed_per_rev = false;
};

struct Arc {
  AxisValues to{};      // end point, every configured axis (helical: the linear axis moves too)
  AxisValues center{};  // centre; only the two plane axes are meaningful
  Space space = Space::Work;
  Plane plane = Plane::XY;
  bool clockwise = true;    // seen from the positive third axis (for G18: from +Y)
  uint32_t extra_turns = 0; // full circles beyond the first (reserved; helical L)
  double feed = 0.0;
  bool feed_per_rev = false;
};

// G31 skip: a linear move at `feed` towards `to` that ends where the skip signal comes on
// (the simulated probe, [machine.probe]), or at `to` when it never does. The VM stores the
// point it stopped at, in work coordinates, in the skip-position variables; the compiler
// does not know it (docs/semantics.md, Skip).
struct Skip {
  AxisValues to{};
  Space space = Space::Work;
  double feed = 0.0;            // mm/min, or mm/rev when feed_per_rev
  bool feed_per_rev = false;
  uint32_t first_variable = 0;  // axis i's skip position goes to #(first_variable + i); 0: none
  bool inch_variables = false;  // G20: the variables hold inches (linear axes)
};

struct Dwell {
  double seconds = 0.0;
  bool revolutions = false;  // true: `seconds` holds spindle revolutions (G95 dwell parameter)
};

// A non-motion machine function, in program order within the block.
struct MachineFunction {
  enum class Kind : uint8_t {
    ProgramStop,      // M00
    OptionalStop,     // M01
    ProgramEnd,       // M02
    ProgramEndRewind, // M30
    SpindleCW,        // M03
    SpindleCCW,       // M04
    SpindleStop,      // M05
    ToolChange,       // M06
    CoolantOn,        // M08
    CoolantOff,       // M09
    SpindleOrient,    // M19
    OtherM,           // any other M code, passed through (code)
    SpindleSpeed,     // S (value rev/min)
    ToolSelect,       // T (code)
  };
  Kind kind = Kind::OtherM;
  int64_t code = 0;   // the M or T number
  double value = 0.0; // S speed
};

// A position check (G27): the commanded position must equal the reference position.
struct ReferenceCheck {
  AxisValues position{};  // machine coordinates reached
  AxisMask axes = 0;
  int reference = 1;
};

// A macro variable written by the program (`#100 = 5`), in program order among the moves, so
// that the VM holds every variable as the program left it (`ncc run --emit=vars`).
struct SetVariable {
  uint32_t number = 0;
  double value = 0.0;
  bool vacant = false;  // `#100 = #0`: the variable becomes vacant again
  // A DIN variable's name (`R10`, `COUNT`, `A[1,2]`; eval/named_variables.h), which the
  // bytecode keeps for printing; empty for `#n`. Inline, so that the op copies as bytes: a name
  // is at most 31 characters and 3 indices.
  InlineString<55> name;
};

// The rest of the program is prepared while it runs (docs/runtime.md): a value it needs is
// known only then (where a G31 stopped, an interface signal), or --defer asked for it. The
// VM's block preparation goes on from here with the same evaluation and lowering, reading
// `store`, the encoded block store (eval/block_store.h): the parsed blocks of every program
// the run may reach and how many blocks were prepared ahead. Nothing follows it.
struct Prepare {
  std::shared_ptr<const std::vector<uint8_t>> store;
  uint64_t ahead_blocks = 0;  // blocks prepared by the compiler before this one
  uint32_t files = 0;         // files in the store (for printing)
  uint64_t blocks = 0;        // blocks in the store (for printing)
};

// One hole of a canned hole cycle (G73-G89), in work space, as lowering decoded it
// (passes/src/lowering_cycles.cpp): where the hole is, the levels on the drilling axis and what
// the cycle does there. The `cycles` pass (passes/src/cycle_expansion.cpp) replaces it by its
// rapid, feed, dwell and spindle operations before work-to-machine; the backend never sees it.
// docs/cycles.md gives each cycle's sequence.
struct HoleCycle {
  // What happens between R and the bottom (the dialect's cycle table maps G codes to these).
  enum class Kind : uint8_t {
    Drill,          // feed to the bottom (G81, G82, G85, G86, G89)
    HighSpeedPeck,  // feed Q, back off d, feed d + Q, ... (G73)
    Peck,           // feed Q, rapid to R, rapid to d above the last depth, ... (G83)
    Tap,            // feed in, reverse the spindle at the bottom, feed out (G84, G74)
    FineBore,       // feed in, orient the spindle, shift off the wall, rapid out (G76)
    BackBore,       // oriented and shifted down to R below the part, bore up to Z (G87)
  };
  Kind kind = Kind::Drill;
  int code10 = 0;           // the G code x 10, for printing and messages
  int axis = 2;             // the drilling axis (the plane's normal)
  AxisValues from{};        // where the tool is before the cycle
  AxisValues hole{};        // the hole position (the drilling axis: from's level, unchanged)
  double initial = 0.0;     // the initial level (latched at the first cycle block)
  double r_level = 0.0;     // the R level
  double bottom = 0.0;      // the hole bottom (Z)
  bool return_to_r = false; // G99: the cycle ends at R; G98: at the initial level
  double feed = 0.0;        // the cutting feed, mm/min, or mm/rev when feed_per_rev
  bool feed_per_rev = false;
  bool positioning_by_feed = false;  // the plane positioning is a G01 move (Mazak: group 01 mode)
  RapidType rapid_type = RapidType::Linear;
  double peck = 0.0;           // Q: the depth of each infeed
  double peck_distance = 0.0;  // d: the back-off (G73) or the stop above the last depth (G83)
  double peck_retract_feed = 0.0;  // G73 back-off at this feed (Mazak 9999 mm/min); 0: rapid
  double dwell = 0.0;          // seconds at the bottom (P), 0: none
  bool dwell_revolutions = false;
  bool feed_out = false;       // the way back to R is a feed (G85, G89, tapping)
  double retract_feed = 0.0;   // the feed of that way back
  bool stop_spindle_at_bottom = false;  // G86: M05 at the bottom, rapid out, M03/M04 again
  bool program_stop_at_bottom = false;  // G88: and M00 (the operator's manual moves) after it
  int spindle_direction = 1;   // +1 M03, -1 M04: the direction the cycle restores
  bool dwell_at_r = false;     // tapping: the dwell P also at R after the way out (FANUC)
  // Tapping with `peck` > 0 (deep-hole tapping, FANUC rigid G84/G74 with Q, Siemens
  // _ZSFI[1] = 2/3): back off `peck_distance` after each infeed (high speed), or out to R and
  // back to `peck_distance` above the last depth (`peck_tap_to_r`), at `peck_approach_feed`.
  bool peck_tap_to_r = false;
  double peck_approach_feed = 0.0;
  // Mazak §13-1: the feed starts `feed_start` below R (a rapid down to there first); an infeed
  // that starts within `slow_zone` of the bottom runs at `slow_feed` (I, J).
  double feed_start = 0.0;
  double slow_zone = 0.0;
  double slow_feed = 0.0;
  AxisValues shift{};          // G76: the shift off the wall at the bottom (a work-space vector)
};

using Operation = std::variant<Rapid, Linear, Arc, Skip, Dwell, MachineFunction, ReferenceCheck,
                               SetVariable, Prepare, HoleCycle>;

// A move of the tool to a target: G00, G01, G02/G03, G31 (a hole cycle is expanded into them).
inline bool isMove(const Operation& op) {
  return std::holds_alternative<Rapid>(op) || std::holds_alternative<Linear>(op) ||
         std::holds_alternative<Arc>(op) || std::holds_alternative<Skip>(op);
}

// `,C` / `,R` at the end of a G01/G02/G03 block: a chamfer (legs of `amount`) or a rounding
// arc (radius `amount`) between the block's move and the next block's. The corners pass
// inserts it and clears the request (docs/semantics.md, Corner chamfer and rounding).
struct CornerRequest {
  // Chamfer: `amount` from the corner along each move (,C; Siemens CHR); Round: the radius
  // (,R; RND); ChamferLength: the chamfer's own length (Siemens CHF).
  enum class Kind : uint8_t { Chamfer, Round, ChamferLength } kind = Kind::Chamfer;
  double amount = 0.0;  // mm
  AxisValues from{};    // where the block's move starts (work space)
  int plane_a = 0, plane_b = 1;  // the machine axes of the plane in force (first, second)
  SourceLocation loc;   // the ,C / ,R word
};

// Cutter radius compensation (G40/G41/G42 with D, G38, G39, and the I J K vectors), as the
// lowering decoded it for a block while compensation is in force or being cancelled: the
// `compensation` pass turns the block's moves into the tool centre's path and clears it
// (passes/src/compensation/, docs/compensation.md). Lowering knows nothing else of it.
struct CutterComp {
  enum class Side : uint8_t { Off, Left, Right };  // G40, G41, G42 in force after the block
  enum class Startup : uint8_t { A, B, C };        // start-up and cancel type (a parameter)
  enum class Special : uint8_t { None, VectorHold, CornerArc };  // G38, G39 (one-shot)
  Side side = Side::Off;
  double radius = 0.0;   // the D register in force, mm; a negative value swaps the side
  int d_number = 0;      // for messages; Mazak/Siemens D00 is radius 0
  int plane_a = 0, plane_b = 1;  // the machine axes of the plane in force (first, second)
  int plane_normal = 2;          // and of its normal (-1: the machine has none)
  bool side_commanded = false;  // G41/G42 written in this block (FANUC: same side again)
  Special special = Special::None;
  bool suspended = false;  // a hole cycle's block: its moves run on the programmed points
  // I J K written with G00/G01 (the end vector is perpendicular to it: FANUC IJ-type vector),
  // with G40 (the direction of a virtual next move), with G39 (the corner arc's end) or with
  // Mazak G38 (a new vector direction): work-space components on X, Y, Z, the plane's two used.
  std::optional<std::array<double, 3>> vector;
  // Mazak 3-D compensation (G41/G42 with I J K): the tool is offset by this work-space vector,
  // r (I,J,K)/|I,J,K| (G41) or its negative (G42), instead of the plane's 2-D offset.
  std::optional<std::array<double, 3>> offset_3d;
  // The dialect's rules and the machine's parameters, recorded so the pass needs nothing else.
  Startup startup = Startup::A;
  bool arc_corners = false;      // outer corners joined by an arc about the corner (FANUC CCC=1)
  int lookahead = 3;             // blocks read ahead (FANUC No.19625, Mazak 5, Siemens 2)
  int max_without_motion = 1;    // blocks without motion in the plane that keep the corner
  bool interference_check = true;
  // An interference between three moves is avoided by leaving the middle one out (FANUC CAV = 1,
  // Mazak F92 bit 5 = 1); false: the alarm.
  bool interference_avoidance = false;
  // G41 again in G41 mode (G42 in G42): the move before ends perpendicular to itself (FANUC
  // §5.4); false: ignored (Mazak).
  bool recommand_perpendicular = false;
  // A change of side runs over its block from perpendicular (old side) to perpendicular (new
  // side) (Siemens §3.5.3); false: the corner is where the old and new offset paths meet (FANUC).
  bool side_change_perpendicular = false;
  double corner_move_limit = 0.0;  // corner moves no longer than this are dropped (FANUC No.5010), mm
  SourceLocation loc;            // the G41/G42/G40 (or D) word, for messages
  friend bool operator==(const CutterComp&, const CutterComp&) = default;
};

// A block's operations: nearly every block has one, held in place (a vector would take a heap
// allocation per block on the compiler's hottest path).
using Operations = absl::InlinedVector<Operation, 1>;

struct Block {
  SourceLocation loc;
  int64_t sequence = -1;  // N number, -1 if none
  Modal modal;
  Frame frame;
  Transform transform;       // lowering -> transform pass only
  bool exact_stop = false;   // G09 in this block, or G61 in force
  Operations ops;
  std::optional<CornerRequest> corner;  // lowering -> corners pass only
  std::optional<CutterComp> comp;       // lowering -> compensation pass only
};

// A block made only of variable writes (`#100 = 1`): no step of the path, which look-ahead
// passes hold beside the block before it.
inline bool onlyVariableWrites(const Block& b) {
  if (b.ops.empty()) return false;
  for (const Operation& op : b.ops)
    if (!std::holds_alternative<SetVariable>(op)) return false;
  return true;
}

// A block that leaves the rest of the program to the VM's preparation (ir::Prepare): a
// look-ahead pass drops what it holds, the VM prepares those blocks again.
inline bool hasPrepare(const Block& b) {
  for (const Operation& op : b.ops)
    if (std::holds_alternative<Prepare>(op)) return true;
  return false;
}

// A pass or the backend: receives blocks one at a time. finish() is called once at the end
// (a look-ahead pass flushes what it holds there).
class BlockSink {
 public:
  virtual ~BlockSink() = default;
  // The block is the sink's to keep or change: one that only looks at it and forwards it moves
  // nothing (a block is large: passing it by reference through each stage saves a copy).
  virtual void accept(Block&& block) = 0;
  virtual void finish() = 0;
};

}  // namespace ncc::ir
