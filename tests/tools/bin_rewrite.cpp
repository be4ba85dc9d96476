// SPDX-License-Identifier: Apache-2.0
// Test helper: reads a DIRSIG lidar BIN file with glint::io::read_bin and writes it again with
// glint::io::write_bin (version 2, little endian, zlib), so an independent reader
// (tests/data/lidar_bin/bin_tool.py) can check glint's writer against glint's reader.
// Usage: bin_rewrite IN.bin OUT.bin
#include <cstdio>
#include <exception>

#include "glint/io/lidar_bin.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: bin_rewrite IN.bin OUT.bin\n");
        return 2;
    }
    try {
        glint::io::write_bin(argv[2], glint::io::read_bin(argv[1]));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bin_rewrite: %s\n", e.what());
        return 1;
    }
    return 0;
}
