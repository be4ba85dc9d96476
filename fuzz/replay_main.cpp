// SPDX-License-Identifier: Apache-2.0
// A main for the fuzz targets without libFuzzer: runs LLVMFuzzerTestOneInput once on every
// file named on the command line and on every file under every folder named (recursively,
// in name order; names starting with '.' and README.md are skipped), printing each file's
// path to stderr before it runs, so a crash or a hang names its input. The normal build
// links each fuzz target with it as tests/fuzz_replay_<target>, and ctest runs it over the
// target's corpus and crash inputs (label fuzz, docs/testing.md).
// Exit status: 0 when every input ran, 1 when a path cannot be read, 2 without arguments.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

bool skipped(const std::filesystem::path& path) {
    const std::string name = path.filename().string();
    return name.empty() || name.front() == '.' || name == "README.md";
}

/// The files to run for one argument; false when it cannot be listed.
bool collect(const std::filesystem::path& argument, std::vector<std::filesystem::path>& files) {
    std::error_code ec;
    if (!std::filesystem::is_directory(argument, ec)) {
        files.push_back(argument);
        return true;
    }
    std::vector<std::filesystem::path> found;
    for (std::filesystem::recursive_directory_iterator it(argument, ec), end; !ec && it != end;
         it.increment(ec)) {
        if (skipped(it->path())) {
            if (it->is_directory()) it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file()) found.push_back(it->path());
    }
    if (ec) {
        std::cerr << "replay: cannot list " << argument.string() << ": " << ec.message() << "\n";
        return false;
    }
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: " << argv[0] << " FILE_OR_FOLDER...\n";
        return 2;
    }
    std::vector<std::filesystem::path> files;
    for (int i = 1; i < argc; ++i) {
        if (!collect(argv[i], files)) return 1;
    }
    for (const std::filesystem::path& file : files) {
        std::cerr << "replay: " << file.string() << std::endl;
        std::ifstream stream(file, std::ios::binary);
        if (!stream) {
            std::cerr << "replay: cannot open " << file.string() << "\n";
            return 1;
        }
        const std::string bytes((std::istreambuf_iterator<char>(stream)),
                                std::istreambuf_iterator<char>());
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
    std::cerr << "replay: " << files.size() << " inputs ran\n";
    return 0;
}
