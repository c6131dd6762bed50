#pragma once
// A short string held inline (no allocation; copying it is copying its bytes): the names the
// per-block hot path copies, such as a word's address or the work offset in force. Text longer
// than Capacity is cut to it: the callers hold names whose length their input bounds (see the
// aliases that use it).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace ncc {

template <size_t Capacity>
class InlineString {
  static_assert(Capacity < 256, "the size is one byte");

 public:
  static constexpr size_t kCapacity = Capacity;
  constexpr InlineString() = default;
  constexpr explicit InlineString(char c) : size_(1) { text_[0] = c; }
  constexpr InlineString(std::string_view text)
      : size_(static_cast<uint8_t>(std::min(text.size(), Capacity))) {
    for (size_t i = 0; i < size_; ++i) text_[i] = text[i];
  }
  constexpr InlineString(const char* text) : InlineString(std::string_view(text)) {}
  InlineString(const std::string& text) : InlineString(std::string_view(text)) {}

  constexpr std::string_view view() const { return {text_.data(), size_}; }
  constexpr operator std::string_view() const { return view(); }
  constexpr const char* c_str() const { return text_.data(); }  // for absl::StrCat
  std::string str() const { return std::string(view()); }
  constexpr size_t size() const { return size_; }
  constexpr bool empty() const { return size_ == 0; }
  constexpr char operator[](size_t i) const { return text_[i]; }
  constexpr bool is(char c) const { return size_ == 1 && text_[0] == c; }  // the one letter c

  friend constexpr bool operator==(const InlineString& a, const InlineString& b) {
    return a.view() == b.view();
  }
  friend constexpr bool operator==(const InlineString& a, std::string_view b) { return a.view() == b; }
  friend constexpr bool operator==(const InlineString& a, const char* b) { return a.view() == b; }
  friend constexpr bool operator==(const InlineString& a, const std::string& b) { return a.view() == b; }

 private:
  std::array<char, Capacity + 1> text_{};  // NUL-terminated
  uint8_t size_ = 0;
};

}  // namespace ncc
