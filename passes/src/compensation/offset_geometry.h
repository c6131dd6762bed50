#pragma once
// The plane geometry of cutter radius compensation (docs/compensation.md): a programmed element
// (a line or an arc in the compensation plane), its offset curve, and the tool centre's path
// around a corner between two elements by the controllers' rules (FANUC 30i §5.4, Mazak
// §12-4, Siemens §3.5). Exact: lines stay lines, arcs stay arcs about the programmed centre.
//
// Offsets are signed: w > 0 puts the tool on the left of the direction of travel (G41 with a
// positive radius), w < 0 on the right. n is the left normal of the direction, so the offset
// point of a programmed point P is P + w n.
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace ncc::passes::comp {

using Vec2 = Eigen::Vector2d;

inline constexpr double kLengthTolerance = 1e-9;  // mm: shorter is no move
inline constexpr double kAngleTolerance = 1e-9;   // rad: closer is tangent

inline Vec2 leftNormal(const Vec2& d) { return {-d.y(), d.x()}; }
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// A programmed element in plane coordinates.
struct Element {
  bool arc = false;
  Vec2 start, end;
  Vec2 centre{0, 0};   // arcs
  bool clockwise = false;
  double radius() const { return (start - centre).norm(); }
  // The unit direction of travel at the start / the end (arcs: the tangent there).
  Vec2 startDirection() const;
  Vec2 endDirection() const;
  // The signed sweep, radians, in (0, 2 pi] (a closed arc is a full circle): clockwise negative.
  double sweep() const;
};

// The signed sweep from `from` to `to` about `centre` in the given direction, in [0, 2 pi)
// (clockwise: the magnitude, as a positive number).
double sweepBetween(const Vec2& centre, const Vec2& from, const Vec2& to, bool clockwise);

// The offset curve of an element at offset w: a line (through `point` along `direction`) or a
// circle about the arc's centre. An arc whose offset radius is not positive has none.
struct OffsetCurve {
  bool circle = false;
  Vec2 point, direction;  // line
  Vec2 centre;            // circle
  double radius = 0.0;
};
std::optional<OffsetCurve> offsetCurve(const Element& e, double w);
// The offset radius of an arc at offset w (R - w on a counterclockwise arc's left side, ...).
double offsetRadius(const Element& e, double w);

// The point of a ∩ b nearest `near`, if they meet.
std::optional<Vec2> intersect(const OffsetCurve& a, const OffsetCurve& b, const Vec2& near);

// The tool centre's path from element A into element B at their common point P.
struct Connector {
  bool arc = false;
  Vec2 to;
  Vec2 centre{0, 0};
  bool clockwise = false;
};
struct CornerPath {
  Vec2 a_end;                        // where A's compensated move ends
  std::vector<Connector> connectors;  // the corner moves after it
  Vec2 b_start() const { return connectors.empty() ? a_end : connectors.back().to; }
};

// How a corner is turned.
struct CornerRules {
  bool arc_connection = false;   // outer corners joined by an arc about P (FANUC CCC=1, G450)
  // A's move ends at P + w n1 (not extended to the corner point): arcs, and a type-B start-up
  // block; B's starts at P + w n2: arcs, and a type-B cancel block.
  bool a_ends_perpendicular = false;
  bool b_starts_perpendicular = false;
  // A change of side, G40 with I J K: where the offset paths meet, else perpendicular to A.
  bool always_intersect = false;
};

enum class CornerKind { Inner, OuterObtuse, OuterAcute, Straight };
// The corner between directions d1 (into P) and d2 (out of P) seen from the tool side w.
CornerKind classify(const Vec2& d1, const Vec2& d2, double w);

// The path around the corner: A at offset wa, B at wb. nullopt: an inner corner whose offset
// curves do not meet (the caller's no-intersection alarm).
std::optional<CornerPath> cornerPath(const Element& a, double wa, const Element& b, double wb,
                                     const CornerRules& rules);

// The tool stops perpendicular to A's end and goes on from there perpendicular to B's start
// (a vector held, too many blocks without motion, FANUC's G41 again).
CornerPath perpendicularPath(const Element& a, double wa, const Element& b, double wb);

}  // namespace ncc::passes::comp
