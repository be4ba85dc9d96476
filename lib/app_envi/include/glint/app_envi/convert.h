// SPDX-License-Identifier: Apache-2.0
// `glint-envi convert IN OUT`: ENVI → PNG/TIFF/JPEG/EXR/PPM (through OpenImageIO), any image
// OpenImageIO reads → ENVI, and ENVI → ENVI (band subset, data type). Streams line by line:
// one pass to write, plus one pass for a min/max stretch or two for a percentile stretch.
//
// Bands are numbered from 0 (`--band 0` is the first band). Default selection for image
// outputs: 1 or 2 bands → band 0; 3 bands → 0,1,2; more, with wavelengths in µm or nm →
// the bands nearest 0.64, 0.55 and 0.46 µm (R,G,B), else 0,1,2. ENVI outputs keep every
// band unless told otherwise.
//
// What reaches an image (see glint/io/stretch.h for the limits):
//   fixed    --min A --max B: s = clamp((v - A) / (B - A), 0, 1)
//   percent  --percent P, 0 <= P < 50: s with the percentile limits of io/stretch.h
//   min/max  the default for 8/16-bit outputs, and for float outputs given --gamma or
//            --per-band: s with the minimum and maximum as limits
//   none     --raw, and the default for float (32-bit, half) outputs: v unchanged
// then s^(1/gamma), times 255 or 65535 and rounded for 8/16-bit outputs. Without a stretch,
// integer outputs get v rounded and clamped to the type's range. Limits are found over all
// output channels together (a band selected twice counts twice) unless per_band. NaN
// becomes 0 in integer outputs. With a stretch, values equal to an ENVI source's
// `data ignore value` count as NaN (left out of the limits, 0 in integer outputs).
//
// Index colour map (glint/app_envi/colormap.h): one selected band of labels becomes three
// channels, index_colour of each value (no data black) times the output's full scale. It
// applies with colormap index, or with automatic when the output is 8- or 16-bit, the one
// band is an index band and no stretch option (--percent, --min/--max, --per-band, --gamma,
// --raw) is given. Colormap index with several bands, an ENVI output or a stretch option is
// a usage error.
//
// ENVI outputs receive the values unchanged (no stretch options allowed), in `data_type`,
// else the type `--bit-depth` names (8 uint8, 16 uint16, 32 float32, 64 float64), else the
// source's type: ENVI sources keep theirs (complex → float32/float64); images map uint8 →
// uint8, int8/int16 → int16, uint16 → uint16, int32 → int32, uint32 → uint32, half/float →
// float32, double → float64. Image channel names become band names; ENVI band metadata
// (names, wavelengths, FWHM, units, description, extra keys) is kept for the selected
// bands; provenance keys `glint tool`, `glint version`, `glint source` (and `glint command line`
// when given) are set.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glint/app_envi/colormap.h"
#include "glint/core/context.h"
#include "glint/io/envi.h"
#include "glint/io/image.h"
#include "glint/io/output_kind.h"
#include "glint/io/stretch.h"

namespace glint::app_envi {

/// Options of `convert`.
struct ConvertOptions {
    std::filesystem::path input;
    std::filesystem::path output;
    /// "png", "tiff", "jpeg", "exr", "ppm" (and their spellings in io::image_format_from_name)
    /// or "envi"; empty = from the output's extension.
    std::string format;
    std::optional<std::size_t> band;  ///< one band (0-based)
    std::vector<std::size_t> bands;   ///< several bands in output channel order (0-based)
    std::optional<double> gamma;      ///< > 0; 1 when unset
    std::optional<double> percent;    ///< percentile stretch, [0, 50)
    bool per_band = false;            ///< stretch limits per band instead of jointly
    std::optional<double> min;        ///< fixed stretch (with max)
    std::optional<double> max;
    bool raw = false;                           ///< no stretch
    std::optional<int> bit_depth;               ///< 8, 16, 32 (64 for ENVI)
    std::optional<io::EnviDataType> data_type;  ///< ENVI output type
    Colormap colormap = Colormap::automatic;    ///< how one band of labels is drawn
    /// A DIRSIG lidar BIN input: the pulse to write (glint/app_envi/bin_commands.h); unset: all.
    std::optional<std::uint64_t> pulse;
    /// A DIRSIG lidar BIN input: range images (convert_bin's `range`) instead of cubes.
    bool range = false;
};

/// What convert did.
struct ConvertResult {
    io::OutputKind kind = io::OutputKind::png;
    std::vector<std::size_t> bands;         ///< source bands written, in order
    std::vector<io::StretchLimits> limits;  ///< per output channel; empty without a stretch
    std::string stored_type;                ///< "uint8", "float", "float32" (ENVI), ...
    bool index_colours = false;             ///< the index colour map was applied
};

/// Converts. Throws glint::Error: usage for contradictory options, an out-of-range band or
/// an output that would overwrite the input; input/io naming the file otherwise. Nothing is
/// left under the output name unless the conversion succeeded.
ConvertResult convert_file(const ConvertOptions& options, Context& ctx);

}  // namespace glint::app_envi
