#include "lowering_settings.h"

#include <algorithm>
#include <cmath>

namespace ncc::passes {

LoweringSettings LoweringSettings::resolve(const DialectTable& table,
                                           const MachineConfig& machine) {
  const ParameterSet& p = machine.params;
  const DialectBehaviour& b = table.behaviour;
  LoweringSettings s;
  std::string policy = p.getString("same_group_in_block", std::string(b.same_group_default));
  s.policy = policy == "error"       ? SameGroupPolicy::Error
             : policy == "per_word"  ? SameGroupPolicy::PerWord
                                     : SameGroupPolicy::LastWins;
  s.values = ValueRules::fromParams(p, b.decimal_point_default);
  if (!b.decimal_point_from_params) s.values.standard = b.decimal_point_default == "standard";
  s.values.digits = b.format_digits;
  s.rapid_type = p.getString("rapid_type", std::string(b.rapid_type_default)) == "per_axis"
                     ? ir::RapidType::PerAxis
                     : ir::RapidType::Linear;
  s.arc_tolerance = p.getNumber("arc_radius_tolerance", b.arc_radius_tolerance_default);
  s.default_feed = p.getNumber("default_feed", 0.0);
  s.helical_feed_along_arc = p.getBool("helical_feed_along_arc", b.helical_feed_along_arc);
  s.offset_count = static_cast<int>(p.getNumber("offset_count", b.offset_count_default));
  // Two manuals, two keys with opposite senses: Mazak's F92 bit 2 forces seconds, Siemens'
  // MD20734 bit 2 enables revolutions. Either key is honoured in every dialect.
  s.dwell_revolutions = b.dwell_revolutions_default;
  if (p.has("dwell_always_seconds")) s.dwell_revolutions = !p.getBool("dwell_always_seconds", false);
  if (p.has("dwell_in_revolutions_with_g95"))
    s.dwell_revolutions = p.getBool("dwell_in_revolutions_with_g95", false);
  s.length_change_moves = p.getBool("tool_length_move_mode", b.length_change_moves_default);
  std::string mode = p.getString("tool_length_mode", "A");
  s.tool_length_mode = mode == "B"   ? ToolLengthMode::B
                       : mode == "C" ? ToolLengthMode::C
                                     : ToolLengthMode::A;
  s.f1_digit = p.getBool("f1_digit_feed", false);
  if (const auto* list = p.getNumberList("f1_f9_feedrates")) s.f1_feeds = *list;
  static const char* const kRefKeys[] = {"reference_point_1", "reference_point_2",
                                         "reference_point_3", "reference_point_4"};
  for (int n = 0; n < 4; ++n) {
    if (const ParamAxisTable* t = p.getAxisTable(kRefKeys[n])) {
      for (const auto& [name, value] : t->by_axis) {
        int axis = machine.axisIndex(name);
        if (axis >= 0 && axis < kMaxAxes) s.reference[n][axis] = value;
      }
    }
  }
  // Siemens §4.1 _ZSFR[1]: "0 means 1 mm" (a positive value below 1 for a smaller d); the
  // machine file holds d itself, so 0 is kept as given elsewhere.
  s.peck_return = p.getNumber("peck_return", 1.0);
  s.peck_clearance = p.getNumber("peck_clearance", 1.0);
  s.boring_shift_direction = static_cast<int>(std::lround(p.getNumber(
      "boring_shift_direction", table.cycles ? table.cycles->default_shift_direction : 1)));
  s.tap_retract_percent = p.getNumber("tap_retract_percent", 100.0);
  if (table.cycles && table.cycles->peck_tapping == CycleRules::PeckTapping::TappingType) {
    const std::string type = p.getString("tapping_type", "rigid");
    s.tapping_pecks = type == "high_speed_peck" || type == "peck";
    s.tapping_peck_to_r = type == "peck";
  } else {
    s.tapping_pecks = true;  // in rigid mode (FANUC): Q selects it
    s.tapping_peck_to_r = p.getString("peck_tapping_type", "high_speed") == "peck";
  }
  s.scale_per_axis = p.getBool("scale_per_axis", false);
  s.scale_factor_unit = p.getNumber("scale_factor_unit", 0.001);
  s.default_scale_factor = p.getNumber("default_scale_factor", 0.0);
  s.default_rotation_angle = p.getNumber("default_rotation_angle", 0.0);
  s.rotation_angle_incremental = p.getBool("rotation_angle_incremental", false);
  s.block_skip = p.getBool("block_skip", false);
  if (const auto* levels = p.getNumberList("block_skip_levels"))
    for (double l : *levels) s.skip_levels.insert(static_cast<int>(std::lround(l)));
  if (const CompRules* c = table.comp) {
    using Startup = ir::CutterComp::Startup;
    static constexpr const char* kStartup[] = {"A", "B", "C"};
    const std::string type = p.getString("startup_type", kStartup[static_cast<int>(c->startup)]);
    s.comp_startup = type == "B" ? Startup::B : type == "C" ? Startup::C : Startup::A;
    s.comp_arc_corners =
        p.getString("outer_corner_connection", c->arc_corners ? "arc" : "linear") == "arc";
    s.comp_lookahead = static_cast<int>(std::lround(p.getNumber("tnrc_lookahead_blocks", c->lookahead)));
    s.comp_max_without_motion =
        c->max_without_motion > 0 ? c->max_without_motion : std::max(0, s.comp_lookahead - 2);
    s.comp_interference_check = p.getBool("interference_check", true);
    s.comp_interference_avoidance = p.getBool("interference_avoidance", false);
    s.comp_corner_move_limit = p.getNumber("corner_move_limit", 0.0);
    s.comp3d_normal_length = p.getNumber("comp3d_normal_length", 0.0);
  }
  s.reset_unit =
      p.getString("reset_unit", "G21") == "G20" ? ir::Units::Inch : ir::Units::Millimetre;
  s.reset_motion =
      p.getString("reset_motion_mode", "G00") == "G01" ? GAction::Linear : GAction::Rapid;
  std::string plane = p.getString("reset_plane", "G17");
  s.reset_plane = plane == "G18"   ? ir::Plane::ZX
                  : plane == "G19" ? ir::Plane::YZ
                                   : ir::Plane::XY;
  return s;
}

}  // namespace ncc::passes
