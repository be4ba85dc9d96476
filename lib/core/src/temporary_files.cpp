// SPDX-License-Identifier: Apache-2.0
// The table of temporary files (glint/core/temporary_files.h). Process-wide by necessity: a
// signal handler can reach nothing else.
#include "glint/core/temporary_files.h"

#include <climits>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace glint::temporary_files {
namespace {

enum : int { kFree = 0, kFilling = 1, kReady = 2 };

char g_paths[kSlots][PATH_MAX];
std::atomic<int> g_state[kSlots];

}  // namespace

int add(const std::filesystem::path& path) noexcept {
    const std::string& text = path.native();
    if (text.size() >= PATH_MAX) return -1;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!g_state[i].compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) {
            continue;
        }
        std::memcpy(g_paths[i], text.c_str(), text.size() + 1);
        g_state[i].store(kReady, std::memory_order_release);
        return i;
    }
    return -1;
}

void remove(int slot) noexcept {
    if (slot < 0 || slot >= kSlots) return;
    g_state[slot].store(kFree, std::memory_order_release);
}

void unlink_all() noexcept {
    for (int i = 0; i < kSlots; ++i) {
        if (g_state[i].load(std::memory_order_acquire) == kReady) ::unlink(g_paths[i]);
    }
}

}  // namespace glint::temporary_files
