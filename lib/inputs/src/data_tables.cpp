// SPDX-License-Identifier: Apache-2.0
// read_data_tables (glint/inputs/data_tables.h): glint's own data files read whole, then
// parsed by the atmosphere component.
#include "glint/inputs/data_tables.h"

#include <memory>
#include <string>

#include "glint/io/input_files.h"

namespace glint::inputs {

atmosphere::DataTables read_data_tables(const std::filesystem::path& data_dir, bool with_gas_table,
                                        bool with_aerosol_table) {
    atmosphere::DataTables tables;
    const std::filesystem::path solar = data_dir / atmosphere::SolarSpectrum::kAstmRelativePath;
    tables.sun =
        std::make_shared<const atmosphere::SolarSpectrum>(atmosphere::SolarSpectrum::from_astm_g173(
            io::read_input_file(solar, solar.string()), solar.string()));
    if (with_gas_table) {
        const std::filesystem::path gases = data_dir / atmosphere::GasBandModel::kRelativePath;
        tables.gases =
            std::make_shared<const atmosphere::GasBandModel>(atmosphere::GasBandModel::from_csv(
                io::read_input_file(gases, gases.string()), gases.string()));
    }
    if (with_aerosol_table) {
        const std::filesystem::path aerosols = data_dir / atmosphere::AerosolTable::kRelativePath;
        tables.aerosols =
            std::make_shared<const atmosphere::AerosolTable>(atmosphere::AerosolTable::from_csv(
                io::read_input_file(aerosols, aerosols.string()), aerosols.string()));
    }
    return tables;
}

}  // namespace glint::inputs
