// SPDX-License-Identifier: Apache-2.0
// Internal: the stages of glint-demosaic — reading the mosaic, and writing the demosaiced
// image as ENVI or through OpenImageIO.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glint/app_demosaic/demosaic.h"

namespace glint::app_demosaic::internal {

/// A mosaic read into memory, and what is known about its file.
struct MosaicSource {
    demosaic::Plane plane;
    std::optional<io::EnviHeader> envi;        ///< the header, for ENVI inputs
    std::string type_name;                     ///< "uint16", "float32", ...
    std::vector<std::filesystem::path> files;  ///< every file read (overwrite checks)
};

/// Reads a one-band ENVI file, or an image when the name has an image extension. Throws
/// glint::Error naming the file.
MosaicSource read_mosaic(const std::filesystem::path& path, Context& ctx);

/// What the writers record about the run.
struct Provenance {
    std::filesystem::path source;
    demosaic::DemosaicOptions used;
    std::string command_line;
};

/// A one-line description: "<pattern> [<phase>] <method> demosaic of <file name>".
std::string describe(const Provenance& provenance);

/// Writes an ENVI file (see demosaic.h); returns the stored type's name.
std::string write_envi(const std::filesystem::path& output, const demosaic::RgbImage& image,
                       const MosaicSource& source, const Provenance& provenance,
                       std::optional<io::EnviDataType> data_type, Context& ctx);

/// Writes an image of `kind` with the stretch the options ask for; fills the result's
/// limits and stored type.
void write_picture(const Options& options, io::OutputKind kind, const demosaic::RgbImage& image,
                   const Provenance& provenance, Result& result, Context& ctx);

}  // namespace glint::app_demosaic::internal
