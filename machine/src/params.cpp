// The registry of `[machine.params]` keys and the ParameterSet accessors.
// The key list is shared/conformance/FORMAT.md's "Parameter vocabulary" plus ncc's own keys;
// docs/machine-file.md is checked against it by tests/machine/docs_test.cpp.
#include "ncc/machine/params.h"

#include <algorithm>

namespace ncc {

std::string_view paramTypeDescription(ParamType type) {
  switch (type) {
    case ParamType::Bool: return "a boolean";
    case ParamType::Number: return "a number";
    case ParamType::String: return "a string";
    case ParamType::AxisTable: return "a table of numbers by axis name";
    case ParamType::NumberList: return "a list of numbers";
    case ParamType::StringList: return "a list of strings";
    case ParamType::Any: return "any value";
    case ParamType::Integer: return "an integer";
    case ParamType::IntegerList: return "a list of integers";
    case ParamType::AxisList: return "a list of axis names";
    case ParamType::AxisNameTable: return "a table of axis names by axis name";
    case ParamType::StringTable: return "a table of strings";
    case ParamType::AxisRangeTable: return "a table of [min, max] pairs by axis name";
  }
  return "a value";
}

namespace {

using T = ParamType;

// One registry entry; the chained setters keep each entry on a few readable lines.
struct Spec {
  ParamSpec s;
  Spec(std::string_view key, T type, std::string_view dialects, std::string_view default_text,
       std::optional<ParamValue> def, std::string_view meaning) {
    s.key = key;
    s.type = type;
    s.dialects = dialects;
    s.default_text = default_text;
    s.default_value = std::move(def);
    s.meaning = meaning;
    s.integral = type == T::Integer || type == T::IntegerList;
  }
  Spec&& oneOf(std::vector<std::string_view> choices) && {
    s.choices = std::move(choices);
    return std::move(*this);
  }
  Spec&& range(double lo, double hi) && {
    s.min_value = lo;
    s.max_value = hi;
    return std::move(*this);
  }
  Spec&& codeKeys(char letter) && {
    s.key_code_letter = letter;
    return std::move(*this);
  }
  Spec&& integers() && {
    s.integral = true;
    return std::move(*this);
  }
  Spec&& atMost(size_t n) && {
    s.max_items = n;
    return std::move(*this);
  }
};

constexpr double kInf = 1e300;
constexpr std::string_view kIso = "fanuc-m, fanuc-t, mazak-m, siemens-iso-m";

std::vector<ParamSpec> buildRegistry() {
  const std::vector<double> no_numbers;
  const std::vector<std::string> no_names;
  std::vector<Spec> specs;
  specs.push_back(Spec("arc_radius_tolerance", T::Number, kIso, "0.01", 0.01,
                       "Allowed difference of an arc's start and end radius, mm; a larger one is "
                       "an alarm (FANUC No.3410, Mazak F19)")
                      .range(0, kInf));
  specs.push_back(Spec("default_feed", T::Number, kIso, "0", 0.0,
                       "The feed, mm/min, of a G94 cutting move when no F has been programmed "
                       "(Sinumerik SD42110 DEFAULT_FEED); 0: none, such a move is the feed alarm "
                       "(PS0011, 816, 10860)")
                      .range(0, 1e6));
  specs.push_back(Spec("base_frames", T::Integer, "siemens-iso-m", "0", 0.0,
                       "Number of base frames (MD $MC_MM_NUM_BASE_FRAMES)")
                      .range(0, 16));
  specs.push_back(Spec("block_skip", T::Bool, "mazak-m", "false", false,
                       "The block-skip switch: blocks starting with / or /1 are skipped when true"));
  specs.push_back(Spec("block_skip_levels", T::IntegerList, kIso, "[] (none)", no_numbers,
                       "Enabled optional block-skip levels 1..9 (/n skips when n is listed; / "
                       "is level 1)")
                      .range(1, 9)
                      .atMost(9));
  // The default is the dialect's (CycleRules::default_shift_direction); the value here is only
  // the registry's placeholder.
  specs.push_back(Spec("boring_shift_direction", T::Integer, "fanuc-m, mazak-m, siemens-iso-m",
                       "1 (+X in G17) in fanuc-m and mazak-m, 0 (-X) in siemens-iso-m", 0.0,
                       "G76 shift direction off the wall at the bottom: 1 + first plane axis, 0 "
                       "or 2 - first, 3 + second, 4 - second (Siemens GUD7 _ZSFI[5]; FANUC "
                       "No.5101 RD1/RD2, Mazak I14 bits 3-4: FANUC common +X)")
                      .range(0, 4));
  specs.push_back(Spec("c_axis_clamp_m_code", T::Integer, "fanuc-t", "0 (none)", 0.0,
                       "M code that clamps the C axis in lathe drilling cycles (FANUC No.5110); "
                       "the unclamp code is this + 1")
                      .range(0, 99999999));
  specs.push_back(Spec("c_axis_unclamp_dwell", T::Number, "fanuc-t", "0", 0.0,
                       "Dwell after the C-axis unclamp M code, s (FANUC No.5111)")
                      .range(0, kInf));
  specs.push_back(Spec("chamfer_address", T::String, "fanuc-t", "\"comma\"", std::string("comma"),
                       "How chamfer/corner R is written: \"comma\" (,C ,R), \"C\" (C/R words, "
                       "CCR=1), \"IJK\" (I/K/C/R forms)")
                      .oneOf({"comma", "C", "IJK"}));
  specs.push_back(Spec("common_variables", T::String, "mazak-m", "\"A\"", std::string("A"),
                       "Common variable set: A #100-#149 and #500-#549, B #100-#199 and "
                       "#500-#599, C #100-#199 and #500-#699, D #100-#199 and #500-#999")
                      .oneOf({"A", "B", "C", "D"}));
  specs.push_back(Spec("comp3d_normal_length", T::Number, "mazak-m", "0", 0.0,
                       "3-D tool radius compensation: length of (I,J,K) used instead of its "
                       "computed length; 0: computed (F11)")
                      .range(0, kInf));
  specs.push_back(Spec("corner_move_limit", T::Number, kIso, "0", 0.0,
                       "Cutter/nose compensation: corner moves shorter than this are dropped, mm "
                       "(FANUC No.5010)")
                      .range(0, kInf));
  specs.push_back(Spec("cutting_edge_default", T::Integer, "siemens-iso-m", "1", 1.0,
                       "Cutting edge active after a tool change (MD20270 "
                       "$MC_CUTTING_EDGE_DEFAULT); 0: no length offset until D is programmed")
                      .range(-2, 12));
  specs.push_back(Spec("cycle_safety_clearance", T::Number, "siemens-iso-m", "1.0", 1.0,
                       "Drilling cycles: safety clearance above the R level, mm (GUD7 _ZSFR[0])")
                      .range(0, kInf));
  specs.push_back(Spec("decimal_point", T::String, "fanuc-t, mazak-m, siemens-iso-m",
                       "\"standard\"", std::string("standard"),
                       "\"calculator\": X10 = 10 mm; \"standard\": a value without a point is in "
                       "least input increments (X10 = 0.010 mm)")
                      .oneOf({"calculator", "standard"}));
  specs.push_back(Spec("drawing_dimension_input", T::Bool, "fanuc-t", "false", false,
                       "Direct drawing dimension input (,A ,C ,R) enabled"));
  specs.push_back(Spec("dwell_always_seconds", T::Bool, "mazak-m", "false", false,
                       "G04 is always in seconds; false: in G95 the dwell is in spindle "
                       "revolutions (F92 bit 2 = 0)"));
  specs.push_back(Spec("dwell_in_revolutions_with_g95", T::Bool, "siemens-iso-m", "false", false,
                       "In G95 G04 counts spindle revolutions; false: G04 is always s / ms "
                       "(MD20734 EXTERN_FUNCTION_MASK bit 2 = 0)"));
  specs.push_back(Spec("eight_digit_program_numbers", T::Bool, "siemens-iso-m", "false", false,
                       "M98 P takes 8-digit program numbers; false: M98 Pnnnmmmm (repeat count "
                       "and 4-digit name) (MD20734 EXTERN_FUNCTION_MASK bit 6)"));
  specs.push_back(Spec("f1_digit_feed", T::Bool, "siemens-iso-m", "false", false,
                       "F1-F9 select the fixed feedrates of f1_f9_feedrates (MD22920 "
                       "EXTERN_FEEDRATE_F1_F9_ACTIV)"));
  specs.push_back(Spec("f1_f9_feedrates", T::NumberList, "siemens-iso-m", "[] (all 0)",
                       no_numbers,
                       "Fixed feedrates of F1..F9, mm/min (SD42160 "
                       "$SC_EXTERN_FIXED_FEEDRATE_F1_F9[0..8])")
                      .range(0, kInf)
                      .atMost(9));
  specs.push_back(Spec("fs15_program_format", T::Bool, "fanuc-t", "false", false,
                       "FANUC Series 15 program format (FCV): one-block G71-G76 with D, M98 P L, "
                       "..."));
  specs.push_back(Spec("g10_geometry_p_limit", T::Integer, "siemens-iso-m", "100", 100.0,
                       "G10 P below this writes geometry, above it wear (MD20734 "
                       "EXTERN_FUNCTION_MASK bit 1 = 0: 100; = 1: 10000)")
                      .range(1, 10000));
  specs.push_back(Spec("gcode_system", T::String, "fanuc-t", "\"A\"", std::string("A"),
                       "Lathe G-code system \"A\", \"B\" or \"C\"")
                      .oneOf({"A", "B", "C"}));
  specs.push_back(Spec("geometry_number_from_tool_select", T::Bool, "fanuc-t", "false", false,
                       "Geometry offset number taken from the tool-select digits of T (LGN, "
                       "No.5002#1)"));
  specs.push_back(Spec("geometry_offset_method", T::String, "fanuc-t", "\"shift\"",
                       std::string("shift"),
                       "How a geometry offset is applied: \"tool_move\" or \"shift\" of the "
                       "coordinate system (LGT, No.5002#4)")
                      .oneOf({"tool_move", "shift"}));
  specs.push_back(Spec("geometry_wear_offsets", T::Bool, "fanuc-t", "true", true,
                       "Separate geometry and wear offset memories"));
  specs.push_back(Spec("helical_feed_along_arc", T::Bool, kIso,
                       "true in fanuc-m (HTG = 0), false in mazak-m and siemens-iso-m",
                       std::nullopt,
                       "Helical interpolation: F is the speed along the arc in its plane (true) "
                       "or along the helix, the linear axes included (false) (FANUC No.1403#5 "
                       "HTG = 0 / 1; Mazak and Sinumerik: along the helix)"));
  specs.push_back(Spec("g_code_macros", T::StringTable, kIso, "{} (none)",
                       ParamStringTable{},
                       "G codes that call a macro program with the block's words as G65 "
                       "arguments, by O number or name, e.g. { G100 = \"9010\" } (FANUC/Mazak "
                       "G-code macro call parameters)")
                      .codeKeys('G'));
  specs.push_back(Spec("increment_system", T::String, "fanuc-t, siemens-iso-m", "\"IS-B\"",
                       std::string("IS-B"),
                       "\"IS-B\" (0.001 mm / 0.0001 in) or \"IS-C\" (0.0001 mm / 0.00001 in)")
                      .oneOf({"IS-B", "IS-C"}));
  specs.push_back(Spec("index_table_1", T::NumberList, "siemens-din", "[] (none)", no_numbers,
                       "Positions of indexing table 1, mm or degrees (MD10910 "
                       "INDEX_AX_POS_TAB_1; its length is MD10900 INDEX_AX_LENGTH_POS_TAB_1)")
                      .atMost(60));
  specs.push_back(Spec("indexing_axes", T::AxisTable, "siemens-din", "{} (none)",
                       ParamAxisTable{},
                       "Indexing axes and the table each uses, e.g. { B = 1 } (MD30500 "
                       "INDEX_AX_ASSIGN_POS_TAB)")
                      .range(1, 2)
                      .integers());
  specs.push_back(Spec("input_unit_x10", T::Bool, "mazak-m", "false", false,
                       "Coordinates without a decimal point are in 0.01 mm (F91 bit 0 = 1); "
                       "H/D offset values are not affected"));
  specs.push_back(Spec("interference_avoidance", T::Bool, kIso, "false", false,
                       "Cutter compensation: an interference between three moves is avoided by "
                       "leaving the middle one out (FANUC CAV No.19607#5 = 1, Mazak F92 bit 5 "
                       "= 1) instead of the alarm"));
  specs.push_back(Spec("interference_check", T::Bool, kIso, "true", true,
                       "Cutter/nose compensation interference check on (FANUC No.5008#3 = 0, "
                       "Mazak F92 bit 5 = 0: an interference is an alarm)"));
  specs.push_back(Spec("m_code_macros", T::StringTable, kIso, "{} (none)",
                       ParamStringTable{},
                       "M codes that call a macro program with the block's words as G65 "
                       "arguments, by O number or name, e.g. { M6 = \"M6_MAKRO\" } or "
                       "{ M60 = \"9020\" } (Sinumerik $MN_EXTERN_M_NO_MAC_CYCLE(_NAME), FANUC/Mazak "
                       "M-code macro call parameters)")
                      .codeKeys('M'));
  specs.push_back(Spec("machine_unit", T::String, "siemens-iso-m", "\"mm\"", std::string("mm"),
                       "The machine's own unit, \"mm\" or \"inch\"")
                      .oneOf({"mm", "inch"}));
  specs.push_back(Spec("modulo_axes", T::AxisList, "siemens-din", "[] (none)", no_names,
                       "Rotary axes that count modulo 360 degrees (MD30310 ROT_IS_MODULO = 1)"));
  specs.push_back(Spec("offset_applied_at", T::String, "fanuc-t", "\"t_code_block\"",
                       std::string("t_code_block"),
                       "When a tool-move offset moves the tool: \"t_code_block\" (in the T "
                       "block) or \"next_motion\" (with the next axis move) (LWM, No.5002#6)")
                      .oneOf({"t_code_block", "next_motion"}));
  specs.push_back(Spec("offset_count", T::Integer, "mazak-m", "128", 128.0,
                       "Size of the tool offset memory: H1-H<n> / D1-D<n> (128 standard, 512 "
                       "option)")
                      .range(1, 9999));
  specs.push_back(Spec("offset_number_digits", T::Integer, "fanuc-t", "2", 2.0,
                       "How many low digits of T are the offset number (FANUC No.5028)")
                      .range(0, 3));
  // The defaults of the compensation keys are the dialect's (CompRules, docs/semantics.md);
  // the values here are the registry's placeholders.
  specs.push_back(Spec("outer_corner_connection", T::String, kIso,
                       "\"linear\"; \"arc\" in siemens-iso-m (G450)", std::string("linear"),
                       "Cutter/nose compensation outer-corner connection: \"linear\" "
                       "(intersection lines) or \"arc\" (FANUC CCC, Siemens G450 transition "
                       "circle)")
                      .oneOf({"linear", "arc"}));
  specs.push_back(Spec("parallel_axes", T::AxisNameTable, "siemens-iso-m", "{} (none)",
                       ParamStringTable{},
                       "Parallel axes by geometry axis, e.g. { X = \"U\" } (MD22930 "
                       "$MC_EXTERN_PARALLEL_GEOAX)"));
  specs.push_back(Spec("peck_clearance", T::Number, "fanuc-m, fanuc-t, mazak-m, siemens-iso-m", "1.0", 1.0,
                       "G83 peck: how far above the last depth the rapid approach stops, d, mm "
                       "(FANUC No.5115, Mazak F13, Siemens ISO _ZSFR[1])")
                      .range(0, kInf));
  specs.push_back(Spec("peck_cycle_type", T::String, "fanuc-t", "\"high_speed\"",
                       std::string("high_speed"),
                       "Lathe G83/G87: \"high_speed\" (retract d) or \"peck\" (retract to R) "
                       "(FANUC RTR, No.5101#2)")
                      .oneOf({"high_speed", "peck"}));
  specs.push_back(Spec("peck_tapping_type", T::String, "fanuc-m", "\"high_speed\"",
                       std::string("high_speed"),
                       "Deep-hole rigid tapping (G84/G74 with Q after M29): \"high_speed\" (back off "
                       "d, peck_return) or \"peck\" (out to R, back to d above, peck_clearance) "
                       "(FANUC PCP, No.5200#5; d is No.5213)")
                      .oneOf({"high_speed", "peck"}));
  specs.push_back(Spec("peck_return", T::Number, "fanuc-m, fanuc-t, mazak-m, siemens-iso-m", "1.0",
                       1.0,
                       "G73 (and high-speed peck) retract amount d, mm (FANUC No.5114, Mazak F12; "
                       "Siemens ISO _ZSFR[1], 0 meaning 1 mm)")
                      .range(0, kInf));
  // The default is the dialect's (DialectBehaviour::rapid_type_default); the value here is
  // only the registry's placeholder.
  specs.push_back(Spec("rapid_type", T::String, kIso,
                       "\"per_axis\" in fanuc-m (LRP = 0), \"linear\" in mazak-m and siemens-iso-m",
                       std::string("linear"),
                       "G00 path: \"linear\" (interpolated straight line) or \"per_axis\" (each "
                       "axis at its own rapid rate, dog-leg) (FANUC No.1401#1 LRP, Mazak F91 "
                       "bit 6)")
                      .oneOf({"linear", "per_axis"}));
  for (int n = 1; n <= 4; ++n) {
    static const char* const keys[] = {"reference_point_1", "reference_point_2",
                                       "reference_point_3", "reference_point_4"};
    static const char* const meanings[] = {
        "First reference point, machine coordinates (G28); axes not listed are at 0",
        "2nd reference point, machine coordinates (G30 P2); axes not listed are at 0",
        "3rd reference point, machine coordinates (G30 P3); axes not listed are at 0",
        "4th reference point, machine coordinates (G30 P4); axes not listed are at 0"};
    specs.push_back(Spec(keys[n - 1], T::AxisTable,
                         n == 4 ? kIso : (n == 2 ? "mazak-m" : "mazak-m, siemens-iso-m"),
                         "{} (all axes 0)", ParamAxisTable{}, meanings[n - 1]));
  }
  specs.push_back(Spec("reset_feed_mode", T::String, "fanuc-t", "\"G99\"", std::string("G99"),
                       "Feed mode at program start (lathe system A): \"G98\" per minute / "
                       "\"G99\" per revolution")
                      .oneOf({"G98", "G99"}));
  specs.push_back(Spec("reset_motion_mode", T::String, "fanuc-t, siemens-din", "\"G00\"",
                       std::string("G00"), "Group-01 code active at program start")
                      .oneOf({"G00", "G01"}));
  specs.push_back(Spec("reset_plane", T::String, "fanuc-t, siemens-din",
                       "the dialect's power-on plane (G17 mill, G18 lathe)", std::nullopt,
                       "Plane at program start")
                      .oneOf({"G17", "G18", "G19"}));
  specs.push_back(Spec("reset_unit", T::String, "mazak-m, siemens-iso-m", "\"G21\"",
                       std::string("G21"), "Unit at program start: \"G20\" inch or \"G21\" mm")
                      .oneOf({"G20", "G21"}));
  specs.push_back(Spec("rigid_tap_retract_override", T::Bool, "fanuc-t", "false", false,
                       "Rigid tapping retract override on (FANUC DOV)"));
  specs.push_back(Spec("rotary_axes", T::AxisList, "siemens-din, all",
                       "the axes named A, B or C", std::nullopt,
                       "Rotary axes (MD30300 IS_ROT_AX = 1); when given, exactly these axes are "
                       "rotary and all others linear"));
  specs.push_back(Spec("rotation_angle_incremental", T::Bool, "fanuc-m, fanuc-t", "false", false,
                       "G68/G68.1 angle R follows G90/G91 (FANUC RIN, No.5400#0); false: R is "
                       "always absolute"));
  specs.push_back(Spec("rough_finish_pass_type1", T::Bool, "fanuc-t", "true", true,
                       "G71/G72 type I: rough finishing pass along the contour after roughing "
                       "(FANUC RF1 = 0)"));
  specs.push_back(Spec("rough_finish_pass_type2", T::Bool, "fanuc-t", "true", true,
                       "G71/G72 type II: rough finishing pass along the contour after roughing "
                       "(FANUC RF2 = 0)"));
  specs.push_back(Spec("same_group_in_block", T::String, kIso, "\"last_wins\"",
                       std::string("last_wins"),
                       "Two G codes of one modal group in a block: \"last_wins\" (the last one "
                       "is effective) or \"error\" (an alarm)")
                      .oneOf({"error", "last_wins"}));
  specs.push_back(Spec("scale_factor_unit", T::Number, "fanuc-m, siemens-iso-m", "0.001", 0.001,
                       "Unit of a G51 scale factor P, I, J, K written without a decimal point "
                       "(MD22910 WEIGHTING_FACTOR_FOR_SCALE = 0: 0.001, = 1: 0.00001; FANUC "
                       "No.5400#7 SCR = 1: 0.001, = 0: 0.00001)")
                      .range(1e-9, 1));
  specs.push_back(Spec("scale_per_axis", T::Bool, "fanuc-m, siemens-iso-m", "false", false,
                       "G51 scales per axis with I J K (a negative factor mirrors); false: one "
                       "factor from P (MD22914 AXES_SCALE_ENABLE = 0; FANUC XSC, No.5401#6)"));
  specs.push_back(Spec("default_scale_factor", T::Number, "fanuc-m, mazak-m, siemens-iso-m",
                       "0 (none: x1)", 0.0,
                       "The G51 factor when the block gives none (FANUC No.5411, Mazak F20, "
                       "SD42140 DEFAULT_SCALE_FACTOR_P); 0: none, the shape keeps its size")
                      .range(0, 1e6));
  specs.push_back(Spec("default_rotation_angle", T::Number, "fanuc-m, siemens-iso-m", "0", 0.0,
                       "The G68 angle, degrees, when the block gives no R (FANUC No.5410, "
                       "SD42150 DEFAULT_ROT_FACTOR_R)")
                      .range(-360, 360));
  specs.push_back(Spec("second_geometry_axes", T::AxisList, "fanuc-t", "[] (none)", no_names,
                       "Axes to which the 2nd geometry offset applies"));
  specs.push_back(Spec("second_geometry_signal_G2SLC", T::Bool, "fanuc-t", "false", false,
                       "2nd geometry offset selected (signal G2SLC)"));
  specs.push_back(Spec("software_limits", T::AxisRangeTable, "siemens-din, all", "{} (none)",
                       ParamAxisRanges{},
                       "Per-axis travel limits [min, max], machine coordinates; sets the axis's "
                       "min_travel / max_travel"));
  specs.push_back(Spec("spindle_encoder", T::Bool, "siemens-din", "true", true,
                       "The spindle has an encoder (CYCLE97 and tapping need it)"));
  specs.push_back(Spec("startup_type", T::String, kIso, "\"A\"", std::string("A"),
                       "Cutter/nose compensation start-up and cancel type: \"A\", \"B\" or \"C\" "
                       "(FANUC SUV/SUP No.5003, Mazak F92 bit 4: 0 = A, 1 = B)")
                      .oneOf({"A", "B", "C"}));
  specs.push_back(Spec("t_code_digits", T::Integer, "fanuc-t", "4", 4.0,
                       "Digits in a T word (FANUC No.3032)")
                      .range(1, 8));
  specs.push_back(Spec("tap_retract_percent", T::Number, "fanuc-m, mazak-m, siemens-iso-m", "100", 100.0,
                       "Tapping retract speed in % of the tapping speed (GUD7 _ZSFI[2])")
                      .range(1, 200));
  specs.push_back(Spec("tapping_type", T::String, "siemens-iso-m", "\"rigid\"",
                       std::string("rigid"),
                       "G84/G74 tapping type (GUD7 _ZSFI[1] = 0, 1, 2, 3): \"rigid\", "
                       "\"floating\" (compensating chuck), \"high_speed_peck\", \"peck\"")
                      .oneOf({"rigid", "floating", "high_speed_peck", "peck"}));
  specs.push_back(Spec("thread_chamfer_signal", T::Bool, "fanuc-t", "false", false,
                       "Thread chamfering (chamfer-out) at the end of G92/G76 on (signal CDZ)"));
  specs.push_back(Spec("tnrc_lookahead_blocks", T::Integer, kIso,
                       "3; 5 in mazak-m, 2 in siemens-iso-m", 3.0,
                       "Cutter/nose compensation look-ahead depth in blocks (FANUC No.19625, "
                       "3-8); in fanuc-m it also sets how many blocks without motion in the "
                       "plane keep the corner (the depth - 2)")
                      .range(3, 8));
  specs.push_back(Spec("tool_length_mode", T::String, "siemens-iso-m", "\"A\"", std::string("A"),
                       "G43/G44 mode (MD20380 TOOL_CORR_MODE_G43G44 = 0, 1, 2): \"A\" H acts on "
                       "Z, \"B\" on the axis normal to the plane, \"C\" on the axis programmed")
                      .oneOf({"A", "B", "C"}));
  specs.push_back(Spec("tool_length_move_mode", T::Bool, "siemens-iso-m", "false", false,
                       "A length offset moves the tool when selected; false: with the next move "
                       "of the axis (MD20382 TOOL_CORR_MOVE_MODE)"));
  specs.push_back(Spec("wear_offset_method", T::String, "fanuc-t", "\"tool_move\"",
                       std::string("tool_move"),
                       "How a wear offset is applied: \"tool_move\" or \"shift\" (LWT, "
                       "No.5002#2)")
                      .oneOf({"tool_move", "shift"}));

  std::vector<ParamSpec> out;
  out.reserve(specs.size());
  for (Spec& spec : specs) out.push_back(std::move(spec.s));
  // Keys of the vocabulary that ncc reads and checks but does not apply yet (no pass or VM
  // stage looks at them): they have no effect in any dialect, so a machine file setting one
  // gets warning NCC0307. Every other key is applied in every dialect.
  static constexpr std::string_view kNotApplied[] = {
      "base_frames", "c_axis_clamp_m_code", "c_axis_unclamp_dwell",
      "chamfer_address",
      "cutting_edge_default", "cycle_safety_clearance", "drawing_dimension_input",
      "fs15_program_format", "g10_geometry_p_limit",
      "gcode_system", "geometry_number_from_tool_select", "geometry_offset_method",
      "geometry_wear_offsets", "index_table_1", "indexing_axes",
      "machine_unit", "offset_applied_at", "offset_number_digits",
      "parallel_axes", "peck_cycle_type", "reset_feed_mode",
      "rigid_tap_retract_override", "rough_finish_pass_type1",
      "rough_finish_pass_type2", "second_geometry_axes",
      "spindle_encoder", "t_code_digits",
      "thread_chamfer_signal", "wear_offset_method"};
  // The hole-cycle keys act in the mill dialects' cycles (docs/cycles.md), not yet in fanuc-t.
  static constexpr std::string_view kMillCycles[] = {"boring_shift_direction", "peck_clearance",
                                                     "peck_return", "tap_retract_percent",
                                                     "tapping_type", "peck_tapping_type"};
  // The transform keys act in the mill dialects' G68/G51 (docs/transforms.md).
  static constexpr std::string_view kMillTransforms[] = {
      "default_rotation_angle", "default_scale_factor", "rotation_angle_incremental",
      "scale_factor_unit", "scale_per_axis"};
  // The cutter compensation keys: lowering records them for the compensation pass in the mill
  // dialects (docs/semantics.md); fanuc-t's nose radius compensation is not built yet.
  static constexpr std::string_view kMillComp[] = {"comp3d_normal_length", "corner_move_limit",
                                                   "interference_avoidance",
                                                   "interference_check", "outer_corner_connection",
                                                   "startup_type", "tnrc_lookahead_blocks"};
  for (ParamSpec& spec : out) {
    if (std::find(std::begin(kMillComp), std::end(kMillComp), spec.key) != std::end(kMillComp))
      spec.applied_in = spec.key == "comp3d_normal_length" ? "mazak-m"
                                                            : "fanuc-m, mazak-m, siemens-iso-m";
    if (std::find(std::begin(kMillTransforms), std::end(kMillTransforms), spec.key) !=
        std::end(kMillTransforms))
      spec.applied_in = spec.key == "rotation_angle_incremental" ? "fanuc-m" : spec.dialects;
    if (std::find(std::begin(kNotApplied), std::end(kNotApplied), spec.key) !=
        std::end(kNotApplied))
      spec.applied_in = "";
    if (std::find(std::begin(kMillCycles), std::end(kMillCycles), spec.key) !=
        std::end(kMillCycles))
      spec.applied_in = spec.key == "tapping_type" || spec.key == "peck_tapping_type"
                            ? spec.dialects
                            : "fanuc-m, mazak-m, siemens-iso-m";
  }
  std::sort(out.begin(), out.end(),
            [](const ParamSpec& a, const ParamSpec& b) { return a.key < b.key; });
  return out;
}

template <typename V>
const V* typed(const ParamValue* v) {
  return v ? std::get_if<V>(v) : nullptr;
}

}  // namespace

const std::vector<ParamSpec>& parameterRegistry() {
  static const std::vector<ParamSpec> registry = buildRegistry();
  return registry;
}

bool paramApplies(const ParamSpec& spec, Dialect dialect) {
  if (spec.applied_in == "all") return true;
  for (std::string_view rest = spec.applied_in; !rest.empty();) {
    const std::size_t comma = rest.find(',');
    std::string_view name = rest.substr(0, comma);
    while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
    if (name == dialectName(dialect)) return true;
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
  }
  return false;
}

const ParamSpec* findParameter(std::string_view key) {
  const auto& reg = parameterRegistry();
  auto it = std::lower_bound(reg.begin(), reg.end(), key,
                             [](const ParamSpec& s, std::string_view k) { return s.key < k; });
  return it != reg.end() && it->key == key ? &*it : nullptr;
}

const ParamValue* ParameterSet::get(std::string_view key) const {
  auto it = values_.find(key);
  return it == values_.end() ? nullptr : &it->second;
}

const ParamValue* ParameterSet::getOrDefault(std::string_view key) const {
  if (const ParamValue* v = get(key)) return v;
  const ParamSpec* spec = findParameter(key);
  return spec && spec->default_value ? &*spec->default_value : nullptr;
}

bool ParameterSet::getBool(std::string_view key, bool fallback) const {
  const bool* v = typed<bool>(get(key));
  return v ? *v : fallback;
}
double ParameterSet::getNumber(std::string_view key, double fallback) const {
  const double* v = typed<double>(get(key));
  return v ? *v : fallback;
}
std::string ParameterSet::getString(std::string_view key, std::string fallback) const {
  const std::string* v = typed<std::string>(get(key));
  return v ? *v : fallback;
}
const ParamAxisTable* ParameterSet::getAxisTable(std::string_view key) const {
  return typed<ParamAxisTable>(get(key));
}

bool ParameterSet::getBool(std::string_view key) const {
  const bool* v = typed<bool>(getOrDefault(key));
  return v ? *v : false;
}
double ParameterSet::getNumber(std::string_view key) const {
  const double* v = typed<double>(getOrDefault(key));
  return v ? *v : 0.0;
}
std::string ParameterSet::getString(std::string_view key) const {
  const std::string* v = typed<std::string>(getOrDefault(key));
  return v ? *v : std::string();
}

const std::vector<double>* ParameterSet::getNumberList(std::string_view key) const {
  return typed<std::vector<double>>(get(key));
}
const std::vector<std::string>* ParameterSet::getStringList(std::string_view key) const {
  return typed<std::vector<std::string>>(get(key));
}
const ParamStringTable* ParameterSet::getStringTable(std::string_view key) const {
  return typed<ParamStringTable>(get(key));
}
const ParamAxisRanges* ParameterSet::getAxisRanges(std::string_view key) const {
  return typed<ParamAxisRanges>(get(key));
}

}  // namespace ncc
