// Calls and returns: M98 (subprogram), M99 (return, repeat, restart), G65 (macro call),
// G66/G66.1 (modal macro calls) and G67. A call opens a frame on the stack of programs; a
// macro call also opens a level of locals holding its arguments.
#include <charconv>
#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"
#include "evaluator_impl.h"

namespace ncc::eval {

namespace {

// The call codes, numbered alike by FANUC, Mazak and Sinumerik ISO mode.
enum class CallCode : uint8_t { None, M98, M99, G65, G66, G661, G67 };

CallCode callCode(const ast::Word& w) {
  // The address first: most words are axis words, and a literal is not free to tell.
  if (w.address.size() != 1 || (w.address[0] != 'M' && w.address[0] != 'G') ||
      !isLiteral(w.value))
    return CallCode::None;
  const double v = literalValue(w.value);
  if (w.address[0] == 'M') return v == 98 ? CallCode::M98 : v == 99 ? CallCode::M99 : CallCode::None;
  if (v == 65) return CallCode::G65;
  if (v == 66) return CallCode::G66;
  if (std::abs(v - 66.1) < 1e-9) return CallCode::G661;
  if (v == 67) return CallCode::G67;
  return CallCode::None;
}

const char* callName(CallCode c) {
  switch (c) {
    case CallCode::M98: return "M98";
    case CallCode::M99: return "M99";
    case CallCode::G65: return "G65";
    case CallCode::G66: return "G66";
    case CallCode::G661: return "G66.1";
    case CallCode::G67: return "G67";
    case CallCode::None: break;
  }
  return "";
}

// Takes the word with this address out of `words`.
std::optional<ast::Word> take(std::vector<ast::Word>& words, char address) {
  for (size_t i = 0; i < words.size(); ++i)
    if (words[i].address.size() == 1 && words[i].address[0] == address) {
      ast::Word w = std::move(words[i]);
      words.erase(words.begin() + static_cast<std::ptrdiff_t>(i));
      return w;
    }
  return std::nullopt;
}

Pending macroCall(int64_t program, int64_t repeats, Variables::Locals arguments,
                  SourceLocation loc, const ProgramPoint& at) {
  Pending p;
  p.kind = Pending::Kind::Call;
  p.program = program;
  p.repeats = repeats;
  p.macro = true;
  p.arguments = std::move(arguments);
  p.loc = loc;
  p.at = at;
  return p;
}

// "M6", "G100": the code a word is, as the machine file names code macros.
std::string codeName(const ast::Word& w) {
  if (w.address.size() != 1 || !isLiteral(w.value)) return {};
  const double v = literalValue(w.value);
  if (v < 0 || v != std::floor(v) || v > 99999999) return {};
  return absl::StrCat(w.address.c_str(), static_cast<int64_t>(v));
}

}  // namespace

bool Evaluator::mayTakeArguments(const ast::Block& block) const {
  if (block.language == frontend::Language::Din) {
    // A call by name or by L: the block's P is its repeat count (din.cpp).
    for (const ast::Statement& st : block.statements)
      if (st.kind == ast::Statement::Kind::Call) return true;
    for (const ast::Word& w : block.words)
      if (w.address.is('L')) return true;
  }
  for (const ast::Word& w : block.words)
    if (impl_->isCallWord(w) || (w.address == "G" && !isLiteral(w.value))) return true;
  return false;
}

bool Evaluator::mayStartModalCall(const ast::Block& block) const {
  for (const ast::Word& w : block.words) {
    if (w.address != "G") continue;
    const CallCode c = callCode(w);
    if (c == CallCode::G66 || c == CallCode::G661 || !isLiteral(w.value)) return true;
  }
  return false;
}

bool Evaluator::modalCallInForce() const { return !impl_->modal_calls.empty(); }

bool Evaluator::Impl::isCallWord(const ast::Word& w) const {
  if (callCode(w) != CallCode::None) return true;
  if (options.code_macros.empty() || (w.address != "M" && w.address != "G")) return false;
  return options.code_macros.count(codeName(w)) > 0;
}

bool Evaluator::Impl::codeMacro(ast::Block& block, const ProgramPoint& at, bool& consumed) {
  for (size_t i = 0; i < block.words.size(); ++i) {
    const ast::Word& w = block.words[i];
    if (w.address != "M" && w.address != "G") continue;
    const std::string code = codeName(w);
    auto it = options.code_macros.find(code);
    if (it == options.code_macros.end()) continue;
    // Inside its own macro the code is the plain code (Mazak §13-9-2, Sinumerik §3.6.4).
    bool inside = false;
    for (const Frame& f : frames) inside = inside || f.code == code;
    if (inside) continue;
    const SourceLocation loc = w.loc;
    block.words.erase(block.words.begin() + static_cast<std::ptrdiff_t>(i));
    std::optional<Variables::Locals> args = arguments(block.words, false);
    if (!args) return false;
    Pending p = macroCall(0, 1, std::move(*args), loc, at);
    int64_t number = 0;
    const std::string& target = it->second;
    auto [end, ec] = std::from_chars(target.data(), target.data() + target.size(), number);
    if (ec == std::errc() && end == target.data() + target.size())
      p.program = number;
    else
      p.name = target;
    p.code = code;
    pending.push_back(std::move(p));
    consumed = true;
    return true;
  }
  return true;
}

std::optional<Variables::Locals> Evaluator::Impl::arguments(const std::vector<ast::Word>& words,
                                                            bool every_block) {
  Variables::Locals locals = variables.freshLocals();
  // Specification II: I J K repeat in groups (#4-#6, #7-#9, ... #31-#33); a letter that does
  // not come after the previous one of its group starts the next group. Specification I's
  // I J K are the first group, so one walk serves both; where they overlap (D and the second
  // I are both #7) the last value written wins, as the manual states.
  int group = 0;
  int last_ijk = -1;
  for (const ast::Word& w : words) {
    const char a = w.address.size() == 1 ? w.address[0] : 0;
    int number = 0;
    if (a == 'I' || a == 'J' || a == 'K') {
      const int index = a - 'I';
      if (index <= last_ijk) ++group;
      last_ijk = index;
      if (group > 9) {
        fail(EvalError::AddressValue, w.loc, "more than 10 groups of I J K arguments");
        return std::nullopt;
      }
      number = 4 + 3 * group + index;
    } else if (a >= 'A' && a <= 'Z') {
      number = rules.argument_spec1[static_cast<size_t>(a - 'A')];
      // G66.1 passes every word of the block: G, L, N, P as #10, #12, #14, #16.
      if (number == 0 && every_block) number = a == 'G' ? 10 : a == 'L' ? 12 : a == 'N' ? 14 : a == 'P' ? 16 : 0;
    }
    if (number == 0 || number > rules.local_count) {
      fail(EvalError::AddressValue, w.loc,
           absl::StrCat("address ", w.address.c_str(), " is not an argument of a macro call"));
      return std::nullopt;
    }
    const double v = options.argument_value ? options.argument_value(w) : literalValue(w.value);
    locals[static_cast<size_t>(number)] = Value::of(v);
  }
  return locals;
}

bool Evaluator::Impl::callWords(ast::Block& block, const ProgramPoint& at, bool& consumed) {
  // G66.1: every block is a macro call with its words as the arguments.
  if (!modal_calls.empty() && modal_calls.back().every_block &&
      frames.size() <= modal_calls.back().depth && !block.words.empty()) {
    bool cancels = false;
    for (const ast::Word& w : block.words) cancels = cancels || callCode(w) == CallCode::G67;
    if (!cancels) {
      const ModalCall& mc = modal_calls.back();
      std::optional<Variables::Locals> args = arguments(block.words, /*every_block=*/true);
      if (!args) return false;
      pending.push_back(macroCall(mc.program, mc.repeats, std::move(*args), block.loc, at));
      consumed = true;
      return true;
    }
  }

  if (!options.code_macros.empty()) {
    if (!codeMacro(block, at, consumed)) return false;
    if (consumed) return true;
  }
  CallCode code = CallCode::None;
  SourceLocation code_loc;
  for (size_t i = 0; i < block.words.size(); ++i) {
    CallCode c = callCode(block.words[i]);
    if (c == CallCode::None) continue;
    if (code != CallCode::None) {
      fail(EvalError::AddressValue, block.words[i].loc,
           absl::StrCat(callName(c), " and ", callName(code), " in one block"));
      return false;
    }
    code = c;
    code_loc = block.words[i].loc;
    block.words.erase(block.words.begin() + static_cast<std::ptrdiff_t>(i));
    --i;
  }
  if (code == CallCode::None) return true;

  auto integerWord = [&](const std::optional<ast::Word>& w, const char* what) -> std::optional<int64_t> {
    return integerOf(w->value, w->loc, what);
  };

  switch (code) {
    case CallCode::G67:
      if (modal_calls.empty()) {
        fail(EvalError::ModalCallCancel, code_loc, "G67 without a modal macro call (G66) in force");
        return false;
      }
      modal_calls.pop_back();
      return true;
    case CallCode::G65:
    case CallCode::G66:
    case CallCode::G661: {
      std::optional<ast::Word> p = take(block.words, 'P');
      if (!p) {
        fail(EvalError::ProgramNotFound, code_loc,
             absl::StrCat(callName(code), " needs P, the number of the macro program"));
        return false;
      }
      std::optional<int64_t> program = integerWord(p, "P (the program number)");
      if (!program) return false;
      int64_t repeats = 1;
      if (std::optional<ast::Word> l = take(block.words, 'L')) {
        std::optional<int64_t> n = integerWord(l, "L (the repeat count)");
        if (!n) return false;
        repeats = *n;
      }
      std::optional<Variables::Locals> args = arguments(block.words, false);
      if (!args) return false;
      consumed = true;
      if (code == CallCode::G65) {
        pending.push_back(macroCall(*program, repeats, std::move(*args), code_loc, at));
      } else {
        ModalCall& mc = modal_calls.emplace_back();
        mc.program = *program;
        mc.arguments = std::move(*args);
        mc.repeats = repeats;
        mc.every_block = code == CallCode::G661;
        mc.depth = frames.size();
        mc.loc = code_loc;
      }
      return true;
    }
    case CallCode::M98: {
      std::optional<ast::Word> p = take(block.words, 'P');
      std::optional<ast::Word> h = take(block.words, 'H');
      std::optional<ast::Word> l = take(block.words, 'L');
      if (!p && !h) {
        fail(EvalError::ProgramNotFound, code_loc, "M98 needs P (a program) or H (a sequence number)");
        return false;
      }
      Pending call;
      call.kind = Pending::Kind::Call;
      call.loc = code_loc;
      call.at = at;
      if (p) {
        std::optional<int64_t> number = integerWord(p, "P (the program number)");
        if (!number) return false;
        call.program = *number;
        if (options.repeat == RepeatEncoding::HighDigitsOfP) {
          int64_t scale = 1;
          for (int i = 0; i < rules.program_number_digits; ++i) scale *= 10;
          if (*number >= scale) {
            call.program = *number % scale;
            call.repeats = *number / scale;
          }
        }
      }
      if (h) {
        std::optional<int64_t> n = integerWord(h, "H (the sequence number)");
        if (!n) return false;
        call.sequence = *n;
        call.local = !p;
      }
      if (l) {
        std::optional<int64_t> n = integerWord(l, "L (the repeat count)");
        if (!n) return false;
        call.repeats = *n;
      }
      // Mazak figure rotation (§13-7: M98 P H I J K L turns each repeat about start + I J K;
      // "when L is 1 or less, the figure is not rotated").
      std::array<std::optional<double>, 3> ijk;
      bool any_ijk = false;
      for (const char a : {'I', 'J', 'K'}) {
        std::optional<ast::Word> w = take(block.words, a);
        if (!w) continue;
        if (!rules.figure_rotation || !options.figure_rotation.begin) {
          fail(EvalError::AddressValue, w->loc,
               absl::StrCat("address ", w->address.c_str(), " has no meaning in M98"));
          return false;
        }
        ijk[static_cast<size_t>(a - 'I')] =
            options.argument_value ? options.argument_value(*w) : literalValue(w->value);
        any_ijk = true;
      }
      if (any_ijk && call.repeats > 1) call.figure = ijk;
      if (call.repeats < 0) {
        fail(EvalError::AddressValue, l ? l->loc : code_loc, "a negative repeat count");
        return false;
      }
      pending.push_back(std::move(call));
      return true;
    }
    case CallCode::M99: {
      Pending r;
      r.kind = Pending::Kind::Return;
      r.loc = code_loc;
      r.at = at;
      if (std::optional<ast::Word> p = take(block.words, 'P')) {
        std::optional<int64_t> n = integerWord(p, "P (the sequence number to return to)");
        if (!n) return false;
        r.sequence = *n;
      }
      if (std::optional<ast::Word> l = take(block.words, 'L')) {
        fail(EvalError::AddressValue, l->loc, "M99 L (changing the repeat count) is not supported");
        return false;
      }
      pending.push_back(std::move(r));
      return true;
    }
    case CallCode::None: break;
  }
  return true;
}

void Evaluator::Impl::modalCallAfter(const ast::Block& block, const ProgramPoint& at) {
  if (modal_calls.empty() || !options.is_axis) return;
  const ModalCall& mc = modal_calls.back();
  if (mc.every_block || frames.size() > mc.depth) return;
  bool moves = false;
  for (const ast::Word& w : block.words) moves = moves || options.is_axis(w.address);
  if (!moves) return;
  if (mc.din) {  // MCALL (din.cpp): in its own program level only
    if (frames.size() != mc.depth) return;
    Pending p;
    p.kind = Pending::Kind::Call;
    p.din = true;
    p.name = mc.name;
    p.din_arguments = mc.din_arguments;
    p.loc = mc.loc;
    p.at = at;
    pending.push_back(std::move(p));
    return;
  }
  pending.push_back(macroCall(mc.program, mc.repeats, mc.arguments, mc.loc, at));
}

bool Evaluator::Impl::perform(const Pending& p) {
  return p.kind == Pending::Kind::Return ? ret(p) : call(p);
}

bool Evaluator::Impl::call(const Pending& p) {
  if (p.repeats == 0) return true;  // L0: the call is not made
  const int calls = static_cast<int>(frames.size()) - 1;
  const int limit = p.din ? rules.max_named_call_nesting : rules.max_call_nesting;
  if (calls >= limit) {
    fail(EvalError::CallNesting, p.loc, absl::StrCat("calls nested more than ", limit, " deep"));
    return false;
  }
  if (p.macro) {
    int macros = 0;
    for (const Frame& f : frames) macros += f.macro ? 1 : 0;
    if (macros >= rules.max_macro_nesting) {
      fail(EvalError::MacroNesting, p.loc,
           absl::StrCat("macro calls nested more than ", rules.max_macro_nesting, " deep"));
      return false;
    }
  }
  Frame& caller = frames.back();
  Frame f;
  if (p.local) {
    // M98 H: a sequence of the calling program, run until its M99.
    const ProgramPoint end_point = programEnd(caller);
    std::optional<ProgramPoint> target = store.findSequence(
        *p.sequence, caller.begin, SequenceSearch::FromStart, caller.begin, end_point);
    if (!target) {
      fail(EvalError::GotoTarget, p.loc,
           absl::StrCat("M98 H", *p.sequence, ": no block starts with N", *p.sequence,
                        " in this program"));
      return false;
    }
    f.cursor = store.open(caller.cursor->file());
    f.begin = *target;
    f.end = end_point;
  } else {
    std::optional<ProgramPoint> found = p.name.empty()
                                            ? store.findProgram(p.program, caller.cursor->file())
                                            : store.findProgramNamed(p.name);
    if (!found && p.din) {
      // Fundamentals: a name that is no variable and no subprogram is not defined.
      fail(EvalError::UndefinedName, p.loc,
           absl::StrCat("'", p.name, "' is not defined: no variable, and no subprogram ", p.name,
                        ".spf (or .mpf) in the program folder"));
      return false;
    }
    if (!found) {
      fail(EvalError::ProgramNotFound, p.loc,
           p.name.empty()
               ? absl::StrCat("program O", p.program, " not found (in this file or the program folder)")
               : absl::StrCat("program '", p.name, "' (", p.code,
                              " in the machine file's code macros) not found in the program folder"));
      return false;
    }
    f.cursor = store.open(found->file);
    f.begin = *found;
    f.header_at_begin = true;
    if (p.sequence) {
      // M98 P H: the program's sequence H.
      const ProgramPoint end_point = programEnd(f);
      std::optional<ProgramPoint> target = store.findSequence(
          *p.sequence, f.begin, SequenceSearch::FromStart, f.begin, end_point);
      if (!target) {
        fail(EvalError::GotoTarget, p.loc,
             absl::StrCat("M98 P", p.program, " H", *p.sequence, ": no block starts with N",
                          *p.sequence, " in O", p.program));
        return false;
      }
      f.begin = *target;
      f.header_at_begin = false;
    }
  }
  if (p.figure) {
    for (const Frame& open : frames)
      if (open.figure_rotation) {
        fail(EvalError::FigureRotationNested, p.loc,
             "a figure rotation (M98 with I J K) cannot be called inside another one");
        return false;
      }
    if (!options.figure_rotation.begin(*p.figure)) {
      fail(EvalError::FigureRotationWithRotation, p.loc,
           "a figure rotation (M98 with I J K) cannot be called while G68 is in force");
      return false;
    }
    f.figure_rotation = true;
  }
  f.cursor->seek(f.begin);
  f.call_point = p.at;
  f.call_loc = p.loc;
  f.repeats_left = p.repeats - 1;
  f.macro = p.macro;
  f.code = p.code;
  if (p.macro) variables.pushLocals(p.arguments);
  // A called program's DEF variables are its own (Fundamentals: local user data), whether it
  // is called by name or, in ISO mode, as a G65/M98/M-code macro body that is DIN (§4.11).
  variables.named().pushScope();
  if (p.din) {  // its PROC binds the arguments
    f.din_call = true;
    f.din_arguments = p.din_arguments;
  }
  frames.push_back(std::move(f));
  return true;
}

void Evaluator::Impl::closeFrame() {
  Frame& f = frames.back();
  if (f.din_call) {
    // VAR parameters: their values go back to the caller's variables.
    std::vector<std::pair<VariableRef, Datum>> back;
    for (const auto& [param, ref] : f.by_reference) {
      Failure failure;
      std::optional<Datum> v = variables.named().readDatum(param, {}, f.call_loc, failure);
      if (v) back.emplace_back(ref, *v);
    }
    variables.named().popScope();
    for (const auto& [ref, v] : back)
      if (!write(ref, v, f.call_loc)) break;
  } else {
    variables.named().popScope();
  }
  if (f.macro) variables.popLocals();
  if (f.figure_rotation) options.figure_rotation.end();
  rejected_closed += f.cursor->rejectedBlocks();
  frames.pop_back();
  // A DIN MCALL belongs to the program level that gave it: it ends with it.
  while (!modal_calls.empty() && modal_calls.back().din && modal_calls.back().depth > frames.size())
    modal_calls.pop_back();
}

bool Evaluator::Impl::ret(const Pending& p) {
  Frame& f = frames.back();
  if (f.is_main && p.din) {
    // M17 or RET in the main program: it ends there.
    end = ProgramEnd::EndOfFile;
    return true;
  }
  if (f.is_main) {
    // M99 in the main program: it starts again (endless on a real control; bounded here by
    // the simulated time, or by the loop limits when it neither moves nor dwells).
    if (!countBackJump(p.loc)) return false;
    f.loops.clear();
    f.structures.clear();
    f.for_resume.reset();
    if (p.sequence)
      return jumpToSequence(f, *p.sequence, p.at, rules.return_search, p.loc,
                            EvalError::GotoTarget);
    f.cursor->seek(f.begin);
    return true;
  }
  if (f.repeats_left > 0) {
    if (!countBackJump(p.loc)) return false;  // nested repeats multiply: bounded as loops
    --f.repeats_left;
    variables.named().popScope();  // each run declares its variables afresh
    variables.named().pushScope();
    f.loops.clear();
    f.structures.clear();
    f.for_resume.reset();
    f.cursor->seek(f.begin);
    if (f.figure_rotation) options.figure_rotation.run(++f.run);
    return true;
  }
  const ProgramPoint call_point = f.call_point;
  closeFrame();
  if (!p.sequence) return true;  // the caller goes on after its call block
  Frame& caller = frames.back();
  return jumpToSequence(caller, *p.sequence, call_point, rules.return_search, p.loc,
                        EvalError::GotoTarget);
}

}  // namespace ncc::eval
