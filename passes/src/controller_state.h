#pragma once
// The state of the controller between blocks: modal codes, position, and the pieces of the
// frame (work offset, G92 shift, G52 local shift, tool length). Small and copyable: a block
// is lowered on a copy that replaces the state only when the block has no error. The offset
// tables written by G10 live apart (OffsetTables) and are written at the commit.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ncc/ir/ir.h"
#include "ncc/machine/axes.h"
#include "ncc/passes/dialect_table.h"

namespace ncc::passes {

// What a rejected block would have written and no later block has determined again: the
// state the real control would be in is not known there (error recovery, lowering_recovery.cpp).
struct UnknownState {
  AxisMask axes = 0;    // positions (the commanded point) of these axes
  uint32_t groups = 0;  // bit (1 << GGroup) per modal group whose code is not known
  bool feed = false;    // the F in force

  static constexpr uint32_t groupBit(GGroup g) { return 1u << static_cast<unsigned>(g); }
  bool group(GGroup g) const { return (groups & groupBit(g)) != 0; }
  bool any() const { return axes != 0 || groups != 0 || feed; }
};

// The canned hole cycle in force (lowering_cycles.cpp): its data stay modal from the first
// cycle block until G80 or a group-01 code clears them (docs/cycles.md).
struct CycleState {
  int code10 = 0;               // the cycle's G code x 10; 0: none (G80)
  bool return_to_r = false;     // G99 in force (group 10; G98 at power-on); kept across G80
  double initial = 0.0;         // the initial level, work coordinates on the drilling axis
  bool has_r = false, has_z = false, has_q = false;
  double r = 0.0;               // the R level, work coordinates
  double z = 0.0;               // the bottom, work coordinates
  bool z_from_r = false;        // Z was given in G91: the bottom follows a new R
  double z_increment = 0.0;     // that distance from R
  double q = 0.0;               // Q as given (mm)
  double p = 0.0;               // P as given (the cycle entry says its unit)
  bool has_p = false;
  double d = 0.0;               // Mazak G73/G83 D (mm); 0: the parameter
  bool has_d = false;
  bool rigid = false;           // FANUC M29: rigid tapping until G80 (deep-hole tapping with Q)
  double feed_start = 0.0;      // Mazak K (G73/G83) / D (G82): from R to the feed start (mm)
  double slow_zone = 0.0;       // Mazak I: the zone above the bottom at the slowed feed (mm)
  double slow_percent = 0.0;    // Mazak J: that feed, % of F; 0: none
};

// The coordinate transforms in force (lowering_transforms.cpp, docs/transforms.md). Centres are
// work coordinates, so a G92, G52 or work-offset change moves them with the work system as the
// manuals state; G92.5's centre is a machine point. Each stage is kept as its map.
struct TransformState {
  // G68: the rotations in force, the first given first (Siemens base frames 1 and 2: the second
  // acts in the first's coordinates). The last 2-D angle, for an incremental R.
  std::vector<ir::Affine> rotations;
  double angle_2d = 0.0;
  bool rotation_3d = false;  // a G68 with I J K is among them
  // G51: the scaled X/Y/Z slots, their centres and factors.
  std::array<bool, 3> scaled{};
  std::array<double, 3> scale_centre{};
  std::array<double, 3> scale_factor{1.0, 1.0, 1.0};
  bool scaling = false;
  // G51.1: the mirrored slots and their centres.
  std::array<bool, 3> mirrored{};
  std::array<double, 3> mirror_centre{};
  // Mazak G92.5: the rotation about a machine point; its centre stays for the next G92.5.
  std::optional<ir::Affine> work_rotation;
  std::array<double, 3> work_rotation_centre{};
  bool work_rotation_just_set = false;  // the next move must be G00/G01 (Mazak 817)
  // Mazak figure rotation (M98 I J K L): the call in progress (its start, work coordinates, and
  // centre on X Y Z, the angle the first run swept) and the turn of the run being made.
  struct FigureCall {
    std::array<double, 3> start{}, centre{};
    AxisValues start_position{};  // ControllerState::position at the call
    ir::Plane plane = ir::Plane::XY;
    double angle = 0.0;           // degrees, known after the first run
  };
  std::optional<FigureCall> figure_call;
  std::optional<ir::Affine> figure;
  // DIN: the programmable frame (TRANS, ROT, SCALE, MIRROR and their A-forms; lowering_frames.cpp),
  // programmed point -> work coordinates. It acts first, before every stage of
  // TransformRules::order: on the 840D it sits between the workpiece and the settable frame.
  std::optional<ir::Affine> programmable;
  // Where the tool is (machine coordinates) when that is not the commanded point, which is
  // `ControllerState::position`: after a block that moved under a transform. A block whose
  // programmed point stays may still move the tool (a transform changed since).
  std::optional<AxisValues> tool_at;

