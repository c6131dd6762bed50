#include "block_words.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "expr_text.h"

namespace ncc::passes {

namespace {

constexpr double kMaxGCode = 10000.0;  // no G code of any table reaches G10000

// A G word as written: `G05.1` stays `G05.1` (its value alone prints `G5.1`). The literal keeps
// its count of digits, so the leading zeros are the digits its shortest form lacks. (A
// trailing zero, `G5.10`, is shown as a leading one: no control numbers a code that way.)
std::string writtenG(const ast::Expr& e) {
  if (e.kind != ast::Expr::Kind::Number) return absl::StrCat("G", exprText(e));
  std::string s = absl::StrFormat("%.4f", e.number);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  size_t shown = 0;
  for (char c : s) shown += c != '.';
  if (s.size() > 1 && s[0] == '0' && s[1] == '.' && e.digits < shown) {
    s.erase(0, 1);  // written ".5"
    --shown;
  }
  if (e.digits > shown) s.insert(0, e.digits - shown, '0');
  if (e.has_point && s.find('.') == std::string::npos) s += '.';
  return absl::StrCat("G", s);
}

std::string groupLabel(const GCodeEntry& e) {
  return e.group_number < 10 ? absl::StrCat("0", e.group_number) : absl::StrCat(e.group_number);
}

// Addresses of features ncc does not implement yet, with what they are for.
const char* unsupportedAddress(std::string_view a) {
  if (a.size() == 1 && a[0] == 'E') return "precise thread lead";
  if (a.size() == 2 && a[0] == ',' && a[1] == 'A') return "drawing angle";
  return nullptr;
}

bool isG(const ast::Word& w) { return w.address.size() == 1 && w.address[0] == 'G'; }

class Decoder {
 public:
  Decoder(const ast::Block& block, const DecodeContext& ctx, DecodedBlock& out)
      : block_(block), ctx_(ctx), out_(out) {}

  bool run() {
    if (!ctx_.statically)
      for (const ast::Statement& st : block_.statements)
        fail(Alarm::MacroNotSupported, st.loc,
             "macro expressions/statements are not supported yet (macro statement)");
    for (size_t n = 0; n < block_.words.size(); ++n)
      if (isG(block_.words[n])) gWord(block_.words[n], static_cast<int>(n));
    initialDistance();
    for (size_t n = 0; n < block_.words.size(); ++n) {
      const ast::Word& w = block_.words[n];
      if (isG(w)) {
        trackDistance(w);
        continue;
      }
      otherWord(w, static_cast<int>(n));
    }
    return !failed_;
  }

 private:
  void fail(Alarm a, SourceLocation loc, std::string message) {
    ctx_.diags.error(std::string(ctx_.table.alarm(a)), loc, std::move(message));
    failed_ = true;
  }

  bool literal(const ast::Word& w, double& v, bool& point) { return literal(w, w.value, v, point); }
  // `e`: the word's value, or the value inside its IC()/AC().
  bool literal(const ast::Word& w, const ast::Expr& e, double& v, bool& point) {
    if (e.kind == ast::Expr::Kind::Number) {  // nearly every word: a number as written
      v = e.number;
      point = e.has_point;
      return true;
    }
    if (foldLiteral(e, v, point)) return true;
    if (ctx_.statically) return false;  // its value is known at run time
    fail(Alarm::MacroNotSupported, w.loc,
         absl::StrCat("macro expressions/statements are not supported yet: ", w.address.c_str(),
                      exprText(w.value)));
    return false;
  }

