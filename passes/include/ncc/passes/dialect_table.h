#pragma once
// The data that makes a dialect: its G-code table (group, power-on default, one-shot or
// modal, what lowering does with the code, or why it is not supported yet), the alarm number
// of every diagnostic lowering raises, and the defaults of the controller parameters it reads.
// Lowering is written against this table only; there is no `if (dialect == ...)` in it.
// docs/semantics.md documents the three tables.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "ncc/ir/ir.h"
#include "ncc/frontend/language.h"
#include "ncc/machine/dialect.h"

namespace ncc::passes {

// What lowering does with a G code (the semantics, independent of the dialect's numbering).
enum class GAction : uint8_t {
  Rapid, Linear, ArcCW, ArcCCW,                 // motion (modal)
  PlaneXY, PlaneZX, PlaneYZ,                    // G17 G18 G19
  Absolute, Incremental,                        // G90 G91
  InverseTime, PerMinute, PerRevolution,        // G93 G94 G95
  Inch, Metric,                                 // G20 G21
  LengthPlus, LengthMinus, LengthCancel,        // G43 G44 G49
  WorkOffset,                                   // G54..G59 (index in `work_index`)
  WorkOffsetExtended,                           // G54.1 Pn
  ExactStopMode, CornerOverride, TappingMode, ContinuousMode,  // G61 G62 G63 G64
  Dwell,                                        // G04
  DwellFeedOrSpindle,                           // DIN G4 F (seconds) / G4 S (revolutions)
  ExactStopOneShot,                             // G09
  DataSet,                                      // G10
  ReferenceCheck,                               // G27
  ReferenceReturn,                              // G28
  ReferenceReturnN,                             // G30
  LocalShift,                                   // G52
  MachineCoordinates,                           // G53
  SetShift,                                     // G92
  ResetShift,                                   // G92.1
  Skip,                                         // G31 (Mazak G31.1-G31.3 too): skip move
  PositionOffset,  // G45 G46 G47 G48: the move +-1 or 2 x the D offset (multiple from the code)
  Rotation, RotationCancel,                     // G68 G69 (2-D, and 3-D with I J K)
  Scaling, ScalingCancel,                       // G51 G50
  Mirror, MirrorCancel,                         // G51.1 G50.1
  WorkRotation,                                 // Mazak G92.5: work coordinate rotation
  CancelNoEffect,  // the cancel/off code of a function ncc never switches on (G40, G80, G50..)
  LanguageDin, LanguageIso,                     // G290 G291
  HoleCycle,       // G73-G89: a canned hole cycle (its entry in DialectTable::cycles)
  CycleCancel,     // G80
  ReturnInitial, ReturnR,                       // G98 G99
  PolarOff, PolarOn,                            // G15 G16: polar coordinate command
  CompCancel, CompLeft, CompRight,              // G40 G41 G42: cutter radius compensation
  CompVectorHold, CompCornerArc,                // G38 G39 (one-shot, in compensation only)
  NotSupported,    // a real code of the controller that ncc does not implement yet
};

// Semantic groups: which codes exclude each other in a block and replace each other modally.
enum class GGroup : uint8_t {
  OneShot, Motion, Plane, Distance, FeedMode, Units, CutterComp, LengthComp, Cycle,
  ReturnLevel, Scaling, MacroModal, Spindle, WorkOffset, PathControl, Rotation, Polar,
  Mirror, StrokeCheck, PolarInterpolation, Profiling, Language, Other,
};

struct GCodeEntry {
  int code10;                 // G code x 10: G54.1 -> 541, G01 -> 10
  GGroup group;
  int group_number;           // the group as the dialect's manual numbers it (docs, messages)
  bool power_on_default;      // '*' in the manual's table
  GAction action;
  int work_index;             // WorkOffset: 1..6 for G54..G59
  std::string_view description;  // "canned drilling cycle", used in diagnostics
};

// Every diagnostic lowering raises; each dialect maps it to its alarm number or an NCC code.
enum class Alarm : uint8_t {
  MacroNotSupported,        // `X#1`, `[..]`, `#1=..`
  CodeNotSupported,         // a known G/M code ncc does not implement yet
  UnknownGCode,             // a G code the controller does not have
  AddressNotSupported,      // Q, E, ,C ... (features not implemented yet)
  AddressNotAnAxis,         // a letter that is not an axis of the machine
  AddressWithoutMeaning,    // I/J/K without an arc, L without G10, ...
  AddressRepeated,          // the same address twice in a block
  SameGroupInBlock,         // two codes of one group in a block (policy "error")
  OneShotConflict,          // two one-shot codes that both need the axis words
  DecimalPointNotAllowed,   // a point at an integer address (policy "error")
  ValueOutOfRange,          // negative S, T; F < 0; ...
  TooManyMCodes,
  FeedMissing,              // G01/G02/G03 (or G93 block) without F
  ArcRadiusMismatch,        // start and end radius differ by more than the tolerance
  ArcRadiusTooSmall,        // R arc with |R| < chord / 2
  ArcCentreMissing,         // G02/G03 without I/J/K or R
  ArcDegenerate,            // centre at the start point, R arc ending at the start, ...
  OffsetNumberOutOfRange,   // H / D beyond offset_count
  ReferenceCheckFailed,     // G27 position is not the reference point
  ReferencePointNumber,     // G30 P other than 2..4 (where that is an error)
  DataSetFormat,            // G10 with a bad L or P
  ExtendedOffsetNumber,     // G54.1 P out of range
  ExtendedOffsetRequired,   // G10 L20 without P outside G54.1 mode
  LocalShiftInExtended,     // G52 while G54.1 is active
  AxisMissing,              // G43 on a machine without the length axis, arc plane axis missing
  G53Incremental,           // G53 in G91 where the controller ignores it (warning)
  TooManyDigits,            // a number longer than its address's format (format_digits)
  LengthCompInArc,          // G43/G44/G49 (or a new H) while G02/G03 is in force
  // ,C / ,R (the corners pass): the next block has no move in the plane; its move is not
  // G01-G03 (G00, G31); an arc where the dialect rounds line-line corners only; the chamfer
  // or radius does not fit in the block's move / in the next block's; the plane or the
  // coordinate system changes between the two blocks.
  CornerNoMoveAfter,
  CornerNotCuttingAfter,
  CornerArcNotAllowed,
  CornerTooLong,
  CornerTooLongAfter,
  CornerContextChange,
  CycleDepthMissing,        // a hole cycle without its bottom (Z) at the first hole
  CyclePeckMissing,         // G73/G83 without the peck depth Q
  CyclePeckInvalid,         // G73/G83 with Q zero (or negative where the sign counts)
  CycleFeedMissing,         // a hole cycle before any F
  CycleSpindleDirection,    // a hole cycle with the spindle neither M03 nor M04 (Siemens)
  CycleReferencePlane,      // R beyond the bottom (Siemens), or a bad repeat count
  // Coordinate transforms (lowering_transforms.cpp, the transform pass).
  TransformArcNotCircle,    // an arc whose image is no circle in a principal plane
  TransformWordMissing,     // G68 without R where R is required, G51.1 / G92.5 without words
  TransformNotAlone,        // a G68/G69/G51/G50 block with another G code (Siemens)
  TransformOrder,           // G51.1/G50.1 while scaling or rotation is in force (Siemens)
  RotationVector,           // 3-D G68 whose I J K is not one axis (Mazak 807)
  RotationNesting,          // more G68 in force than the control stacks
  ScaleFactorRange,         // G51 factor zero or beyond the range
  RotationAngleRange,       // G68 / G92.5 angle beyond +-360 degrees
  FigureRotationWithRotation,  // figure rotation and G68 together (Mazak 850)
  ArcAfterWorkRotation,     // the move after G92.5 is an arc (Mazak 817)
  PolarNotAllowed,          // in G16: a code, an arc or a corner the dialect's rules refuse
  // Cutter radius compensation (lowering_cutter_comp.cpp, the compensation pass).
  CompStartInArc,           // start-up or cancel in a G02/G03 block
  CompPlaneChange,          // G17/G18/G19 changes the plane while compensating
  CompSkip,                 // G31 while compensating
  CompReferenceReturn,      // G28/G30 while compensating (Siemens)
  CompSideChangeEarly,      // G41<->G42 in the start-up block or the one after it
  CompCornerArcMove,        // G39 with a move
  CompNoIntersection,       // an inner corner whose offset paths do not meet
  CompInterference,         // the compensated path runs against the programmed one: a gouge
  CompWithoutMotion,        // too many blocks without motion in the plane before an inner corner
  CompInCycle,              // a hole cycle while compensating, where that is an alarm
  // DIN: a name that is no variable, axis or address (`E_MULT=1` without DEF E_MULT).
  NameNotDefined,
  kCount,
};

// Where a dialect differs in behaviour; each field says which manual statement it encodes.
struct DialectBehaviour {
  // Default of `same_group_in_block`: "error", "last_wins" or "per_word" (G90/G91 switch for
  // the words that follow them; two codes of another group are an error).
  std::string_view same_group_default;
  std::string_view decimal_point_default;  // "standard" | "calculator"
  std::string_view rapid_type_default;     // "linear" | "per_axis"
  double arc_radius_tolerance_default;     // mm
  int offset_count_default;                // H/D numbers 1..n
  int max_m_codes;                         // M codes per block
  bool m_overflow_keeps_last;              // more than max: keep the last ones (Mazak)
  int max_t_words;                         // T words per block (Mazak: tool + next tool)
  bool duplicate_h_d_last_wins;            // Mazak: "only one H/D per block: the last wins"
  bool integer_point_is_error;             // FANUC PS0007; others drop the fraction
  bool dwell_p_point_is_error;             // G04 P12.5: FANUC PS0007, Mazak drops it
  bool dwell_revolutions_default;          // G04 in G95 counts revolutions by default
  bool reference_return_cancels_length;    // G28/G30 leave G49 in force after the return
  bool local_shift_per_work_offset;        // G52 belongs to the work system it was set in
  bool local_shift_in_extended_is_error;   // Mazak 949: G52 while G54.1 is active
  bool work_offset_write_on_reselect;      // G10 L2/L20 act when the system is selected again
  enum class G53InG91 : uint8_t { Incremental, Absolute, Ignored } g53_in_g91;
  enum class G30P : uint8_t { ErrorOutside2To4, OtherMeansSecond } g30_p;
  bool g10_l2_p_lenient;                   // Mazak: P outside 0-6 -> 1, P missing -> last P
  int extended_offset_count;               // G54.1 P1..n (FANUC/Mazak 48) / G54 P1..n (Siemens 93)
  bool extended_offset_is_g54_p;           // Siemens: `G54 P1` instead of `G54.1 P1`
  bool inverse_time_arc_per_radius;        // Mazak G93: F = speed / radius on arcs
  bool length_change_moves_default;        // G43 H / G49 alone moves the length axis
  // Digits of a number: an integer address (H D P L S T M) has at most this many, a value
  // (axes, I J K R, F, G04 X, G10 R) at most this many least input increments.
  int format_digits;
  bool length_comp_in_arc_is_error;        // G43/G44/G49 only in G00/G01 mode (Siemens)
  // A count of turns given with G02/G03: none (the address has no meaning), Mazak's helical
  // P (§6-7: the number of pitches p in l = Z / ((2pi p + theta) / 2pi), theta in [0, 2pi)) or
  // Siemens' full-circle L (§2.1.3: `G02 I J Ln` runs the full circle n times).
  enum class ArcTurns : uint8_t { None, PitchesP, FullCircleRepeatsL } arc_turns;
  // F of a helical arc is the speed along the arc in its plane (FANUC: the linear axis runs at
  // F x its length / the arc length) rather than along the helix (Mazak §6-7, Siemens §2.1.4).
  // The default of [machine.params] helical_feed_along_arc (FANUC HTG).
  bool helical_feed_along_arc;
  // Mazak §8-1: with inch input an X written before G04 is read as a coordinate, in least
  // input increments, and then counted in 0.001 s: `X5. G04` = X50000 = 50 s.
  bool dwell_x_before_g04_is_coordinate;
  // Siemens §3.3.1: "the dwell block contains no command other than G04" (X or P).
  bool dwell_block_alone;
  // G31's F: true, the F of the block (or the modal F) as for G01, and it stays modal; false
  // (Mazak §4.10): "F missing -> K41 (K41 = 0 -> error); the modal F is not changed".
  bool skip_feed_is_modal;
  // ,C / ,R between arcs as well as lines (Siemens §4.8.2; FANUC common); false: line-line
  // corners only (Mazak §13-14: an arc in the next block is alarm 911).
  bool corner_with_arcs;
  // The address of the line angle (Mazak §13-12: `G01 Aa Zz`, the end point's other plane
  // coordinate computed from the angle; only where A is not an axis of the machine). Empty: none.
  std::string_view line_angle_address;
  // Data addresses (block_words.h, AddressMap) this language gives another meaning, not built
  // yet: such a letter, unless it is an axis of the machine, is "not supported yet". Siemens
  // DIN reads R as a parameter, L as a subprogram call, P as a repeat count, H as an auxiliary
  // function. Empty: every data address as ISO reads it.
  std::string_view other_meaning_addresses = "";
  // Whether [machine.params] decimal_point applies (MD10884 EXTERN_FLOATINGPOINT_PROG is an
  // ISO-mode parameter: Siemens DIN always reads `X20` as 20 mm).
  bool decimal_point_from_params = true;
  // Siemens DIN: D n makes edge n's length active as well as its radius (no G43/H), on the
  // axis normal to the working plane; D0 deselects both. The edges are numbered flat (MD18102
  // = 1): D n is register n, whatever T is.
  bool d_selects_length = false;
};

// What a block of system variables (#1000 and up) holds; the controller model reads and
// writes them (passes/src/system_variables.cpp).
enum class SystemVariable : uint8_t {
  LengthGeometry, LengthWear, RadiusGeometry, RadiusWear,  // register (#n - first + 1)
  ExternalOffset,      // per axis (#n - first)
  WorkOffset,          // G54..G59: system (#n - first) / stride + 1, axis (#n - first) % stride
  ExtendedWorkOffset,  // G54.1 P1..: same layout
  ModalGroup,          // the G code in force in group (#n - first + 1), as the manual numbers it
  ModalWord,           // the word in force: #n - first + 1 is the letter's argument number
  EndPoint,            // the last block's end point, work coordinates, per axis
  MachinePosition,     // per axis, machine coordinates
  WorkPosition,        // per axis, work coordinates
  ToolLengthVector,    // per axis: the tool length offset in force
  SkipPosition,        // per axis, work coordinates: where the last G31 stopped (the VM writes it)
  InputSignal,         // interface inputs: the machine's ([machine.signals]), known when run
  OutputSignal,        // interface outputs: what the program last wrote (the model keeps them)
  TimerMs,             // a timer in ms of the run's time, settable (#3001): known when run
  TimerHours,          // the same in hours (FANUC #3002)
  RunTime,             // servo lag: known when run, not simulated
};

struct SystemVariableRange {
  int64_t first;
  int64_t last;
  SystemVariable kind;
  int64_t stride;          // WorkOffset / ExtendedWorkOffset: variables per system
  std::string_view what;   // for messages: "G54-G59 work offsets"
};

// One canned hole cycle of the dialect: what its G code does (docs/cycles.md).
struct CycleEntry {
  int code10;
  ir::HoleCycle::Kind kind;
  bool dwell;            // reads P: a dwell at the bottom
  bool feed_out;         // back to R at the cutting feed (G85, G89)
  bool spindle_stop;     // M05 at the bottom, rapid out, spindle on again (G86)
  int tap_direction;     // tapping: +1 cuts in with M03 (G84), -1 with M04 (G74); else 0
  bool p_in_seconds;     // P counts seconds (Mazak G74/G84 "arrêt temporisé en secondes")
  bool q_shift;          // Q is the shift off the wall at the bottom (G76, G87)
  bool manual_stop;      // M00 after the spindle stop at the bottom (G88)
  bool dwell_at_r;       // tapping: the dwell P also at R after the way out
  bool pitch_feed;       // F is the thread pitch, per revolution (Mazak G84.2/G84.3)
  // Mazak §13-1 optional words: the address of the distance from R down to where the cutting
  // feed starts (K in G73/G83, D in G82; 0: none), and I J as the slow zone above the bottom
  // (I its length, J the feed in %; G73 G82 G83).
  char feed_start_address = 0;
  bool slow_zone = false;
};

// How the dialect's cycles read their words and where they differ; each field names its manual.
struct CycleRules {
  std::span<const CycleEntry> entries;
  char repeat_address;              // 'K' (FANUC, Siemens) or 'L' (Mazak)
  bool positioning_in_motion_mode;  // Mazak §13-1-1 1.: positioned by the group-01 code (G01)
  bool spindle_direction_required;  // Siemens App. D 61102: M03/M04 before a cycle
  bool q_sign_ignored;              // Siemens §4.1: Q is taken positive; else Q <= 0 is an alarm
  bool r_beyond_bottom_is_error;    // Siemens 61101 (reference plane wrong)
  double peck_retract_feed;         // G73 back-off feed, mm/min (Mazak f2 = 9999); 0: rapid
  // Mazak §13-1-6 / §13-1-9: D in G73/G83 is d (the return amount / the stop above the last
  // depth; D omitted or D0: the parameter F12/F13), not a radius offset number.
  bool d_is_peck_distance;
  // The shift of G76 in the plane (first, second axis): its default direction when the
  // machine file sets none (boring_shift_direction).
  int default_shift_direction;
  // Peck tapping (G84/G74 with Q): none (Q is stored cycle data), in rigid mode only (FANUC
  // deep-hole rigid tapping: after M29 `rigid_tap_m_code`, the type by peck_tapping_type, PCP),
  // or by the tapping type (Siemens §4.1.13: tapping_type = _ZSFI[1] high_speed_peck / peck).
  enum class PeckTapping : uint8_t { None, RigidMode, TappingType } peck_tapping;
  int rigid_tap_m_code;             // M29 (FANUC; Siemens MD20095); 0: none
  // The peck type's way back down from R: at F (Siemens §4.1.13) or at the retract speed
  // (FANUC: "2, 3 and bottom -> R use the retract override").
  bool peck_tap_approach_at_feed;

