#pragma once
// Backlash (notes §4.1, MD 32450): the mechanics and the control's compensation, kept apart so
// that a machine with play can be run with and without (or with a mistuned) compensation.
namespace ncc::vm {

// Play of `play` mm between the nut and the table, centred. Positive play (the normal case,
// the encoder ahead of the table): the table stays put until the nut has taken up the play,
// then is dragged |play|/2 behind it. Negative play mirrors this: the table leads the nut.
class MechanicalPlay {
 public:
  explicit MechanicalPlay(double play = 0.0)
      : half_(0.5 * (play < 0.0 ? -play : play)), sign_(play < 0.0 ? -1.0 : 1.0) {}
  double load(double nut) {
    // lag_ = nut - table for positive play, kept within [-half, +half] (a play operator
    // on the nut's motion since the last step).
    const double moved = nut - last_nut_;
    last_nut_ = nut;
    lag_ += moved;
    if (lag_ > half_) lag_ = half_;
    if (lag_ < -half_) lag_ = -half_;
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

// The control adds +compensation/2 while the setpoint moves positive and -compensation/2
// while it moves negative: a step of the full value on each reversal. 0 until the first move
// (the direction of approach is not known after reset).
class BacklashCompensation {
 public:
  explicit BacklashCompensation(double compensation = 0.0) : half_(0.5 * compensation) {}
  void reset() { value_ = 0.0; }
  // `delta`: this tick's setpoint change; 0 keeps the last direction.
  double update(double delta) {
    if (delta > 0.0) value_ = half_;
    if (delta < 0.0) value_ = -half_;
    return value_;
  }

 private:
  double half_;
  double value_ = 0.0;
};

}  // namespace ncc::vm
