// mazak-m: Mazak MAZATROL FUSION 640M, EIA/ISO mode (mazak-fusion640m-eia-iso.fr.md §3 for the
// groups, §6 for the alarms).
#include "dialect_tables.h"

namespace ncc::passes {

namespace {
using A = GAction;
using G = GGroup;

constexpr GCodeEntry kCodes[] = {
    // group 00 (one-shot)
    {40, G::OneShot, 0, false, A::Dwell, 0, "dwell"},
    {90, G::OneShot, 0, false, A::ExactStopOneShot, 0, "exact stop check"},
    {100, G::OneShot, 0, false, A::DataSet, 0, "programmed data setting"},
    {270, G::OneShot, 0, false, A::ReferenceCheck, 0, "reference point check"},
    {280, G::OneShot, 0, false, A::ReferenceReturn, 0, "reference point return"},
    {290, G::OneShot, 0, false, A::NotSupported, 0, "start point return"},
    {300, G::OneShot, 0, false, A::ReferenceReturnN, 0, "2nd/3rd/4th reference point return"},
    {310, G::OneShot, 0, false, A::Skip, 0, "skip function"},
    {311, G::OneShot, 0, false, A::Skip, 0, "multi-step skip"},
    {312, G::OneShot, 0, false, A::Skip, 0, "multi-step skip"},
    {313, G::OneShot, 0, false, A::Skip, 0, "multi-step skip"},
    {370, G::OneShot, 0, false, A::NotSupported, 0, "automatic tool length measurement"},
    {380, G::OneShot, 0, false, A::CompVectorHold, 0, "tool radius compensation vector selection"},
    {390, G::OneShot, 0, false, A::CompCornerArc, 0, "tool radius compensation corner arc"},
    {450, G::OneShot, 0, false, A::PositionOffset, 0, "tool position offset extension"},
    {460, G::OneShot, 0, false, A::PositionOffset, 0, "tool position offset reduction"},
    {470, G::OneShot, 0, false, A::PositionOffset, 0, "tool position offset double extension"},
    {480, G::OneShot, 0, false, A::PositionOffset, 0, "tool position offset double reduction"},
    {520, G::OneShot, 0, false, A::LocalShift, 0, "local coordinate system setting"},
    {530, G::OneShot, 0, false, A::MachineCoordinates, 0, "machine coordinate system selection"},
    {600, G::OneShot, 0, false, A::NotSupported, 0, "one-way positioning"},
    {650, G::OneShot, 0, false, A::NotSupported, 0, "user macro simple call"},
    {920, G::OneShot, 0, false, A::SetShift, 0, "coordinate system setting"},
    {21, G::OneShot, 0, false, A::NotSupported, 0, "spiral interpolation CW"},
    {31, G::OneShot, 0, false, A::NotSupported, 0, "spiral interpolation CCW"},
    {50, G::Other, 0, false, A::NotSupported, 0, "high-speed machining mode"},
    {70, G::Other, 0, false, A::NotSupported, 0, "virtual axis interpolation"},
    {925, G::OneShot, 0, false, A::WorkRotation, 0, "work coordinate system rotation"},
    // group 01
    {0, G::Motion, 1, true, A::Rapid, 0, "positioning"},
    {10, G::Motion, 1, false, A::Linear, 0, "linear interpolation"},
    {20, G::Motion, 1, false, A::ArcCW, 0, "circular interpolation CW"},
    {30, G::Motion, 1, false, A::ArcCCW, 0, "circular interpolation CCW"},
    {61, G::Motion, 1, false, A::NotSupported, 0, "spline interpolation"},
    {62, G::Motion, 1, false, A::NotSupported, 0, "NURBS interpolation"},
    {330, G::Motion, 1, false, A::NotSupported, 0, "thread cutting"},
    // group 02
    {170, G::Plane, 2, true, A::PlaneXY, 0, "XY plane"},
    {180, G::Plane, 2, false, A::PlaneZX, 0, "ZX plane"},
    {190, G::Plane, 2, false, A::PlaneYZ, 0, "YZ plane"},
    // group 03
    {900, G::Distance, 3, true, A::Absolute, 0, "absolute data input"},
    {910, G::Distance, 3, false, A::Incremental, 0, "incremental data input"},
    // group 04
    {220, G::StrokeCheck, 4, false, A::NotSupported, 0, "pre-move stroke check on"},
    {230, G::StrokeCheck, 4, true, A::CancelNoEffect, 0, "pre-move stroke check off"},
    // group 05
    {930, G::FeedMode, 5, false, A::InverseTime, 0, "inverse time feed"},
    {940, G::FeedMode, 5, true, A::PerMinute, 0, "feed per minute"},
    {950, G::FeedMode, 5, false, A::PerRevolution, 0, "feed per revolution"},
    // group 06 (power-on unit: parameter reset_unit, F91 bit 4)
    {200, G::Units, 6, false, A::Inch, 0, "inch data input"},
    {210, G::Units, 6, true, A::Metric, 0, "metric data input"},
    // group 07
    {400, G::CutterComp, 7, true, A::CompCancel, 0, "tool radius compensation cancel"},
    {410, G::CutterComp, 7, false, A::CompLeft, 0, "tool radius compensation left"},
    {420, G::CutterComp, 7, false, A::CompRight, 0, "tool radius compensation right"},
    // group 08
    {430, G::LengthComp, 8, false, A::LengthPlus, 0, "tool length offset +"},
    {440, G::LengthComp, 8, false, A::LengthMinus, 0, "tool length offset -"},
    {490, G::LengthComp, 8, true, A::LengthCancel, 0, "tool length offset cancel"},
    // group 09
    {711, G::Cycle, 9, false, A::NotSupported, 0, "chamfering cycle"},
    {721, G::Cycle, 9, false, A::NotSupported, 0, "chamfering cycle"},
    {730, G::Cycle, 9, false, A::HoleCycle, 0, "high-speed deep hole drilling cycle"},
    {740, G::Cycle, 9, false, A::HoleCycle, 0, "reverse tapping cycle"},
    {750, G::Cycle, 9, false, A::NotSupported, 0, "boring cycle"},
    {760, G::Cycle, 9, false, A::HoleCycle, 0, "fine boring cycle"},
    {770, G::Cycle, 9, false, A::NotSupported, 0, "back spot facing cycle"},
    {780, G::Cycle, 9, false, A::NotSupported, 0, "boring cycle"},
    {790, G::Cycle, 9, false, A::NotSupported, 0, "boring cycle"},
    {800, G::Cycle, 9, true, A::CycleCancel, 0, "fixed cycle cancel"},
    {810, G::Cycle, 9, false, A::HoleCycle, 0, "canned drilling cycle"},
    {820, G::Cycle, 9, false, A::HoleCycle, 0, "canned drilling cycle with dwell"},
    {830, G::Cycle, 9, false, A::HoleCycle, 0, "canned deep hole drilling cycle"},
    {840, G::Cycle, 9, false, A::HoleCycle, 0, "canned tapping cycle"},
    {842, G::Cycle, 9, false, A::HoleCycle, 0, "synchronous tapping cycle"},
    {843, G::Cycle, 9, false, A::HoleCycle, 0, "synchronous reverse tapping cycle"},
    {850, G::Cycle, 9, false, A::HoleCycle, 0, "canned reaming cycle"},
    {860, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    {870, G::Cycle, 9, false, A::HoleCycle, 0, "canned back boring cycle"},
    {880, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    {890, G::Cycle, 9, false, A::HoleCycle, 0, "canned boring cycle"},
    {1300, G::Cycle, 9, false, A::NotSupported, 0, "TORNADO cycle"},
    // group 10: return level, only meaningful with canned cycles (never active)
    {980, G::ReturnLevel, 10, true, A::ReturnInitial, 0, "fixed cycle initial point level return"},
    {990, G::ReturnLevel, 10, false, A::ReturnR, 0, "fixed cycle R point level return"},
    // group 11
    {500, G::Scaling, 11, true, A::ScalingCancel, 0, "scaling cancel"},
    {510, G::Scaling, 11, false, A::Scaling, 0, "scaling"},
    // group 12
    {540, G::WorkOffset, 12, true, A::WorkOffset, 1, "work coordinate system 1"},
    {550, G::WorkOffset, 12, false, A::WorkOffset, 2, "work coordinate system 2"},
    {560, G::WorkOffset, 12, false, A::WorkOffset, 3, "work coordinate system 3"},
    {570, G::WorkOffset, 12, false, A::WorkOffset, 4, "work coordinate system 4"},
    {580, G::WorkOffset, 12, false, A::WorkOffset, 5, "work coordinate system 5"},
    {590, G::WorkOffset, 12, false, A::WorkOffset, 6, "work coordinate system 6"},
    {541, G::WorkOffset, 12, false, A::WorkOffsetExtended, 0, "additional work coordinate system"},
    // group 13
    {610, G::PathControl, 13, false, A::ExactStopMode, 0, "exact stop mode"},
    {611, G::PathControl, 13, false, A::NotSupported, 0, "shape correction"},
    {620, G::PathControl, 13, false, A::CornerOverride, 0, "automatic corner override"},
    {630, G::PathControl, 13, false, A::TappingMode, 0, "tapping mode"},
    {640, G::PathControl, 13, true, A::ContinuousMode, 0, "cutting mode"},
    // group 14
    {660, G::MacroModal, 14, false, A::NotSupported, 0, "user macro modal call"},
    {661, G::MacroModal, 14, false, A::NotSupported, 0, "user macro modal call"},
    {670, G::MacroModal, 14, true, A::CancelNoEffect, 0, "user macro modal call cancel"},
    // group 15
    {401, G::Profiling, 15, true, A::CancelNoEffect, 0, "normal line control cancel"},
    {411, G::Profiling, 15, false, A::NotSupported, 0, "normal line control left"},
    {421, G::Profiling, 15, false, A::NotSupported, 0, "normal line control right"},
    // group 16
    {680, G::Rotation, 16, false, A::Rotation, 0, "coordinate rotation"},
    {690, G::Rotation, 16, true, A::RotationCancel, 0, "coordinate rotation cancel"},
    // group 19
    {501, G::Mirror, 19, true, A::MirrorCancel, 0, "programmable mirror image cancel"},
    {511, G::Mirror, 19, false, A::Mirror, 0, "programmable mirror image"},
    // Five-face machining (ch. 21): real codes of the control, not built in ncc yet.
    {171, G::Other, 0, false, A::NotSupported, 0, "five-face machining: top face mode"},
    {172, G::Other, 0, false, A::NotSupported, 0, "five-face machining: 0 deg face mode"},
    {173, G::Other, 0, false, A::NotSupported, 0, "five-face machining: 90 deg face mode"},
    {174, G::Other, 0, false, A::NotSupported, 0, "five-face machining: 180 deg face mode"},
    {175, G::Other, 0, false, A::NotSupported, 0, "five-face machining: 270 deg face mode"},
    {179, G::Other, 0, false, A::NotSupported, 0, "five-face machining: face mode cancel"},
    {451, G::Other, 0, false, A::NotSupported, 0, "head offset"},
    {491, G::Other, 0, false, A::NotSupported, 0, "head offset cancel"},
};

// Indexed by Alarm; numbers from the manual's alarm list (notes §6).
constexpr std::string_view kAlarms[] = {
    "NCC2001",  // MacroNotSupported
    "NCC2010",  // CodeNotSupported
    "NCC2012",  // UnknownGCode (the manual: "unknown codes raise an alarm", no number)
    "NCC2011",  // AddressNotSupported
    "NCC2013",  // AddressNotAnAxis
    "NCC2014",  // AddressWithoutMeaning
    "NCC2015",  // AddressRepeated
    "NCC2020",  // SameGroupInBlock
    "NCC2021",  // OneShotConflict
    "NCC2030",  // DecimalPointNotAllowed (not raised: fractions are dropped)
    "NCC2031",  // ValueOutOfRange
    "NCC2032",  // TooManyMCodes (warning: the last four win)
    "816",      // FeedMissing: AVANCE D'USINAGE = ZERO
    "817",      // ArcRadiusMismatch: radius difference above F19
    "818",      // ArcRadiusTooSmall: IMPOSSIBLE DE CHERCHER CENTRE
    "NCC2043",  // ArcCentreMissing
    "NCC2044",  // ArcDegenerate
    "839",      // OffsetNumberOutOfRange: No. DE CORRECT. NON AUTORISE
    "NCC2060",  // ReferenceCheckFailed (no number in the notes)
    "NCC2061",  // ReferencePointNumber (not raised: bad P selects the 2nd point)
    "903",      // DataSetFormat: G10 L/P
    "809",      // ExtendedOffsetNumber: G54.1 P
    "807",      // ExtendedOffsetRequired: G10 L20 without P in G54-G59
    "949",      // LocalShiftInExtended: G52 in G54.1
    "NCC2080",  // AxisMissing
    "NCC2081",  // G53Incremental (not raised: G53 is incremental in G91)
    "809",      // TooManyDigits: number of more than 8 digits
    "NCC2045",  // LengthCompInArc (not raised)
    "912",      // CornerNoMoveAfter: PAS CDE DEPLACE APRES R/C (§13-14)
    "912",      // CornerNotCuttingAfter: the next block is not linear interpolation
    "911",      // CornerArcNotAllowed: OPTION COIN R/C NON TROUVEE (next block an arc)
    "913",      // CornerTooLong: COMMANDE R/C INCORRECT
    "914",      // CornerTooLongAfter: COMMANDE INCORRECT APRES R/C
    "NCC2095",  // CornerContextChange (no number stated)
    "NCC2096",  // CycleDepthMissing (no number in the manual)
    "809",      // CyclePeckMissing: §13-1-3 "Q omitted or Q0: the alarm"
    "809",      // CyclePeckInvalid: §13-1-6 Q0 -> 809 NOMBRE NON AUTORISE
    "816",      // CycleFeedMissing: AVANCE D'USINAGE = ZERO
    "NCC2098",  // CycleSpindleDirection (not raised)
    "NCC2099",  // CycleReferencePlane (not raised)
    "NCC2110",  // TransformArcNotCircle
    "807",      // TransformWordMissing: format error
    "807",      // TransformNotAlone: a 3-D G68/G69 with another G code (ch. 22 §5.2)
    "943",      // TransformOrder: G51 / G54-G59 in 3-D G68 mode (ch. 22 §2)
    "807",      // RotationVector: 3-D G68 I J K not one axis (ch. 22)
    "NCC2115",  // RotationNesting (not raised: nested 3-D G68 compose)
    "809",      // ScaleFactorRange: G51 P too large (§13-10 3.A)
    "809",      // RotationAngleRange: number not allowed
    "850",      // FigureRotationWithRotation: G68 with M98 (§13-7 note 4)
    "817",      // ArcAfterWorkRotation: an arc after G92.5 (§14-13)
    "NCC2088",  // PolarNotAllowed (not raised: the manual has no G16)
    "835",      // CompStartInArc: G40/D00 or a start-up in an arc block (§12-4)
    "NCC2121",  // CompPlaneChange (the manual names no alarm)
    "NCC2122",  // CompSkip: G31 in compensation is an error (no number given)
    "NCC2123",  // CompReferenceReturn (not raised: the vector is cleared for that block)
    "NCC2124",  // CompSideChangeEarly: no flip in the 1st or 2nd compensated block
    "NCC2125",  // CompCornerArcMove (no number given)
    "836",      // CompNoIntersection: no intersection (§12-4)
    "837",      // CompInterference: interference (§12-4)
    "NCC2128",  // CompWithoutMotion (more than 4 in a row: the controller over- or under-cuts)
    "901",      // CompInCycle: a cycle in 3-D compensation
    "NCC2011",  // NameNotDefined (DIN only)
};
static_assert(std::size(kAlarms) == static_cast<size_t>(Alarm::kCount));

// The hole cycles, §13-1-2 (list and arguments) and §13-1-3 ff. (docs/cycles.md). P is a dwell
// in the cycles whose format has it; G74/G84 count it in seconds (§13-1-2 "Remarques").
using CK = ir::HoleCycle::Kind;
constexpr CycleEntry kCycleEntries[] = {
    // code kind              dwell  feed_out stop   tap  P in s shift  M00   dwell R pitch
    // §13-1-6, -14, -15: K (G73/G83) or D (G82) from R to the feed start; I J the slow zone.
    {730, CK::HighSpeedPeck, true, false, false, 0, false, false, false, false, false, 'K', true},
    {740, CK::Tap, true, false, false, -1, true, false, false, false, false},
    {760, CK::FineBore, true, false, false, 0, false, true, false, false, false},
    {810, CK::Drill, false, false, false, 0, false, false, false, false, false},
    {820, CK::Drill, true, false, false, 0, false, false, false, false, false, 'D', true},
    {830, CK::Peck, true, false, false, 0, false, false, false, false, false, 'K', true},
    {840, CK::Tap, true, false, false, 1, true, false, false, false, false},
    // §13-1-22: synchronous tapping, F the pitch; P at Z and at R (in seconds, as G84's);
    // the way out at K90 % (tap_retract_percent).
    {842, CK::Tap, true, false, false, 1, true, false, false, true, true},
    {843, CK::Tap, true, false, false, -1, true, false, false, true, true},
    {850, CK::Drill, true, true, false, 0, false, false, false, false, false},
    {860, CK::Drill, true, false, true, 0, false, false, false, false, false},
    {870, CK::BackBore, true, false, false, 0, false, true, false, false, false},
    {880, CK::Drill, true, false, true, 0, false, false, true, false, false},
    {890, CK::Drill, true, true, false, 0, false, false, false, false, false},
};
constexpr CycleRules kCycles{
    .entries = kCycleEntries,
    .repeat_address = 'L',                // §13-1-3: L repeats, L0 stores the data only
    .positioning_in_motion_mode = true,   // §13-1-1 movement 1: the group-01 code (G01: feed)
    .spindle_direction_required = false,
    .q_sign_ignored = false,              // Q0 -> 809; a negative Q likewise (not a depth)
    .r_beyond_bottom_is_error = false,
    .peck_retract_feed = 9999.0,          // §13-1-6: f2, the fixed return speed, 9999 mm/min
    .d_is_peck_distance = true,
    .default_shift_direction = 1,         // I14 bits 3-4 = 0: +X in G17
    .peck_tapping = CycleRules::PeckTapping::None,  // §13-1: no Q in G74/G84
    .rigid_tap_m_code = 0,
    .peck_tap_approach_at_feed = false,
};

constexpr DialectBehaviour kBehaviour{
    .same_group_default = "per_word",       // §5-1: G90X300. G91Y100.
    .decimal_point_default = "standard",    // F91 bit 5 = 0 (type 1)
    .rapid_type_default = "linear",         // F91 bit 6 = 0
    .arc_radius_tolerance_default = 0.01,   // F19
    .offset_count_default = 128,            // standard offset memory H1-H128
    .max_m_codes = 4,                       // ch. 3: at most 4 M codes, the last 4 win
    .m_overflow_keeps_last = true,
    .max_t_words = 2,                       // `T01 T00 M06`: tool and next tool
    .duplicate_h_d_last_wins = true,        // "only one H/D per block: the last wins"
    .integer_point_is_error = false,        // D H L M N O S T ignore fractions
    .dwell_p_point_is_error = false,        // G04 P12.345 -> 12 ms
    .dwell_revolutions_default = true,      // F92 bit 2 = 0: G95 dwell in revolutions
    .reference_return_cancels_length = true,  // §12-2 5.4
    .local_shift_per_work_offset = true,    // §14-11: set in G54 it does not apply in G55
    .local_shift_in_extended_is_error = true,
    .work_offset_write_on_reselect = false, // §12-6 E11: the display changes at once
    .g53_in_g91 = DialectBehaviour::G53InG91::Incremental,  // §14-3
    .g30_p = DialectBehaviour::G30P::OtherMeansSecond,        // §14-7
    .g10_l2_p_lenient = true,               // §12-6: P outside 0-6 -> 1, P missing -> last P
    .extended_offset_count = 48,
    .extended_offset_is_g54_p = false,
    .inverse_time_arc_per_radius = true,    // §7-10: arcs F = speed / radius
    .length_change_moves_default = true,    // §12-2: move = ±z + (lh1 - lh0)
    .format_digits = 8,                     // §5: "5+3 digits with a point, or 8 digits without" (809)
    .length_comp_in_arc_is_error = false,  // the notes do not forbid it
    .arc_turns = DialectBehaviour::ArcTurns::PitchesP,  // §6-7: helical P = number of pitches
    .helical_feed_along_arc = false,        // §6-7: F is the tangential speed of the tool
    .dwell_x_before_g04_is_coordinate = true,  // §8-1: inch `X5. G04` = X50000 = 50 s
    .dwell_block_alone = false,             // §8-1: M, S, T, B in a G04 block run with it
    .skip_feed_is_modal = false,            // §4.10: K41 = 0, the modal F is not changed
    .corner_with_arcs = false,
    .line_angle_address = "A",   // §13-12 line angle
    .other_meaning_addresses = "",
    .decimal_point_from_params = true,
};
// §13-9-4 (notes §4.8, System variables); F96 bit 0 = 0 (the #2001 ranges, up to 200 offsets).
constexpr SystemVariableRange kSystemVariables[] = {
    {1000, 1035, SystemVariable::InputSignal, 0, "interface input signals"},
    {1100, 1135, SystemVariable::OutputSignal, 0, "interface output signals"},
    {2001, 2200, SystemVariable::LengthGeometry, 0, "tool length geometry offsets"},
    {2201, 2400, SystemVariable::LengthWear, 0, "tool length wear offsets"},
    {2401, 2600, SystemVariable::RadiusGeometry, 0, "tool radius geometry offsets"},
    {2601, 2800, SystemVariable::RadiusWear, 0, "tool radius wear offsets"},
    // §13-9-4 8.: both in ms (the table's unit cell spans both rows); #3001 counts from
    // power-on, #3002 in automatic operation: both the run's time here.
    {3001, 3002, SystemVariable::TimerMs, 0, "timer, ms"},
    {4001, 4021, SystemVariable::ModalGroup, 0, "modal G codes"},
    {4101, 4130, SystemVariable::ModalWord, 0, "modal words"},
    {5001, 5006, SystemVariable::EndPoint, 0, "block end point"},
    {5021, 5026, SystemVariable::MachinePosition, 0, "machine position"},
    {5041, 5046, SystemVariable::WorkPosition, 0, "work position"},
    {5061, 5066, SystemVariable::SkipPosition, 0, "skip position"},
    {5081, 5086, SystemVariable::ToolLengthVector, 0, "tool length offset"},
    {5101, 5106, SystemVariable::RunTime, 0, "servo deviation"},
    {5201, 5206, SystemVariable::ExternalOffset, 0, "external work offset"},
    {5221, 5340, SystemVariable::WorkOffset, 20, "G54-G59 work offsets"},
    {7001, 7960, SystemVariable::ExtendedWorkOffset, 20, "G54.1 P1-P48 work offsets"},
};

// Coordinate rotation, scaling, mirror and figure rotation (docs/transforms.md): §13-7, §13-8
// (rotation before mirror, offsets after), §13-10 (the scaling centre turns with a rotation
// given before it), §13-11, ch. 22 (3-D G68).
constexpr TransformRules kTransforms{
    .order = {TransformRules::Stage::FigureRotation, TransformRules::Stage::Scaling,
              TransformRules::Stage::Rotation, TransformRules::Stage::Mirror},
    .rotation_angle_required = true,   // §13-8 2.: R is part of the format
    .rotation_angle_follows_distance = true,
    .rotation_stacks_2d = false,       // §13-8 3.4: a new centre and angle
    .rotation_stacks_3d = true,        // ch. 22: nested G68 compose
    .max_rotations = 0,
    .extra_rotation_replaces_last = false,
    .rotation_3d_unit_axis_only = true,
    .rotation_3d_centre_is_origin = true,   // ch. 22 §2: the current work zero
    .rotation_3d_centre_is_new_zero = true,
    .rotation_3d_restricted = true,
    .rotation_3d_angle_absolute = true,
    .transform_block_alone = false,
    .scale_centre_omitted = TransformRules::ScaleCentre::AxisNotScaled,  // §13-10 3.A
    .scale_centre_follows_distance = true,
    .rescale_adds_axes = true,
    .scale_p_point_only_after_g51 = true,
    .scale_p_fixed_increment = true,
    .scale_p_increment = 0.000001,
    .scale_factor_max = 99.999999,
    .scale_tiny_factor_is_one = true,
    .scale_cancel_moves = true,
    .reference_return_cancels_scaling = true,
    .mirror_centre_follows_distance = true,
    .mirror_only_outside_others = false,
};
}  // namespace

// G40/G41/G42, G38, G39 (§12-4).
constexpr CompRules kComp{
    .lookahead = 5,                  // "after the next five blocks are read"
    .max_without_motion = 4,         // "more than 4 blocks without motion": over- or under-cut
    .startup = ir::CutterComp::Startup::A,  // F92 bit 4 = 0
    .arc_corners = false,
    .side_change_early_is_error = true,   // "not in the first and second compensated blocks"
    .cancel_in_arc_is_error = true,  // 835: G40/D00 in an arc block
    .reference_return_is_error = false,   // "the vector is cleared for that block"
    .skip_is_error = true,           // G31 in compensation is an error
    .d_zero_cancels = true,          // "cancelled by G40 or D00"
    .same_side_recommand_counts = false,  // "G41 or G42 given in compensation is ignored"
    .side_change_perpendicular = false,  // "changes directly" (§12-4-3 3.)
    .vector_with_motion = false,     // I J K with G01 only as 3-D compensation (all three)
    .vector_with_cancel = true,      // G40 X Y I J (§12-4-3 6.)
    .vector_with_hold = true,        // G38 I J D: a new vector direction
    .has_3d = true,                  // G41/G42 X Y Z I J K D
    .cycle_in_3d_is_error = true,    // 901
};

const DialectTable kMazakMTable{Dialect::MazakM, kCodes, kAlarms, kBehaviour, kSystemVariables,
                                &kCycles, &kTransforms, nullptr, &kComp};

}  // namespace ncc::passes