  void gWord(const ast::Word& w, int order) {
    double v;
    bool point;
    if (!literal(w, v, point)) return;
    const GCodeEntry* e = nullptr;
    if (v >= 0 && v < kMaxGCode) {  // also keeps lround in range
      int code10 = static_cast<int>(std::lround(v * 10.0));
      if (std::fabs(v * 10.0 - code10) < 1e-6) e = ctx_.table.findG(code10);
    }
    if (!e) {
      fail(Alarm::UnknownGCode, w.loc,
           absl::StrCat(writtenG(w.value), " is not a G code of ",
                        std::string(dialectName(ctx_.table.dialect))));
      return;
    }
    if (e->action == GAction::NotSupported) {
      fail(Alarm::CodeNotSupported, w.loc,
           absl::StrCat(writtenG(w.value), " (", std::string(e->description),
                        ") is not supported yet"));
      return;
    }
    GWord g{e, w.loc, order};
    if (e->action == GAction::ExactStopOneShot) {
      out_.exact_stop = g;
      return;
    }
    if (e->action == GAction::CompVectorHold || e->action == GAction::CompCornerArc) {
      if (out_.comp_special || out_.one_shot) {
        const GWord& other = out_.comp_special ? *out_.comp_special : *out_.one_shot;
        fail(Alarm::OneShotConflict, w.loc,
             absl::StrCat(gCodeName(e->code10), " and ", gCodeName(other.entry->code10),
                          " cannot be given in one block"));
        return;
      }
      out_.comp_special = g;
      return;
    }
    if (e->group == GGroup::OneShot) {
      if (out_.one_shot || out_.comp_special) {
        const GWord& other = out_.one_shot ? *out_.one_shot : *out_.comp_special;
        fail(Alarm::OneShotConflict, w.loc,
             absl::StrCat(gCodeName(e->code10), " and ", gCodeName(other.entry->code10),
                          " cannot be given in one block"));
        return;
      }
      out_.one_shot = g;
      return;
    }
    auto& slot = out_.modal[static_cast<size_t>(e->group)];
    if (slot && slot->entry != e) {
      bool per_word_ok = ctx_.policy == SameGroupPolicy::PerWord && e->group == GGroup::Distance;
      if (ctx_.policy == SameGroupPolicy::Error ||
          (ctx_.policy == SameGroupPolicy::PerWord && !per_word_ok)) {
        fail(Alarm::SameGroupInBlock, w.loc,
             absl::StrCat(gCodeName(e->code10), " and ", gCodeName(slot->entry->code10),
                          " are both group ", groupLabel(*e), " codes; only one may be given in "
                          "a block (same_group_in_block = \"error\")"));
        return;
      }
    }
    slot = g;  // last_wins / per_word: the last written is the block's modal code
  }

  // The G90/G91 a G word selects, looked up in the dialect table (nullopt for other codes).
  std::optional<ir::DistanceMode> distanceOf(const ast::Word& w) const {
    double v;
    bool point;
    if (!isG(w) || !foldLiteral(w.value, v, point) || !(v >= 0 && v < kMaxGCode))
      return std::nullopt;
    const GCodeEntry* e = ctx_.table.findG(static_cast<int>(std::lround(v * 10.0)));
    if (!e || e->group != GGroup::Distance) return std::nullopt;
    return e->action == GAction::Incremental ? ir::DistanceMode::Incremental
                                             : ir::DistanceMode::Absolute;
  }

  // Words before the first G90/G91 of the block follow that first code (the block-level
  // reading); later words follow the most recent one (Mazak's per-word switch).
  void initialDistance() {
    distance_ = ctx_.modal_distance;
    for (const ast::Word& w : block_.words) {
      if (auto d = distanceOf(w)) {
        distance_ = *d;
        break;
      }
    }
    if (ctx_.policy != SameGroupPolicy::PerWord) {
      if (const auto& g = out_.group(GGroup::Distance))
        distance_ = g->entry->action == GAction::Absolute ? ir::DistanceMode::Absolute
                                                          : ir::DistanceMode::Incremental;
    }
  }

  void trackDistance(const ast::Word& w) {
    if (ctx_.policy != SameGroupPolicy::PerWord) return;
    if (auto d = distanceOf(w)) distance_ = *d;
  }

  void store(std::optional<WordValue>& slot, WordValue wv, bool last_wins = false) {
    if (slot && !last_wins) {
      fail(Alarm::AddressRepeated, wv.loc,
           absl::StrCat("address ", std::string(wv.address), " is given twice in the block"));
      return;
    }
    slot = std::move(wv);
  }

