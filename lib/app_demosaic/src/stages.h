// SPDX-License-Identifier: Apache-2.0
// Internal: the stages of glint-demosaic — opening the mosaic and reading its lines, passes of
// a DemosaicStream over it, and writing the demosaiced lines as ENVI or through OpenImageIO.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glint/app_demosaic/demosaic_tool.h"

namespace glint::app_demosaic::internal {

/// A mosaic file, described (its lines are read by line_reader).
struct MosaicSource {
    std::filesystem::path path;
    std::size_t width = 0;
    std::size_t height = 0;
    std::size_t max_memory_bytes = kDefaultMaxMemoryBytes;  ///< --max-memory, for the readers
    std::optional<io::EnviHeader> envi;                     ///< the header, for ENVI inputs
    std::string type_name;                                  ///< "uint16", "float32", ...
    std::vector<std::filesystem::path> files;               ///< every file read (overwrite checks)
};

/// Opens a one-band ENVI file, or an image when the name has an image extension, and
/// describes it. Throws glint::Error naming the file (also for a line over the readers' share
/// of `max_memory_bytes`, glint/io/line_memory.h).
MosaicSource open_mosaic(const std::filesystem::path& path, std::size_t max_memory_bytes);

/// A reader of the mosaic's lines as doubles, over its own handle on the file (one per pass);
/// its errors name the file.
demosaic::MosaicLineReader line_reader(const MosaicSource& source);

/// Demosaics the whole mosaic once, handing each output line (width × 3 values) to `use` in
/// order; polls cancellation and reports progress as `stage`.
void demosaic_pass(const MosaicSource& source, const demosaic::DemosaicOptions& used,
                   const std::string& stage, Context& ctx,
                   const std::function<void(std::size_t y, std::span<const double> rgb)>& use);

/// What the writers record about the run.
struct Provenance {
    std::filesystem::path source;
    demosaic::DemosaicOptions used;
    std::string command_line;
};

/// A one-line description: "<pattern> [<phase>] <method> demosaic of <file name>".
std::string describe(const Provenance& provenance);

/// Demosaics into an ENVI file (see demosaic.h); returns the stored type's name.
std::string write_envi(const std::filesystem::path& output, const MosaicSource& source,
                       const Provenance& provenance, std::optional<io::EnviDataType> data_type,
                       Context& ctx);

/// Demosaics into an image of `kind` with the stretch the options ask for (the limits take one
/// or two more passes); fills the result's limits and stored type.
void write_picture(const Options& options, io::OutputKind kind, const MosaicSource& source,
                   const Provenance& provenance, Result& result, Context& ctx);

}  // namespace glint::app_demosaic::internal
