#pragma once
// The settings reference, docs/settings.md: every field of settings_fields.h with its default,
// the values it accepts, the default's source and why. `slamkit settings --markdown` prints it
// and a test keeps the committed file equal to it.
#include <string>
#include <type_traits>

#include "core/number_format.h"
#include "settings/settings_fields.h"

namespace slamkit {

// A setting's value as a settings file holds it (as `slamkit settings` writes it).
template <class T>
std::string setting_value_text(const T& value) {
  if constexpr (std::is_same_v<T, bool>) {
    return value ? "true" : "false";
  } else if constexpr (std::is_enum_v<T>) {
    return name_of(enum_names(value), value);
  } else if constexpr (std::is_floating_point_v<T>) {
    return format_exact(value);
  } else {
    return std::to_string(value);
  }
}

// Markdown: one table per top-level section, one row per field, keyed by dotted name.
std::string settings_reference_markdown();

}  // namespace slamkit
