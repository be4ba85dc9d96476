// SPDX-License-Identifier: Apache-2.0
// Running independent programs from oracle tests: an argv through glint's process runner (no
// shell), whether a program or Python module is there (tests skip with a message if not),
// and small Python scripts run by GLINT_ORACLE_PYTHON (Debian's /usr/bin/python3).
#pragma once

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "glint/process/process.h"
#include "glint/test/temp_dir.h"

#ifndef GLINT_ORACLE_PYTHON
#error "oracle tests need GLINT_ORACLE_PYTHON (set by glint_add_oracle_test)"
#endif

namespace glint::test {

struct CommandResult {
    int exit_status = -1;
    std::string out;  ///< stdout
    std::string err;  ///< stderr
};

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream stream(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
}

/// Runs `argv` (no shell) through glint's process runner, capturing stdout and stderr.
inline CommandResult run_command(const std::vector<std::string>& argv) {
    process::ProcessOptions options;
    options.argv = argv;
    options.stdout_mode = process::OutputMode::capture;
    options.capture_limit_bytes = 64 << 20;
    options.timeout = std::chrono::seconds(120);
    const process::ProcessResult result = process::run_process(options);
    return CommandResult{result.exit_code, result.stdout_text, result.stderr_text};
}

inline bool program_exists(const std::string& name) {
    return process::find_program(name).has_value();
}

/// Whether GLINT_ORACLE_PYTHON can import every module of `modules` ("spectral, numpy").
inline bool python_has(const std::string& modules) {
    return run_command({GLINT_ORACLE_PYTHON, "-c", "import " + modules}).exit_status == 0;
}

/// Writes a Python script into `dir` and returns the argv that runs it with `args`.
inline std::vector<std::string> python_command(const TempDir& dir, const std::string& script,
                                               const std::vector<std::string>& args) {
    const std::filesystem::path path = dir.path() / "oracle.py";
    std::ofstream(path) << script;
    std::vector<std::string> argv{GLINT_ORACLE_PYTHON, path.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
}

}  // namespace glint::test
