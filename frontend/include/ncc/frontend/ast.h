#pragma once
// The syntax tree of one block, in either language of the controllers: ISO (FANUC, Mazak,
// Siemens ISO mode) and Siemens DIN. A block is one line (or an ISO block between ';' marks). The tree says what was written, nothing more: values keep whether they
// had a decimal point (the decimal-point rules are semantics, applied in lowering), addresses
// keep their letter, and macro expressions stay unevaluated.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "ncc/frontend/language.h"
#include "ncc/support/inline_string.h"
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

// An owned node that copies deeply: the recursive members of the tree (a statement inside a
// statement). Empty, or holding one T.
template <class T>
class Box {
 public:
  using element_type = T;
  Box() = default;
  Box(T value) : p_(std::make_unique<T>(std::move(value))) {}
  Box(const Box& o) : p_(o.p_ ? std::make_unique<T>(*o.p_) : nullptr) {}
  Box(Box&&) noexcept = default;
  Box& operator=(const Box& o) {
    if (this != &o) p_ = o.p_ ? std::make_unique<T>(*o.p_) : nullptr;
    return *this;
  }
  Box& operator=(Box&&) noexcept = default;

  explicit operator bool() const { return p_ != nullptr; }
  T& operator*() const { return *p_; }
  T* operator->() const { return p_.get(); }
  T& emplace() { p_ = std::make_unique<T>(); return *p_; }

 private:
  std::unique_ptr<T> p_;
};

// The operators and functions an expression can apply, one table for everything that reads or
// writes them (both parsers, the printers, the evaluator, the block store): a new one is added
// here and nowhere can forget it. The block store writes an operator as its index here: add
// new ones at the end (and raise the store's version). `text` is the canonical spelling (aliases such as ATN or SQR
// are resolved by the parser); `arity` is the argument count (0: it varies, ATAN takes 1 or 2,
// SUBSTR 2 or 3, SPRINT a format and its values).
enum class Op : uint8_t {
  None,  // a node that applies none (a literal, a variable, a bracket)
  Plus, Minus, Times, Divide, Mod, Or, Xor, And, Eq, Ne, Gt, Lt, Ge, Le,
  Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Abs, Bin, Bcd, Round, Fix, Fup, Ln, Exp, Pow, Adp,
  // DIN only: integer division, the logic and bit operators, and its functions.
  Div, Not, BAnd, BOr, BXor, BNot, Atan2, Pot, Trunc, MinVal, MaxVal,
  // DIN: an axis word's value given incrementally or absolutely for this block (`X=IC(5)`).
  Ic, Ac,
  // DIN strings (docs/din.md, Strings): concatenation, and the string functions.
  Concat, StrLen, Index, RIndex, MIndex, Match, SubStr, ToUpper, ToLower, Number, IsNumber, Sprint,
  // DIN: the values of an array (`A[0]=SET(1,2,3)`, `REP(0)`), not values themselves.
  Set, Rep,
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
    OpInfo{Op::Div, "DIV", 2},   OpInfo{Op::Not, "NOT", 1},   OpInfo{Op::BAnd, "B_AND", 2},
    OpInfo{Op::BOr, "B_OR", 2},  OpInfo{Op::BXor, "B_XOR", 2}, OpInfo{Op::BNot, "B_NOT", 1},
    OpInfo{Op::Atan2, "ATAN2", 2}, OpInfo{Op::Pot, "POT", 1}, OpInfo{Op::Trunc, "TRUNC", 1},
    OpInfo{Op::MinVal, "MINVAL", 2}, OpInfo{Op::MaxVal, "MAXVAL", 2},
    OpInfo{Op::Ic, "IC", 1},     OpInfo{Op::Ac, "AC", 1},
    OpInfo{Op::Concat, "<<", 2}, OpInfo{Op::StrLen, "STRLEN", 1}, OpInfo{Op::Index, "INDEX", 2},
    OpInfo{Op::RIndex, "RINDEX", 2}, OpInfo{Op::MIndex, "MINDEX", 2}, OpInfo{Op::Match, "MATCH", 2},
    OpInfo{Op::SubStr, "SUBSTR", 0}, OpInfo{Op::ToUpper, "TOUPPER", 1},
    OpInfo{Op::ToLower, "TOLOWER", 1}, OpInfo{Op::Number, "NUMBER", 1},
    OpInfo{Op::IsNumber, "ISNUMBER", 1}, OpInfo{Op::Sprint, "SPRINT", 0},
    OpInfo{Op::Set, "SET", 0},   OpInfo{Op::Rep, "REP", 0},
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
  return (op >= Op::Mod && op <= Op::Le) || op == Op::Div || op == Op::BAnd || op == Op::BOr ||
         op == Op::BXor;
}

