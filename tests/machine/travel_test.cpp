// Stored stroke limits (ncc/machine/travel.h): end points, arc extents (quadrant points,
// spirals, helix axes, many turns) and the alarm numbers per dialect.
#include "ncc/machine/travel.h"

#include <cmath>

#include "gtest/gtest.h"

namespace ncc {
namespace {

AxisValues xyz(double x, double y, double z) {
  AxisValues v{};
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

MachineConfig limited(double x_min, double x_max, double y_min, double y_max) {
  MachineConfig m = defaultMachine();
  m.axes[0].min_travel = x_min;
  m.axes[0].max_travel = x_max;
  m.axes[1].min_travel = y_min;
  m.axes[1].max_travel = y_max;
  return m;
}

TEST(Travel, EndPointWithinAndBeyond) {
  const MachineConfig m = limited(-10, 10, -20, 20);
  EXPECT_FALSE(travelViolation(m.axes, xyz(10, -20, 1e8)));
  const std::optional<TravelViolation> plus = travelViolation(m.axes, xyz(50, 0, 0));
  ASSERT_TRUE(plus);
  EXPECT_EQ(plus->axis, 0);
  EXPECT_TRUE(plus->above);
  EXPECT_EQ(plus->position, 50.0);
  EXPECT_EQ(plus->limit, 10.0);
  const std::optional<TravelViolation> minus = travelViolation(m.axes, xyz(0, -20.5, 0));
  ASSERT_TRUE(minus);
  EXPECT_EQ(minus->axis, 1);
  EXPECT_FALSE(minus->above);
  EXPECT_EQ(minus->limit, -20.0);
  // Rounding of an end point computed through offsets is not an overtravel; NaN is.
  EXPECT_FALSE(travelViolation(m.axes, xyz(10.0 + 1e-9, 0, 0)));
  EXPECT_TRUE(travelViolation(m.axes, xyz(std::nan(""), 0, 0)));
}

TEST(Travel, HalfCircleBulgesBeyondWhileItsEndsAreInside) {
  const MachineConfig m = limited(-100, 100, -4, 20);
  // G03 from (-5, 0) to (5, 0) around the origin: through the bottom, Y -5.
  ArcMove ccw{xyz(-5, 0, 0), xyz(5, 0, 0), 0, 1, 0.0, 0.0, false, 0};
  const AxisBox box = arcExtent(ccw, 3);
  EXPECT_DOUBLE_EQ(box.low[1], -5.0);
  EXPECT_DOUBLE_EQ(box.high[1], 0.0);
  EXPECT_DOUBLE_EQ(box.low[0], -5.0);
  EXPECT_DOUBLE_EQ(box.high[0], 5.0);
  const std::optional<TravelViolation> v = arcTravelViolation(m.axes, ccw);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->axis, 1);
  EXPECT_FALSE(v->above);
  EXPECT_DOUBLE_EQ(v->position, -5.0);
  // G02 goes through the top: within.
  ArcMove cw = ccw;
  cw.cw = true;
  EXPECT_DOUBLE_EQ(arcExtent(cw, 3).high[1], 5.0);
  EXPECT_FALSE(arcTravelViolation(m.axes, cw));
}

TEST(Travel, FullCircleAndQuarter) {
  // Start = end: a full turn, every quadrant point.
  ArcMove full{xyz(10, 0, 0), xyz(10, 0, 0), 0, 1, 0.0, 0.0, false, 0};
  const AxisBox box = arcExtent(full, 3);
  EXPECT_DOUBLE_EQ(box.low[0], -10.0);
  EXPECT_DOUBLE_EQ(box.high[0], 10.0);
  EXPECT_DOUBLE_EQ(box.low[1], -10.0);
  EXPECT_DOUBLE_EQ(box.high[1], 10.0);
  EXPECT_NEAR(arcSweep(full), 2.0 * M_PI, 1e-12);
  // A quarter from 0 to 90 degrees passes no quadrant point inside it: the ends only.
  ArcMove quarter{xyz(10, 0, 0), xyz(0, 10, 0), 0, 1, 0.0, 0.0, false, 0};
  const AxisBox q = arcExtent(quarter, 3);
  EXPECT_DOUBLE_EQ(q.low[0], 0.0);
  EXPECT_DOUBLE_EQ(q.high[0], 10.0);
  EXPECT_DOUBLE_EQ(q.low[1], 0.0);
  EXPECT_DOUBLE_EQ(q.high[1], 10.0);
}

TEST(Travel, SpiralTakesTheRadiusAtEachQuadrantPoint) {
  // From radius 10 at 0 degrees counter-clockwise to radius 20 at 180 degrees: at 90 degrees
  // the radius is 15 (linear in the angle, as the VM's spiral).
  ArcMove spiral{xyz(10, 0, 0), xyz(-20, 0, 0), 0, 1, 0.0, 0.0, false, 0};
  const AxisBox box = arcExtent(spiral, 3);
  EXPECT_DOUBLE_EQ(box.high[1], 15.0);
  EXPECT_DOUBLE_EQ(box.low[1], 0.0);
  EXPECT_DOUBLE_EQ(box.low[0], -20.0);
}

TEST(Travel, HelixAxisAndManyTurnsInConstantTime) {
  const MachineConfig m = limited(-100, 100, -100, 100);
  ArcMove helix{xyz(10, 0, 0), xyz(10, 0, -50), 0, 1, 0.0, 0.0, true, 1'000'000};
  const AxisBox box = arcExtent(helix, 3);
  EXPECT_DOUBLE_EQ(box.low[2], -50.0);
  EXPECT_DOUBLE_EQ(box.high[2], 0.0);
  EXPECT_DOUBLE_EQ(box.low[1], -10.0);
  EXPECT_NEAR(arcSweep(helix), -2.0 * M_PI * 1'000'001, 1e-3);
  EXPECT_FALSE(arcTravelViolation(m.axes, helix));
  // The helix axis leaving its range is found too.
  MachineConfig z = m;
  z.axes[2].min_travel = -40.0;
  const std::optional<TravelViolation> v = arcTravelViolation(z.axes, helix);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->axis, 2);
}

TEST(Travel, ArcsInOtherPlanes) {
  // G18 (ZX): axis1 = Z, axis2 = X; a half circle from Z5 to Z-5 around Z0 X0, counter-
  // clockwise in (Z, X), passes X = 5 (90 degrees: the high side of axis2).
  ArcMove zx{xyz(0, 0, 5), xyz(0, 0, -5), 2, 0, 0.0, 0.0, false, 0};
  const AxisBox box = arcExtent(zx, 3);
  EXPECT_DOUBLE_EQ(box.high[0], 5.0);
  EXPECT_DOUBLE_EQ(box.low[0], 0.0);
}

TEST(Travel, AlarmNumbersAreTheDialects) {
  EXPECT_EQ(travelAlarmCodes(Dialect::FanucM).plus, "OT0500");
  EXPECT_EQ(travelAlarmCodes(Dialect::FanucM).minus, "OT0501");
  EXPECT_EQ(travelAlarmCodes(Dialect::FanucT).minus, "OT0501");
  EXPECT_EQ(travelAlarmCodes(Dialect::SiemensIsoM).plus, "10720");
  EXPECT_EQ(travelAlarmCodes(Dialect::SiemensDin).minus, "10720");
  EXPECT_EQ(travelAlarmCodes(Dialect::MazakM).plus, "NCC7210");
}

}  // namespace
}  // namespace ncc
