#pragma once
// The syntax tree of one block of an ISO-family program (FANUC, Mazak, Siemens ISO mode).
// A block is one line. The tree says what was written, nothing more: values keep whether they
// had a decimal point (the decimal-point rules are semantics, applied in lowering), addresses
// keep their letter, and macro expressions stay unevaluated.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
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

// An expression: a literal, a `#` variable, a bracketed expression, an operator or a function.
struct Expr {
  enum class Kind : uint8_t {
    Number,    // literal; `number`, `has_point`
    Variable,  // #n or #[expr]; args[0] is the number expression
    Unary,     // op = "-", "+"; args[0]
    Binary,    // op = "+", "-", "*", "/", "OR", "XOR", "AND", "MOD", "EQ", "NE", "GT", "LT", "GE", "LE"
    Call,      // op = "SIN", "COS", ..., "ROUND", "BIN", "BCD" ...; args
    Bracket,   // [ expr ]; args[0]
    Vacant,    // #0 literal handled as Variable; Vacant reserved for an empty argument
  };
  Kind kind = Kind::Number;
  double number = 0.0;
  bool has_point = false;  // literal written with a decimal point ("10." or "1.5")
  uint8_t digits = 0;      // count of digits written, for per-address digit-limit checks
  std::string op;
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
  std::string address;  // upper-case letter, or ",C" / ",R" / ",A" for comma addresses
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
