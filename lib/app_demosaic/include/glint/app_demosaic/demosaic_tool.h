// SPDX-License-Identifier: Apache-2.0
// `glint-demosaic IN OUT`: a one-band colour filter array image (ENVI, or any image
// OpenImageIO reads) demosaiced (lib/demosaic) to three bands R, G, B, written as ENVI or as
// PNG/TIFF/JPEG/EXR/PPM through OpenImageIO, atomically. The image is streamed: a
// demosaic::DemosaicStream reads the mosaic line by line and each output line is written as it
// is made, so memory holds a window of lines (a few dozen lines' worth at most), whatever the
// height; a mosaic so wide that the window would pass the context's --max-memory is refused
// with the memory it needs (pan-guided: 536 bytes per pixel of width). A stretch whose limits come
// from the data reads the mosaic once more (min/max) or twice more (percentiles) before writing.
//
// Output kind: `format` (png, tiff, jpeg, exr, ppm, envi), else the output's extension
// (.png, .tif/.tiff, .jpg/.jpeg, .exr, .ppm/.pnm; .img, .dat, .raw, .bsq, .bil, .bip, .envi
// → ENVI).
//
// ENVI outputs get the demosaiced values unchanged in `data_type`, else the input's ENVI type
// (complex → float32/float64; image inputs: float32); integer types are rounded and clamped
// (MHC may overshoot the input's range near edges; ask for float32 to keep it). Band names
// R, G, B; data units copied from an ENVI input; provenance keys `glint tool`, `glint
// version`, `glint source`, `glint command line` (when given), `glint cfa pattern`, `glint cfa
// phase` (Bayer only) and `glint demosaic method`.
//
// Pattern and phase: as given, else as the input's header records them (`glint cfa pattern`,
// `glint cfa phase`, the keys glint-detect writes), else bayer and rggb. Given values that
// differ from the header's are used, with a warning.
//
// Image outputs go through the stretch of glint-envi convert (glint/io/stretch.h), one
// stretch for the three channels so that colours keep their balance:
//   fixed    min and max: s = clamp((v - min) / (max - min), 0, 1)
//   percent  percent P in [0, 50): the percentile limits of io/stretch.h
//   min/max  the default for 8/16-bit outputs (and for float outputs given a gamma)
//   none     raw, and the default for float (EXR, 32-bit TIFF) outputs: values unchanged
// then s^(1/gamma), times 255 or 65535 and rounded for 8/16-bit outputs. PNG, JPEG and PPM
// default to 8 bits, TIFF to 8, EXR to float; bit_depth picks 8, 16 or 32 where the format
// stores it.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "glint/core/context.h"
#include "glint/demosaic/demosaic.h"
#include "glint/io/envi.h"
#include "glint/io/output_kind.h"
#include "glint/io/stretch.h"

namespace glint::app_demosaic {

/// Options of glint-demosaic.
struct Options {
    std::filesystem::path input;
    std::filesystem::path output;
    /// Unset: the input header's `glint cfa pattern` (glint-detect writes it), else bayer.
    std::optional<demosaic::CfaPattern> pattern;
    /// Bayer only. Unset: the input header's `glint cfa phase`, else rggb.
    std::optional<demosaic::BayerPhase> phase;
    std::optional<demosaic::DemosaicMethod> method;  ///< default_method(pattern) when unset
    /// "png", "tiff", "jpeg", "exr", "ppm" or "envi"; empty = from the output's extension.
    std::string format;
    std::optional<double> percent;  ///< percentile stretch, [0, 50)
    std::optional<double> min;      ///< fixed stretch (with max)
    std::optional<double> max;
    std::optional<double> gamma;                ///< > 0; 1 when unset
    bool raw = false;                           ///< image outputs: no stretch
    std::optional<int> bit_depth;               ///< image outputs: 8, 16 or 32
    std::optional<io::EnviDataType> data_type;  ///< ENVI outputs
};

/// What glint-demosaic did.
struct Result {
    std::size_t width = 0;
    std::size_t height = 0;
    demosaic::DemosaicOptions used;  ///< pattern, phase and method applied
    io::OutputKind kind = io::OutputKind::envi;
    std::optional<io::StretchLimits> limits;  ///< image outputs with a stretch
    std::string stored_type;  ///< "uint8", "uint16", "float" (images) or the ENVI type name
};

/// Pattern for a command-line name; throws glint::Error (usage) naming the choices.
demosaic::CfaPattern parse_pattern(const std::string& name);
/// Bayer phase for a command-line name; throws glint::Error (usage) naming the choices.
demosaic::BayerPhase parse_phase(const std::string& name);
/// Method for a command-line name; throws glint::Error (usage) naming the choices.
demosaic::DemosaicMethod parse_method(const std::string& name);

/// Reads, demosaics and writes. Throws glint::Error: usage for contradictory options, a
/// method or phase that does not apply to the pattern (checked once the input's header is
/// read, before anything is written), an unknown output format or an output
/// that would overwrite the input; input for a file that is not a one-band image or is
/// smaller than one block of the pattern (both naming the file); io for read/write failures.
/// Nothing is left under the output name unless it succeeded.
Result demosaic_file(const Options& options, Context& ctx);

/// glint-demosaic: demosaic_file; returns the exit status (0; failures are thrown). `out`
/// (stdout) gets nothing: the tool writes its output file.
int run(const Options& options, Context& ctx, std::ostream& out);

}  // namespace glint::app_demosaic
