#include "io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cstring>
#include <fstream>

#include "core/error.h"

namespace fs = std::filesystem;

namespace slamkit {
namespace {

// Temporaries in progress, one slot each, so that a signal handler can remove them without
// locks or allocation. Writers beyond the slots simply go unregistered.
constexpr int kSlots = 8;
constexpr size_t kPathMax = 4096;
std::atomic<int> g_slot_state[kSlots];  // 0 free, 1 being filled, 2 holds a path
char g_slot_path[kSlots][kPathMax];

int register_temporary(const std::string& path) {
  if (path.size() >= kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!g_slot_state[i].compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_slot_path[i], path.c_str(), path.size() + 1);
    g_slot_state[i].store(2);
    return i;
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0) g_slot_state[slot].store(0);
}

}  // namespace

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  const fs::path temporary = path.parent_path() / (path.filename().string() + ".tmp");
  const int slot = register_temporary(temporary.string());
  std::error_code error;
  const auto give_up = [&](const std::string& message) {
    fs::remove(temporary, error);
    unregister_temporary(slot);
    throw_input_error(path.string(), message);
  };
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) give_up("cannot write file (folder missing or not writable?)");
    try {
      write(out);
    } catch (...) {
      out.close();
      fs::remove(temporary, error);
      unregister_temporary(slot);
      throw;
    }
    out.close();
    if (!out) give_up("cannot write file (disk full?)");
  }
  fs::rename(temporary, path, error);
  if (error) give_up("cannot move the written file into place: " + error.message());
  unregister_temporary(slot);
}

void remove_pending_temporaries() noexcept {
  for (int i = 0; i < kSlots; ++i)
    if (g_slot_state[i].load() == 2) ::unlink(g_slot_path[i]);
}

}  // namespace slamkit
