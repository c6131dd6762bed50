#include "golden_cases.h"

namespace ncc::passes::testing {
namespace {

using Side = ir::CutterComp::Side;
using Startup = ir::CutterComp::Startup;
using Special = ir::CutterComp::Special;

// Notation of the derivations: r = 5 (the tool radius) unless stated; P the programmed corner;
// d1, d2 the unit directions into and out of P; n = (-dy, dx) the left normal of a direction
// d; G41 puts the tool at +r n, G42 at -r n. Offset lines meet (linear outer and all inner
// line corners) at P + r (n1 + n2) / (1 + n1.n2). An arc's offset circle has the programmed
// centre and radius R - r on the tool's side towards the centre (G41 on a counterclockwise
// arc, G42 on a clockwise one), R + r on the other.
//
// The offset-mode cases share one frame: a lead-in along +X from (-20,0) (G41/G42 at (0,0),
// collinear with the first element, so type A starts at P + r n2 = (0, +-5)), element A ending
// at P = (40,0) along +X, element B out of P, and a G40 move continuing B's end direction
// (a straight cancel: B ends at r n of its end, then the tool goes to the programmed point).
// Arc A is the counterclockwise arc about (40,20), R = 20, from (20,20) to (40,0); its lead-in
// runs down from (20,40) (tangent to it).

// The settings go first: each block carries the ones in force when it is built.
CompProgram leadInLine(Side side = Side::Left, double r = 5, bool arc_corners = false) {
  CompProgram p;
  p.settings().arc_corners = arc_corners;
  p.rapid(-20, 0).side(side, r).line(0, 0).line(40, 0);
  return p;
}
CompProgram leadInArc(Side side = Side::Left, bool arc_corners = false,
                      Startup t = Startup::A) {
  CompProgram p;
  p.settings().arc_corners = arc_corners;
  p.settings().startup = t;
  p.rapid(20, 40).side(side, 5).line(20, 20).arc(40, 0, 40, 20, false);
  return p;
}
CompProgram startupType(Startup t, bool arc_corners = false) {
  // Start-up: from (0,-20) up to P = (0,0) with G41 (d1 = +Y, n1 = (-1,0)).
  CompProgram p;
  p.settings().startup = t;
  p.settings().arc_corners = arc_corners;
  p.rapid(0, -20).side(Side::Left, 5).line(0, 0);
  return p;
}
CompProgram cancelType(Startup t, bool arc_corners = false) {
  // Cancel after A = (0,0) -> (40,0) with G41 (n1 = (0,1)): the G40 block leaves P = (40,0).
  CompProgram p;
  p.settings().startup = t;
  p.settings().arc_corners = arc_corners;
  p.rapid(-20, 0).side(Side::Left, 5).line(0, 0).line(40, 0).cancel();
  return p;
}

std::vector<GoldenCase> makeCases() {
  std::vector<GoldenCase> c;
  auto add = [&](std::string name, std::string title, std::function<CompProgram()> build,
                 std::string expected, std::vector<std::string> errors = {},
                 std::vector<std::string> warnings = {}) {
    c.push_back({std::move(name), std::move(title), std::move(build), std::move(expected),
                 std::move(errors), std::move(warnings)});
  };
  // ---- Offset mode, line -> line (G41, A = (0,0)->(40,0): n1 = (0,1), A's offset y = 5).
  // B turns left 90 degrees to (40,30): inner. Offset lines y = 5 and x = 35 meet at (35,5).
  // Cancel straight up: B ends at (40,30) + 5 (-1,0) = (35,30).
  add("ll_inner", "line-line, inner corner (G41)",
      [] { return leadInLine().line(40, 30).cancel().line(40, 40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 35.000 5.000\n4: L 35.000 30.000\n"
      "5: L 40.000 40.000\n");
  // B turns right 45 degrees to (70,-30): outer obtuse. n2 = (1,1)/sqrt2, 1 + n1.n2 = 1.7071;
  // P + 5 (0.7071, 1.7071) / 1.7071 = (42.071, 5). B ends at (70,-30) + 5 n2 = (73.536,-26.464).
  add("ll_outer_obtuse_linear", "line-line, outer obtuse corner, linear connection",
      [] { return leadInLine().line(70, -30).cancel().line(80, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 42.071 5.000\n4: L 73.536 -26.464\n"
      "5: L 80.000 -40.000\n");
  // The same with arc connection: A ends at P + 5 n1 = (40,5), an arc of radius 5 about P,
  // clockwise (the tool is on the left of a right turn), to P + 5 n2 = (43.536, 3.536).
  add("ll_outer_obtuse_arc", "line-line, outer obtuse corner, arc connection",
      [] { return leadInLine(Side::Left, 5, true).line(70, -30).cancel().line(80, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n3: A 43.536 3.536 40.000 0.000 cw\n"
      "4: L 73.536 -26.464\n5: L 80.000 -40.000\n");
  // B turns right 90 degrees to (40,-30): n2 = (1,0), n1.n2 = 0: P + 5 (1,1) = (45,5) (90
  // degrees counts as obtuse). B ends at (45,-30).
  add("ll_outer_90_linear", "line-line, outer 90 degree corner, linear connection",
      [] { return leadInLine().line(40, -30).cancel().line(40, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 45.000 5.000\n4: L 45.000 -30.000\n"
      "5: L 40.000 -40.000\n");
  // B turns right 135 degrees to (10,-30): outer acute, d2 = (-1,-1)/sqrt2, n2 = (1,-1)/sqrt2.
  // Two extended vectors: P + 5 n1 + 5 d1 = (45,5), P + 5 n2 - 5 d2 = (43.536 + 3.536,
  // -3.536 + 3.536) = (47.071, 0). B ends at (10,-30) + 5 n2 = (13.536,-33.536).
  add("ll_outer_acute_linear", "line-line, outer acute corner, linear connection",
      [] { return leadInLine().line(10, -30).cancel().line(0, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 45.000 5.000\n3: L 47.071 0.000\n"
      "4: L 13.536 -33.536\n5: L 0.000 -40.000\n");
  // Arc connection: (40,5), clockwise about P to P + 5 n2 = (43.536,-3.536).
  add("ll_outer_acute_arc", "line-line, outer acute corner, arc connection",
      [] { return leadInLine(Side::Left, 5, true).line(10, -30).cancel().line(0, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n3: A 43.536 -3.536 40.000 0.000 cw\n"
      "4: L 13.536 -33.536\n5: L 0.000 -40.000\n");
  // Collinear: both offsets are (40,5); no corner move. B ends at (70,5).
  add("ll_straight", "line-line, straight (collinear)",
      [] { return leadInLine().line(70, 0).cancel().line(80, 0); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: L 70.000 5.000\n"
      "5: L 80.000 0.000\n");

  // ---- Offset mode, line -> arc (A as above, B out of P = (40,0)).
  // B counterclockwise about (20,0), R = 20, to (20,20): starts along +Y (a left turn, inner).
  // G41 on a ccw arc: radius 20 - 5 = 15. y = 5 meets it at x = 20 + sqrt(15^2 - 5^2) =
  // 34.142. B ends at (20,20) + 5 n(-1,0) = (20,15). Cancel straight: then to (10,20).
  add("la_inner", "line-arc, inner corner",
      [] { return leadInLine().arc(20, 20, 20, 0, false).cancel().line(10, 20); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 34.142 5.000\n4: A 20.000 15.000 20.000 0.000 ccw\n"
      "5: L 10.000 20.000\n");
  // B clockwise about (20,0) to (20,-20): starts along -Y (outer, 90 degrees), n2 = (1,0),
  // offset radius 25. Linear: the tangent lines meet at P + 5 (1,1) = (45,5), then to B's
  // start perpendicular P + 5 n2 = (45,0) (an arc starts on its offset circle). B ends at
  // (20,-20) + 5 n(-1,0) = (20,-25).
  add("la_outer_obtuse_linear", "line-arc, outer corner, linear connection",
      [] { return leadInLine().arc(20, -20, 20, 0, true).cancel().line(10, -20); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 45.000 5.000\n3: L 45.000 0.000\n"
      "4: A 20.000 -25.000 20.000 0.000 cw\n5: L 10.000 -20.000\n");
  // Arc connection: (40,5), clockwise about P to (45,0).
  add("la_outer_obtuse_arc", "line-arc, outer corner, arc connection",
      [] { return leadInLine(Side::Left, 5, true).arc(20, -20, 20, 0, true).cancel().line(10, -20); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n3: A 45.000 0.000 40.000 0.000 cw\n"
      "4: A 20.000 -25.000 20.000 0.000 cw\n5: L 10.000 -20.000\n");
  // B clockwise about (30,10), R = 10 sqrt2, half round to (20,20): starts along
  // (-1,-1)/sqrt2 (outer acute, 135 degrees), n2 = (1,-1)/sqrt2. Extended vectors (45,5),
  // (47.071,0) as for lines, then to B's perpendicular start (43.536,-3.536). B ends along
  // (1,1)/sqrt2 at (20,20) + 5 (-1,1)/sqrt2 = (16.464,23.536) (radius 19.142 about (30,10)).
  add("la_outer_acute_linear", "line-arc, outer acute corner, linear connection",
      [] { return leadInLine().arc(20, 20, 30, 10, true).cancel().line(30, 30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 45.000 5.000\n3: L 47.071 0.000\n"
      "3: L 43.536 -3.536\n4: A 16.464 23.536 30.000 10.000 cw\n5: L 30.000 30.000\n");
  // B counterclockwise about (40,20) to (60,20): tangent to A (straight). Offset radius 15:
  // from (40,5) to (60,20) + 5 n(0,1) = (55,20).
  add("la_tangent", "line-arc, tangent",
      [] { return leadInLine().arc(60, 20, 40, 20, false).cancel().line(60, 30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: A 55.000 20.000 40.000 20.000 ccw\n"
      "5: L 60.000 30.000\n");

  // ---- Offset mode, arc -> line (A ccw about (40,20), R = 20, offset radius 15, starting at
  // (25,20) after the tangent lead-in from (20,40): 2: (20,20) + 5 n(0,-1) = (25,20)).
  // B up to (40,30): inner. x = 35 meets the circle at y = 20 - sqrt(15^2 - 5^2) = 5.858.
  add("al_inner", "arc-line, inner corner",
      [] { return leadInArc().line(40, 30).cancel().line(40, 40); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 35.000 5.858 40.000 20.000 ccw\n"
      "4: L 35.000 30.000\n5: L 40.000 40.000\n");
  // B down to (40,-30): outer 90 degrees. The arc ends perpendicular, (40,5), then to the
  // tangent lines' meeting point P + 5 (1,1) = (45,5); B ends at (45,-30).
  add("al_outer_obtuse_linear", "arc-line, outer corner, linear connection",
      [] { return leadInArc().line(40, -30).cancel().line(40, -40); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "3: L 45.000 5.000\n4: L 45.000 -30.000\n5: L 40.000 -40.000\n");
  add("al_outer_obtuse_arc", "arc-line, outer corner, arc connection",
      [] { return leadInArc(Side::Left, true).line(40, -30).cancel().line(40, -40); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "3: A 45.000 0.000 40.000 0.000 cw\n4: L 45.000 -30.000\n5: L 40.000 -40.000\n");
  // B to (10,-30), outer acute: (40,5), (45,5), (47.071,0); B ends (13.536,-33.536).
  add("al_outer_acute_linear", "arc-line, outer acute corner, linear connection",
      [] { return leadInArc().line(10, -30).cancel().line(0, -40); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "3: L 45.000 5.000\n3: L 47.071 0.000\n4: L 13.536 -33.536\n5: L 0.000 -40.000\n");

  // Arc connection: the arc ends perpendicular (40,5), a clockwise arc about P to
  // P + 5 n2 = (43.536,-3.536).
  add("al_outer_acute_arc", "arc-line, outer acute corner, arc connection",
      [] { return leadInArc(Side::Left, true).line(10, -30).cancel().line(0, -40); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "3: A 43.536 -3.536 40.000 0.000 cw\n4: L 13.536 -33.536\n5: L 0.000 -40.000\n");
  add("la_outer_acute_arc", "line-arc, outer acute corner, arc connection",
      [] { return leadInLine(Side::Left, 5, true).arc(20, 20, 30, 10, true).cancel().line(30, 30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n3: A 43.536 -3.536 40.000 0.000 cw\n"
      "4: A 16.464 23.536 30.000 10.000 cw\n5: L 30.000 30.000\n");

  // ---- Offset mode, arc -> arc.
  // B ccw about (20,0) to (20,20): inner. Circles (40,20) r 15 and (20,0) r 15: their
  // centres 20 sqrt2 apart, the common chord through the midpoint (30,10) across (1,-1)/sqrt2
  // at h = sqrt(225 - 200) = 5: (30 +- 3.536, 10 -+ 3.536); nearer P: (33.536, 6.464).
  add("aa_inner", "arc-arc, inner corner",
      [] { return leadInArc().arc(20, 20, 20, 0, false).cancel().line(10, 20); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 33.536 6.464 40.000 20.000 ccw\n"
      "4: A 20.000 15.000 20.000 0.000 ccw\n5: L 10.000 20.000\n");
  // B cw about (20,0) to (20,-20): outer. (40,5), (45,5), (45,0), then B to (20,-25).
  add("aa_outer_obtuse_linear", "arc-arc, outer corner, linear connection",
      [] { return leadInArc().arc(20, -20, 20, 0, true).cancel().line(10, -20); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "3: L 45.000 5.000\n3: L 45.000 0.000\n4: A 20.000 -25.000 20.000 0.000 cw\n"
      "5: L 10.000 -20.000\n");
  add("aa_outer_obtuse_arc", "arc-arc, outer corner, arc connection",
      [] { return leadInArc(Side::Left, true).arc(20, -20, 20, 0, true).cancel().line(10, -20); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "3: A 45.000 0.000 40.000 0.000 cw\n4: A 20.000 -25.000 20.000 0.000 cw\n"
      "5: L 10.000 -20.000\n");
  // B the half circle clockwise about (30,10) of la_outer_acute_linear (outer acute): the arc
  // A ends perpendicular (40,5), then (45,5), (47.071,0) and B's perpendicular start
  // (43.536,-3.536); B ends at (16.464,23.536).
  add("aa_outer_acute_linear", "arc-arc, outer acute corner, linear connection",
      [] { return leadInArc().arc(20, 20, 30, 10, true).cancel().line(30, 30); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "3: L 45.000 5.000\n3: L 47.071 0.000\n3: L 43.536 -3.536\n"
      "4: A 16.464 23.536 30.000 10.000 cw\n5: L 30.000 30.000\n");
  add("aa_outer_acute_arc", "arc-arc, outer acute corner, arc connection",
      [] { return leadInArc(Side::Left, true).arc(20, 20, 30, 10, true).cancel().line(30, 30); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "3: A 43.536 -3.536 40.000 0.000 cw\n4: A 16.464 23.536 30.000 10.000 cw\n"
      "5: L 30.000 30.000\n");
  // B continues A's circle: ccw about (40,20) to (60,20), tangent (straight); one circle of
  // radius 15 through (40,5) to (55,20).
  add("aa_tangent", "arc-arc, tangent",
      [] { return leadInArc().arc(60, 20, 40, 20, false).cancel().line(60, 30); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "4: A 55.000 20.000 40.000 20.000 ccw\n5: L 60.000 30.000\n");
  // G42 on the same arcs: the inner corner becomes outer and back; aa_outer with G42 is
  // inner: B cw about (20,0) (G42 on cw: towards the centre, 15) and A (G42 on ccw: 25):
  // circles (40,20) r 25 and (20,0) r 15: a = (625 - 225 + 800) / (2 * 28.284) = 21.213 from
  // (40,20) towards (20,0), h = sqrt(625 - 450) = 13.229; points (40,20) + 21.213 u +- 13.229 v,
  // u = (-1,-1)/sqrt2, v = (1,-1)/sqrt2: (25 + 9.354, 5 - 9.354) = (34.354,-4.354) nearer P
  // (the other is (15.646, 14.354)).
  add("aa_inner_g42", "arc-arc, inner corner with G42 (different offset radii)",
      [] { return leadInArc(Side::Right).arc(20, -20, 20, 0, true).cancel().line(10, -20); },
      "1: R 20.000 40.000\n2: L 15.000 20.000\n3: A 34.354 -4.354 40.000 20.000 ccw\n"
      "4: A 20.000 -15.000 20.000 0.000 cw\n5: L 10.000 -20.000\n");

  // ---- Start-up: from (0,-20) up to P = (0,0) with G41 (d1 = +Y, n1 = (-1,0)); B out of P,
  // then a straight G40 move. Type C with motion in its start-up block is type A.
  // B to (40,0): outer 90 degrees, n2 = (0,1). A: straight to P + 5 n2 = (0,5).
  for (const auto& [t, name] : {std::pair{Startup::A, "a"}, std::pair{Startup::C, "c"}})
    add(std::string("startup_") + name + "_outer", std::string("start-up type ") + name +
            ", outer corner: straight to perpendicular to the next move",
        [t = t] { return startupType(t).line(40, 0).cancel().line(50, 0); },
        "1: R 0.000 -20.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: L 50.000 0.000\n");
  // B: perpendicular to the start-up move P + 5 n1 = (-5,0), then the offset lines' meeting
  // point P + 5 (n1 + n2) / 1 = (-5,5).
  add("startup_b_outer", "start-up type B, outer corner, linear",
      [] { return startupType(Startup::B).line(40, 0).cancel().line(50, 0); },
      "1: R 0.000 -20.000\n2: L -5.000 0.000\n2: L -5.000 5.000\n3: L 40.000 5.000\n"
      "4: L 50.000 0.000\n");
  // B, arc connection: (-5,0), clockwise about P to (0,5).
  add("startup_b_outer_arc", "start-up type B, outer corner, arc connection",
      [] { return startupType(Startup::B, true).line(40, 0).cancel().line(50, 0); },
      "1: R 0.000 -20.000\n2: L -5.000 0.000\n2: A 0.000 5.000 0.000 0.000 cw\n"
      "3: L 40.000 5.000\n4: L 50.000 0.000\n");
  // B to (30,-30), outer acute: d2 = (1,-1)/sqrt2, n2 = (1,1)/sqrt2. A: P + 5 n2 =
  // (3.536,3.536). B: (-5,0), P + 5 n1 + 5 d1 = (-5,5), P + 5 n2 - 5 d2 = (0,7.071).
  // B ends at (30,-30) + 5 n2 = (33.536,-26.464).
  add("startup_a_acute", "start-up type A, outer acute corner",
      [] { return startupType(Startup::A).line(30, -30).cancel().line(40, -40); },
      "1: R 0.000 -20.000\n2: L 3.536 3.536\n3: L 33.536 -26.464\n4: L 40.000 -40.000\n");
  add("startup_b_acute", "start-up type B, outer acute corner, linear",
      [] { return startupType(Startup::B).line(30, -30).cancel().line(40, -40); },
      "1: R 0.000 -20.000\n2: L -5.000 0.000\n2: L -5.000 5.000\n2: L 0.000 7.071\n"
      "3: L 33.536 -26.464\n4: L 40.000 -40.000\n");
  // B to (-40,0): inner, every type: P + 5 (n1 + n2), n2 = (0,-1): (-5,-5).
  for (const auto& [t, name] :
       {std::pair{Startup::A, "a"}, std::pair{Startup::B, "b"}, std::pair{Startup::C, "c"}})
    add(std::string("startup_") + name + "_inner",
        std::string("start-up type ") + name + ", inner corner: the offset lines' intersection",
        [t = t] { return startupType(t).line(-40, 0).cancel().line(-50, 0); },
        "1: R 0.000 -20.000\n2: L -5.000 -5.000\n3: L -40.000 -5.000\n4: L -50.000 0.000\n");
  // B straight on to (0,40): A and B both end at P + 5 n1 = (-5,0).
  for (const auto& [t, name] : {std::pair{Startup::A, "a"}, std::pair{Startup::B, "b"}})
    add(std::string("startup_") + name + "_straight",
        std::string("start-up type ") + name + ", straight on",
        [t = t] { return startupType(t).line(0, 40).cancel().line(0, 50); },
        "1: R 0.000 -20.000\n2: L -5.000 0.000\n3: L -5.000 40.000\n4: L 0.000 50.000\n");
  // B an arc clockwise about (0,-20), R = 20, to (20,-20): starts along +X (outer 90), offset
  // radius 25. A: to P + 5 n2 = (0,5) (on the offset circle). B: (-5,0), (-5,5), then B's
  // perpendicular start (0,5). The arc ends at (20,-20) + 5 n(0,-1) = (25,-20).
  add("startup_a_line_arc", "start-up type A into an arc",
      [] { return startupType(Startup::A).arc(20, -20, 0, -20, true).cancel().line(20, -30); },
      "1: R 0.000 -20.000\n2: L 0.000 5.000\n3: A 25.000 -20.000 0.000 -20.000 cw\n"
      "4: L 20.000 -30.000\n");
  add("startup_b_line_arc", "start-up type B into an arc",
      [] { return startupType(Startup::B).arc(20, -20, 0, -20, true).cancel().line(20, -30); },
      "1: R 0.000 -20.000\n2: L -5.000 0.000\n2: L -5.000 5.000\n2: L 0.000 5.000\n"
      "3: A 25.000 -20.000 0.000 -20.000 cw\n4: L 20.000 -30.000\n");
  // Type C with motion in its start-up block is type A: the acute corner, straight on, into an
  // arc give type A's points.
  add("startup_c_acute", "start-up type C with motion, outer acute corner (as A)",
      [] { return startupType(Startup::C).line(30, -30).cancel().line(40, -40); },
      "1: R 0.000 -20.000\n2: L 3.536 3.536\n3: L 33.536 -26.464\n4: L 40.000 -40.000\n");
  add("startup_c_straight", "start-up type C with motion, straight on (as A)",
      [] { return startupType(Startup::C).line(0, 40).cancel().line(0, 50); },
      "1: R 0.000 -20.000\n2: L -5.000 0.000\n3: L -5.000 40.000\n4: L 0.000 50.000\n");
  add("startup_c_line_arc", "start-up type C with motion into an arc (as A)",
      [] { return startupType(Startup::C).arc(20, -20, 0, -20, true).cancel().line(20, -30); },
      "1: R 0.000 -20.000\n2: L 0.000 5.000\n3: A 25.000 -20.000 0.000 -20.000 cw\n"
      "4: L 20.000 -30.000\n");
  // Type B into an arc with arc connection: (-5,0), clockwise about P to (0,5), the arc.
  add("startup_b_line_arc_arc", "start-up type B into an arc, arc connection",
      [] { return startupType(Startup::B, true).arc(20, -20, 0, -20, true).cancel().line(20, -30); },
      "1: R 0.000 -20.000\n2: L -5.000 0.000\n2: A 0.000 5.000 0.000 0.000 cw\n"
      "3: A 25.000 -20.000 0.000 -20.000 cw\n4: L 20.000 -30.000\n");
  // G41 in a block without motion at (0,0). Type C: the tool moves there to perpendicular to
  // the next move, P + 5 n(1,0) = (0,5) (a rapid: no feed is in force); type A: nothing moves
  // in it, the next move is the start-up and ramps from (0,0) to (40,5).
  add("startup_c_without_motion", "start-up type C in a block without motion",
      [] {
        CompProgram p;
        p.settings().startup = Startup::C;
        p.rapid(0, 0).side(Side::Left, 5).still().line(40, 0).cancel().line(50, 0);
        return p;
      },
      "1: R 0.000 0.000\n2: R 0.000 5.000\n3: L 40.000 5.000\n4: L 50.000 0.000\n");
  add("startup_a_without_motion", "start-up type A after G41 in a block without motion",
      [] {
        CompProgram p;
        p.rapid(0, 0).side(Side::Left, 5).still().line(40, 0).cancel().line(50, 0);
        return p;
      },
      "1: R 0.000 0.000\n3: L 40.000 5.000\n4: L 50.000 0.000\n");

  // ---- Cancel: after A = (0,0) -> (40,0) with G41 (n1 = (0,1)), the G40 move out of P.
  // Inner (G40 up to (40,30)), every type: the offset lines meet at (35,5).
  for (const auto& [t, name] : {std::pair{Startup::A, "a"}, std::pair{Startup::B, "b"}})
    add(std::string("cancel_") + name + "_inner", std::string("cancel type ") + name + ", inner",
        [t = t] { return cancelType(t).line(40, 30); },
        "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 35.000 5.000\n4: L 40.000 30.000\n");
  // Outer 90 (down to (40,-30)). A: A ends perpendicular, (40,5), then to the point.
  add("cancel_a_outer", "cancel type A, outer corner",
      [] { return cancelType(Startup::A).line(40, -30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: L 40.000 -30.000\n");
  // B: the intersection (45,5), then perpendicular to the G40 move P + 5 n(0,-1) = (45,0).
  add("cancel_b_outer", "cancel type B, outer corner, linear",
      [] { return cancelType(Startup::B).line(40, -30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 45.000 5.000\n3: L 45.000 0.000\n"
      "4: L 40.000 -30.000\n");
  add("cancel_b_outer_arc", "cancel type B, outer corner, arc connection",
      [] { return cancelType(Startup::B, true).line(40, -30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n3: A 45.000 0.000 40.000 0.000 cw\n"
      "4: L 40.000 -30.000\n");
  // Outer acute (G40 to (10,-30), n2 = (1,-1)/sqrt2). A: (40,5). B: (45,5), (47.071,0),
  // then perpendicular to the G40 move, P + 5 n2 = (43.536,-3.536).
  add("cancel_a_acute", "cancel type A, outer acute corner",
      [] { return cancelType(Startup::A).line(10, -30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: L 10.000 -30.000\n");
  add("cancel_b_acute", "cancel type B, outer acute corner, linear",
      [] { return cancelType(Startup::B).line(10, -30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 45.000 5.000\n3: L 47.071 0.000\n"
      "3: L 43.536 -3.536\n4: L 10.000 -30.000\n");
  // After an arc (A ccw about (40,20), ending at (40,0) along +X), G40 down to (40,-30).
  // A: the arc ends perpendicular (40,5). B: then (45,5), (45,0).
  add("cancel_a_arc_line", "cancel type A after an arc",
      [] { return leadInArc().cancel().line(40, -30); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "4: L 40.000 -30.000\n");
  add("cancel_b_arc_line", "cancel type B after an arc",
      [] { return leadInArc(Side::Left, false, Startup::B).cancel().line(40, -30); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 40.000 5.000 40.000 20.000 ccw\n"
      "3: L 45.000 5.000\n3: L 45.000 0.000\n4: L 40.000 -30.000\n");
  // After the arc, an inner G40 move up to (40,30): the offset circle (radius 15) meets the
  // G40 move's offset x = 35 at (35, 20 - sqrt(200)) = (35,5.858).
  add("cancel_arc_inner", "cancel after an arc, inner corner",
      [] { return leadInArc().cancel().line(40, 30); },
      "1: R 20.000 40.000\n2: L 25.000 20.000\n3: A 35.000 5.858 40.000 20.000 ccw\n"
      "4: L 40.000 30.000\n");
  // Cancel type C with motion is type A.
  add("cancel_c_outer", "cancel type C with motion, outer corner (as A)",
      [] { return cancelType(Startup::C).line(40, -30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: L 40.000 -30.000\n");
  // G40 in a block without motion. A: the vector (40,5) stays; the next move leaves it.
  // C: the tool moves back to (40,0) in the G40 block.
  add("cancel_a_without_motion", "cancel type A in a block without motion",
      [] { return cancelType(Startup::A).still().line(60, -10); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n5: L 60.000 -10.000\n");
  add("cancel_c_without_motion", "cancel type C in a block without motion",
      [] { return cancelType(Startup::C).still().line(60, -10); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: L 40.000 0.000\n"
      "5: L 60.000 -10.000\n");
  // G40 I1 J-1: a virtual move along (1,-1)/sqrt2 out of P on the same side, by intersection:
  // its offset line through P + 5 (1,1)/sqrt2 along (1,-1) meets y = 5 at (42.071,5).
  add("cancel_ij", "G40 with I J: the intersection with a virtual move",
      [] { return cancelType(Startup::A).vector(1, -1).line(40, -30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 42.071 5.000\n4: L 40.000 -30.000\n");

  // ---- G38, G39, I J vectors.
  // G39 (no I J) between A and a move down to (40,-30): A ends perpendicular (40,5), the G39
  // block turns an arc of radius 5 about P, clockwise, to perpendicular to the next move (45,0).
  add("g39_corner_arc", "G39 corner arc",
      [] { return leadInLine().special(Special::CornerArc).still().line(40, -30).cancel().line(40, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: A 45.000 0.000 40.000 0.000 cw\n"
      "5: L 45.000 -30.000\n6: L 40.000 -40.000\n");
  // G39 I1 J-1: the arc ends perpendicular to (1,-1): P + 5 (1,1)/sqrt2 = (43.536,3.536); the
  // next move starts there and ends at (45,-30).
  add("g39_corner_arc_ij", "G39 corner arc with I J",
      [] {
        return leadInLine().special(Special::CornerArc).vector(1, -1).still().line(40, -30)
            .cancel().line(40, -40);
      },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: A 43.536 3.536 40.000 0.000 cw\n"
      "5: L 45.000 -30.000\n6: L 40.000 -40.000\n");
  // I1 J1 in the G01 block of A (FANUC IJ type): A ends at P + 5 n(1,1)/sqrt2 =
  // (36.464,3.536), whatever the corner; B (up to (40,30)) starts there, ends at (35,30).
  add("ij_vector_g01", "an I J vector in a G01 block (FANUC IJ type)",
      [] {
        CompProgram p;
        p.rapid(-20, 0).side(Side::Left, 5).line(0, 0).vector(1, 1).line(40, 0).line(40, 30)
            .cancel().line(40, 40);
        return p;
      },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 36.464 3.536\n4: L 35.000 30.000\n"
      "5: L 40.000 40.000\n");
  // I1 J1 in a block without motion after A: it sets A's end vector, (36.464,3.536).
  add("ij_vector_without_motion", "an I J vector in a block without motion",
      [] { return leadInLine().vector(1, 1).still().line(40, 30).cancel().line(40, 40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 36.464 3.536\n5: L 35.000 30.000\n"
      "6: L 40.000 40.000\n");
  // G38 on the move down to (40,-30): the block before it ends perpendicular to itself (FANUC
  // §5.5: "G38 の 1 つ前のブロックの終点において、そのブロックに垂直なベクトル"), (40,5), and
  // the G38 move keeps that vector (0,5) to its end: (40,-25); the next move (to (70,-30))
  // starts there and ends at its corner with the cancel, (70,-25).
  add("g38_vector_hold", "G38 holds the vector",
      [] {
        return leadInLine().special(Special::VectorHold).line(40, -30).line(70, -30).cancel()
            .line(80, -30);
      },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: L 40.000 -25.000\n"
      "5: L 70.000 -25.000\n6: L 80.000 -30.000\n");

  // ---- Blocks without motion in the plane (the limit: 1 by default).
  // One (an M08) between A and the move down: the corner is kept, (45,5).
  add("without_motion_within", "a block without motion: the corner is kept",
      [] { return leadInLine().still().line(40, -30).cancel().line(40, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 45.000 5.000\n5: L 45.000 -30.000\n"
      "6: L 40.000 -40.000\n");
  // A zero-length move counts as one: its target is the corner point (45,5).
  add("zero_length_move", "a zero-length move is a block without motion",
      [] { return leadInLine().line(40, 0).line(40, -30).cancel().line(40, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 45.000 5.000\n4: L 45.000 5.000\n"
      "5: L 45.000 -30.000\n6: L 40.000 -40.000\n");
  // Two, at an outer corner: the look-ahead runs dry, A ends perpendicular to itself (40,5)
  // (FANUC §5.4: "more than N-2 consecutive: perpendicular vector"), and the next move goes on
  // from there to its own end vector (45,-30): the corner is left uncut, a warning.
  add("without_motion_beyond_outer", "too many blocks without motion at an outer corner",
      [] { return leadInLine().still().still().line(40, -30).cancel().line(40, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n"
      "6: L 45.000 -30.000\n7: L 40.000 -40.000\n",
      {}, {"NCC2128"});
  // Two at an inner corner: A ends perpendicular (40,5), and going on from there would cut
  // into the corner: an alarm at the move after them (line 6); everything passes unchanged
  // after it.
  add("without_motion_beyond_inner", "too many blocks without motion at an inner corner: alarm",
      [] { return leadInLine().still().still().line(40, 30).cancel().line(40, 40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n6: L 40.000 30.000\n"
      "7: L 40.000 40.000\n",
      {"NCC2128"});

  // ---- Changes while compensating.
  // G41 -> G42 on the move down: the old and new offset paths y = 5 and (G42 on -Y) x = 35
  // meet at (35,5); the cancel leaves (40,-30) + (-5) (1,0) = (35,-30).
  add("side_change", "G41 to G42 while compensating",
      [] { return leadInLine().side(Side::Right, 5).line(40, -30).cancel().line(40, -40); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 35.000 5.000\n4: L 35.000 -30.000\n"
      "5: L 40.000 -40.000\n");
  // Straight on: y = 5 and y = -5 never meet: A ends perpendicular (40,5), then to
  // perpendicular to the next move on the new side (40,-5).
  add("side_change_straight", "G41 to G42 on a straight line",
      [] { return leadInLine().side(Side::Right, 5).line(80, 0).cancel().line(90, 0); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n3: L 40.000 -5.000\n"
      "4: L 80.000 -5.000\n5: L 90.000 0.000\n");
  // D 5 -> 8 on a straight line: the new radius acts at the end of its block; the line ramps
  // from (40,5) to (80,8).
  add("radius_change", "a new radius while compensating",
      [] { return leadInLine().side(Side::Left, 8).line(80, 0).cancel().line(90, 0); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: L 80.000 8.000\n"
      "5: L 90.000 0.000\n");
  // G41 -> G42 into the clockwise arc about (20,0) (G42 on a cw arc: towards the centre, radius
  // 15): y = 5 meets it at (20 + sqrt(15^2 - 5^2), 5) = (34.142,5); the arc ends at
  // (20,-20) - 5 n(-1,0) = (20,-15).
  add("side_change_into_arc", "G41 to G42 into an arc",
      [] { return leadInLine().side(Side::Right, 5).arc(20, -20, 20, 0, true).cancel().line(10, -20); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 34.142 5.000\n4: A 20.000 -15.000 20.000 0.000 cw\n"
      "5: L 10.000 -20.000\n");
  // D 5 -> 8 on the tangent arc of la_tangent: an arc takes the new radius at once (radius
  // 20 - 8 = 12 about (40,20)), after a step from (40,5) to (40,8) at the corner; it ends at
  // (60,20) + 8 n(0,1) = (52,20).
  add("radius_change_into_arc", "a new radius on an arc",
      [] { return leadInLine().side(Side::Left, 8).arc(60, 20, 40, 20, false).cancel().line(60, 30); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n3: L 40.000 8.000\n"
      "4: A 52.000 20.000 40.000 20.000 ccw\n5: L 60.000 30.000\n");
  // A machine-space move (G53/G28's last leg) after A: A ends perpendicular (40,5), the move
  // runs to its programmed point, and the next move takes the vector up from there: it ends at
  // (80,50) + 5 (0,1) = (80,55).
  add("temporary_cancel", "a machine-space move is a temporary cancel",
      [] { return leadInLine().machineRapid(50, 50).line(80, 50).cancel().line(90, 50); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: R 50.000 50.000\n"
      "5: L 80.000 55.000\n6: L 90.000 50.000\n");
  // A hole cycle's move likewise.
  add("hole_cycle_suspends", "a hole cycle's moves run on the programmed points",
      [] { return leadInLine().suspend().rapid(50, 50).line(80, 50).cancel().line(90, 50); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: R 50.000 50.000\n"
      "5: L 80.000 55.000\n6: L 90.000 50.000\n");
  // Radius 0: the programmed path.
  add("radius_zero", "radius 0: the programmed path",
      [] { return leadInLine(Side::Left, 0).line(40, 30).cancel().line(40, 40); },
      "1: R -20.000 0.000\n2: L 0.000 0.000\n3: L 40.000 0.000\n4: L 40.000 30.000\n"
      "5: L 40.000 40.000\n");
  // G41 with -5 is G42 with 5: the left turn is outer. Lead-in (0,-5); the offset lines y = -5
  // and x = 45 meet at (45,-5); up to (45,30).
  add("radius_negative", "a negative radius swaps the side",
      [] { return leadInLine(Side::Left, -5).line(40, 30).cancel().line(40, 40); },
      "1: R -20.000 0.000\n2: L 0.000 -5.000\n3: L 45.000 -5.000\n4: L 45.000 30.000\n"
      "5: L 40.000 40.000\n");

  // ---- Arcs.
  // A full circle ccw about (20,0) from (0,0) (starting along -Y), G41: radius 15, from
  // (5,0) all the way round to (5,0). Tangent lead-in down from (0,20), straight cancel.
  add("full_circle", "a full circle",
      [] {
        CompProgram p;
        p.rapid(0, 20).side(Side::Left, 5).line(0, 0).arc(0, 0, 20, 0, false).cancel()
            .line(0, -20);
        return p;
      },
      "1: R 0.000 20.000\n2: L 5.000 0.000\n3: A 5.000 0.000 20.000 0.000 ccw\n"
      "4: L 0.000 -20.000\n");

  // ---- Robustness.
  // A left turn of 1e-6 rad (B to (80, 40e-6)): inner, the intersection is
  // (40 - 5 tan(0.5e-6), 5) = (40.000, 5.000); B ends at (80 - 5e-6, 5 + 4e-5).
  add("nearly_tangent", "a nearly tangent corner",
      [] { return leadInLine().line(80, 40e-6).cancel().line(120, 80e-6); },
      "1: R -20.000 0.000\n2: L 0.000 5.000\n3: L 40.000 5.000\n4: L 80.000 5.000\n"
      "5: L 120.000 0.000\n");
  // G42, B back to (0,1): an outer corner of 178.6 degrees. d2 = (-40,1)/40.0125,
  // n2 = (-1,-40)/40.0125. P - 5 n1 + 5 d1 = (45,-5); P - 5 n2 = (40.125, 4.998), minus 5 d2:
  // (45.123, 4.873). B ends at (0,1) - 5 n2 = (0.125, 5.998).
  add("near_reversal", "a nearly reversing outer corner",
      [] { return leadInLine(Side::Right).line(0, 1).cancel().line(-40, 2); },
      "1: R -20.000 0.000\n2: L 0.000 -5.000\n3: L 45.000 -5.000\n3: L 45.123 4.873\n"
      "4: L 0.125 5.998\n5: L -40.000 2.000\n");
  // A groove 3 wide under a tool 10 wide: the compensated bottom (line 5) would run backwards
  // (from x = 25 to x = 18): PS0041 there, and the blocks from it on pass unchanged. The wall
  // before it (line 4) was sent on before the check (it ends at (25,-5)); the error makes the
  // driver write no program.
  add("narrow_groove", "a groove narrower than the tool: the interference alarm",
      [] {
        CompProgram p;
        p.rapid(-10, 10).side(Side::Left, 5).line(0, 0).line(20, 0).line(20, -10).line(23, -10)
            .line(23, 0).line(40, 0).cancel().line(50, 10);
        return p;
      },
      "1: R -10.000 10.000\n2: L 2.071 5.000\n3: L 25.000 5.000\n4: L 25.000 -5.000\n"
      "5: L 23.000 -10.000\n6: L 23.000 0.000\n7: L 40.000 0.000\n8: L 50.000 10.000\n",
      {"PS0041"});
  return c;
}

}  // namespace

const std::vector<GoldenCase>& goldenCases() {
  static const std::vector<GoldenCase> cases = makeCases();
  return cases;
}

}  // namespace ncc::passes::testing
