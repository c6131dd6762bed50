#pragma once
// Exhaustive visits of IR operations. A pass that looks at operations names what each kind is
// to it, one case per kind:
//
//   std::visit(ir::Overloaded{
//       [&](ir::Rapid& o) { ... }, [&](ir::Linear& o) { ... }, ...,
//       ir::Leave<ir::HoleCycle>{},  // said, not skipped
//       ir::NoPoint{},
//   }, op);
//
// std::visit does not compile unless some case takes every kind of ir::Operation, so a kind
// added to the IR cannot pass silently through a pass that does not know it (the bytecode
// encoder, backend/src/encode.cpp, and the verifier are written this way too). A generic
// `[](auto&)` case would defeat that: passes do not write one.
#include "ncc/ir/ir.h"

namespace ncc::ir {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
// Clang before 17 does not deduce aggregate template arguments (the fuzz build uses clang).
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// Cases that leave the kinds they name as they are.
template <class T>
struct LeaveOne {
  void operator()(T&) const {}
  void operator()(const T&) const {}
};
template <class... T>
struct Leave : LeaveOne<T>... {
  using LeaveOne<T>::operator()...;
};

// The operation kinds that carry no point (no target, no position): a pass that maps or moves
// points leaves them. A kind added to the IR joins this list or gets its own case in each pass.
using NoPoint = Leave<Dwell, MachineFunction, SetVariable, Prepare>;

}  // namespace ncc::ir
