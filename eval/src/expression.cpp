// Macro B expressions (docs/macro.md, Expressions). The manuals' statements this follows:
//  - vacant is 0 in arithmetic and in GT LT GE LE, and differs from 0 only in EQ and NE;
//    `#1=#0` keeps #1 vacant (Mazak §13-9-3 2. A and C);
//  - OR XOR AND work on each bit of 32-bit integers (Mazak §13-9-5 table);
//  - functions take degrees; TAN is SIN/COS (§13-9-5 note); ROUND is to the nearest integer,
//    FIX toward 0, FUP away from 0, for negative numbers too (§13-9-5 rows 17-19);
//  - LN of a negative number is "calculation impossible" (§13-9-5 row 20: Mazak 860);
//  - [ ] nest at most five deep, function brackets included (§13-6, §13-9-5 2.).
#include "ncc/eval/expression.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "absl/container/inlined_vector.h"
#include "absl/strings/ascii.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "number_format.h"

namespace ncc::eval {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

bool fail(Failure& failure, EvalError error, SourceLocation loc, std::string message) {
  failure.error = error;
  failure.loc = loc;
  failure.message = std::move(message);
  return false;
}

// Binary floating point cannot hold 0.1: 0.1*3*10 is 3.0000000000000004. The controllers
// compute in decimal digits, so a value this close to a whole number is that number before
// FIX / FUP / a variable number take its integer part.
double snapToInteger(double v) {
  const double r = std::round(v);
  return std::fabs(v - r) <= 1e-9 * std::max(1.0, std::fabs(v)) ? r : v;
}

// sin and cos of degrees, exact at multiples of 90 (COS[90] is 0, not 6e-17).
double sinDegrees(double deg) {
  const double r = std::fmod(deg, 360.0);
  if (r == 0.0) return 0.0;
  if (std::fabs(r) == 180.0) return 0.0;
  if (r == 90.0 || r == -270.0) return 1.0;
  if (r == -90.0 || r == 270.0) return -1.0;
  return std::sin(r * kDegree);
}
double cosDegrees(double deg) { return sinDegrees(deg + 90.0); }

// Integer operands of OR XOR AND: "each bit of 32 bits" (Mazak §13-9-5).
std::optional<int32_t> bits32(double v) {
  const double r = std::round(v);
  if (!(r >= -2147483648.0 && r <= 2147483647.0)) return std::nullopt;
  return static_cast<int32_t>(static_cast<uint32_t>(static_cast<int64_t>(r)));
}

class Evaluator {
 public:
  Evaluator(const ExpressionContext& context, Failure& failure)
      : rules_(context.rules), context_(context), failure_(failure) {}

  std::optional<std::string> evalText(const ast::Expr& e) { return text(e); }

  std::optional<Value> eval(const ast::Expr& e) {
    // A tree the parser did not build (a test, a fuzzer) must not be read past its ends.
    if (e.args.size() < operandCount(e)) {
      fail(failure_, EvalError::Domain, e.loc, "malformed expression: an operand is missing");
      return std::nullopt;
    }
    switch (e.kind) {
      case ast::Expr::Kind::Number:
        return Value::of(e.number);
      case ast::Expr::Kind::Vacant:
        return Value::none();
      case ast::Expr::Kind::Bracket:
        // A bracket is no operation: [#1] with #1 vacant is vacant (`X[#1]` is dropped).
        return eval(e.args[0]);
      case ast::Expr::Kind::Variable:
        return variable(e);
      case ast::Expr::Kind::Unary:
        return unary(e);
      case ast::Expr::Kind::Binary:
        return binary(e);
      case ast::Expr::Kind::Call:
        return call(e);
      case ast::Expr::Kind::RParam:
        return rParameter(e);
      case ast::Expr::Kind::Name:
        return named(e);
      case ast::Expr::Kind::String:
        return notANumber(e);
    }
    fail(failure_, EvalError::Domain, e.loc, "unknown expression");
    return std::nullopt;
  }

  // ---- strings (docs/din.md, Strings) ----

  ValueKind kind(const ast::Expr& e) const { return kindOf(e, context_.variables); }

  std::optional<Value> notANumber(const ast::Expr& e) {
    fail(failure_, EvalError::TypeMismatch, e.loc,
         "a string where a number is needed (NUMBER(...) reads the number a string holds)");
    return std::nullopt;
  }

