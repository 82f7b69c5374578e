#pragma once
// Names of enum values in files and on command lines. One table per enum serves printing,
// parsing and the list of choices in error messages, so the three cannot drift apart.
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace slamkit {

template <class E>
struct EnumName {
  E value;
  const char* name;
};

template <class E, size_t N>
using EnumNames = std::array<EnumName<E>, N>;

template <class E, size_t N>
const char* name_of(const EnumNames<E, N>& names, E value) {
  for (const EnumName<E>& entry : names)
    if (entry.value == value) return entry.name;
  throw std::logic_error("an enum value without a name");
}

template <class E, size_t N>
std::optional<E> value_named(const EnumNames<E, N>& names, std::string_view name) {
  for (const EnumName<E>& entry : names)
    if (name == entry.name) return entry.value;
  return std::nullopt;
}

// The choices for a message: "a, b or c".
template <class E, size_t N>
std::string choices(const EnumNames<E, N>& names) {
  std::string text;
  for (size_t i = 0; i < N; ++i)
    text += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(names[i].name);
  return text;
}

}  // namespace slamkit
