#pragma once
// The arithmetic of ir::Affine, the map of programmed points that coordinate rotation, scaling,
// mirror and figure rotation make (docs/transforms.md). The lowering builds and composes them
// (lowering_transforms.cpp); the transform pass applies them (transform_pass.cpp). Slots 0, 1, 2
// are X, Y, Z; Affine::axes maps them to machine axis indices.
#include <array>
#include <optional>

#include "ncc/ir/ir.h"

namespace ncc::passes {

using Vec3 = std::array<double, 3>;

// The identity on the given machine indices of X, Y, Z (-1: the machine has no such axis).
ir::Affine identityAffine(const std::array<int8_t, 3>& axes);
bool isIdentity(const ir::Affine& a);
// `outer` after `inner`: p -> outer(inner(p)).
ir::Affine compose(const ir::Affine& outer, const ir::Affine& inner);
std::optional<ir::Affine> inverse(const ir::Affine& a);

// A rotation by `degrees` (counterclockwise seen from the tip of `axis`) about the line through
// `centre` along `axis` (not normalised; a zero axis is the caller's error).
ir::Affine rotation(const std::array<int8_t, 3>& axes, const Vec3& centre, const Vec3& axis,
                    double degrees);
// Per-slot factors about `centre` (a negative factor mirrors).
ir::Affine scaling(const std::array<int8_t, 3>& axes, const Vec3& centre, const Vec3& factors);

Vec3 slots(const ir::Affine& a, const AxisValues& v);  // the X, Y, Z components of v
Vec3 applyPoint(const ir::Affine& a, const Vec3& p);
// Maps the X, Y, Z components of a machine-indexed point; the other axes stay.
void applyPoint(const ir::Affine& a, AxisValues& v);

// The whole map of a block's transforms in work space, `frame_total` its frame (Frame::total):
// G92.5 turns about a machine point, i.e. shift by the frame, turn, shift back.
ir::Affine workSpaceMap(const ir::Transform& t, const AxisValues& frame_total);
// The same map acting on machine coordinates: p -> workSpaceMap(p - frame) + frame.
ir::Affine machineSpaceMap(const ir::Transform& t, const AxisValues& frame_total);
// The distance of two machine-indexed points in `plane` (its two axes among a's X, Y, Z).
double planeDistance(const ir::Affine& a, ir::Plane plane, const AxisValues& p,
                     const AxisValues& q);

// Where an arc in `plane` goes under `a`: its new plane and direction, or nullopt when the image
// is no circle in a principal plane (unequal scaling in the plane, a 3-D rotation tilting it) or
// a helix would turn oblique (`helical`: the arc also moves along the plane's normal).
struct ArcImage {
  ir::Plane plane;
  bool clockwise;
};
// `similarity`: also nullopt when the plane is not mapped by a similarity (its circle would
// become an ellipse); without it the image of the end point and centre is what the caller uses.
std::optional<ArcImage> arcImage(const ir::Affine& a, ir::Plane plane, bool clockwise,
                                 bool helical, bool similarity = false);

// The slots (0 X, 1 Y, 2 Z) of a plane: first axis, second axis, normal.
std::array<int, 3> planeSlots(ir::Plane plane);

}  // namespace ncc::passes
