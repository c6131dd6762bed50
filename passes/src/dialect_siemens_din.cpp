// siemens-din: the Sinumerik 840D DIN language, as far as ncc reads it (docs/din.md): the
// G codes a plain-word DIN block can carry, by the DIN numbering of their groups (Programming
// Manual Fundamentals, "List of G functions" [ext]; the codes the 840Di manuals show are cited
// from the notes). The rest of the table (alarms, cycles, transforms, compensation rules) is
// the ISO mode's: one controller, one state, two languages (siemens-840di-iso-milling-gcode.ja
// §4.1: a switch "does not change the active tool, tool offsets or zero offsets").
#include "dialect_tables.h"

namespace ncc::passes {

namespace {
using A = GAction;
using G = GGroup;

constexpr GCodeEntry kCodes[] = {
    // group 1 (extended-functions notes §3: "G0 G1 G2 G3 CIP group 1")
    {0, G::Motion, 1, true, A::Rapid, 0, "rapid traverse"},
    {10, G::Motion, 1, false, A::Linear, 0, "linear interpolation"},
    {20, G::Motion, 1, false, A::ArcCW, 0, "circular interpolation CW"},
    {30, G::Motion, 1, false, A::ArcCCW, 0, "circular interpolation CCW"},
    // group 2 (non-modal): DIN's G4 takes F seconds or S spindle revolutions, not ISO's X/P
    {40, G::OneShot, 2, false, A::DwellFeedOrSpindle, 0, "dwell (G4 F seconds / G4 S revolutions)"},
    // group 6 (cycles notes §3: G17 X/Y, G18 Z/X, G19 Y/Z)
    {170, G::Plane, 6, true, A::PlaneXY, 0, "working plane X/Y"},
    {180, G::Plane, 6, false, A::PlaneZX, 0, "working plane Z/X"},
    {190, G::Plane, 6, false, A::PlaneYZ, 0, "working plane Y/Z"},
    // group 7: the radius of the active edge (D), on the ISO mode's compensation rules
    {400, G::CutterComp, 7, true, A::CompCancel, 0, "tool radius compensation off"},
    {410, G::CutterComp, 7, false, A::CompLeft, 0, "tool radius compensation left"},
    {420, G::CutterComp, 7, false, A::CompRight, 0, "tool radius compensation right"},
    // group 8: settable zero offsets (cycles notes §3: "G54 settable zero offset"); G500
    // (no settable frame) and G505..G599 wait for the frame chain
    {5000, G::WorkOffset, 8, false, A::NotSupported, 0, "settable frame off"},
    {540, G::WorkOffset, 8, false, A::WorkOffset, 1, "settable zero offset 1"},
    {550, G::WorkOffset, 8, false, A::WorkOffset, 2, "settable zero offset 2"},
    {560, G::WorkOffset, 8, false, A::WorkOffset, 3, "settable zero offset 3"},
    {570, G::WorkOffset, 8, false, A::WorkOffset, 4, "settable zero offset 4"},
    // group 9 (non-modal frame suppression): the frame chain decides what G53 suppresses
    {530, G::OneShot, 9, false, A::NotSupported, 0, "suppress the current frames"},
    {1530, G::OneShot, 9, false, A::NotSupported, 0, "suppress frames and the base frame"},
    // group 10 (extended-functions notes §3: "G9 G60 G64 exact stop (non-modal) / exact stop
    // / continuous path")
    {600, G::PathControl, 10, false, A::ExactStopMode, 0, "exact stop"},
    {640, G::PathControl, 10, true, A::ContinuousMode, 0, "continuous-path mode"},
    {6410, G::PathControl, 10, false, A::NotSupported, 0, "continuous path with smoothing"},
    {6420, G::PathControl, 10, false, A::NotSupported, 0, "continuous path, axial tolerances"},
    // group 11
    {90, G::OneShot, 11, false, A::ExactStopOneShot, 0, "exact stop, non-modal"},
    // group 13: G700/G710 are ISO's G20/G21 (lengths and feeds); G70/G71 change the geometry
    // only, the feeds stay in the basic system (not built yet)
    {700, G::Units, 13, false, A::NotSupported, 0, "inch dimensions (geometry)"},
    {710, G::Units, 13, false, A::NotSupported, 0, "metric dimensions (geometry)"},
    {7000, G::Units, 13, false, A::Inch, 0, "inch dimensions and feeds"},
    {7100, G::Units, 13, false, A::Metric, 0, "metric dimensions and feeds"},
    // group 14
    {900, G::Distance, 14, true, A::Absolute, 0, "absolute dimensions"},
    {910, G::Distance, 14, false, A::Incremental, 0, "incremental dimensions"},
    // group 15 (extended-functions notes §3: "G94/G95 feed mm/min / mm/rev")
    {930, G::FeedMode, 15, false, A::InverseTime, 0, "inverse-time feed"},
    {940, G::FeedMode, 15, true, A::PerMinute, 0, "feed per minute"},
    {950, G::FeedMode, 15, false, A::PerRevolution, 0, "feed per revolution"},
    {960, G::Spindle, 15, false, A::NotSupported, 0, "constant cutting speed"},
    {970, G::Spindle, 15, false, A::CancelNoEffect, 0, "constant cutting speed off"},
    // group 3: the pole of polar coordinates
    {1100, G::Polar, 3, false, A::NotSupported, 0, "pole relative to the last position"},
    {1110, G::Polar, 3, false, A::NotSupported, 0, "pole relative to the workpiece zero"},
    {1120, G::Polar, 3, false, A::NotSupported, 0, "pole relative to the last pole"},
    // group 18: corners with tool radius compensation: G450, the power-on setting, joins outer
    // corners by an arc (the ISO mode's rule, CompRules::arc_corners); G451 is not built yet
    {4500, G::Other, 18, false, A::CancelNoEffect, 0, "transition circle at outer corners"},
    {4510, G::Other, 18, false, A::NotSupported, 0, "intersection at outer corners"},
    // group 47 (iso-milling notes §4.1): G290 in DIN text changes nothing; G291 back to ISO
    {2900, G::Language, 47, false, A::LanguageDin, 0, "Siemens DIN mode"},
    {2910, G::Language, 47, false, A::LanguageIso, 0, "ISO mode"},
};

// Fundamentals, circular interpolation (CR= radius) and chamfer/rounding: CHF= the chamfer's
// length, CHR= its legs (as ISO's ,C), RND= the rounding radius (,R).
constexpr AddressAlias kAliases[] = {
    {"CR", "R"}, {"CHR", ",C"}, {"RND", ",R"}, {"CHF", "CHF"}};

// DIN addresses not built yet (Fundamentals: circles, polar coordinates, contour definition;
// positioning axes; feeds), refused by name.
constexpr UnbuiltAddress kUnbuilt[] = {
    {"AR", "opening angle of an arc"},         {"TURN", "helix turns"},
    {"AP", "polar angle"},                     {"RP", "polar radius"},
    {"ANG", "contour angle"},                  {"RNDM", "modal rounding"},
    {"I1", "intermediate point of CIP"},       {"J1", "intermediate point of CIP"},
    {"K1", "intermediate point of CIP"},       {"ADIS", "smoothing distance"},
    {"ADISPOS", "smoothing distance of rapids"}, {"FA", "positioning axis feed"},
    {"POS", "positioning axis"},               {"POSA", "positioning axis"},
    {"SPOS", "spindle position"},              {"SPOSA", "spindle position"},
    {"ACC", "acceleration override"},          {"OVR", "feed override"},
    {"FL", "axis velocity limit"},             {"FXS", "travel to fixed stop"},
    {"OFFN", "contour offset"},
};

// Fundamentals, "Frames": the programmable frame's instructions (one per block, alone in it).
using FC = FrameCommand::Component;
constexpr FrameCommand kFrameCommands[] = {
    {"TRANS", FC::Translation, false}, {"ATRANS", FC::Translation, true},
    {"ROT", FC::Rotation, false},      {"AROT", FC::Rotation, true},
    {"SCALE", FC::Scale, false},       {"ASCALE", FC::Scale, true},
    {"MIRROR", FC::Mirror, false},     {"AMIRROR", FC::Mirror, true},
};

}  // namespace

const DialectTable& siemensDinTable() {
  // Built on first use (lowering runs after static initialisation): the ISO mode's table with
  // the DIN codes and the two behaviours DIN reads otherwise.
  static const DialectTable table = [] {
    DialectTable t = kSiemensIsoMTable;
    t.dialect = Dialect::SiemensDin;
    t.gcodes = kCodes;
    t.address_aliases = kAliases;
    t.frame_commands = kFrameCommands;
    t.unbuilt_addresses = kUnbuilt;
    // R, L, P, H mean other things in DIN (a parameter, a subprogram call, a repeat count, an
    // auxiliary function): not read until they are built. T selects the tool as in ISO mode;
    // D the edge, with its length.
    t.behaviour.other_meaning_addresses = "RLPQH";
    t.behaviour.d_selects_length = true;
    t.behaviour.decimal_point_from_params = false;  // `X20` is 20 mm in DIN
    t.behaviour.decimal_point_default = "calculator";
    return t;
  }();
  return table;
}

}  // namespace ncc::passes
