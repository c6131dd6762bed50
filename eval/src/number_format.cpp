#include "number_format.h"

#include <cstdio>

namespace ncc::eval {

std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

}  // namespace ncc::eval