// An address as written: a letter (`X`), a comma address (`,C`), or a machine axis name of up
// to 8 characters (`X1`); DIN's short names (`CR`, `I1`, `ADIS`) fit too. Held inline: a block
// has a handful of words and copying them must not allocate.
using Address = InlineString<14>;

// An expression: a literal, a `#` variable, a bracketed expression, an operator or a function;
// in DIN also a named variable, an R parameter or a string.
struct Expr {
  enum class Kind : uint8_t {
    Number,    // literal; `number`, `has_point`
    Variable,  // #n or #[expr]; args[0] is the number expression
    Unary,     // op = Minus, Plus, Not, BNot; args[0]
    Binary,    // op = Plus ... Le, Div, BAnd ... BXor, Concat (the operators); args[0..1]
    Call,      // op = Sin ... Adp, Atan2 ... MaxVal, StrLen ... Sprint (the functions); args
    Bracket,   // [ expr ] (DIN: ( expr )); args[0]
    Vacant,    // an omitted argument (DIN `F(1,,3)`); #0 is a Variable
    Name,      // DIN: a name (`COUNT`, `$P_UIFR`, a label) in `text`; args: its indices `A[i,j]`
    RParam,    // DIN: R n or R[expr]; args[0] is the number expression
    String,    // DIN: a string literal, in `text`
  };
  Kind kind = Kind::Number;
  bool has_point = false;  // literal written with a decimal point ("10." or "1.5")
  uint8_t digits = 0;      // count of digits written, for per-address digit-limit checks
  Op op = Op::None;
  SourceLocation loc;
  double number = 0.0;
  std::vector<Expr> args;
  // Name and String: the text (a name upper-cased, a string as written). Boxed: an ISO tree
  // never has one and its nodes stay small.
  Box<std::string> text;

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

// The most characters a DIN STRING holds (Job Planning, variable types: STRING[n], n <= 200).
inline constexpr int kMaxStringLength = 200;

// The type of a DIN variable (DEF INT ...).
enum class DataType : uint8_t { None, Int, Real, Bool, Char, String, Axis, Frame };
inline constexpr std::array<const char*, 8> kDataTypeNames = {"", "INT", "REAL", "BOOL", "CHAR",
                                                              "STRING", "AXIS", "FRAME"};

// Where a jump searches for its target. ISO GOTO n searches as the dialect says
// (MacroRules::goto_search); DIN names the direction (GOTOF forward, GOTOB backward, GOTO and
// GOTOC forward then backward, GOTOC without an alarm when there is no such target).
enum class Jump : uint8_t { Sequence, Forward, Backward, Both, BothQuiet };

// The statements of a block: Macro B's, and DIN's.
struct Statement {
  enum class Kind : uint8_t {
    Assign,      // #target = value; DIN: a variable or R parameter = value
    Goto,        // GOTO target (`jump` says where it searches)
    IfGoto,      // IF [cond] GOTO target
    IfThen,      // IF [cond] THEN assignment (then_assign)
    While,       // WHILE [cond] DO id
    End,         // END id
    Define,      // DIN: DEF type target [= value]; target is a Name, its args the dimensions
    Label,       // DIN: a jump label `NAME:` (target is the Name)
    Call,        // DIN: a subprogram call by name; target is the Name, its args the arguments
    // DIN control structures, each alone in its block (docs/din.md, Control structures). WHILE
    // is `While` above with loop_id 0 (ISO's DO m pairs by number, DIN's by nesting).
    If,          // IF cond (value) ... [ELSE ...] ENDIF
    Else,
    EndIf,
    EndWhile,
    For,         // FOR var = start TO end: then_assign is `var = start`, value the end
    EndFor,
    Repeat,      // REPEAT ... UNTIL cond
    Until,       // value: the condition that ends the loop
    Loop,        // LOOP ... ENDLOOP (left by a jump)
    EndLoop,
    Case,        // CASE (value) OF: the CaseBranch statements after it in the block
    CaseBranch,  // a constant (value; Vacant for DEFAULT) and its jump (target, jump)
    // DIN subprograms: `PROC NAME(REAL A, VAR INT B)` (target: the Name) and a Parameter
    // statement after it for each parameter (type, target: its Name; loop_id 1 for VAR, a
    // parameter passed by reference); RET returns to the caller.
    Proc,
    Parameter,
    Return,
    // DIN: `REPEAT START END P=n` repeats a program section n times (Job Planning, program
    // section repetition): target is the start label, target.args[0] the end label when
    // written; value is P (Vacant: once); loop_id 1 for REPEATB (the label's block alone).
    RepeatSection,
  };
  Kind kind = Kind::Assign;
  SourceLocation loc;
  Expr target;  // Assign: the variable; Goto/IfGoto/CaseBranch: a sequence number, or a Name (DIN label)
  Expr value;   // Assign: the value; If*/While/Until/Case: the condition; Define: the initial value
  int loop_id = 0;  // DO m / END m; Parameter: 1 for VAR
  Box<Statement> then_assign;  // IfThen, For (copies are deep: the evaluator keeps loop bodies)
  DataType type = DataType::None;  // Define
  Jump jump = Jump::Sequence;      // Goto, IfGoto, CaseBranch
  int length = 0;                  // Define, Parameter of type STRING[n]: n (0: not written)
};

struct Block {
  SourceLocation loc;               // start of the line
  int skip_level = -1;              // -1: no '/'; 1..9 for /1../9; a bare '/' is level 1
  std::optional<int64_t> sequence;  // N number
  std::optional<int64_t> program_number;  // O number (or ':' on some controls)
  bool percent = false;             // the '%' tape start/end mark
  // The language the block was read in (G290/G291, block_reader.h): lowering reads it with
  // that language's table.
  frontend::Language language = frontend::Language::Iso;
  std::vector<Word> words;          // in written order
  std::vector<Statement> statements;
  std::vector<std::string> comments;  // text inside ( ), kept for printing
  bool empty() const {
    return words.empty() && statements.empty() && !sequence && !program_number && !percent;
  }
};

// ---- The schema: every member of every node, listed once ------------------------------------
// The block store's codec (eval/src/block_store.cpp: writer, reader, nesting) and the tests'
// deep comparison walk these lists rather than naming members, so a member listed here reaches
// all of them. The size checks catch a member added to a node and not to its list. Members are
// listed parents' location first: the codec codes the locations inside a node relative to it.
template <class Node, class T>
struct Field {
  const char* name;
  T Node::*member;
};
template <class Node, class T>
constexpr Field<Node, T> field(const char* name, T Node::*member) {
  return {name, member};
}

// Schema<Node>::fields; `masked`: whether the codec writes which members differ from their
// default (false: every member is always written, for a node that has no optional members);
// `nests`: whether the node is a level of nesting (the decoder bounds the levels, and the
// evaluator and printer recurse once per level).
template <class Node>
struct Schema;
template <>
struct Schema<Expr> {
  static constexpr bool masked = true;
  static constexpr bool nests = true;
  static constexpr auto fields =
      std::tuple{field("kind", &Expr::kind), field("loc", &Expr::loc), field("has_point", &Expr::has_point),
                 field("digits", &Expr::digits), field("op", &Expr::op), field("number", &Expr::number),
                 field("args", &Expr::args), field("text", &Expr::text)};
};
template <>
struct Schema<Word> {
  static constexpr bool masked = false;
  static constexpr bool nests = false;
  static constexpr auto fields = std::tuple{field("address", &Word::address), field("loc", &Word::loc),
                                            field("value", &Word::value)};
};
template <>
struct Schema<Statement> {
  static constexpr bool masked = true;
  static constexpr bool nests = true;
  static constexpr auto fields =
      std::tuple{field("kind", &Statement::kind), field("loc", &Statement::loc),
                 field("target", &Statement::target), field("value", &Statement::value),
                 field("loop_id", &Statement::loop_id), field("then_assign", &Statement::then_assign),
                 field("type", &Statement::type), field("jump", &Statement::jump),
                 field("length", &Statement::length)};
};
template <>
struct Schema<Block> {
  static constexpr bool masked = true;
  static constexpr bool nests = false;
  static constexpr auto fields =
      std::tuple{field("loc", &Block::loc), field("skip_level", &Block::skip_level),
                 field("sequence", &Block::sequence), field("program_number", &Block::program_number),
                 field("percent", &Block::percent), field("words", &Block::words),
                 field("statements", &Block::statements), field("comments", &Block::comments),
                 field("language", &Block::language)};
};
// A new member: list it above, then update the size here (x86-64, the platform CI builds).
// (A member that fits in padding keeps the size: list it all the same.)
static_assert(sizeof(Expr) == 56, "Expr changed: update Schema<Expr>");
static_assert(sizeof(Word) == 88, "Word changed: update Schema<Word>");
static_assert(sizeof(Statement) == 152, "Statement changed: update Schema<Statement>");
static_assert(sizeof(Block) == 128, "Block changed: update Schema<Block>");

// Walking a schema: f(field) for each Field of node type N, in order.
template <class T>
concept SchemaNode = requires { Schema<T>::fields; };
template <SchemaNode N, class F>
constexpr void forEachField(F&& f) {
  std::apply([&](const auto&... field) { (f(field), ...); }, Schema<N>::fields);
}
template <SchemaNode N>
constexpr size_t fieldCount() {
  return std::tuple_size_v<std::remove_cvref_t<decltype(Schema<N>::fields)>>;
}
// The member types a schema walker handles besides nodes, scalars and strings.
template <class T> inline constexpr bool kIsList = false;
template <class T> inline constexpr bool kIsList<std::vector<T>> = true;
template <class T> inline constexpr bool kIsOptional = false;
template <class T> inline constexpr bool kIsOptional<std::optional<T>> = true;
template <class T> inline constexpr bool kIsBox = false;
template <class T> inline constexpr bool kIsBox<Box<T>> = true;
template <class T> inline constexpr bool kIsInline = false;
template <size_t N> inline constexpr bool kIsInline<InlineString<N>> = true;

// The number of values of each enum of the tree: the codec refuses others.
template <class E>
inline constexpr uint8_t kEnumValues = 0;
template <>
inline constexpr uint8_t kEnumValues<Expr::Kind> = static_cast<uint8_t>(Expr::Kind::String) + 1;
template <>
inline constexpr uint8_t kEnumValues<Statement::Kind> = static_cast<uint8_t>(Statement::Kind::RepeatSection) + 1;
template <>
inline constexpr uint8_t kEnumValues<DataType> = static_cast<uint8_t>(kDataTypeNames.size());
template <>
inline constexpr uint8_t kEnumValues<Jump> = static_cast<uint8_t>(Jump::BothQuiet) + 1;
template <>
inline constexpr uint8_t kEnumValues<Op> = static_cast<uint8_t>(kOps.size());
template <>
inline constexpr uint8_t kEnumValues<frontend::Language> = static_cast<uint8_t>(frontend::Language::Din) + 1;

}  // namespace ncc::ast
