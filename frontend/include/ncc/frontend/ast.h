#pragma once
// The syntax tree of one block of an ISO-family program (FANUC, Mazak, Siemens ISO mode).
// A block is one line. The tree says what was written, nothing more: values keep whether they
// had a decimal point (the decimal-point rules are semantics, applied in lowering), addresses
// keep their letter, and macro expressions stay unevaluated.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncc/support/source_location.h"

namespace ncc::ast {

// The deepest expression tree a program may write: the nodes on the longest path from the
// root to a leaf (a literal is 1, `1+2` is 2, a chain of n terms `1+1+...+1` is n because it is
// a left-deep tree, and each sign, bracket, `#` and function adds one). Everything that walks a
// tree (evaluation, the printer, copies, destruction, the block store) recurses once per level,
// so the frontend refuses deeper text as it reads it (NCC1017) and the evaluator refuses deeper
// trees from elsewhere: a few hundred levels stay far below the stack even with AddressSanitizer,
// and controllers allow 5 bracket levels in blocks of a few hundred characters
// (docs/macro.md, Expression depth).
inline constexpr int kMaxExprDepth = 256;

// The operators and functions an expression can apply, one table for everything that reads or
// writes them (both parsers, the printers, the evaluator, the block store): a new one is added
// here and nowhere can forget it. `text` is the canonical spelling (aliases such as ATN or SQR
// are resolved by the parser); `arity` is the argument count (ATAN takes 1 or 2: 0 here).
enum class Op : uint8_t {
  None,  // a node that applies none (a literal, a variable, a bracket)
  Plus, Minus, Times, Divide, Mod, Or, Xor, And, Eq, Ne, Gt, Lt, Ge, Le,
  Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Abs, Bin, Bcd, Round, Fix, Fup, Ln, Exp, Pow, Adp,
};
struct OpInfo {
  Op op;
  const char* text;
  uint8_t arity;
};
inline constexpr std::array kOps = {
    OpInfo{Op::None, "", 0},     OpInfo{Op::Plus, "+", 2},    OpInfo{Op::Minus, "-", 2},
    OpInfo{Op::Times, "*", 2},   OpInfo{Op::Divide, "/", 2},  OpInfo{Op::Mod, "MOD", 2},
    OpInfo{Op::Or, "OR", 2},     OpInfo{Op::Xor, "XOR", 2},   OpInfo{Op::And, "AND", 2},
    OpInfo{Op::Eq, "EQ", 2},     OpInfo{Op::Ne, "NE", 2},     OpInfo{Op::Gt, "GT", 2},
    OpInfo{Op::Lt, "LT", 2},     OpInfo{Op::Ge, "GE", 2},     OpInfo{Op::Le, "LE", 2},
    OpInfo{Op::Sin, "SIN", 1},   OpInfo{Op::Cos, "COS", 1},   OpInfo{Op::Tan, "TAN", 1},
    OpInfo{Op::Asin, "ASIN", 1}, OpInfo{Op::Acos, "ACOS", 1}, OpInfo{Op::Atan, "ATAN", 0},
    OpInfo{Op::Sqrt, "SQRT", 1}, OpInfo{Op::Abs, "ABS", 1},   OpInfo{Op::Bin, "BIN", 1},
    OpInfo{Op::Bcd, "BCD", 1},   OpInfo{Op::Round, "ROUND", 1}, OpInfo{Op::Fix, "FIX", 1},
    OpInfo{Op::Fup, "FUP", 1},   OpInfo{Op::Ln, "LN", 1},     OpInfo{Op::Exp, "EXP", 1},
    OpInfo{Op::Pow, "POW", 2},   OpInfo{Op::Adp, "ADP", 1},
};
static_assert([] {
  for (size_t i = 0; i < kOps.size(); ++i)
    if (static_cast<size_t>(kOps[i].op) != i) return false;
  return true;
}(), "kOps is indexed by Op");

constexpr const OpInfo& opInfo(Op op) { return kOps[static_cast<size_t>(op)]; }
constexpr const char* opText(Op op) { return opInfo(op).text; }
// The operator or function spelled `text` (canonical, upper case); nullopt when none is.
constexpr std::optional<Op> opNamed(std::string_view text) {
  for (const OpInfo& i : kOps)
    if (i.op != Op::None && std::string_view(i.text) == text) return i.op;
  return std::nullopt;
}
// A word operator (MOD, OR, EQ ...), printed with spaces around it.
constexpr bool isWordOperator(Op op) {
  return op >= Op::Mod && op <= Op::Le;
}

// An address as written: a letter (`X`), a comma address (`,C`), or a machine axis name of up
// to 8 characters (`X1`); DIN's short names (`CR`, `I1`, `ADIS`) fit too. Held inline: a block
// has a handful of words and copying them must not allocate.
class Address {
 public:
  static constexpr size_t kCapacity = 14;
  constexpr Address() = default;
  constexpr explicit Address(char letter) : size_(1) { text_[0] = letter; }
  // Longer text is cut to kCapacity: callers check lengths that input controls (the block
  // store's reader, the machine file's axis names).
  constexpr Address(std::string_view text) : size_(static_cast<uint8_t>(std::min(text.size(), kCapacity))) {
    for (size_t i = 0; i < size_; ++i) text_[i] = text[i];
  }
  constexpr Address(const char* text) : Address(std::string_view(text)) {}
  Address(const std::string& text) : Address(std::string_view(text)) {}