  void otherWord(const ast::Word& w, int order) {
    const std::string_view a = w.address;
    const char* what = ctx_.addresses.slot(a) == AddressMap::Slot::Axis ? nullptr : unsupportedAddress(a);
    if (what) {  // a machine axis E is the axis
      fail(Alarm::AddressNotSupported, w.loc,
           absl::StrCat("address ", std::string(a), " (", what, ") is not supported yet"));
      return;
    }
    WordValue wv;
    wv.mode = distance_;
    const ast::Expr* value = &w.value;
    if (w.value.kind == ast::Expr::Kind::Call && w.value.args.size() == 1 &&
        (w.value.op == ast::Op::Ic || w.value.op == ast::Op::Ac)) {
      // DIN `X=IC(5)`: this word incremental (AC: absolute) whatever G90/G91 says
      // (Fundamentals, absolute and incremental dimensions).
      const bool axis = ctx_.addresses.slot(a) == AddressMap::Slot::Axis ||
                        (a.size() > 1 && ctx_.machine.axisIndex(a) >= 0);
      if (!axis) {
        fail(Alarm::AddressNotSupported, w.loc,
             absl::StrCat("address ", std::string(a), "=", ast::opText(w.value.op),
                          "(..) is not supported yet: IC and AC are read on axis positions"));
        return;
      }
      wv.mode = w.value.op == ast::Op::Ic ? ir::DistanceMode::Incremental : ir::DistanceMode::Absolute;
      value = &w.value.args[0];
    }
    if (!literal(w, *value, wv.value, wv.point)) return;
    wv.loc = w.loc;
    wv.address = a;
    wv.order = order;
    const DialectBehaviour& b = ctx_.table.behaviour;
    using Slot = AddressMap::Slot;
    switch (ctx_.addresses.slot(a)) {
      case Slot::Axis: {
        if (!out_.first_axis_loc) out_.first_axis_loc = w.loc;
        return store(out_.axes[ctx_.addresses.axis(a)], std::move(wv));
      }
      case Slot::I: return store(out_.i, std::move(wv));
      case Slot::J: return store(out_.j, std::move(wv));
      case Slot::K: return store(out_.k, std::move(wv));
      case Slot::R: return store(out_.r, std::move(wv));
      case Slot::F: return store(out_.f, std::move(wv));
      case Slot::S: return store(out_.s, std::move(wv));
      case Slot::P: return store(out_.p, std::move(wv));
      case Slot::L: return store(out_.l, std::move(wv));
      case Slot::Q: {
        // Cycle data (lowering_cycles.cpp): only with a hole cycle in force or in the block.
        const auto& cycle = out_.group(GGroup::Cycle);
        if (!ctx_.statically && !ctx_.cycle_in_force &&
            !(cycle && cycle->entry->action == GAction::HoleCycle)) {
          fail(Alarm::AddressWithoutMeaning, w.loc,
               "address Q (canned cycle data) has no meaning outside a hole cycle");
          return;
        }
        return store(out_.q, std::move(wv));
      }
      case Slot::H: return store(out_.h, std::move(wv), b.duplicate_h_d_last_wins);
      case Slot::D: return store(out_.d, std::move(wv), b.duplicate_h_d_last_wins);
      case Slot::M: out_.m.push_back(std::move(wv)); return;
      case Slot::T: {
        if (static_cast<int>(out_.t.size()) >= b.max_t_words) {
          fail(Alarm::AddressRepeated, w.loc,
               absl::StrCat("address T is given more than ", b.max_t_words,
                            b.max_t_words == 1 ? " time" : " times", " in the block"));
          return;
        }
        out_.t.push_back(std::move(wv));
        return;
      }
      case Slot::LineAngle: return store(out_.line_angle, std::move(wv));
      case Slot::Other: break;
    }
    // A machine axis with a longer name (the map holds one-letter names).
    if (const int axis = ctx_.machine.axisIndex(a); axis >= 0 && axis < kMaxAxes) {
      if (!out_.first_axis_loc) out_.first_axis_loc = w.loc;
      return store(out_.axes[axis], std::move(wv));
    }
    // ,C / ,R: one corner per block; of both, the last written is used (Mazak §13-14).
    if (a == ",C" || a == ",R") return store(out_.corner, std::move(wv), a != out_.corner_kind());
    if (const FrameCommand* c = ctx_.table.findFrameCommand(a)) {
      if (out_.frame) {
        fail(Alarm::OneShotConflict, w.loc,
             absl::StrCat(std::string(a), " and ", std::string(out_.frame->name),
                          " cannot be given in one block: one frame instruction per block"));
        return;
      }
      out_.frame = c;
      return;
    }
    if (a == "RPL" && !ctx_.table.frame_commands.empty()) return store(out_.rpl, std::move(wv));
    // A name with another address's meaning (DIN: CR= is R, CHR= ,C ...): looked up only here,
    // for what no slot and no axis took, so the common words never search the list.
    for (const AddressAlias& alias : ctx_.table.address_aliases) {
      if (a != alias.name) continue;
      wv.address = alias.to;
      if (alias.to == "R") return store(out_.r, std::move(wv));
      return store(out_.corner, std::move(wv), alias.to != out_.corner_kind());  // ,C ,R CHF
    }
    if (a.size() == 1 && std::string_view("XYZABCUVW").find(a[0]) != std::string_view::npos) {
      fail(Alarm::AddressNotAnAxis, w.loc,
           absl::StrCat("address ", std::string(a), ": the machine has no axis ", std::string(a)));
      return;
    }
    for (const UnbuiltAddress& u : ctx_.table.unbuilt_addresses)
      if (a == u.name) {
        fail(Alarm::AddressNotSupported, w.loc,
             absl::StrCat("address ", std::string(a), "= (", std::string(u.what), ") is not supported yet"));
        return;
      }
    if (a.size() > 1 && a[0] != ',') {  // DIN: a name (ISO addresses are one letter)
      fail(Alarm::NameNotDefined, w.loc,
           absl::StrCat("'", std::string(a),
                        "' is not defined: no variable (DEF), machine axis or address has that name"));
      return;
    }
    fail(Alarm::AddressNotSupported, w.loc,
         absl::StrCat("address ", std::string(a), " is not supported yet"));
  }

