#include "affine.h"

#include <cmath>
#include <numbers>

#include <Eigen/Dense>

namespace ncc::passes {

namespace {

using M3 = Eigen::Matrix3d;
using V3 = Eigen::Vector3d;

M3 matrix(const ir::Affine& a) {
  M3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = a.m[3 * r + c];
  return m;
}

ir::Affine fromEigen(const std::array<int8_t, 3>& axes, const M3& m, const V3& t) {
  ir::Affine a;
  a.axes = axes;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) a.m[3 * r + c] = m(r, c);
    a.t[r] = t(r);
  }
  return a;
}

V3 vec(const Vec3& v) { return V3(v[0], v[1], v[2]); }

// An affine map about `centre`: p -> m (p - c) + c.
ir::Affine about(const std::array<int8_t, 3>& axes, const M3& m, const Vec3& centre) {
  const V3 c = vec(centre);
  return fromEigen(axes, m, c - m * c);
}

constexpr double kExact = 1e-12;

}  // namespace

ir::Affine identityAffine(const std::array<int8_t, 3>& axes) {
  ir::Affine a;
  a.axes = axes;
  return a;
}

bool isIdentity(const ir::Affine& a) {
  static const ir::Affine id;
  for (int i = 0; i < 9; ++i)
    if (std::fabs(a.m[i] - id.m[i]) > kExact) return false;
  for (double t : a.t)
    if (std::fabs(t) > kExact) return false;
  return true;
}

ir::Affine compose(const ir::Affine& outer, const ir::Affine& inner) {
  const M3 mo = matrix(outer), mi = matrix(inner);
  const V3 to = vec(outer.t), ti = vec(inner.t);
  return fromEigen(outer.axes, mo * mi, mo * ti + to);
}

std::optional<ir::Affine> inverse(const ir::Affine& a) {
  const M3 m = matrix(a);
  if (std::fabs(m.determinant()) < 1e-12) return std::nullopt;
  const M3 inv = m.inverse();
  return fromEigen(a.axes, inv, -(inv * vec(a.t)));
}

ir::Affine rotation(const std::array<int8_t, 3>& axes, const Vec3& centre, const Vec3& axis,
                    double degrees) {
  const double rad = degrees * std::numbers::pi / 180.0;
  M3 m = Eigen::AngleAxisd(rad, vec(axis).normalized()).toRotationMatrix();
  // Exact quarter turns: cos 90 is 6e-17, which would print as a tiny move on the other axis.
  for (int i = 0; i < 9; ++i) {
    double& v = m.data()[i];
    const double r = std::round(v);
    if (std::fabs(v - r) < 1e-15) v = r;
  }
  return about(axes, m, centre);
}

ir::Affine scaling(const std::array<int8_t, 3>& axes, const Vec3& centre, const Vec3& factors) {
  return about(axes, vec(factors).asDiagonal().toDenseMatrix(), centre);
}

Vec3 slots(const ir::Affine& a, const AxisValues& v) {
  Vec3 p{};
  for (int s = 0; s < 3; ++s)
    if (a.axes[s] >= 0 && a.axes[s] < kMaxAxes) p[s] = v[a.axes[s]];
  return p;
}

Vec3 applyPoint(const ir::Affine& a, const Vec3& p) {
  const V3 q = matrix(a) * vec(p) + vec(a.t);
  return {q(0), q(1), q(2)};
}

void applyPoint(const ir::Affine& a, AxisValues& v) {
  const Vec3 q = applyPoint(a, slots(a, v));
  for (int s = 0; s < 3; ++s)
    if (a.axes[s] >= 0 && a.axes[s] < kMaxAxes) v[a.axes[s]] = q[s];
}

namespace {

// `map` seen from coordinates shifted by `o` (on the slots): p -> map(p + o) - o.
ir::Affine conjugated(const ir::Affine& map, const Vec3& o) {
  ir::Affine shift = identityAffine(map.axes), back = identityAffine(map.axes);
  shift.t = o;
  back.t = {-o[0], -o[1], -o[2]};
  return compose(back, compose(map, shift));
}

Vec3 negated(const Vec3& v) { return {-v[0], -v[1], -v[2]}; }

}  // namespace

ir::Affine workSpaceMap(const ir::Transform& t, const AxisValues& frame_total) {
  const std::array<int8_t, 3> axes = t.work ? t.work->axes : t.machine ? t.machine->axes
                                                                       : std::array<int8_t, 3>{0, 1, 2};
  ir::Affine map = t.work ? *t.work : identityAffine(axes);
  if (t.machine) map = compose(conjugated(*t.machine, slots(*t.machine, frame_total)), map);
  return map;
}

ir::Affine machineSpaceMap(const ir::Transform& t, const AxisValues& frame_total) {
  const ir::Affine work = workSpaceMap(t, frame_total);
  return conjugated(work, negated(slots(work, frame_total)));
}

double planeDistance(const ir::Affine& a, ir::Plane plane, const AxisValues& p,
                     const AxisValues& q) {
  const auto sl = planeSlots(plane);
  const int i = a.axes[sl[0]], j = a.axes[sl[1]];
  if (i < 0 || j < 0) return 0.0;
  return std::hypot(p[i] - q[i], p[j] - q[j]);
}

std::array<int, 3> planeSlots(ir::Plane plane) {
  switch (plane) {
    case ir::Plane::XY: return {0, 1, 2};
    case ir::Plane::ZX: return {2, 0, 1};
    case ir::Plane::YZ: return {1, 2, 0};
  }
  return {0, 1, 2};
}

std::optional<ArcImage> arcImage(const ir::Affine& a, ir::Plane plane, bool clockwise,
                                 bool helical, bool similarity) {
  const M3 m = matrix(a);
  const auto [sa, sb, sn] = planeSlots(plane);
  const V3 ea = m.col(sa), eb = m.col(sb);
  const double la = ea.norm(), lb = eb.norm();
  if (la < 1e-12 || lb < 1e-12) return std::nullopt;
  // A circle stays a circle only under a similarity of its plane: equal lengths, right angle.
  if (similarity && (std::fabs(la - lb) > 1e-9 * std::max(1.0, la) ||
                     std::fabs(ea.dot(eb)) > 1e-9 * la * lb))
    return std::nullopt;
  if (ea.cross(eb).norm() < 1e-12) return std::nullopt;
  const V3 normal = ea.cross(eb).normalized();
  int axis = -1;
  for (int s = 0; s < 3; ++s)
    if (std::fabs(std::fabs(normal(s)) - 1.0) < 1e-9) axis = s;
  if (axis < 0) return std::nullopt;  // tilted out of every principal plane
  if (helical) {  // the helix axis must stay normal to the image plane
    const V3 en = m.col(sn);
    if (en.norm() < 1e-12 || std::fabs(std::fabs(en.normalized()(axis)) - 1.0) > 1e-9)
      return std::nullopt;
  }
  const ir::Plane image = axis == 2 ? ir::Plane::XY : axis == 1 ? ir::Plane::ZX : ir::Plane::YZ;
  // Clockwise seen from +normal of the image plane: kept when the mapped plane's orientation
  // agrees with the image plane's, reversed when it is mirrored.
  const bool same = normal(axis) > 0;
  return ArcImage{image, same ? clockwise : !clockwise};
}

}  // namespace ncc::passes
