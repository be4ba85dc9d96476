// SPDX-License-Identifier: Apache-2.0
// glint's gas band-model table (data/atmosphere/gas_band_model.csv) for the tests that need
// the parametric atmosphere's gas absorption: read once per test executable.
#pragma once

#include <filesystem>
#include <memory>

#include "glint/atmosphere/gas_absorption.h"
#include "glint/io/input_files.h"

namespace glint::test {

/// The table, read from the source tree on first use.
inline std::shared_ptr<const atmosphere::GasBandModel> gas_table() {
    static const auto loaded =
        std::make_shared<const atmosphere::GasBandModel>(atmosphere::GasBandModel::from_csv(
            io::read_input_file(std::filesystem::path(GLINT_SOURCE_DIR) / "data" /
                                atmosphere::GasBandModel::kRelativePath),
            atmosphere::GasBandModel::kRelativePath));
    return loaded;
}

}  // namespace glint::test
