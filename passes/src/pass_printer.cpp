#include "ncc/passes/pass_printer.h"

namespace ncc::passes {

void PassPrinter::header(std::string_view pass) {
  if (current_ == pass) return;
  out_ << "; after " << pass << '\n';
  current_ = pass;
  shown_.emplace(pass);
}

void PassPrinter::print(std::string_view pass, const ir::Block& block) {
  header(pass);
  ir::printBlock(out_, block, axes_);
}

void PassPrinter::printLine(std::string_view pass, std::string_view line) {
  header(pass);
  out_ << line << '\n';
}

void PassPrinter::finish(std::string_view pass) {
  if (!shown_.contains(std::string(pass))) header(pass);
}

}  // namespace ncc::passes