  const ast::Block& block_;
  const DecodeContext& ctx_;
  DecodedBlock& out_;
  ir::DistanceMode distance_ = ir::DistanceMode::Absolute;
  bool failed_ = false;
};

}  // namespace

AddressMap::AddressMap(const DialectTable& table, const MachineConfig& machine) {
  using S = Slot;
  // The named slots, in the order the decoder used to try them: a machine axis comes first
  // (a lathe's or a fifth axis named like a data address takes the letter), then the line
  // angle of dialects that have one.
  constexpr std::pair<char, Slot> kNamed[] = {{'I', S::I}, {'J', S::J}, {'K', S::K}, {'R', S::R},
                                              {'F', S::F}, {'S', S::S}, {'P', S::P}, {'L', S::L},
                                              {'Q', S::Q}, {'H', S::H}, {'D', S::D}, {'M', S::M},
                                              {'T', S::T}};
  axes_.fill(-1);
  const std::string_view other = table.behaviour.other_meaning_addresses;
  for (const auto& [letter, slot] : kNamed)
    if (other.find(letter) == std::string_view::npos) slots_[static_cast<size_t>(letter - 'A')] = slot;
  const std::string_view angle = table.behaviour.line_angle_address;
  if (angle.size() == 1 && angle[0] >= 'A' && angle[0] <= 'Z') {
    const size_t i = static_cast<size_t>(angle[0] - 'A');
    if (slots_[i] == S::Other) slots_[i] = S::LineAngle;
  }
  for (char letter = 'A'; letter <= 'Z'; ++letter) {
    const int axis = machine.axisIndex(std::string_view(&letter, 1));
    if (axis < 0 || axis >= kMaxAxes) continue;
    slots_[static_cast<size_t>(letter - 'A')] = S::Axis;
    axes_[static_cast<size_t>(letter - 'A')] = static_cast<int8_t>(axis);
  }
}

bool decodeBlock(const ast::Block& block, const DecodeContext& ctx, DecodedBlock& out) {
  return Decoder(block, ctx, out).run();
}

std::optional<DecodedBlock> decodeBlock(const ast::Block& block, const DecodeContext& ctx) {
  DecodedBlock out;
  if (!decodeBlock(block, ctx, out)) return std::nullopt;
  return out;
}

}  // namespace ncc::passes