  std::optional<std::string> text(const ast::Expr& e) {
    if (e.args.size() < operandCount(e)) {
      fail(failure_, EvalError::Domain, e.loc, "malformed expression: an operand is missing");
      return std::nullopt;
    }
    switch (e.kind) {
      case ast::Expr::Kind::String:
        return e.text ? *e.text : std::string();
      case ast::Expr::Kind::Vacant:
        return std::string();
      case ast::Expr::Kind::Bracket:
        return text(e.args[0]);
      case ast::Expr::Kind::Name:
        if (kind(e) != ValueKind::Number) {
          std::optional<std::vector<int64_t>> indices = indicesOf(e.args, context_, failure_);
          if (!indices) return std::nullopt;
          return context_.variables.readText(*e.text, *indices, e.loc, failure_);
        }
        break;
      case ast::Expr::Kind::Binary:
        if (e.op == ast::Op::Concat) {
          std::optional<std::string> a = text(e.args[0]);
          if (!a) return std::nullopt;
          std::optional<std::string> b = text(e.args[1]);
          if (!b) return std::nullopt;
          return bounded(*a + *b, e);
        }
        break;
      case ast::Expr::Kind::Call:
        switch (e.op) {
          case ast::Op::SubStr: return substr(e);
          case ast::Op::ToUpper:
          case ast::Op::ToLower: {
            std::optional<std::string> a = text(e.args[0]);
            if (!a) return std::nullopt;
            for (char& c : *a)
              c = e.op == ast::Op::ToUpper ? absl::ascii_toupper(c) : absl::ascii_tolower(c);
            return a;
          }
          case ast::Op::Sprint: return sprint(e);
          default: break;
        }
        break;
      default:
        break;
    }
    std::optional<Value> v = eval(e);
    if (!v) return std::nullopt;
    return formatNumber(v->arithmetic());
  }

  // A string longer than any STRING holds is refused where it is made (a `<<` in a loop
  // would otherwise grow without bound).
  std::optional<std::string> bounded(std::string s, const ast::Expr& e) {
    if (s.size() > kMaxText) {
      fail(failure_, EvalError::ValueRange, e.loc,
           absl::StrCat("a string of ", s.size(), " characters: strings hold at most ", kMaxText));
      return std::nullopt;
    }
    return s;
  }
  static constexpr size_t kMaxText = 2 * ast::kMaxStringLength;

  // A comparison of two strings (or a CHAR and a string): by character codes.
  std::optional<Value> compareTexts(const ast::Expr& e) {
    const ValueKind a = kind(e.args[0]), b = kind(e.args[1]);
    if (a == ValueKind::Number || b == ValueKind::Number) {
      const ast::Expr& number = a == ValueKind::Number ? e.args[0] : e.args[1];
      fail(failure_, EvalError::TypeMismatch, number.loc,
           "a string is compared with a number (NUMBER(...) reads the number a string holds)");
      return std::nullopt;
    }
    std::optional<std::string> x = text(e.args[0]);
    if (!x) return std::nullopt;
    std::optional<std::string> y = text(e.args[1]);
    if (!y) return std::nullopt;
    const int c = x->compare(*y);
    bool r = false;
    switch (e.op) {
      case ast::Op::Eq: r = c == 0; break;
      case ast::Op::Ne: r = c != 0; break;
      case ast::Op::Lt: r = c < 0; break;
      case ast::Op::Gt: r = c > 0; break;
      case ast::Op::Le: r = c <= 0; break;
      default: r = c >= 0; break;
    }
    return Value::of(r ? 1.0 : 0.0);
  }

  // STRLEN INDEX RINDEX MINDEX MATCH NUMBER ISNUMBER: numbers from strings. Positions count
  // from 0; -1 when there is none.
  std::optional<Value> textFunction(const ast::Expr& e) {
    std::optional<std::string> s = text(e.args[0]);
    if (!s) return std::nullopt;
    using O = ast::Op;
    const auto position = [](size_t at) {
      return Value::of(at == std::string::npos ? -1.0 : static_cast<double>(at));
    };
    switch (e.op) {
      case O::StrLen: return Value::of(static_cast<double>(s->size()));
      case O::Number:
      case O::IsNumber: {
        std::optional<double> n = numberIn(*s);
        if (e.op == O::IsNumber) return Value::of(n ? 1.0 : 0.0);
        if (!n) {
          fail(failure_, EvalError::TypeMismatch, e.args[0].loc,
               absl::StrCat("NUMBER: \"", s->substr(0, 40), "\" is not a number"));
          return std::nullopt;
        }
        return result(*n, e);
      }
      default: break;
    }
    std::optional<std::string> t = text(e.args[1]);
    if (!t) return std::nullopt;
    if (e.op == O::Match) return position(s->find(*t));
    if (e.op == O::MIndex) return position(s->find_first_of(*t));
    if (t->size() != 1) {
      fail(failure_, EvalError::TypeMismatch, e.args[1].loc,
           absl::StrCat(ast::opText(e.op), " looks for one character, not \"", t->substr(0, 40), "\""));
      return std::nullopt;
    }
    return position(e.op == O::Index ? s->find((*t)[0]) : s->rfind((*t)[0]));
  }

