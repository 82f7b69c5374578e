#pragma once
// The settings reference, docs/settings.md: every field of settings_fields.h with its default,
// the values it accepts, the default's source and why. `slamkit settings --markdown` prints it
// and a test keeps the committed file equal to it.
#include <string>

namespace slamkit {

// Markdown: one table per top-level section, one row per field, keyed by dotted name.
std::string settings_reference_markdown();

}  // namespace slamkit
