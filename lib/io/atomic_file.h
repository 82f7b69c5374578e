#pragma once
// Output files written whole or not at all: the bytes go to "<name>.tmp" in the same folder,
// which is renamed into place once complete, so a crash or a full disk never leaves a
// truncated file under the real name.
#include <filesystem>
#include <functional>
#include <ostream>

namespace slamkit {

// Calls `write` on a stream to the temporary, then renames it to `path`. The folder must
// exist. Throws InputError naming `path` when it cannot be written; the temporary is removed
// on any failure, including an exception from `write`.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

// Removes the temporaries being written at this moment. Async-signal-safe (unlink only): for
// a handler that ends the process mid-write.
void remove_pending_temporaries() noexcept;

}  // namespace slamkit
