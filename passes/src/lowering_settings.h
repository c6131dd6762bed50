#pragma once
// The controller parameters lowering reads, resolved once per run from the machine's
// [machine.params] with the dialect's defaults (docs/semantics.md, Parameters).
#include <array>
#include <set>
#include <string>
#include <vector>

#include "block_words.h"
#include "ncc/machine/machine_config.h"
#include "ncc/passes/dialect_table.h"
#include "value_rules.h"

namespace ncc::passes {

// Where the tool length applies (tool_length_mode, Siemens MD20380): A = Z, B = the axis
// normal to the plane, C = the axis programmed with H (not supported yet).
enum class ToolLengthMode : uint8_t { A, B, C };

struct LoweringSettings {
  SameGroupPolicy policy = SameGroupPolicy::Error;
  ValueRules values;
  ir::RapidType rapid_type = ir::RapidType::Linear;
  double arc_tolerance = 0.01;
  bool helical_feed_along_arc = false; // F along the arc in its plane (FANUC HTG = 0)
  double default_feed = 0.0;          // mm/min for a G94 cut before any F (SD42110); 0: alarm
  int offset_count = 400;
  bool dwell_revolutions = false;      // G04 in G95 counts revolutions
  bool length_change_moves = true;     // G43 H / G49 without the length axis moves it
  ToolLengthMode tool_length_mode = ToolLengthMode::A;
  bool f1_digit = false;
  std::vector<double> f1_feeds;        // F1..F9, mm/min
  std::array<AxisValues, 4> reference{};  // reference points 1..4, machine coordinates
  bool block_skip = false;             // Mazak's single block-skip switch
  std::set<int> skip_levels;           // block_skip_levels
  // Canned hole cycles (docs/cycles.md, Parameters).
  double peck_return = 1.0;        // G73 back-off d (FANUC No.5114, Mazak F12, Siemens _ZSFR[1])
  double peck_clearance = 1.0;     // G83 stop above the last depth d (FANUC No.5115, Mazak F13)
  int boring_shift_direction = 1;  // G76 shift: 1 +first plane axis, 0/2 -first, 3 +second, 4 -second
  double tap_retract_percent = 100.0;  // tapping way out, % of the way in (Siemens _ZSFI[2])
  // Peck tapping: Siemens tapping_type (_ZSFI[1]) high_speed_peck / peck; FANUC
  // peck_tapping_type (PCP) high_speed / peck. Whether pecking is on, and its type.
  bool tapping_pecks = false;         // Siemens: tapping_type is a peck type
  bool tapping_peck_to_r = false;     // the "peck" type: out to R after each infeed
  // Coordinate transforms (docs/transforms.md, Parameters).
  bool scale_per_axis = false;        // G51 I J K factors (MD22914, FANUC XSC)
  double scale_factor_unit = 0.001;   // P/I/J/K without a point (MD22910, FANUC SCR)
  double default_scale_factor = 0.0;  // G51 without a factor; 0: x1
  double default_rotation_angle = 0.0;  // G68 without R, degrees
  bool rotation_angle_incremental = false;  // FANUC RIN: R follows G90/G91
  // Cutter radius compensation (lowering_cutter_comp.cpp): the dialect's CompRules with the
  // machine's parameters, recorded in every ir::CutterComp.
  ir::CutterComp::Startup comp_startup = ir::CutterComp::Startup::A;  // startup_type
  bool comp_arc_corners = false;      // outer_corner_connection = "arc"
  int comp_lookahead = 3;             // tnrc_lookahead_blocks
  int comp_max_without_motion = 1;    // from the look-ahead or fixed (CompRules)
  bool comp_interference_check = true;  // interference_check
  bool comp_interference_avoidance = false;  // interference_avoidance
  double comp_corner_move_limit = 0.0;  // corner_move_limit, mm
  double comp3d_normal_length = 0.0;  // comp3d_normal_length (Mazak F11); 0: |I J K|
  // Power-on state (reset_unit, reset_motion_mode, reset_plane), resolved from the strings.
  ir::Units reset_unit = ir::Units::Millimetre;
  GAction reset_motion = GAction::Rapid;
  ir::Plane reset_plane = ir::Plane::XY;

  static LoweringSettings resolve(const DialectTable& table, const MachineConfig& machine);
};

}  // namespace ncc::passes