  const CycleEntry* find(int code10) const {
    for (const CycleEntry& e : entries)
      if (e.code10 == code10) return &e;
    return nullptr;
  }
};

// How the dialect's coordinate transforms read their words and compose (docs/transforms.md);
// each field names its manual.
struct TransformRules {
  // The stages, in the order they act on a programmed point (first to last).
  enum class Stage : uint8_t { FigureRotation, Mirror, Scaling, Rotation };
  std::array<Stage, 4> order;
  // ---- G68 / G69 ----
  bool rotation_angle_required;        // R missing is an alarm; else the default angle parameter
  // A 2-D R follows G90/G91 (Mazak §13-8 3.3, Siemens §3.1.9); else absolute unless the
  // rotation_angle_incremental parameter (FANUC RIN) says so.
  bool rotation_angle_follows_distance;
  // G68 while one is in force: stacked on it (Siemens base frames 1 and 2) rather than
  // replacing its centre and angle (Mazak §13-8 3.4).
  bool rotation_stacks_2d;
  bool rotation_stacks_3d;
  int max_rotations;                   // stacked rotations at most (0: no limit)
  bool extra_rotation_replaces_last;   // beyond the limit: replaces the last (Siemens) or alarm
  bool rotation_3d_unit_axis_only;     // 3-D: I J K all given, exactly one is 1 (Mazak ch. 22, 807)
  bool rotation_3d_centre_is_origin;   // 3-D centre omitted: the work origin (else the position)
  // 3-D X Y Z are the new program zero (Mazak ch. 22 §4, Siemens §3.1.10 "acts like an origin
  // offset": p -> c + R p); else the centre the system turns about (p -> c + R (p - c)).
  bool rotation_3d_centre_is_new_zero;
  // 3-D mode: G68/G69 hold no other G code than the plane; G51 and G54-G59 are refused in it
  // (Mazak ch. 22 §5.2, §2: 807, 943).
  bool rotation_3d_restricted;
  bool rotation_3d_angle_absolute;     // 3-D R always absolute (Siemens §3.1.10)
  bool transform_block_alone;          // G68/G69/G51/G50 blocks hold no other G code (Siemens)
  // ---- G51 / G50 ----
  enum class ScaleCentre : uint8_t { CurrentPosition, WorkOrigin, AxisNotScaled };
  ScaleCentre scale_centre_omitted;    // a centre word left out
  bool scale_centre_follows_distance;  // the centre in G90/G91 (Mazak); else always absolute
  bool rescale_adds_axes;              // G51 in G51 mode adds axes, its P for all (Mazak 13-10 11)
  bool scale_p_point_only_after_g51;   // Mazak §13-10 4.7: `P0.5 G51` is P = 0, i.e. x1
  bool scale_p_fixed_increment;        // P without a point counts this increment (else the
  double scale_p_increment;            // scale_factor_unit parameter)
  double scale_factor_max;             // a larger factor is an alarm
  bool scale_tiny_factor_is_one;       // Mazak: below 0.000001 counts as 1; else an alarm
  bool scale_cancel_moves;             // Mazak §13-10 3.B: G50 moves every axis back (deviation)
  bool reference_return_cancels_scaling;  // Mazak §13-10 5.4/5.5: G27/G28/G30 end scaling
  // ---- G51.1 / G50.1 ----
  bool mirror_centre_follows_distance; // Mazak §13-11: absolute or incremental; else absolute
  bool mirror_only_outside_others;     // Siemens §3.2.4: not while scaling or rotation is in force
};

// How the dialect reads the polar coordinate command G16 (group 17; lowering_polar.cpp,
// docs/semantics.md). Common to FANUC and Siemens: the plane's first axis word is the radius,
// the second the angle (degrees, counter-clockwise from the first axis); the pole is the work
// origin for an absolute radius and the current position for an incremental one; without a
// radius the pole is the work origin and the radius the current position's distance from it.
struct PolarRules {
  // The angle an incremental or omitted angle starts from while the pole is the current
  // position: true, 0 (the plane's first axis; Siemens §4.5 N15: `G91 X100 Y0` moves along +X);
  // false, the current position's angle about the work origin (FANUC: the angle in force).
  bool angle_from_axis_at_current_pole;
  // G02/G03 in G16: the end point polar, the arc's radius by R only (FANUC "specify the radius
  // of circular interpolation with R in the polar coordinate mode"), or not supported (the
  // Siemens §4.5 text says nothing of arcs).
  enum class Arcs : uint8_t { RadiusOnly, NotSupported } arcs;
  bool corners_allowed;  // ,C / ,R (FANUC: "cannot be specified in the polar coordinate mode")
};

// How the dialect's cutter radius compensation differs (lowering_cutter_comp.cpp,
// docs/semantics.md). Lowering records these (with the machine's parameters) in every
// ir::CutterComp, so the compensation pass needs nothing else; each field names its manual.
struct CompRules {
  int lookahead;                 // blocks read ahead (FANUC No.19625 = 3, Mazak 5, Siemens 2)
  // Blocks without motion in the plane that keep the corner; 0: the look-ahead - 2 (FANUC
  // §5.4.3 "(N-2) >= M"), else fixed (Mazak "more than 4", Siemens "at most 2").
  int max_without_motion;
  ir::CutterComp::Startup startup;  // the start-up/cancel type (FANUC SUV/SUP, Mazak F92 bit 4)
  bool arc_corners;              // outer corners joined by an arc (Siemens G450; FANUC CCC = 0)
  bool side_change_early_is_error;  // G41<->G42 in the start-up block or the next (FANUC, Mazak)
  bool cancel_in_arc_is_error;      // G40 (D00) in G02/G03 mode (FANUC PS0034, Mazak 835)
  bool reference_return_is_error;   // G28/G30 in G41/G42 (Siemens §2.2); else the vector drops
  bool skip_is_error;               // G31 in G41/G42 (all three manuals)
  bool d_zero_cancels;              // Mazak §12-4: "G40 or D00" cancels; else D00 = radius 0
  bool same_side_recommand_counts;  // FANUC: G41 in G41 re-makes the vector; Mazak: ignored
  // A change of side runs over its block, perpendicular to perpendicular (Siemens §3.5.3); else
  // the corner is where the old and new offset paths meet (FANUC §5.4, Mazak §12-4-3 3.).
  bool side_change_perpendicular;
  // Where I J K (the plane's two) are a vector, not an arc centre: with G00/G01 (FANUC IJ-type
  // vector), with G40 (the direction of a virtual next move), with G38 (Mazak: a new vector).
  bool vector_with_motion;
  bool vector_with_cancel;
  bool vector_with_hold;
  bool has_3d;                      // Mazak: G41/G42 with all of I J K is 3-D compensation
  bool cycle_in_3d_is_error;        // Mazak 901: a hole cycle in 3-D compensation
};

// An address written with another's meaning: DIN's CR= is the arc radius R, CHR= and RND= the
// ISO corner words ,C and ,R; CHF= (a chamfer by its own length) names itself.
struct AddressAlias {
  std::string_view name;
  std::string_view to;
};

// An address of the language that ncc does not build yet, with what it is for (DIN `AR=`, the
// opening angle of an arc): refused by name, never mistaken for an undefined variable.
struct UnbuiltAddress {
  std::string_view name;
  std::string_view what;
};

// A DIN frame instruction (Fundamentals, "Frames"; lowering_frames.cpp): the programmable
// frame's translation (TRANS X.. Y.. Z..), rotation (ROT X.. Y.. Z.. in space, or RPL= in the
// plane), scale factors (SCALE) or mirrored axes (MIRROR X0). The plain command replaces the
// whole programmable frame (alone, it deletes it); the A-form (ATRANS ...) acts onto the frame
// in force, in its coordinates.
struct FrameCommand {
  std::string_view name;
  enum class Component : uint8_t { Translation, Rotation, Scale, Mirror } component;
  bool additive;
};

struct DialectTable {
  Dialect dialect;
  std::span<const GCodeEntry> gcodes;
  std::span<const std::string_view> alarm_codes;  // indexed by Alarm
  DialectBehaviour behaviour;
  std::span<const SystemVariableRange> system_variables;
  const CycleRules* cycles = nullptr;  // the canned hole cycles
  const TransformRules* transforms = nullptr;  // coordinate rotation, scaling, mirror
  const PolarRules* polar = nullptr;   // G16; null where the dialect has no polar command
  const CompRules* comp = nullptr;     // G40/G41/G42; null: compensation is not supported
  std::span<const AddressAlias> address_aliases{};
  std::span<const FrameCommand> frame_commands{};  // DIN TRANS, ATRANS ...; empty in ISO
  std::span<const UnbuiltAddress> unbuilt_addresses{};

