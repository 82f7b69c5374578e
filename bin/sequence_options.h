#pragma once
// The options every command that reads a TUM sequence shares.
#include <CLI/CLI.hpp>
#include <memory>
#include <optional>

#include "core/settings/pipeline_settings.h"
#include "io/tum_sequence.h"

namespace slamkit::cli {

// Adds --calibration, --association, --depth-scale, --max-diff, --offset to `command`,
// writing into `options` (which must outlive parsing).
void add_sequence_options(CLI::App* command, SequenceOptions& options);

// Adds --lost-frames omit|motion-model (track and run): what trajectory files hold for a frame
// whose tracking failed; unset, the settings decide (pipeline.lost_frames, default omit).
void add_lost_frames_option(CLI::App* command, std::optional<LostFrames>& lost_frames);

}  // namespace slamkit::cli