  bool mirrorsAny() const { return mirrored[0] || mirrored[1] || mirrored[2]; }
  // A stage or G92.5 is in force (tool_at alone is not a transform).
  bool inForce() const {
    return work_rotation || figure || programmable || scaling || mirrorsAny() || !rotations.empty();
  }
};

// Cutter radius compensation in force (lowering_cutter_comp.cpp): what the next block's
// ir::CutterComp starts from. The D number is ControllerState::d_selected; its radius is read
// from the offset tables at each block, so a G10 write is seen from its own block on.
struct CompState {
  ir::CutterComp::Side side = ir::CutterComp::Side::Off;  // G40 at power-on, reset, M02/M30
  // Blocks compensated since the start-up block (1 = the start-up block itself): a side change
  // in the first two is CompSideChangeEarly where the dialect says so.
  int blocks = 0;
  // Mazak 3-D compensation: the start-up's (I,J,K) / |I,J,K| (comp3d_normal_length in place
  // of |I,J,K| when set), negated for G42; the offset is the radius x this, fixed until G40/D00.
  std::optional<std::array<double, 3>> direction_3d;

  bool active() const { return side != ir::CutterComp::Side::Off; }
};

// A part of the state that blocks nearly always only read: a copy of the state shares it, and
// the first write through edit() in a block copies it then (copy on write). A block is lowered
// on a copy of the whole state, so a large part written rarely (the transforms) should not be
// copied with every block. Reads of a part never written give the default value.
template <class T>
class CopyOnWrite {
 public:
  const T& operator*() const { return p_ ? *p_ : defaultValue(); }
  const T* operator->() const { return &**this; }
  T& edit() {
    if (!p_)
      p_ = std::make_shared<T>();
    else if (p_.use_count() > 1)
      p_ = std::make_shared<T>(*p_);
    return *p_;
  }

 private:
  // A function's static, not a static member: initialised on first use, whatever the order of
  // the program's static initialisers.
  static const T& defaultValue() {
    static const T value{};
    return value;
  }
  std::shared_ptr<T> p_;
};

struct ControllerState {
  ir::Modal modal;
  GAction motion = GAction::Rapid;     // group 01
  bool feed_programmed = false;        // an F (or F1-F9) has been given since the start
  AxisValues position{};               // machine coordinates of the commanded point

  ir::WorkOffsetName work_name = "G54";
  AxisValues work_value{};             // the selected work offset, as latched
  AxisValues external{};               // G10 L2 P0: added to every work offset
  AxisValues g92{};                    // G92 shift, shared by all work systems
  AxisValues local{};                  // G52 (dialects where it is shared)
  std::map<std::string, AxisValues, std::less<>> local_by_work;  // G52 per work system (Mazak)

  int h_selected = 0;                  // H number last programmed (modal even in G49)
  int d_selected = 0;
  int tool_length_axis = -1;           // axis carrying the length offset, -1 if none
  double tool_length = 0.0;            // signed length applied on that axis
  // A length change not yet traversed (length_change_moves = false, Siemens MD20382): the
  // frame holds the new length, the position does not; taken up when the axis is programmed.
  int length_pending_axis = -1;
  double length_pending = 0.0;
  bool feed_after_inverse_time = false;  // G94/G95 after G93 without a new F yet
  int last_g10_l2_p = 1;               // Mazak: G10 L2 without P reuses the last P
  UnknownState unknown;                // nothing after power-on; see UnknownState
  CycleState cycle;                    // the canned hole cycle in force
  CopyOnWrite<TransformState> transforms;  // G68, G51, G51.1, G92.5, figure rotation
  int spindle_direction = 0;           // +1 M03, -1 M04, 0 stopped (M05, power-on)
  // Axes whose commanded position is where a G31 stopped: known when the program runs, not
  // here (`position` holds G31's end point for them). An absolute word makes one known again
  // (lowering_skip.cpp).
  AxisMask skip_axes = 0;
  bool polar = false;                  // G16 in force (group 17; lowering_polar.cpp)
  CompState comp;                      // G40/G41/G42 (group 07)
};

struct OffsetTables {
  std::map<std::string, AxisValues, std::less<>> work;  // "G54".., "G54.1P1".., "G54P1"..
  std::map<int, double> length, length_wear, radius, radius_wear;

  double toolLength(int h) const {
    double v = 0.0;
    if (auto it = length.find(h); it != length.end()) v += it->second;
    if (auto it = length_wear.find(h); it != length_wear.end()) v += it->second;
    return v;
  }
  AxisValues workOffset(std::string_view name) const {
    auto it = work.find(name);
    return it == work.end() ? AxisValues{} : it->second;
  }
};

// A G10 write, applied to OffsetTables when its block commits.
struct TableWrite {
  enum class Target : uint8_t { Work, External, Length, LengthWear, Radius, RadiusWear };
  Target target = Target::Work;
  ir::WorkOffsetName work_name;  // Target::Work
  int number = 0;         // register targets
  AxisValues values{};    // Work/External: per axis; registers: values[0]
  AxisMask axes = 0;
  bool add = false;       // G91: add to the stored value
};

}  // namespace ncc::passes
