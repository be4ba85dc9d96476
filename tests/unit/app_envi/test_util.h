// SPDX-License-Identifier: Apache-2.0
// Helpers of the app_envi tests: a temporary folder per test and a small ENVI cube writer.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "glint/core/context.h"
#include "glint/core/error.h"
#include "glint/io/envi.h"
#include "glint/test/temp_dir.h"

namespace glint::app_envi::testing {

/// A fresh folder under the system temp folder, removed after the test.
class TempDirTest : public ::testing::Test {
protected:
    std::filesystem::path path(const std::string& name) const { return m_temp / name; }

    /// Writes a BIP cube whose value at (x, y, b) is value(x, y, b).
    std::filesystem::path write_cube(
        const std::string& name, std::size_t samples, std::size_t lines, std::size_t bands,
        io::EnviDataType type,
        const std::function<double(std::size_t, std::size_t, std::size_t)>& value,
        io::EnviHeader header = {}) const {
        header.samples = samples;
        header.lines = lines;
        header.bands = bands;
        header.data_type = type;
        io::EnviWriter writer(path(name), header);
        std::vector<double> line(samples * bands);
        for (std::size_t y = 0; y < lines; ++y) {
            for (std::size_t x = 0; x < samples; ++x) {
                for (std::size_t b = 0; b < bands; ++b) line[x * bands + b] = value(x, y, b);
            }
            writer.write_line(line);
        }
        writer.commit();
        return path(name);
    }

    /// Names in the folder containing ".tmp-" (temporary files that should be gone).
    std::vector<std::string> temporaries() const {
        std::vector<std::string> found;
        for (const auto& entry : std::filesystem::directory_iterator(m_temp.path())) {
            const std::string name = entry.path().filename().string();
            if (name.find(".tmp-") != std::string::npos) found.push_back(name);
        }
        return found;
    }

    glint::test::TempDir m_temp;
    Context m_ctx;
};

/// Expects `run` to throw a usage error whose message contains `needle`.
inline void expect_usage_error(const std::function<void()>& run, const std::string& needle) {
    try {
        run();
        ADD_FAILURE() << "expected an error: " << needle;
    } catch (const Error& e) {
        EXPECT_EQ(e.category(), ErrorCategory::usage) << e.what();
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
}

}  // namespace glint::app_envi::testing
