// fanuc-m: common FANUC 0i/30i-M behaviour (the Mazak and Siemens ISO manuals describe it; the
// FANUC 30i lathe manual gives the shared alarm numbers PS0007/PS0010 and the group rules).
#include "dialect_tables.h"

namespace ncc::passes {

namespace {
using A = GAction;
using G = GGroup;

constexpr GCodeEntry kCodes[] = {
    // group 00: one-shot
    {40, G::OneShot, 0, false, A::Dwell, 0, "dwell"},
    {50, G::OneShot, 0, false, A::NotSupported, 0, "high-speed cycle machining"},
    {71, G::OneShot, 0, false, A::NotSupported, 0, "cylindrical interpolation"},
    {80, G::OneShot, 0, false, A::NotSupported, 0, "look-ahead control"},
    {90, G::OneShot, 0, false, A::ExactStopOneShot, 0, "exact stop"},
    {100, G::OneShot, 0, false, A::DataSet, 0, "data setting"},
    {110, G::OneShot, 0, false, A::NotSupported, 0, "data setting mode cancel"},
    {270, G::OneShot, 0, false, A::ReferenceCheck, 0, "reference position return check"},
    {280, G::OneShot, 0, false, A::ReferenceReturn, 0, "reference position return"},
    {290, G::OneShot, 0, false, A::NotSupported, 0, "return from reference position"},
    {300, G::OneShot, 0, false, A::ReferenceReturnN, 0, "2nd/3rd/4th reference position return"},
    {310, G::OneShot, 0, false, A::Skip, 0, "skip function"},
    {370, G::OneShot, 0, false, A::NotSupported, 0, "automatic tool length measurement"},
    {380, G::OneShot, 0, false, A::CompVectorHold, 0, "cutter compensation vector hold"},
    {390, G::OneShot, 0, false, A::CompCornerArc, 0, "corner circular interpolation"},
    {450, G::OneShot, 0, false, A::NotSupported, 0, "tool position offset"},
    {460, G::OneShot, 0, false, A::NotSupported, 0, "tool position offset"},
    {470, G::OneShot, 0, false, A::NotSupported, 0, "tool position offset"},
    {480, G::OneShot, 0, false, A::NotSupported, 0, "tool position offset"},
    {520, G::OneShot, 0, false, A::LocalShift, 0, "local coordinate system setting"},
    {530, G::OneShot, 0, false, A::MachineCoordinates, 0, "machine coordinate system selection"},
    {600, G::OneShot, 0, false, A::NotSupported, 0, "single direction positioning"},
    {650, G::OneShot, 0, false, A::NotSupported, 0, "macro call"},
    {920, G::OneShot, 0, false, A::SetShift, 0, "workpiece coordinate system setting"},
    {921, G::OneShot, 0, false, A::ResetShift, 0, "workpiece coordinate system preset"},
    // group 01
    {0, G::Motion, 1, true, A::Rapid, 0, "positioning"},
    {10, G::Motion, 1, false, A::Linear, 0, "linear interpolation"},
    {20, G::Motion, 1, false, A::ArcCW, 0, "circular interpolation CW"},
    {30, G::Motion, 1, false, A::ArcCCW, 0, "circular interpolation CCW"},
    {330, G::Motion, 1, false, A::NotSupported, 0, "thread cutting"},
    // group 02
    {170, G::Plane, 2, true, A::PlaneXY, 0, "XY plane"},
    {180, G::Plane, 2, false, A::PlaneZX, 0, "ZX plane"},
    {190, G::Plane, 2, false, A::PlaneYZ, 0, "YZ plane"},
    // group 03
    {900, G::Distance, 3, true, A::Absolute, 0, "absolute command"},
    {910, G::Distance, 3, false, A::Incremental, 0, "incremental command"},
    // group 04
    {220, G::StrokeCheck, 4, false, A::NotSupported, 0, "stored stroke check on"},
    {230, G::StrokeCheck, 4, true, A::CancelNoEffect, 0, "stored stroke check off"},
    // group 05
    {930, G::FeedMode, 5, false, A::InverseTime, 0, "inverse time feed"},
    {940, G::FeedMode, 5, true, A::PerMinute, 0, "feed per minute"},
    {950, G::FeedMode, 5, false, A::PerRevolution, 0, "feed per revolution"},
    // group 06 (power-on unit: parameter reset_unit)
    {200, G::Units, 6, false, A::Inch, 0, "inch input"},
    {210, G::Units, 6, true, A::Metric, 0, "metric input"},
    // group 07
    {400, G::CutterComp, 7, true, A::CompCancel, 0, "cutter compensation cancel"},
    {410, G::CutterComp, 7, false, A::CompLeft, 0, "cutter compensation left"},
    {420, G::CutterComp, 7, false, A::CompRight, 0, "cutter compensation right"},
    // group 08
    {430, G::LengthComp, 8, false, A::LengthPlus, 0, "tool length compensation +"},
    {440, G::LengthComp, 8, false, A::LengthMinus, 0, "tool length compensation -"},
    {431, G::LengthComp, 8, false, A::NotSupported, 0, "tool length compensation in tool axis direction"},
    {434, G::LengthComp, 8, false, A::NotSupported, 0, "tool center point control"},
    {490, G::LengthComp, 8, true, A::LengthCancel, 0, "tool length compensation cancel"},
    // group 09
    {730, G::Cycle, 9, false, A::HoleCycle, 0, "peck drilling cycle"},
    {740, G::Cycle, 9, false, A::HoleCycle, 0, "left-hand tapping cycle"},
    {760, G::Cycle, 9, false, A::HoleCycle, 0, "fine boring cycle"},
    {800, G::Cycle, 9, true, A::CycleCancel, 0, "canned cycle cancel"},
    {810, G::Cycle, 9, false, A::HoleCycle, 0, "canned drilling cycle"},
    {820, G::Cycle, 9, false, A::HoleCycle, 0, "canned drilling cycle with dwell"},
    {830, G::Cycle, 9, false, A::HoleCycle, 0, "canned peck drilling cycle"},
    {840, G::Cycle, 9, false, A::HoleCycle, 0, "canned tapping cycle"},
    {850, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    {860, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    {870, G::Cycle, 9, false, A::HoleCycle, 0, "canned back boring cycle"},
    {880, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    {890, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    // group 10: return level, meaningful only with canned cycles (never active)
    {980, G::ReturnLevel, 10, true, A::ReturnInitial, 0, "canned cycle initial level return"},
    {990, G::ReturnLevel, 10, false, A::ReturnR, 0, "canned cycle R point level return"},
    // group 11
    {500, G::Scaling, 11, true, A::ScalingCancel, 0, "scaling cancel"},
    {510, G::Scaling, 11, false, A::Scaling, 0, "scaling"},
    // group 12
    {660, G::MacroModal, 12, false, A::NotSupported, 0, "macro modal call"},
    {670, G::MacroModal, 12, true, A::CancelNoEffect, 0, "macro modal call cancel"},
    // group 13
    {960, G::Spindle, 13, false, A::NotSupported, 0, "constant surface speed control"},
    {970, G::Spindle, 13, true, A::CancelNoEffect, 0, "constant surface speed control cancel"},
    // group 14
    {540, G::WorkOffset, 14, true, A::WorkOffset, 1, "workpiece coordinate system 1"},
    {550, G::WorkOffset, 14, false, A::WorkOffset, 2, "workpiece coordinate system 2"},
    {560, G::WorkOffset, 14, false, A::WorkOffset, 3, "workpiece coordinate system 3"},
    {570, G::WorkOffset, 14, false, A::WorkOffset, 4, "workpiece coordinate system 4"},
    {580, G::WorkOffset, 14, false, A::WorkOffset, 5, "workpiece coordinate system 5"},
    {590, G::WorkOffset, 14, false, A::WorkOffset, 6, "workpiece coordinate system 6"},
    {541, G::WorkOffset, 14, false, A::WorkOffsetExtended, 0, "additional workpiece coordinate system"},
    // group 15
    {610, G::PathControl, 15, false, A::ExactStopMode, 0, "exact stop mode"},
    {620, G::PathControl, 15, false, A::CornerOverride, 0, "automatic corner override"},
    {630, G::PathControl, 15, false, A::TappingMode, 0, "tapping mode"},
    {640, G::PathControl, 15, true, A::ContinuousMode, 0, "cutting mode"},
    // group 16
    {680, G::Rotation, 16, false, A::Rotation, 0, "coordinate system rotation"},
    {690, G::Rotation, 16, true, A::RotationCancel, 0, "coordinate system rotation cancel"},
    // group 17
    {150, G::Polar, 17, true, A::PolarOff, 0, "polar coordinates command cancel"},
    {160, G::Polar, 17, false, A::PolarOn, 0, "polar coordinates command"},
    // group 22
    {501, G::Mirror, 22, true, A::MirrorCancel, 0, "programmable mirror image cancel"},
    {511, G::Mirror, 22, false, A::Mirror, 0, "programmable mirror image"},
    // Further codes of the FANUC 30i series (the 30i manual's G-code table, notes §3.1, and
    // the 30i-M functions): real on the control, not built in ncc yet. Listed so that they
    // say "not supported yet" instead of "not a G code" (PS0010 stays for codes no table has).
    {22, G::Other, 1, false, A::NotSupported, 0, "involute interpolation CW"},
    {32, G::Other, 1, false, A::NotSupported, 0, "involute interpolation CCW"},
    {23, G::Other, 1, false, A::NotSupported, 0, "exponential interpolation CW"},
    {33, G::Other, 1, false, A::NotSupported, 0, "exponential interpolation CCW"},
    {24, G::Other, 1, false, A::NotSupported, 0, "3-D circular interpolation CW"},
    {34, G::Other, 1, false, A::NotSupported, 0, "3-D circular interpolation CCW"},
    {51, G::Other, 0, false, A::NotSupported, 0, "AI contour control / nano smoothing"},
    {54, G::Other, 0, false, A::NotSupported, 0, "HRV3/HRV4 control on/off"},
    {62, G::Other, 1, false, A::NotSupported, 0, "NURBS interpolation"},
    {70, G::Other, 0, false, A::NotSupported, 0, "hypothetical axis interpolation"},
    {106, G::Other, 0, false, A::NotSupported, 0, "tool retract and recover"},
    {121, G::Other, 21, false, A::NotSupported, 0, "polar coordinate interpolation"},
    {131, G::Other, 21, false, A::NotSupported, 0, "polar coordinate interpolation cancel"},
    {250, G::Other, 8, false, A::NotSupported, 0, "spindle speed fluctuation detection off"},
    {260, G::Other, 8, false, A::NotSupported, 0, "spindle speed fluctuation detection on"},
    {301, G::Other, 0, false, A::NotSupported, 0, "floating reference point return"},
    {318, G::Other, 0, false, A::NotSupported, 0, "EGB skip"},
    {412, G::Other, 7, false, A::NotSupported, 0, "3-D cutter compensation left"},
    {422, G::Other, 7, false, A::NotSupported, 0, "3-D cutter compensation right"},
    {435, G::Other, 8, false, A::NotSupported, 0, "tool center point control type 2"},
    {531, G::Other, 0, false, A::NotSupported, 0, "tool axis direction control"},
    {542, G::Other, 14, false, A::NotSupported, 0, "rotary table dynamic fixture offset"},
    {681, G::Other, 16, false, A::NotSupported, 0, "3-D coordinate conversion"},
    {682, G::Other, 16, false, A::NotSupported, 0, "tilted working plane command"},
    {691, G::Other, 16, false, A::NotSupported, 0, "3-D coordinate conversion cancel"},
    {721, G::Other, 0, false, A::NotSupported, 0, "figure copy (rotation)"},
    {722, G::Other, 0, false, A::NotSupported, 0, "figure copy (parallel)"},
    {911, G::Other, 0, false, A::NotSupported, 0, "maximum incremental command check"},
};

// Indexed by Alarm. FANUC numbers: PS0007/PS0010 from the 30i manual's alarm list; PS0009,
// PS0011, PS0020, PS0030, PS0031, PS0046, PS0092 are the common FANUC program alarms.
constexpr std::string_view kAlarms[] = {
    "NCC2001",  // MacroNotSupported
    "NCC2010",  // CodeNotSupported
    "PS0010",   // UnknownGCode: improper G-code
    "NCC2011",  // AddressNotSupported
    "PS0009",   // AddressNotAnAxis: improper NC-address
    "NCC2014",  // AddressWithoutMeaning
    "NCC2015",  // AddressRepeated
    "NCC2020",  // SameGroupInBlock
    "NCC2021",  // OneShotConflict
    "PS0007",   // DecimalPointNotAllowed: illegal use of decimal point
    "NCC2031",  // ValueOutOfRange
    "NCC2032",  // TooManyMCodes
    "PS0011",   // FeedMissing: feed zero (command)
    "PS0020",   // ArcRadiusMismatch: over tolerance of radius
    "PS0020",   // ArcRadiusTooSmall: no centre exists, same alarm
    "NCC2043",  // ArcCentreMissing
    "NCC2044",  // ArcDegenerate
    "PS0030",   // OffsetNumberOutOfRange: illegal offset number
    "PS0092",   // ReferenceCheckFailed: zero return check (G27) error
    "PS0046",   // ReferencePointNumber: illegal reference return command
    "PS0031",   // DataSetFormat: illegal P command in G10
    "NCC2071",  // ExtendedOffsetNumber
    "NCC2072",  // ExtendedOffsetRequired
    "NCC2073",  // LocalShiftInExtended
    "NCC2080",  // AxisMissing
    "NCC2081",  // G53Incremental
    "PS0003",   // TooManyDigits: too many digits
    "NCC2045",  // LengthCompInArc (not raised)
    "PS0051",   // CornerNoMoveAfter: missing move after CNR/CHF (FANUC common)
    "PS0052",   // CornerNotCuttingAfter: code is not G01 after CNR/CHF (FANUC common)
    "NCC2092",  // CornerArcNotAllowed (not raised: arcs are allowed)
    "PS0055",   // CornerTooLong: missing move value in CNR/CHF (FANUC common)
    "PS0055",   // CornerTooLongAfter: the same alarm (FANUC common)
    "PS0051",   // CornerContextChange: plane selected in the next block (FANUC common)
    "NCC2096",  // CycleDepthMissing (no FANUC number known)
    "PS0045",   // CyclePeckMissing: address Q not found (G73/G83) (FANUC common)
    "NCC2097",  // CyclePeckInvalid: Q zero or negative (no FANUC number known)
    "PS0011",   // CycleFeedMissing: feed zero (command)
    "NCC2098",  // CycleSpindleDirection (not raised)
    "NCC2099",  // CycleReferencePlane (not raised)
    "NCC2110",  // TransformArcNotCircle
    "NCC2111",  // TransformWordMissing
    "NCC2112",  // TransformNotAlone (not raised)
    "NCC2113",  // TransformOrder (not raised)
    "NCC2114",  // RotationVector (not raised: any I J K vector)
    "NCC2115",  // RotationNesting: a third G68 (FANUC 3-D conversion nests twice)
    "PS0142",   // ScaleFactorRange: illegal scale rate (FANUC common)
    "NCC2116",  // RotationAngleRange
    "NCC2118",  // FigureRotationWithRotation (not raised)
    "NCC2119",  // ArcAfterWorkRotation (not raised)
    "NCC2088",  // PolarNotAllowed (the FANUC alarm number is not in the project's manuals)
    "PS0034",   // CompStartInArc: start-up/cancel in G02/G03 (§5.4)
    "PS0037",   // CompPlaneChange: offset plane changed (§5.3)
    "PS0035",   // CompSkip: G31 in compensation mode
    "NCC2123",  // CompReferenceReturn (not raised: G28/G30 cancel the vector for the move, §5.4)
    "NCC2124",  // CompSideChangeEarly (the manual names no alarm)
    "NCC2125",  // CompCornerArcMove: a move in the G39 block (no number given)
    "PS0033",   // CompNoIntersection: no intersection in compensation (§5.4)
    "PS0041",   // CompInterference: interference in compensation (§5.4.6)
    "NCC2128",  // CompWithoutMotion (the controller overcuts silently)
    "NCC2129",  // CompInCycle (not raised: the cycle runs on the programmed points)
    "NCC2011",  // NameNotDefined (DIN only)
};
static_assert(std::size(kAlarms) == static_cast<size_t>(Alarm::kCount));

// The hole cycles (docs/cycles.md). There is no FANUC mill manual here: the sequences are the
// FANUC-family ones the Mazak EIA/ISO manual shares (§13-1, §13-2), and the details marked
// "FANUC common" (no P in G73/G83/G85/G86, the G84 dwell at R, the +X shift of G76 with
// No.5101 RD1 = RD2 = 0) are common FANUC knowledge.
using CK = ir::HoleCycle::Kind;
constexpr CycleEntry kCycleEntries[] = {
    // code kind              dwell  feed_out stop   tap  P in s shift  M00   dwell R pitch
    {730, CK::HighSpeedPeck, false, false, false, 0, false, false, false, false, false},
    {740, CK::Tap, true, false, false, -1, false, false, false, true, false},
    {760, CK::FineBore, true, false, false, 0, false, true, false, false, false},
    {810, CK::Drill, false, false, false, 0, false, false, false, false, false},
    {820, CK::Drill, true, false, false, 0, false, false, false, false, false},
    {830, CK::Peck, false, false, false, 0, false, false, false, false, false},
    {840, CK::Tap, true, false, false, 1, false, false, false, true, false},
    {850, CK::Drill, false, true, false, 0, false, false, false, false, false},
    {860, CK::Drill, false, false, true, 0, false, false, false, false, false},
    {870, CK::BackBore, true, false, false, 0, false, true, false, false, false},
    {880, CK::Drill, true, false, true, 0, false, false, true, false, false},
    {890, CK::Drill, true, true, false, 0, false, false, false, false, false},
};
constexpr CycleRules kCycles{
    .entries = kCycleEntries,
    .repeat_address = 'K',
    .positioning_in_motion_mode = false,  // FANUC common: positioning is always rapid
    .spindle_direction_required = false,
    .q_sign_ignored = false,
    .r_beyond_bottom_is_error = false,
    .peck_retract_feed = 0.0,             // G73 backs off at rapid (FANUC common)
    .d_is_peck_distance = false,
    .default_shift_direction = 1,         // FANUC common: RD1 = RD2 = 0, +X in G17
    .peck_tapping = CycleRules::PeckTapping::RigidMode,  // deep-hole rigid tapping (lathe §4.4)
    .rigid_tap_m_code = 29,
    .peck_tap_approach_at_feed = false,
};

constexpr DialectBehaviour kBehaviour{
    .same_group_default = "error",          // the issue asks for an alarm (docs/semantics.md)
    .decimal_point_default = "standard",    // FANUC DPI (No.3401#0) = 0
    .rapid_type_default = "per_axis",       // FANUC LRP (No.1401#1) = 0: non-linear positioning
    .arc_radius_tolerance_default = 0.01,   // FANUC No.3410
    .offset_count_default = 400,            // 0i-F: 400 offset pairs
    .max_m_codes = 3,                       // M3B (No.3404#7) = 1: up to three M codes
    .m_overflow_keeps_last = false,
    .max_t_words = 1,
    .duplicate_h_d_last_wins = false,
    .integer_point_is_error = true,         // PS0007
    .dwell_p_point_is_error = true,         // P is an integer address: PS0007
    .dwell_revolutions_default = false,     // DWL (No.3405#1) = 0: always seconds
    .reference_return_cancels_length = true,
    .local_shift_per_work_offset = false,   // "G52 sets a local system in all of G54-G59"
    .local_shift_in_extended_is_error = false,
    .work_offset_write_on_reselect = false, // a G10 write to the active system acts at once
    .g53_in_g91 = DialectBehaviour::G53InG91::Ignored,  // "G53 in G91 is ignored"
    .g30_p = DialectBehaviour::G30P::ErrorOutside2To4,
    .g10_l2_p_lenient = false,
    .extended_offset_count = 48,
    .extended_offset_is_g54_p = false,
    .inverse_time_arc_per_radius = false,
    .length_change_moves_default = true,
    .format_digits = 8,                     // FANUC: 8-digit address format (PS0003)
    .length_comp_in_arc_is_error = false,  // kept: a straight line at the modal F
    .arc_turns = DialectBehaviour::ArcTurns::None,  // no turn count with G02/G03
    .helical_feed_along_arc = true,         // HTG (No.1403#5) = 0: F along the arc (notes §4.3)
    .dwell_x_before_g04_is_coordinate = false,
    .dwell_block_alone = false,
    .skip_feed_is_modal = true,             // G31 takes F like G01
    .corner_with_arcs = true,
    .line_angle_address = "",
    .other_meaning_addresses = "",
    .decimal_point_from_params = true,
};
// FANUC Series 0i-MD/30i-M custom macro system variables (tool offset memory C, up to 200
// offsets: H wear #2001, H geometry #2201, D wear #2401, D geometry #2601). The project has no
// FANUC milling manual; these are the documented FANUC numbers (docs/macro.md).
constexpr SystemVariableRange kSystemVariables[] = {
    {1000, 1035, SystemVariable::InputSignal, 0, "interface input signals"},
    {1100, 1135, SystemVariable::OutputSignal, 0, "interface output signals"},
    {2001, 2200, SystemVariable::LengthWear, 0, "tool length wear offsets"},
    {2201, 2400, SystemVariable::LengthGeometry, 0, "tool length geometry offsets"},
    {2401, 2600, SystemVariable::RadiusWear, 0, "tool radius wear offsets"},
    {2601, 2800, SystemVariable::RadiusGeometry, 0, "tool radius geometry offsets"},
    {3001, 3001, SystemVariable::TimerMs, 0, "timer, ms"},     // FANUC common
    {3002, 3002, SystemVariable::TimerHours, 0, "timer, hours"},  // FANUC common
    {4001, 4030, SystemVariable::ModalGroup, 0, "modal G codes"},
    {4101, 4130, SystemVariable::ModalWord, 0, "modal words"},
    {5001, 5020, SystemVariable::EndPoint, 0, "block end point"},
    {5021, 5040, SystemVariable::MachinePosition, 0, "machine position"},
    {5041, 5060, SystemVariable::WorkPosition, 0, "work position"},
    {5061, 5080, SystemVariable::SkipPosition, 0, "skip position"},
    {5081, 5100, SystemVariable::ToolLengthVector, 0, "tool length offset"},
    {5101, 5120, SystemVariable::RunTime, 0, "servo deviation"},
    {5201, 5220, SystemVariable::ExternalOffset, 0, "external work offset"},
    {5221, 5340, SystemVariable::WorkOffset, 20, "G54-G59 work offsets"},
    {7001, 7960, SystemVariable::ExtendedWorkOffset, 20, "G54.1 P1-P48 work offsets"},
};

// Coordinate rotation, scaling and mirror (docs/transforms.md). There is no FANUC mill manual
// here: these are the FANUC-family rules the lathe manual states for G68.1 (§5.9: centre
// absolute, the position when omitted, R absolute unless RIN) and the common FANUC mill ones
// (scaling before rotation; "a mirror on one axis reverses the rotation", so the mirror acts
// last; G51 centre absolute, the position when omitted; P in
// scale_factor_unit; 3-D conversion with I J K nests twice).
constexpr TransformRules kTransforms{
    .order = {TransformRules::Stage::FigureRotation, TransformRules::Stage::Scaling,
              TransformRules::Stage::Rotation, TransformRules::Stage::Mirror},
    .rotation_angle_required = false,  // R omitted: the parameter's angle (No.5410)
    .rotation_angle_follows_distance = false,
    .rotation_stacks_2d = false,
    .rotation_stacks_3d = true,
    .max_rotations = 2,
    .extra_rotation_replaces_last = false,
    .rotation_3d_unit_axis_only = false,
    .rotation_3d_centre_is_origin = false,
    .rotation_3d_centre_is_new_zero = false,
    .rotation_3d_restricted = false,
    .rotation_3d_angle_absolute = true,
    .transform_block_alone = false,
    .scale_centre_omitted = TransformRules::ScaleCentre::CurrentPosition,
    .scale_centre_follows_distance = false,
    .rescale_adds_axes = false,
    .scale_p_point_only_after_g51 = false,
    .scale_p_fixed_increment = false,
    .scale_p_increment = 0.0,
    .scale_factor_max = 999.999,
    .scale_tiny_factor_is_one = false,
    .scale_cancel_moves = false,
    .reference_return_cancels_scaling = false,
    .mirror_centre_follows_distance = false,
    .mirror_only_outside_others = false,
};
}  // namespace

// G15/G16 (FANUC Series 0i/30i-M "polar coordinate command"; docs/semantics.md).
constexpr PolarRules kPolar{
    .angle_from_axis_at_current_pole = false,  // an incremental angle continues the angle in force
    .arcs = PolarRules::Arcs::RadiusOnly,      // "specify the radius ... with R"
    .corners_allowed = false,                  // ,C / ,R "cannot be specified" in G16
};

// G40/G41/G42, G38, G39 (FANUC 30i §5.3-5.6, the mill rules of the lathe manual's algorithm).
constexpr CompRules kComp{
    .lookahead = 3,                  // No.19625 (3-8)
    .max_without_motion = 0,         // §5.4.3: intersection while (N - 2) >= M
    .startup = ir::CutterComp::Startup::A,  // SUV = SUP = 0
    .arc_corners = false,            // CCC (No.19607#2) = 0: linear
    .side_change_early_is_error = true,   // "no G41/G42 change in the start-up block and the next"
    .cancel_in_arc_is_error = true,  // PS0034: start-up or cancel in G02/G03
    .reference_return_is_error = false,   // G28/G30 remove the vector for the block (§5.4)
    .skip_is_error = true,           // PS0035
    .d_zero_cancels = false,         // D0 is radius 0 (the lathe's T□□00 is the T word)
    .same_side_recommand_counts = true,  // G41 in G41: the vector perpendicular to the previous block
    .side_change_perpendicular = false,  // the old and new paths' intersection
    .vector_with_motion = true,      // G00/G01 with I J K: the IJ-type vector
    .vector_with_cancel = true,      // G40 X Y I J
    .vector_with_hold = false,       // G38 IP_ only
    .has_3d = false,                 // G41.2/G42.2 are a separate function (not supported)
    .cycle_in_3d_is_error = false,
};

const DialectTable kFanucMTable{Dialect::FanucM, kCodes, kAlarms, kBehaviour, kSystemVariables,
                                &kCycles, &kTransforms, &kPolar, &kComp};

}  // namespace ncc::passes
