#pragma once
// absl::StrCat / StrJoin that also take std::string_view: Debian's abseil is built with its
// own absl::string_view class, which does not convert from std::string_view.
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace ncc::machine_file {

template <typename T>
decltype(auto) alphaNum(const T& v) {
  if constexpr (std::is_convertible_v<const T&, std::string_view> &&
                !std::is_convertible_v<const T&, absl::string_view>) {
    std::string_view s = v;
    return absl::string_view(s.data(), s.size());
  } else {
    return (v);
  }
}

template <typename... Args>
std::string cat(const Args&... args) {
  return absl::StrCat(alphaNum(args)...);
}

template <typename Range>
std::string join(const Range& items, std::string_view separator) {
  std::string out;
  bool first = true;
  for (const auto& item : items) {
    if (!first) out += separator;
    out += std::string_view(item);
    first = false;
  }
  return out;
}

}  // namespace ncc::machine_file
