// SPDX-License-Identifier: Apache-2.0
// glint's aerosol optics table (data/atmosphere/aerosol_optics.csv) for the tests that need the
// parametric atmosphere's layered aerosol: read once per test executable.
#pragma once

#include <filesystem>
#include <memory>

#include "glint/atmosphere/aerosol_table.h"
#include "glint/io/input_files.h"

namespace glint::test {

/// The table, read from the source tree on first use.
inline std::shared_ptr<const atmosphere::AerosolTable> aerosol_table() {
    static const auto loaded =
        std::make_shared<const atmosphere::AerosolTable>(atmosphere::AerosolTable::from_csv(
            io::read_input_file(std::filesystem::path(GLINT_SOURCE_DIR) / "data" /
                                atmosphere::AerosolTable::kRelativePath),
            atmosphere::AerosolTable::kRelativePath));
    return loaded;
}

}  // namespace glint::test
