// SPDX-License-Identifier: Apache-2.0
// What every fuzz target shares: the input as text, ReadOptions whose files come from memory
// (the input under a fixed path in a folder that does not exist, a one-triangle OBJ for any
// `.obj`, nothing else), and the rule that glint::Error is a normal outcome. Anything else a
// reader lets escape (another exception, a crash, a sanitizer report, a hang, a memory blow-up)
// is a finding. docs/testing.md ("Fuzzing") describes the targets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "glint/core/diagnostics.h"
#include "glint/core/error.h"
#include "glint/dirsig/read_options.h"
#include "glint/io/input_files.h"

namespace glint::fuzz {

/// The folder the fuzz inputs pretend to live in; it does not exist, so a path the input
/// names that is not served from memory is a missing file.
inline const std::filesystem::path kFolder = "/nonexistent-glint-fuzz";

/// A valid one-triangle OBJ, served for every `.obj` path the input names.
inline constexpr const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

inline std::string as_text(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

/// ReadOptions reading `input` as `kFolder/name` and `extra` texts by their paths; every
/// other file is missing. No variable is defined (`$DIRSIG_HOME` is an error), so the run
/// does not depend on the environment.
inline dirsig::ReadOptions memory_options(const std::string& name, std::string input,
                                          std::map<std::filesystem::path, std::string> extra = {}) {
    extra[kFolder / name] = std::move(input);
    auto texts =
        std::make_shared<const std::map<std::filesystem::path, std::string>>(std::move(extra));
    dirsig::ReadOptions options;
    options.paths.environment = [](const std::string&) -> std::optional<std::string> {
        return std::nullopt;
    };
    options.files = std::make_shared<io::InputFiles>(
        Log{}, [texts](const std::filesystem::path& path, const std::string& display_name) {
            const std::string& shown = display_name.empty() ? path.string() : display_name;
            const auto found = texts->find(path.lexically_normal());
            if (found != texts->end()) return found->second;
            if (path.extension() == ".obj") return std::string(kTriangleObj);
            throw io_error("cannot open file: No such file or directory", shown);
        });
    return options;
}

/// Runs `read`, treating glint::Error as a normal outcome (a reader may throw it instead of
/// filling its diagnostics). Everything else propagates to libFuzzer as a crash.
template <typename Read>
int run(Read&& read) {
    try {
        Diagnostics diagnostics;
        read(diagnostics);
        for (const Diagnostic& d : diagnostics.items()) (void)d.text();  // messages format
    } catch (const Error& error) {
        (void)error.what();
    }
    return 0;
}

}  // namespace glint::fuzz
