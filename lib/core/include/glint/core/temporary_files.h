// SPDX-License-Identifier: Apache-2.0
// The temporary files a tool has open under their final folders (AtomicFile's
// `.NAME.tmp-XXXXXX`), for the one place that cannot run their destructors: a second stop
// signal, which ends the process at once — the tool runner's signal handler removes them
// first. A fixed table, filled and read with atomics, so the handler only reads memory and
// calls unlink(2), both async-signal-safe.
#pragma once

#include <filesystem>

namespace glint::temporary_files {

/// How many temporary files are tracked at once (a render writes a few per focal plane).
inline constexpr int kSlots = 256;

/// Registers `path`; returns its slot, or -1 when the table is full or the path longer than
/// PATH_MAX (it is then removed by its owner only).
int add(const std::filesystem::path& path) noexcept;
/// Forgets `slot` once its file is renamed into place or removed; -1 does nothing.
void remove(int slot) noexcept;
/// Unlinks every registered file. Async-signal-safe.
void unlink_all() noexcept;

}  // namespace glint::temporary_files
