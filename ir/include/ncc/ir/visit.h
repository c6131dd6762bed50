#pragma once
// Exhaustive visits of IR operations. A pass that looks at operations names what each kind is
// to it, one case per kind:
//
//   std::visit(ir::Overloaded{
//       [&](ir::Rapid& o) { ... }, [&](ir::Linear& o) { ... }, ...,
//       [](ir::Prepare&) {},  // nothing to map: said, not skipped
//   }, op);
//
// std::visit does not compile unless some case takes every kind of ir::Operation, so a kind
// added to the IR cannot pass silently through a pass that does not know it (the bytecode
// encoder, backend/src/encode.cpp, and the verifier are written this way too). A generic
// `[](auto&)` case would defeat that: passes do not write one.
namespace ncc::ir {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
// Clang before 17 does not deduce aggregate template arguments (the fuzz build uses clang).
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace ncc::ir
