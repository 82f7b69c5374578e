#pragma once
// The options every command that reads a TUM sequence shares.
#include <CLI/CLI.hpp>
#include <memory>

#include "io/tum_sequence.h"

namespace slamkit::cli {

// Adds --calibration, --association, --depth-scale, --max-diff, --offset to `command`,
// writing into `options` (which must outlive parsing).
void add_sequence_options(CLI::App* command, SequenceOptions& options);

}  // namespace slamkit::cli
