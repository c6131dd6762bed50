// siemens-iso-m: Sinumerik 840Di ISO mode M (siemens-840di-iso-milling-gcode.ja.md §3.1,
// table A.3; group 18 is the one-shot group).
#include "dialect_tables.h"

namespace ncc::passes {

namespace {
using A = GAction;
using G = GGroup;

constexpr GCodeEntry kCodes[] = {
    // group 1
    {0, G::Motion, 1, true, A::Rapid, 0, "positioning"},
    {10, G::Motion, 1, false, A::Linear, 0, "linear interpolation"},
    {20, G::Motion, 1, false, A::ArcCW, 0, "circular/helical interpolation CW"},
    {30, G::Motion, 1, false, A::ArcCCW, 0, "circular/helical interpolation CCW"},
    // group 2
    {170, G::Plane, 2, true, A::PlaneXY, 0, "XY plane"},
    {180, G::Plane, 2, false, A::PlaneZX, 0, "ZX plane"},
    {190, G::Plane, 2, false, A::PlaneYZ, 0, "YZ plane"},
    // group 3
    {900, G::Distance, 3, true, A::Absolute, 0, "absolute command"},
    {910, G::Distance, 3, false, A::Incremental, 0, "incremental command"},
    // group 4
    {220, G::StrokeCheck, 4, false, A::NotSupported, 0, "stored stroke limit on"},
    {230, G::StrokeCheck, 4, true, A::CancelNoEffect, 0, "stored stroke limit off"},
    // group 5
    {940, G::FeedMode, 5, true, A::PerMinute, 0, "feed per minute"},
    {950, G::FeedMode, 5, false, A::PerRevolution, 0, "feed per revolution"},
    {930, G::FeedMode, 5, false, A::InverseTime, 0, "inverse time feed"},
    // group 6 (reset value: parameter reset_unit, MD20154[5])
    {200, G::Units, 6, false, A::Inch, 0, "inch input"},
    {210, G::Units, 6, true, A::Metric, 0, "metric input"},
    // group 7
    {400, G::CutterComp, 7, true, A::CompCancel, 0, "cutter radius compensation cancel"},
    {410, G::CutterComp, 7, false, A::CompLeft, 0, "cutter radius compensation left"},
    {420, G::CutterComp, 7, false, A::CompRight, 0, "cutter radius compensation right"},
    // group 8
    {430, G::LengthComp, 8, false, A::LengthPlus, 0, "tool length compensation +"},
    {440, G::LengthComp, 8, false, A::LengthMinus, 0, "tool length compensation -"},
    {490, G::LengthComp, 8, true, A::LengthCancel, 0, "tool length compensation cancel"},
    // group 9
    {730, G::Cycle, 9, false, A::HoleCycle, 0, "high-speed peck drilling cycle"},
    {740, G::Cycle, 9, false, A::HoleCycle, 0, "counter tapping cycle"},
    {760, G::Cycle, 9, false, A::HoleCycle, 0, "fine boring cycle"},
    {800, G::Cycle, 9, true, A::CycleCancel, 0, "canned cycle cancel"},
    {810, G::Cycle, 9, false, A::HoleCycle, 0, "canned drilling cycle"},
    {820, G::Cycle, 9, false, A::HoleCycle, 0, "canned drilling cycle with dwell"},
    {830, G::Cycle, 9, false, A::HoleCycle, 0, "canned peck drilling cycle"},
    {840, G::Cycle, 9, false, A::HoleCycle, 0, "canned tapping cycle"},
    {850, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    {860, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    {870, G::Cycle, 9, false, A::HoleCycle, 0, "canned back boring cycle"},
    {890, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    // group 10: return level, only meaningful with canned cycles (never active)
    {980, G::ReturnLevel, 10, true, A::ReturnInitial, 0, "canned cycle initial level return"},
    {990, G::ReturnLevel, 10, false, A::ReturnR, 0, "canned cycle R level return"},
    // group 11
    {500, G::Scaling, 11, true, A::ScalingCancel, 0, "scaling cancel"},
    {510, G::Scaling, 11, false, A::Scaling, 0, "scaling"},
    // group 12
    {660, G::MacroModal, 12, false, A::NotSupported, 0, "macro modal call"},
    {670, G::MacroModal, 12, true, A::CancelNoEffect, 0, "macro modal call cancel"},
    // group 13
    {960, G::Spindle, 13, false, A::NotSupported, 0, "constant surface speed control"},
    {970, G::Spindle, 13, true, A::CancelNoEffect, 0, "constant surface speed control cancel"},
    // group 14 (G54 P1..P93: the extended work offsets)
    {540, G::WorkOffset, 14, true, A::WorkOffset, 1, "work coordinate system 1"},
    {550, G::WorkOffset, 14, false, A::WorkOffset, 2, "work coordinate system 2"},
    {560, G::WorkOffset, 14, false, A::WorkOffset, 3, "work coordinate system 3"},
    {570, G::WorkOffset, 14, false, A::WorkOffset, 4, "work coordinate system 4"},
    {580, G::WorkOffset, 14, false, A::WorkOffset, 5, "work coordinate system 5"},
    {590, G::WorkOffset, 14, false, A::WorkOffset, 6, "work coordinate system 6"},
    // group 15
    {610, G::PathControl, 15, false, A::ExactStopMode, 0, "exact stop mode"},
    {630, G::PathControl, 15, false, A::TappingMode, 0, "tapping mode"},
    {640, G::PathControl, 15, true, A::ContinuousMode, 0, "continuous path mode"},
    {620, G::PathControl, 15, false, A::CornerOverride, 0, "automatic corner override"},
    // group 16
    {680, G::Rotation, 16, false, A::Rotation, 0, "coordinate rotation"},
    {690, G::Rotation, 16, true, A::RotationCancel, 0, "coordinate rotation cancel"},
    // group 17
    {150, G::Polar, 17, true, A::PolarOff, 0, "polar coordinates cancel"},
    {160, G::Polar, 17, false, A::PolarOn, 0, "polar coordinates"},
    // group 18 (one-shot)
    {40, G::OneShot, 18, false, A::Dwell, 0, "dwell"},
    {90, G::OneShot, 18, false, A::ExactStopOneShot, 0, "exact stop"},
    {100, G::OneShot, 18, false, A::DataSet, 0, "data setting"},
    {280, G::OneShot, 18, false, A::ReferenceReturn, 0, "reference point return"},
    {300, G::OneShot, 18, false, A::ReferenceReturnN, 0, "2nd/3rd/4th reference point return"},
    {310, G::OneShot, 18, false, A::Skip, 0, "skip function"},
    {520, G::OneShot, 18, false, A::LocalShift, 0, "local coordinate system"},
    {530, G::OneShot, 18, false, A::MachineCoordinates, 0, "machine coordinate system"},
    {650, G::OneShot, 18, false, A::NotSupported, 0, "macro call"},
    {920, G::OneShot, 18, false, A::SetShift, 0, "work coordinate system setting"},
    {80, G::OneShot, 18, false, A::NotSupported, 0, "feed-forward control"},
    {270, G::OneShot, 18, false, A::ReferenceCheck, 0, "reference point check"},
    {721, G::OneShot, 18, false, A::NotSupported, 0, "figure copy (rotation)"},
    {722, G::OneShot, 18, false, A::NotSupported, 0, "figure copy (parallel)"},
    {71, G::OneShot, 18, false, A::NotSupported, 0, "cylindrical interpolation"},
    {106, G::OneShot, 18, false, A::NotSupported, 0, "retract"},
    {50, G::OneShot, 18, false, A::NotSupported, 0, "high-speed cycle cutting"},
    {301, G::OneShot, 18, false, A::NotSupported, 0, "floating reference point return"},
    {921, G::OneShot, 18, false, A::ResetShift, 0, "work coordinate system reset"},
    // group 22
    {501, G::Mirror, 22, true, A::MirrorCancel, 0, "programmable mirror cancel"},
    {511, G::Mirror, 22, false, A::Mirror, 0, "programmable mirror"},
    // group 25
    {131, G::PolarInterpolation, 25, true, A::CancelNoEffect, 0, "polar interpolation cancel"},
    {121, G::PolarInterpolation, 25, false, A::NotSupported, 0, "polar interpolation"},
    // group 31
    {2900, G::Language, 31, false, A::LanguageDin, 0, "Siemens DIN mode"},
    {2910, G::Language, 31, true, A::LanguageIso, 0, "ISO mode"},
};

// Indexed by Alarm. 10860 (no feedrate programmed), 14040 (error in end point of circle) and
// 12470 (unknown G function) are Sinumerik NCK alarms.
constexpr std::string_view kAlarms[] = {
    "NCC2001",  // MacroNotSupported
    "NCC2010",  // CodeNotSupported
    "12470",    // UnknownGCode
    "NCC2011",  // AddressNotSupported
    "NCC2013",  // AddressNotAnAxis
    "NCC2014",  // AddressWithoutMeaning
    "NCC2015",  // AddressRepeated
    "NCC2020",  // SameGroupInBlock (not raised by default: the last one wins)
    "NCC2021",  // OneShotConflict
    "NCC2030",  // DecimalPointNotAllowed: G04 P (integer addresses drop the fraction)
    "NCC2031",  // ValueOutOfRange
    "NCC2032",  // TooManyMCodes (more than 5)
    "10860",    // FeedMissing
    "14040",    // ArcRadiusMismatch
    "14040",    // ArcRadiusTooSmall
    "NCC2043",  // ArcCentreMissing
    "NCC2044",  // ArcDegenerate
    "NCC2050",  // OffsetNumberOutOfRange
    "NCC2060",  // ReferenceCheckFailed
    "NCC2061",  // ReferencePointNumber
    "NCC2070",  // DataSetFormat
    "NCC2071",  // ExtendedOffsetNumber
    "NCC2072",  // ExtendedOffsetRequired
    "NCC2073",  // LocalShiftInExtended
    "NCC2080",  // AxisMissing
    "NCC2081",  // G53Incremental
    "NCC2033",  // TooManyDigits (no number in the notes)
    "NCC2045",  // LengthCompInArc
    "NCC2090",  // CornerNoMoveAfter (§4.8.2: "an alarm", no number)
    "NCC2091",  // CornerNotCuttingAfter
    "NCC2092",  // CornerArcNotAllowed (not raised: arcs are allowed)
    "NCC2093",  // CornerTooLong
    "NCC2094",  // CornerTooLongAfter
    "NCC2095",  // CornerContextChange (§4.8.2: plane or coordinate change)
    "61808",    // CycleDepthMissing: final or single drilling depth missing (App. D)
    "61808",    // CyclePeckMissing: the same alarm (Q is the single depth)
    "61808",    // CyclePeckInvalid: Q0 is no single depth
    "61003",    // CycleFeedMissing: no feed programmed in the cycle
    "61102",    // CycleSpindleDirection: no spindle direction programmed
    "61101",    // CycleReferencePlane: reference plane wrong
    "NCC2110",  // TransformArcNotCircle
    "NCC2111",  // TransformWordMissing
    "NCC2112",  // TransformNotAlone: §3.1.9, §3.2.3 (no alarm number given)
    "NCC2113",  // TransformOrder: §3.2.4 (no alarm number given)
    "NCC2114",  // RotationVector (not raised: any vector)
    "NCC2115",  // RotationNesting (not raised: a third G68 replaces the second)
    "NCC2116",  // ScaleFactorRange: a zero factor
    "NCC2116",  // RotationAngleRange
    "NCC2118",  // FigureRotationWithRotation (not raised)
    "NCC2119",  // ArcAfterWorkRotation (not raised)
    "NCC2088",  // PolarNotAllowed (§4.5 names no alarm)
    "NCC2120",  // CompStartInArc: start-up in G02/G03 is an error (§3.5.3, no number)
    "NCC2121",  // CompPlaneChange: an error (§3.5.3, no number)
    "NCC2122",  // CompSkip: G31 with compensation (§3.5.3, no number)
    "NCC2123",  // CompReferenceReturn: G28/G30 in G41/G42 (§2.2, no number)
    "NCC2124",  // CompSideChangeEarly (not raised: the side changes in that block, §3.5.3)
    "NCC2125",  // CompCornerArcMove (not raised: no G39)
    "NCC2126",  // CompNoIntersection: CDOF finds no intersection (§3.5.4, no number)
    "NCC2127",  // CompInterference: CDON bottleneck (§3.5.4, no number)
    "NCC2128",  // CompWithoutMotion (3 or more: the tool stops at the previous offset point)
    "NCC2129",  // CompInCycle (not raised: compensation is ignored in cycles, §3.5.3)
    "12550",  // NameNotDefined: name not defined (Sinumerik NCK)
};
static_assert(std::size(kAlarms) == static_cast<size_t>(Alarm::kCount));

// The hole cycles, §4.1 (shell cycles CYCLE381M-CYCLE387M; docs/cycles.md). P is in ms.
using CK = ir::HoleCycle::Kind;
constexpr CycleEntry kCycleEntries[] = {
    // code kind              dwell  feed_out stop   tap  P in s shift  M00   dwell R pitch
    {730, CK::HighSpeedPeck, false, false, false, 0, false, false, false, false, false},
    {740, CK::Tap, true, false, false, -1, false, false, false, false, false},
    {760, CK::FineBore, true, false, false, 0, false, true, false, false, false},
    {810, CK::Drill, false, false, false, 0, false, false, false, false, false},
    {820, CK::Drill, true, false, false, 0, false, false, false, false, false},
    {830, CK::Peck, false, false, false, 0, false, false, false, false, false},
    {840, CK::Tap, true, false, false, 1, false, false, false, false, false},
    {850, CK::Drill, false, true, false, 0, false, false, false, false, false},
    {860, CK::Drill, false, false, true, 0, false, false, false, false, false},
    {870, CK::BackBore, true, false, false, 0, false, true, false, false, false},
    {890, CK::Drill, true, true, false, 0, false, false, false, false, false},
};
constexpr CycleRules kCycles{
    .entries = kCycleEntries,
    .repeat_address = 'K',
    .positioning_in_motion_mode = false,
    .spindle_direction_required = true,   // App. D 61102
    .q_sign_ignored = true,               // §4.1: "Q must be positive; the sign is ignored"
    .r_beyond_bottom_is_error = true,     // App. D 61101
    .peck_retract_feed = 0.0,
    .d_is_peck_distance = false,
    .default_shift_direction = 0,         // _ZSFI[5] = 0: -X in G17
    .peck_tapping = CycleRules::PeckTapping::TappingType,  // §4.1.13
    .rigid_tap_m_code = 29,  // MD20095 (ISO mode; rigid is the tapping_type default anyway)
    .peck_tap_approach_at_feed = true,
};

constexpr DialectBehaviour kBehaviour{
    .same_group_default = "last_wins",      // §3.2.1: the one given last is effective
    .decimal_point_default = "calculator",  // MD10884 EXTERN_FLOATINGPOINT_PROG = 1
    .rapid_type_default = "linear",         // MD20732 EXTERN_G0_LINEAR_MODE = 1
    .arc_radius_tolerance_default = 0.01,   // MD21000 CIRCLE_ERROR_CONST
    .offset_count_default = 9999,           // no limit stated: H names a $TC_DPH entry
    .max_m_codes = 5,                       // §3.6: at most 5 M codes per block
    .m_overflow_keeps_last = false,
    .max_t_words = 1,
    .duplicate_h_d_last_wins = false,
    .integer_point_is_error = false,
    .dwell_p_point_is_error = true,         // §3.3.1 table 3.8: "P takes no decimal point"
    .dwell_revolutions_default = false,     // MD20734 bit 2 = 0
    .reference_return_cancels_length = false,  // §2.2: TLC stays unless cancelled first
    .local_shift_per_work_offset = false,
    .local_shift_in_extended_is_error = false,
    .work_offset_write_on_reselect = true,  // §3.1.3 example 2: acts when G54 is programmed
    .g53_in_g91 = DialectBehaviour::G53InG91::Absolute,  // §3.1.1: absolute only
    .g30_p = DialectBehaviour::G30P::ErrorOutside2To4,
    .g10_l2_p_lenient = false,
    .extended_offset_count = 93,            // G54 P1..P93
    .extended_offset_is_g54_p = true,
    .inverse_time_arc_per_radius = false,
    .length_change_moves_default = false,   // MD20382 TOOL_CORR_MOVE_MODE = FALSE
    .format_digits = 8,                     // ISO mode takes the FANUC 8-digit format
    .length_comp_in_arc_is_error = true,  // §3.5.2: "only in G00/G01 mode; in G02/G03 an error"
    .arc_turns = DialectBehaviour::ArcTurns::FullCircleRepeatsL,  // §2.1.3: `G02 I J Ln`
    .helical_feed_along_arc = false,        // §2.1.4: F is the tangential speed in 3-D space
    .dwell_x_before_g04_is_coordinate = false,
    .dwell_block_alone = true,              // §3.3.1: nothing but G04 in the dwell block
    .skip_feed_is_modal = true,             // G31 X Y Z F: F as for G01
    .corner_with_arcs = true,
    .line_angle_address = "",
    .other_meaning_addresses = "",
    .decimal_point_from_params = true,  // MD10884 EXTERN_FLOATINGPOINT_PROG (ISO mode)
};
// Sinumerik ISO mode defines no FANUC system variables (notes §4.11: "the manual does not
// define ... FANUC system variables"); its programs read the machine through DIN ($ variables).
constexpr std::span<const SystemVariableRange> kSystemVariables{};

// Coordinate rotation, scaling and mirror (docs/transforms.md): §3.1.9-§3.1.10 (G68 2-D and
// 3-D, two base frames), §3.2.3 (G51), §3.2.4 (G51.1). The order: G51.1 is base frame [1] and
// G68 needs three (frame [2] acts first on the point), and table 3.6 says a single-axis mirror
// reverses the rotation, i.e. the mirror acts after it. "Mirror, scaling, rotation" in §3.2.4 is
// the order they are switched on in.
constexpr TransformRules kTransforms{
    .order = {TransformRules::Stage::FigureRotation, TransformRules::Stage::Scaling,
              TransformRules::Stage::Rotation, TransformRules::Stage::Mirror},
    .rotation_angle_required = false,  // R omitted: SD42150 DEFAULT_ROT_FACTOR_R
    .rotation_angle_follows_distance = true,
    .rotation_stacks_2d = true,        // §3.1.10 "座標回転の重ね合わせ": base frames 1 and 2
    .rotation_stacks_3d = true,
    .max_rotations = 2,
    .extra_rotation_replaces_last = true,  // a third G68 replaces the second
    .rotation_3d_unit_axis_only = false,
    .rotation_3d_centre_is_origin = true,
    .rotation_3d_centre_is_new_zero = true,
    .rotation_3d_restricted = false,
    .rotation_3d_angle_absolute = true,
    .transform_block_alone = true,
    .scale_centre_omitted = TransformRules::ScaleCentre::WorkOrigin,  // "always the work origin"
    .scale_centre_follows_distance = false,
    .rescale_adds_axes = false,
    .scale_p_point_only_after_g51 = false,
    .scale_p_fixed_increment = false,
    .scale_p_increment = 0.0,
    .scale_factor_max = 99999.999,
    .scale_tiny_factor_is_one = false,
    .scale_cancel_moves = false,
    .reference_return_cancels_scaling = false,
    .mirror_centre_follows_distance = false,
    .mirror_only_outside_others = true,
};
}  // namespace

// G15/G16, §4.5 (docs/semantics.md).
constexpr PolarRules kPolar{
    // N15 `G91 X100 Y0` from X70.711 Y70.711 ends at X170.711 Y70.711: the angle from +X.
    .angle_from_axis_at_current_pole = true,
    .arcs = PolarRules::Arcs::NotSupported,  // §4.5 says nothing of G02/G03 in G16
    .corners_allowed = true,                 // §4.8.2 puts no limit; the corner is Cartesian
};

// G40/G41/G42 (§3.5.3; no G38/G39 in ISO mode).
constexpr CompRules kComp{
    .lookahead = 2,                  // "the NC buffers 2 blocks"
    .max_without_motion = 2,         // "at most 2 consecutive blocks without motion in the plane"
    .startup = ir::CutterComp::Startup::A,
    .arc_corners = true,             // G450: the transition circle is the default
    .side_change_early_is_error = false,  // the side changes in that block (§3.5.3)
    .cancel_in_arc_is_error = false,  // §3.5.3 names the start-up only
    .reference_return_is_error = true,    // §2.2: G28 in G41/G42 is an alarm
    .skip_is_error = true,           // §3.5.3: G31 while compensating
    .d_zero_cancels = false,         // D00 = radius 0
    .same_side_recommand_counts = false,  // the manual gives G41 in G41 no meaning
    .side_change_perpendicular = true,  // "at the start and end points of that block"
    .vector_with_motion = false,
    .vector_with_cancel = false,
    .vector_with_hold = false,
    .has_3d = false,
    .cycle_in_3d_is_error = false,
};

const DialectTable kSiemensIsoMTable{Dialect::SiemensIsoM, kCodes, kAlarms, kBehaviour, kSystemVariables,
                                &kCycles, &kTransforms, &kPolar, &kComp};

}  // namespace ncc::passes