  // "12.5", " -3 ": a number and nothing else (blanks around it allowed).
  static std::optional<double> numberIn(const std::string& text) {
    const absl::string_view s = absl::StripAsciiWhitespace(text);
    double v = 0.0;
    if (s.empty() || !absl::SimpleAtod(s, &v) || !std::isfinite(v)) return std::nullopt;
    for (char c : s)  // SimpleAtod also reads "inf", "nan" and hexadecimal
      if (!(absl::ascii_isdigit(c) || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E'))
        return std::nullopt;
    return v;
  }

  // SUBSTR(s, start[, length]): from character `start` (from 0), `length` characters or to the end.
  std::optional<std::string> substr(const ast::Expr& e) {
    std::optional<std::string> s = text(e.args[0]);
    if (!s) return std::nullopt;
    std::optional<int64_t> start = count(e.args[1], "SUBSTR's start");
    if (!start) return std::nullopt;
    int64_t length = static_cast<int64_t>(s->size());
    if (e.args.size() > 2) {
      std::optional<int64_t> n = count(e.args[2], "SUBSTR's length");
      if (!n) return std::nullopt;
      length = *n;
    }
    if (*start >= static_cast<int64_t>(s->size())) return std::string();
    return s->substr(static_cast<size_t>(*start), static_cast<size_t>(length));
  }

  // A count or position: a whole number from 0.
  std::optional<int64_t> count(const ast::Expr& e, std::string_view what) {
    std::optional<Value> v = eval(e);
    if (!v) return std::nullopt;
    const double r = std::round(snapToInteger(v->arithmetic()));
    if (!(r >= 0.0 && r <= 1e6)) {
      fail(failure_, EvalError::Domain, e.loc,
           absl::StrCat(std::string(what), " is ", formatNumber(v->arithmetic()),
                        ": a whole number from 0 is needed"));
      return std::nullopt;
    }
    return static_cast<int64_t>(r);
  }

  // SPRINT("format", values...) (Job Planning, string functions): the format's text with each
  // %... replaced by the next value: %D an integer, %F a number with 6 decimals (%.nF n), %E
  // exponent notation, %G the shorter, %S a string, %C a character, %B TRUE or FALSE, %X
  // hexadecimal, %% a '%'. A width before the letter pads on the left (%8.3F).
  std::optional<std::string> sprint(const ast::Expr& e) {
    std::optional<std::string> format = text(e.args[0]);
    if (!format) return std::nullopt;
    std::string out;
    size_t next = 1;
    for (size_t i = 0; i < format->size(); ++i) {
      const char c = (*format)[i];
      if (c != '%') {
        out += c;
        continue;
      }
      size_t j = i + 1;
      int width = 0, precision = -1;
      while (j < format->size() && absl::ascii_isdigit((*format)[j]) && width < 1000)
        width = width * 10 + ((*format)[j++] - '0');
      if (j < format->size() && (*format)[j] == '.') {
        precision = 0;
        for (++j; j < format->size() && absl::ascii_isdigit((*format)[j]) && precision < 1000;)
          precision = precision * 10 + ((*format)[j++] - '0');
      }
      if (j >= format->size()) return badFormat(e, *format, "ends inside a %");
      const char letter = absl::ascii_toupper((*format)[j]);
      i = j;
      if (letter == '%') {
        out += '%';
        continue;
      }
      if (width > ast::kMaxStringLength || precision > 20)
        return badFormat(e, *format, "has a width above 200 or more than 20 decimals");
      if (next >= e.args.size()) return badFormat(e, *format, "has more % than values");
      const ast::Expr& arg = e.args[next++];
      std::string piece;
      if (letter == 'S' || letter == 'C') {
        std::optional<std::string> t = text(arg);
        if (!t) return std::nullopt;
        piece = letter == 'C' ? t->substr(0, 1) : *t;
      } else {
        if (kind(arg) == ValueKind::String) {
          notANumber(arg);
          return std::nullopt;
        }
        std::optional<Value> v = eval(arg);
        if (!v) return std::nullopt;
        const double x = v->arithmetic();
        switch (letter) {
          case 'D':
          case 'I': piece = absl::StrCat(static_cast<int64_t>(std::llround(std::clamp(x, -9e15, 9e15)))); break;
          case 'F': piece = absl::StrFormat("%.*f", precision < 0 ? 6 : precision, x); break;
          case 'E': piece = absl::StrFormat("%.*E", precision < 0 ? 6 : precision, x); break;
          case 'G': piece = absl::StrFormat("%.*G", precision < 0 ? 6 : precision, x); break;
          case 'B': piece = x != 0.0 ? "TRUE" : "FALSE"; break;
          case 'X': {
            auto bits = bits32(x);
            if (!bits) {
              bitRange(arg, x);
              return std::nullopt;
            }
            piece = absl::StrFormat("%X", static_cast<uint32_t>(*bits));
            break;
          }
          default:
            return badFormat(e, *format, absl::StrCat("has %", std::string(1, letter),
                                                      " (D F E G S C B X are the conversions)"));
        }
      }
      if (static_cast<int>(piece.size()) < width) piece.insert(0, width - piece.size(), ' ');
      out += piece;
      if (out.size() > kMaxText) return bounded(std::move(out), e);
    }
    if (next < e.args.size()) return badFormat(e, *format, "has fewer % than values");
    return out;
  }

  std::optional<std::string> badFormat(const ast::Expr& e, std::string_view format,
                                       std::string_view why) {
    fail(failure_, EvalError::Domain, e.loc,
         absl::StrCat("SPRINT: the format \"", std::string(format.substr(0, 40)), "\" ",
                      std::string(why)));
    return std::nullopt;
  }

 private:
  static size_t operandCount(const ast::Expr& e) {
    switch (e.kind) {
      case ast::Expr::Kind::Binary:
        return 2;
      case ast::Expr::Kind::Bracket:
      case ast::Expr::Kind::Variable:
      case ast::Expr::Kind::RParam:
      case ast::Expr::Kind::Unary:
      case ast::Expr::Kind::Call:
        return 1;
      default:
        return 0;
    }
  }

  std::optional<Value> rParameter(const ast::Expr& e) {
    auto index = eval(e.args[0]);
    if (!index) return std::nullopt;
    auto n = variableNumber(*index, rules_, e.loc, failure_);
    if (!n) return std::nullopt;
    return context_.variables.readR(*n, e.loc, failure_);
  }

  std::optional<Value> named(const ast::Expr& e) {
    const std::string_view name = e.text ? std::string_view(*e.text) : std::string_view();
    if (!name.empty() && name[0] == '$') return system(e, name);
    std::optional<std::vector<int64_t>> indices = indicesOf(e.args, context_, failure_);
    if (!indices) return std::nullopt;
    return context_.variables.readNamed(name, *indices, e.loc, failure_);
  }

  // `$AA_IW[Z]`: a name that is no variable is an axis name; anything else a number.
  std::optional<Value> system(const ast::Expr& e, std::string_view name) {
    absl::InlinedVector<SystemIndex, 2> indices;
    for (const ast::Expr& a : e.args) {
      SystemIndex& index = indices.emplace_back();
      if (a.kind == ast::Expr::Kind::Name && a.args.empty() && a.text) {
        Failure unused;
        if (!context_.variables.readNamed(*a.text, {}, a.loc, unused)) {
          index.axis = *a.text;
          continue;
        }
      }
      std::optional<Value> v = eval(a);
      if (!v) return std::nullopt;
      if (v->vacant || !std::isfinite(v->number) || std::fabs(v->number) > 1e9) {
        fail(failure_, EvalError::Domain, a.loc, absl::StrCat("the index of ", std::string(name), " is out of range"));
        return std::nullopt;
      }
      index.number = static_cast<int64_t>(std::llround(v->number));
    }
    return context_.variables.readSystem(name, indices, e.loc, failure_);
  }

  std::optional<Value> variable(const ast::Expr& e) {
    auto index = eval(e.args[0]);
    if (!index) return std::nullopt;
    auto n = variableNumber(*index, rules_, e.loc, failure_);
    if (!n) return std::nullopt;
    return context_.variables.read(*n, e.loc, failure_);
  }

  // A sign on a vacant value leaves it vacant, as the bracket does: `X-#1` with #1 vacant
  // is dropped like `X#1` (the manuals show `X-#2` as "#2 with its sign inverted").
  std::optional<Value> unary(const ast::Expr& e) {
    auto v = eval(e.args[0]);
    if (!v || v->vacant) return v;
    switch (e.op) {
      case ast::Op::Minus: return Value::of(-v->number);
      case ast::Op::Not: return Value::of(v->number == 0.0 ? 1.0 : 0.0);
      case ast::Op::BNot: {
        auto x = bits32(v->number);
        if (!x) return bitRange(e, v->number);
        return Value::of(static_cast<double>(~*x));
      }
      default: return v;
    }
  }

  std::optional<Value> bitRange(const ast::Expr& e, double outside) {
    fail(failure_, EvalError::ValueRange, e.loc,
         absl::StrCat(ast::opText(e.op), " works on 32-bit integers; ", formatNumber(outside),
                      " is outside them"));
    return std::nullopt;
  }

  std::optional<Value> result(double v, const ast::Expr& e) {
    if (!std::isfinite(v) || std::fabs(v) > rules_.max_magnitude) {
      const bool bounded = rules_.max_magnitude < std::numeric_limits<double>::max();
      fail(failure_, EvalError::ValueRange, e.loc,
           bounded ? absl::StrCat("the result of ", describe(e),
                                  " is beyond the value range (|x| <= ",
                                  formatNumber(rules_.max_magnitude), ")")
                   : absl::StrCat("the result of ", describe(e), " overflows"));
      return std::nullopt;
    }
    return Value::of(v == 0.0 ? 0.0 : v);  // no -0
  }

  static std::string describe(const ast::Expr& e) {
    if (e.kind == ast::Expr::Kind::Call) return ast::opText(e.op);
    return absl::StrCat("'", ast::opText(e.op), "'");
  }

  std::optional<Value> unknown(const ast::Expr& e, const char* what) {
    fail(failure_, EvalError::Domain, e.loc,
         absl::StrCat("unknown ", what, " '", ast::opText(e.op), "'"));
    return std::nullopt;
  }

  std::optional<Value> binary(const ast::Expr& e) {
    using O = ast::Op;
    if (context_.din) {
      if (e.op == O::Concat) return notANumber(e);
      const bool comparison = e.op == O::Eq || e.op == O::Ne || e.op == O::Lt ||
                              e.op == O::Gt || e.op == O::Le || e.op == O::Ge;
      if (comparison && (kind(e.args[0]) == ValueKind::String || kind(e.args[1]) == ValueKind::String))
        return compareTexts(e);
    }
    auto lhs = eval(e.args[0]);
    if (!lhs) return std::nullopt;
    auto rhs = eval(e.args[1]);
    if (!rhs) return std::nullopt;
    const O op = e.op;
    // EQ and NE tell vacant from 0 (vacant equals only vacant); the other comparisons and
    // the arithmetic read vacant as 0.
    if (op == O::Eq || op == O::Ne) {
      const bool equal = lhs->vacant || rhs->vacant ? lhs->vacant == rhs->vacant
                                                    : lhs->number == rhs->number;
      return Value::of((op == O::Eq) == equal ? 1.0 : 0.0);
    }
    const double a = lhs->arithmetic();
    const double b = rhs->arithmetic();
    switch (op) {
      case O::Gt: return Value::of(a > b ? 1.0 : 0.0);
      case O::Lt: return Value::of(a < b ? 1.0 : 0.0);
      case O::Ge: return Value::of(a >= b ? 1.0 : 0.0);
      case O::Le: return Value::of(a <= b ? 1.0 : 0.0);
      case O::Plus: return result(a + b, e);
      case O::Minus: return result(a - b, e);
      case O::Times: return result(a * b, e);
      case O::Divide:
      case O::Mod:
      case O::Div:
        if (b == 0.0) {
          fail(failure_, EvalError::DivisionByZero, e.loc,
               absl::StrCat(op == O::Divide ? "division" : ast::opText(op), " by zero"));
          return std::nullopt;
        }
        // DIV: the integer part of the quotient (Fundamentals: 3 DIV 4 = 0).
        if (op == O::Div) return result(std::trunc(snapToInteger(a / b)), e);
        return result(op == O::Divide ? a / b : std::fmod(a, b), e);
      case O::Or:
      case O::Xor:
      case O::And:
        if (context_.din) {
          const bool x = a != 0.0, y = b != 0.0;
          const bool r = op == O::Or ? (x || y) : op == O::Xor ? (x != y) : (x && y);
          return Value::of(r ? 1.0 : 0.0);
        }
        [[fallthrough]];
      case O::BOr:
      case O::BXor:
      case O::BAnd: {
        auto x = bits32(a);
        auto y = bits32(b);
        if (!x || !y) return bitRange(e, x ? b : a);
        const bool is_or = op == O::Or || op == O::BOr, is_xor = op == O::Xor || op == O::BXor;
        const int32_t r = is_or ? (*x | *y) : is_xor ? (*x ^ *y) : (*x & *y);
        return Value::of(static_cast<double>(r));
      }
      default:
        return unknown(e, "operator");
    }
  }

  std::optional<Value> domain(const ast::Expr& e, double x, std::string_view why) {
    fail(failure_, EvalError::Domain, e.loc,
         absl::StrCat(ast::opText(e.op), "[", formatNumber(x), "]: ", std::string(why)));
    return std::nullopt;
  }

  std::optional<Value> call(const ast::Expr& e) {
    switch (e.op) {
      case ast::Op::StrLen: case ast::Op::Index: case ast::Op::RIndex: case ast::Op::MIndex:
      case ast::Op::Match: case ast::Op::Number: case ast::Op::IsNumber:
        return textFunction(e);
      case ast::Op::SubStr: case ast::Op::ToUpper: case ast::Op::ToLower: case ast::Op::Sprint:
        return notANumber(e);
      case ast::Op::Set: case ast::Op::Rep:
        fail(failure_, EvalError::TypeMismatch, e.loc,
             absl::StrCat(ast::opText(e.op), "(...) gives an array its values (A[0]=",
                          ast::opText(e.op), "(...)); it is not a value"));
        return std::nullopt;
      default:
        break;
    }
    double x[2] = {0.0, 0.0};
    for (size_t i = 0; i < e.args.size() && i < 2; ++i) {
      auto v = eval(e.args[i]);
      if (!v) return std::nullopt;
      x[i] = v->arithmetic();  // a vacant argument counts as 0
    }
    using O = ast::Op;
    const double a = x[0];
    switch (e.op) {
      case O::Sin: return result(sinDegrees(a), e);
      case O::Cos: return result(cosDegrees(a), e);
      case O::Tan: {
        // TAN is SIN/COS (Mazak §13-9-5 note): at an odd multiple of 90 degrees it has no value.
        const double c = cosDegrees(a);
        if (c == 0.0) return domain(e, a, "the tangent of an odd multiple of 90 degrees");
        return result(sinDegrees(a) / c, e);
      }
      case O::Asin:
      case O::Acos:
        if (a < -1.0 || a > 1.0) return domain(e, a, "the argument must be in [-1, 1]");
        return result((e.op == O::Asin ? std::asin(a) : std::acos(a)) / kDegree, e);
      case O::Atan: {
        if (e.args.size() == 1) return result(std::atan(a) / kDegree, e);
        // ATAN[y]/[x] and ATAN[y,x]: the angle of (x, y) from 0 to 360 degrees.
        const double y = a, xx = x[1];
        if (y == 0.0 && xx == 0.0) return domain(e, 0.0, "ATAN[0]/[0] has no angle");
        double deg = std::atan2(y, xx) / kDegree;
        if (deg < 0.0) deg += 360.0;
        return result(deg, e);
      }
      case O::Sqrt:
        if (a < 0.0) return domain(e, a, "the square root of a negative number");
        return result(std::sqrt(a), e);
      case O::Abs: return result(std::fabs(a), e);
      // ROUND[-14/3] = -5, FIX[-14/3] = -4, FUP[-14/3] = -5 (Mazak §13-9-5 rows 17-19).
      case O::Round: return result(std::round(a), e);
      case O::Fix: return result(std::trunc(snapToInteger(a)), e);
      case O::Fup: {
        const double s = snapToInteger(a);
        return result(s >= 0.0 ? std::ceil(s) : std::floor(s), e);
      }
      case O::Ln:
        if (a <= 0.0) return domain(e, a, "the logarithm needs a number greater than 0");
        return result(std::log(a), e);
      case O::Exp: return result(std::exp(a), e);
      case O::Pow: {
        const double b = x[1];
        if (a == 0.0 && b < 0.0) return domain(e, a, "0 to a negative power");
        if (a < 0.0 && b != std::trunc(b))
          return domain(e, a, "a negative number to a fractional power");
        return result(std::pow(a, b), e);
      }
      case O::Adp: return result(a * context_.adp_scale, e);
      case O::Atan2: {
        // ATAN2(y, x): the angle of (x, y), -180 to 180 degrees (Fundamentals).
        if (a == 0.0 && x[1] == 0.0) return domain(e, 0.0, "ATAN2(0, 0) has no angle");
        return result(std::atan2(a, x[1]) / kDegree, e);
      }
      case O::Pot: return result(a * a, e);
      case O::Trunc: return result(std::trunc(snapToInteger(a)), e);
      case O::MinVal: return result(std::min(a, x[1]), e);
      case O::MaxVal: return result(std::max(a, x[1]), e);
      case O::Bin:
      case O::Bcd: return bcd(e, a);
      case O::Ic:
      case O::Ac:
        // Only an address's whole value (X=IC(5)): the evaluator reads it there.
        fail(failure_, EvalError::AddressValue, e.loc,
             absl::StrCat(ast::opText(e.op), "() gives an axis its value for one block (X=",
                          ast::opText(e.op), "(5)); it is not a value of an expression"));
        return std::nullopt;
      default:
        return unknown(e, "function");
    }
  }

  // BIN: the BCD digits in the bits of x, as a number (BIN[100] = 64: 100 = 0x64).
  // BCD: x written as BCD digits, as a number (BCD[100] = 256 = 0x100). Mazak §13-9-5 16.
  std::optional<Value> bcd(const ast::Expr& e, double a) {
    const double r = snapToInteger(a);
    if (r != std::trunc(r) || r < 0.0)
      return domain(e, a, "a whole number from 0 is needed");
    if (e.op == ast::Op::Bin) {
      if (r > 4294967295.0) return domain(e, a, "more than 32 bits");
      uint64_t bits = static_cast<uint64_t>(r);
      int64_t value = 0, scale = 1;
      for (; bits != 0; bits >>= 4, scale *= 10) {
        const uint64_t digit = bits & 0xF;
        if (digit > 9) return domain(e, a, "a nibble above 9 is not a BCD digit");
        value += static_cast<int64_t>(digit) * scale;
      }
      return Value::of(static_cast<double>(value));
    }
    if (r > 99999999.0) return domain(e, a, "more than 8 BCD digits (32 bits)");
    int64_t n = static_cast<int64_t>(r);
    uint64_t bits = 0;
    for (int shift = 0; n != 0; n /= 10, shift += 4) bits |= static_cast<uint64_t>(n % 10) << shift;
    return Value::of(static_cast<double>(bits));
  }

  const MacroRules& rules_;
  const ExpressionContext& context_;
  Failure& failure_;
};

// Brackets a node opens: [ ], a function's brackets, #[ ] (a variable whose number is not a
// plain literal: the parser keeps no node for the brackets of #[..]).
int opens(const ast::Expr& e) {
  switch (e.kind) {
    case ast::Expr::Kind::Bracket:
    case ast::Expr::Kind::Call:
      return 1;
    case ast::Expr::Kind::Variable:
      return e.args.empty() || e.args[0].isLiteral() ? 0 : 1;
    default:
      return 0;
  }
}

// `level` counts the nodes from the root (1 at the root). The frontend builds no tree deeper
// than ast::kMaxExprDepth; one from elsewhere (a block store, a test) is refused here, before
// this walk or the evaluator recurse once per level into it.
bool depthWithin(const ast::Expr& e, int depth, int level, const MacroRules& rules,
                 Failure& failure) {
  if (level > ast::kMaxExprDepth)
    return fail(failure, EvalError::BracketNesting, e.loc,
                absl::StrCat("expression nested deeper than ", ast::kMaxExprDepth, " levels"));
  depth += opens(e);
  if (depth > rules.max_bracket_depth)
    return fail(failure, EvalError::BracketNesting, e.loc,
                absl::StrCat("brackets nested ", depth, " deep; at most ",
                             rules.max_bracket_depth, " levels, function brackets included"));
  for (const ast::Expr& arg : e.args)
    if (!depthWithin(arg, depth, level + 1, rules, failure)) return false;
  return true;
}

}  // namespace

bool checkBracketDepth(const ast::Expr& expr, const MacroRules& rules, int enclosing,
                       Failure& failure) {
  return depthWithin(expr, enclosing, 1, rules, failure);
}

std::optional<Value> evaluate(const ast::Expr& expr, const ExpressionContext& context,
                              Failure& failure) {
  if (!checkBracketDepth(expr, context.rules, context.enclosing_brackets, failure))
    return std::nullopt;
  return Evaluator(context, failure).eval(expr);
}

ValueKind kindOf(const ast::Expr& e, const VariableReader& variables) {
  switch (e.kind) {
    case ast::Expr::Kind::String:
      return ValueKind::String;
    case ast::Expr::Kind::Bracket:
      return e.args.empty() ? ValueKind::Number : kindOf(e.args[0], variables);
    case ast::Expr::Kind::Name: {
      if (!e.text || (*e.text)[0] == '$') return ValueKind::Number;
      const ast::DataType t = variables.namedType(*e.text);
      return t == ast::DataType::String ? ValueKind::String
             : t == ast::DataType::Char ? ValueKind::Char
                                        : ValueKind::Number;
    }
    case ast::Expr::Kind::Binary:
      return e.op == ast::Op::Concat ? ValueKind::String : ValueKind::Number;
    case ast::Expr::Kind::Call:
      return e.op == ast::Op::SubStr || e.op == ast::Op::ToUpper || e.op == ast::Op::ToLower ||
                     e.op == ast::Op::Sprint
                 ? ValueKind::String
                 : ValueKind::Number;
    default:
      return ValueKind::Number;
  }
}

std::optional<std::string> evaluateText(const ast::Expr& expr, const ExpressionContext& context,
                                        Failure& failure) {
  if (!checkBracketDepth(expr, context.rules, context.enclosing_brackets, failure))
    return std::nullopt;
  return Evaluator(context, failure).evalText(expr);
}

std::optional<int64_t> variableNumber(const Value& value, const MacroRules& rules,
                                      SourceLocation loc, Failure& failure) {
  if (value.vacant) {
    fail(failure, EvalError::VariableNumber, loc, "the variable number is vacant");
    return std::nullopt;
  }
  const double snapped = snapToInteger(value.number);
  const double n = rules.variable_number_rounding == Rounding::Nearest ? std::round(snapped)
                                                                       : std::trunc(snapped);
  if (n < 0.0 || !(n <= 2147483647.0)) {
    fail(failure, EvalError::VariableNumber, loc,
         absl::StrCat("variable number ", formatNumber(value.number),
                      n < 0.0 ? " is negative" : " is out of range"));
    return std::nullopt;
  }
  return static_cast<int64_t>(n);
}

std::optional<int64_t> assignmentTarget(const ast::Expr& target, const ExpressionContext& context,
                                        Failure& failure) {
  if (target.kind != ast::Expr::Kind::Variable || target.args.empty()) {
    fail(failure, EvalError::VariableNumber, target.loc, "the left side is not a variable");
    return std::nullopt;
  }
  ExpressionContext inner = context;
  inner.enclosing_brackets += opens(target);
  auto index = evaluate(target.args[0], inner, failure);
  if (!index) return std::nullopt;
  auto n = variableNumber(*index, context.rules, target.loc, failure);
  if (!n) return std::nullopt;
  if (*n == 0) {
    fail(failure, EvalError::VariableReadOnly, target.loc,
         "#0 is always vacant and cannot be assigned");
    return std::nullopt;
  }
  return n;
}

bool isTrue(const Value& value) { return !value.vacant && value.number != 0.0; }

std::optional<Value> VariableReader::readR(int64_t n, SourceLocation loc, Failure& failure) {
  fail(failure, EvalError::UndefinedName, loc, absl::StrCat("R", n, " is not a variable here"));
  return std::nullopt;
}

std::optional<Value> VariableReader::readNamed(std::string_view name, std::span<const int64_t>,
                                               SourceLocation loc, Failure& failure) {
  fail(failure, EvalError::UndefinedName, loc, absl::StrCat("'", std::string(name), "' is not defined"));
  return std::nullopt;
}

ast::DataType VariableReader::namedType(std::string_view) const { return ast::DataType::None; }

std::optional<std::string> VariableReader::readText(std::string_view name, std::span<const int64_t>,
                                                    SourceLocation loc, Failure& failure) {
  fail(failure, EvalError::UndefinedName, loc, absl::StrCat("'", std::string(name), "' is not defined"));
  return std::nullopt;
}

std::optional<Value> unsupportedSystemVariable(std::string_view name, SourceLocation loc,
                                               Failure& failure) {
  fail(failure, EvalError::NotSupported, loc,
       absl::StrCat("system variable ", std::string(name), " is not supported yet (docs/din.md)"));
  return std::nullopt;
}

std::optional<Value> VariableReader::readSystem(std::string_view name, std::span<const SystemIndex>,
                                                SourceLocation loc, Failure& failure) {
  return unsupportedSystemVariable(name, loc, failure);
}

std::optional<std::vector<int64_t>> indicesOf(const std::vector<ast::Expr>& args,
                                              const ExpressionContext& context, Failure& failure) {
  std::vector<int64_t> out;
  out.reserve(args.size());
  for (const ast::Expr& a : args) {
    std::optional<Value> v = evaluate(a, context, failure);
    if (!v) return std::nullopt;
    const double r = std::round(snapToInteger(v->arithmetic()));
    if (!(r >= -2147483648.0 && r <= 2147483647.0)) {
      fail(failure, EvalError::ArrayIndex, a.loc,
           absl::StrCat("index ", formatNumber(v->arithmetic()), " is out of range"));
      return std::nullopt;
    }
    out.push_back(static_cast<int64_t>(r));
  }
  return out;
}

}  // namespace ncc::eval