  const FrameCommand* findFrameCommand(std::string_view name) const {
    for (const FrameCommand& c : frame_commands)
      if (c.name == name) return &c;
    return nullptr;
  }
  const GCodeEntry* findG(int code10) const;
  std::string_view alarm(Alarm a) const { return alarm_codes[static_cast<size_t>(a)]; }
  // The power-on code of a group (nullptr if the group has none).
  const GCodeEntry* powerOnDefault(GGroup group) const;
};

// The table of an ISO-milling dialect; nullptr for dialects lowering does not handle
// (fanuc-t, siemens-din).
const DialectTable* dialectTable(Dialect dialect);

// The tables a dialect's blocks are lowered with, by the language they were read in
// (ast::Block::language): siemens-iso-m reads ISO text and, after G290, DIN text; siemens-din
// starts in DIN and G291 switches it to ISO mode; the other dialects read ISO only (din:
// nullptr).
struct LanguageTables {
  const DialectTable* iso = nullptr;
  const DialectTable* din = nullptr;
  frontend::Language initial = frontend::Language::Iso;  // the language a file starts in
  const DialectTable* of(frontend::Language language) const {
    return language == frontend::Language::Din ? din : iso;
  }
};
LanguageTables languageTables(Dialect dialect);

// "G54.1", "G01": the code as written in diagnostics.
std::string gCodeName(int code10);

}  // namespace ncc::passes
