#pragma once
// Backlash (notes §4.1, MD 32450): the mechanics and the control's compensation, kept apart so
// that a machine with play can be run with and without (or with a mistuned) compensation.
namespace ncc::vm {

// Play of 2 * half mm between the nut and the table, centred. `lag` = nut - table for positive
// play, kept within [-half, +half]: a play operator on the nut's motion `moved` since the last
// cycle. Returns the new lag.
inline double takeUpPlay(double lag, double moved, double half) {
  lag += moved;
  if (lag > half) lag = half;
  if (lag < -half) lag = -half;
  return lag;
}

// The control adds +compensation/2 while the setpoint moves positive and -compensation/2
// while it moves negative: a step of the full value on each reversal. 0 until the first move
// (the direction of approach is not known after reset). `delta`: this cycle's setpoint change;
// 0 keeps the last direction. Returns the new value.
inline double backlashCompensation(double value, double delta, double half) {
  value = delta > 0.0 ? half : value;
  return delta < 0.0 ? -half : value;
}

// One axis's play, for use on its own. Positive play (the normal case, the encoder ahead of
// the table): the table stays put until the nut has taken up the play, then is dragged
// |play|/2 behind it. Negative play mirrors this: the table leads the nut.
class MechanicalPlay {
 public:
  explicit MechanicalPlay(double play = 0.0)
      : half_(0.5 * (play < 0.0 ? -play : play)), sign_(play < 0.0 ? -1.0 : 1.0) {}
  double load(double nut) {
    lag_ = takeUpPlay(lag_, nut - last_nut_, half_);
    last_nut_ = nut;
    return nut - sign_ * lag_;
  }
  void reset(double nut) {
    lag_ = 0.0;
    last_nut_ = nut;
  }

 private:
  double half_;
  double sign_;
  double lag_ = 0.0;
  double last_nut_ = 0.0;
};

}  // namespace ncc::vm