  constexpr std::string_view view() const { return {text_.data(), size_}; }
  constexpr const char* c_str() const { return text_.data(); }  // for absl::StrCat
  constexpr operator std::string_view() const { return view(); }
  std::string str() const { return std::string(view()); }
  constexpr size_t size() const { return size_; }
  constexpr bool empty() const { return size_ == 0; }
  constexpr char operator[](size_t i) const { return text_[i]; }
  // One letter `c`: the common test in passes.
  constexpr bool is(char c) const { return size_ == 1 && text_[0] == c; }

  friend constexpr bool operator==(const Address& a, const Address& b) { return a.view() == b.view(); }
  friend constexpr bool operator==(const Address& a, std::string_view b) { return a.view() == b; }
  friend constexpr bool operator==(const Address& a, const char* b) { return a.view() == b; }

 private:
  std::array<char, kCapacity + 1> text_{};  // NUL-terminated
  uint8_t size_ = 0;
};

// An expression: a literal, a `#` variable, a bracketed expression, an operator or a function.
struct Expr {
  enum class Kind : uint8_t {
    Number,    // literal; `number`, `has_point`
    Variable,  // #n or #[expr]; args[0] is the number expression
    Unary,     // op = Minus, Plus; args[0]
    Binary,    // op = Plus ... Le (the arithmetic, logic and comparison operators); args[0..1]
    Call,      // op = Sin ... Adp (the functions); args
    Bracket,   // [ expr ]; args[0]
    Vacant,    // #0 literal handled as Variable; Vacant reserved for an empty argument
  };
  Kind kind = Kind::Number;
  double number = 0.0;
  bool has_point = false;  // literal written with a decimal point ("10." or "1.5")
  uint8_t digits = 0;      // count of digits written, for per-address digit-limit checks
  Op op = Op::None;
  std::vector<Expr> args;
  SourceLocation loc;

  static Expr literal(double v, bool point, SourceLocation l) {
    Expr e;
    e.kind = Kind::Number;
    e.number = v;
    e.has_point = point;
    e.loc = l;
    return e;
  }
  bool isLiteral() const { return kind == Kind::Number; }
};

// One address word: `G01`, `X-20.`, `F#1`, `,C10.`, `,R5.`.
struct Word {
  Address address;  // upper-case letter, ",C" / ",R" / ",A", or a machine axis name
  Expr value;
  SourceLocation loc;   // of the address letter
};

// Macro statements written in a block (Macro B). Parsed now, evaluated by the Macro B issue.
struct Statement {
  enum class Kind : uint8_t {
    Assign,      // #target = value
    Goto,        // GOTO target
    IfGoto,      // IF [cond] GOTO target
    IfThen,      // IF [cond] THEN assignment (then_assign)
    While,       // WHILE [cond] DO id
    End,         // END id
  };
  Kind kind = Kind::Assign;
  Expr target;  // Assign: the variable (a Variable expr); Goto/IfGoto: the sequence number
  Expr value;   // Assign: the value; If*/While: the condition
  int loop_id = 0;  // DO m / END m
  std::unique_ptr<Statement> then_assign;  // IfThen
  SourceLocation loc;

  // Copies are deep (the evaluator keeps parsed loop bodies).
  Statement() = default;
  Statement(const Statement& o)
      : kind(o.kind), target(o.target), value(o.value), loop_id(o.loop_id),
        then_assign(o.then_assign ? std::make_unique<Statement>(*o.then_assign) : nullptr),
        loc(o.loc) {}
  Statement(Statement&&) noexcept = default;
  Statement& operator=(const Statement& o) {
    if (this != &o) *this = Statement(o);
    return *this;
  }
  Statement& operator=(Statement&&) noexcept = default;
};

struct Block {
  SourceLocation loc;               // start of the line
  int skip_level = -1;              // -1: no '/'; 1..9 for /1../9; a bare '/' is level 1
  std::optional<int64_t> sequence;  // N number
  std::optional<int64_t> program_number;  // O number (or ':' on some controls)
  bool percent = false;             // the '%' tape start/end mark
  std::vector<Word> words;          // in written order
  std::vector<Statement> statements;
  std::vector<std::string> comments;  // text inside ( ), kept for printing
  bool empty() const {
    return words.empty() && statements.empty() && !sequence && !program_number && !percent;
  }
};

}  // namespace ncc::ast
