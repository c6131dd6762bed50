#pragma once
// Cutter radius compensation (G40/G41/G42 with D, G38, G39, the I J K vectors; docs/
// compensation.md): a look-ahead pass between `transform` and `work-to-machine`. Lowering
// records what the controller knows in ir::Block::comp; this pass turns the programmed moves
// into the tool centre's path by the controllers' rules (FANUC 30i §5.4, Mazak §12-4, Siemens
// §3.5) and clears it.
//
// Streaming with a bounded window: the last compensated move is held until the next move in
// the plane arrives (the corner between them decides where it ends); the blocks after it
// (without motion in the plane) are held with it, up to the dialect's limit of such blocks:
// past it the tool stops perpendicular to the held move and they go on (the controller's
// look-ahead has run dry too). The geometry is offset_geometry.h's.
//
// Positions are compared in one frame for the whole program, work + work offset + shift (the
// tool length left out: compensation acts on the tool's tip), so that a change of work offset
// or G92 does not break a corner. Moves in machine space (G28/G30, G53) and a hole cycle's
// moves run on their programmed points: the vector is dropped for them and taken up again by
// the next move (FANUC §5.4 "temporary vector cancel", Mazak "reference return").
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "ncc/ir/ir.h"
#include "ncc/machine/dialect.h"
#include "ncc/passes/dialect_table.h"
#include "ncc/support/diagnostics.h"
#include "offset_geometry.h"

namespace ncc::passes {

class CompensationPass : public ir::BlockSink {
 public:
  // compensate = false: every request is dropped, the programmed path goes on (ncc plot).
  CompensationPass(ir::BlockSink& next, Dialect dialect, DiagnosticEngine& diags,
                   bool compensate = true);
  void accept(ir::Block&& block) override;
  void finish() override;

 private:
  // A block not yet sent on, with the corner moves placed around its operations.
  struct Pending {
    ir::Block block;
    std::vector<std::vector<ir::Operation>> before, after;  // per operation
    std::vector<ir::Operation> tail;                        // after all of them
  };
  struct Ref {
    uint64_t block = 0;  // the number of the block (counted from the first accepted)
    size_t op = 0;
  };
  // The last compensated move: where it ends is decided by the next one.
  struct Open {
    Ref ref;
    comp::Element e;           // programmed, plane coordinates
    AxisValues start{}, end{}; // programmed, every axis
    double w = 0.0;            // signed offset in force at its end
    comp::Vec2 comp_start;     // where its compensated move starts
    bool startup = false;      // the start-up move: it starts without a vector
    std::optional<comp::Vec2> fixed_end;  // G38 / an I J vector: its end point is given
    ir::CutterComp comp;
  };
  enum class State { Off, Starting, On };
  // With interference avoidance on, the move ended before the held one, as it was before: an
  // interference of the held move is then avoided by joining this move with the next directly.
  struct Closed {
    Open a;
    ir::Operation op;                  // its operation before it was ended
    std::vector<ir::Operation> after;  // the moves after it then
    std::vector<Ref> between;          // the moves off the plane placed at its corner
  };

  Pending& at(uint64_t n) { return window_[n - first_]; }
  void process(uint64_t n);
  void admit(uint64_t n, size_t i, const AxisValues& start, const AxisValues& end);
  void join(Open& b);
  void cancel(uint64_t n, size_t i, const AxisValues& start, const AxisValues& end);
  void cancelWithoutMotion(uint64_t n);
  void close(const comp::CornerPath& path, uint64_t connector_block);
  void finishMove(const Open& a, comp::Vec2 end);
  void placeBetween(const comp::CornerPath& path, uint64_t connector_block);
  void spendCorner();
  void stopPerpendicular();
  bool judgePerpendicular(const comp::Vec2& d1, double w, const comp::Vec2& d2, double wb,
                          const ir::Block& at, const std::string& what);
  void placeAt(const Ref& r, const comp::Vec2& p, const ir::CutterComp& c);
  bool checkInterference(const Open& a, const comp::Vec2& end);
  bool interferes(const Open& a, const comp::Vec2& end, std::string* by = nullptr) const;
  bool avoid(Open& c);
  ir::Operation connector(const Open& a, const comp::Connector& c, const ir::Block& in);
  void release(uint64_t before);
  void fail(Alarm alarm, SourceLocation loc, std::string message);
  void reset();

  ir::BlockSink& next_;
  const DialectTable* table_;
  DiagnosticEngine& diags_;
  std::deque<Pending> window_;
  uint64_t first_ = 0;  // the number of window_.front()
  uint64_t count_ = 0;  // blocks accepted
  AxisValues last_{};   // the programmed position (the pass's frame)
  State state_ = State::Off;
  std::optional<Open> open_;
  std::optional<Closed> closed_;  // interference avoidance only
  // More blocks without motion in the plane followed the last move than keep its corner (the
  // controller's look-ahead ran dry): the tool stopped perpendicular to that move (or on an I J
  // vector), the blocks went on, and the next move starts from there.
  struct Stopped {
    comp::Vec2 point;
    comp::Vec2 direction;  // the last move's, at its end
    double w = 0.0;
    int blocks = 0, limit = 0;
    bool judge = true;     // false: an I J vector put it there, as the program said
  };
  std::optional<Stopped> stopped_;
  ir::CutterComp last_comp_;      // the last request seen (its plane, for a block without one)
  std::vector<Ref> between_;      // moves off the plane after open_: placed at the corner
  int without_motion_ = 0;        // blocks without motion in the plane since open_
  std::optional<comp::Vec2> given_vector_;  // I J in a block without motion (FANUC IJ type)
  std::optional<uint64_t> corner_arc_;      // a G39 block since open_
  std::optional<comp::Vec2> corner_arc_vector_;
  std::optional<uint64_t> shift_block_;     // type C: the start-up block without motion
  bool recommanded_ = false;                // G41 again in G41 mode (FANUC): perpendicular
  bool compensate_ = true;
  bool failed_ = false;           // after an alarm every block passes as it is
};

}  // namespace ncc::passes
