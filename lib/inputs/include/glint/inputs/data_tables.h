// SPDX-License-Identifier: Apache-2.0
// glint's own data files, read as inputs are: the solar spectrum (solar/astm_g173.csv), the
// gas band-model table (atmosphere/gas_band_model.csv) and the aerosol optics table
// (atmosphere/aerosol_optics.csv) of its data folder, handed to the render as
// atmosphere::DataTables (the atmosphere component parses them and opens no file).
#pragma once

#include <filesystem>

#include "glint/atmosphere/atmosphere.h"

namespace glint::inputs {

/// Reads glint's data tables from `data_dir`: the solar spectrum, the gas band-model table
/// when `with_gas_table` (atmosphere::needs_gas_table of the run's atmosphere) and the aerosol
/// optics table when `with_aerosol_table` (atmosphere::needs_aerosol_table). Throws
/// glint::Error (io when a file is unreadable, input with file:line when it is malformed).
atmosphere::DataTables read_data_tables(const std::filesystem::path& data_dir, bool with_gas_table,
                                        bool with_aerosol_table = false);

}  // namespace glint::inputs
