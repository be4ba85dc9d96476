// SPDX-License-Identifier: Apache-2.0
// Internal interface between the two halves of the `.platform` reader: platform_reader.cpp
// (the attachment tree, mounts, instruments, focal planes, detector arrays, clocks, truth)
// and capture_reader.cpp (capture method, image file, spectral response), with
// capture_extras_reader.cpp (the capture extras that the manual places either in
// <capturemethod> or directly in <focalplane>) and focal_plane_checks.cpp.
#pragma once

#include <filesystem>

#include "glint/core/diagnostics.h"
#include "glint/dirsig/read_options.h"
#include "glint/io/xml.h"
#include "glint/model/instrument.h"

namespace glint::dirsig::detail {

/// What a reader function needs besides the node: options and the folder of the file.
struct ReadContext {
    const ReadOptions& options;
    std::filesystem::path base_dir;  ///< folder of the file being read (relative paths)
};

/// Reads `<capturemethod>`.
model::CaptureMethod read_capture_method(const io::XmlNode& node, const ReadContext& context,
                                         Diagnostics& diagnostics);

/// Reads the capture extras (psf, activearea, convergence, processing, detectormodel) under
/// `parent` into `capture`. `in_focal_plane`: `parent` is the focal plane, and what the
/// capture method already holds must not be given again (capture_extras_reader.cpp).
void read_capture_extras(const io::XmlNode& parent, model::CaptureMethod& capture,
                         const ReadContext& context, Diagnostics& diagnostics, bool in_focal_plane);

/// Reads the capture extras written directly under `<focalplane>` (psf, activearea,
/// convergence, processing, detectormodel) into `capture`; a value given in both places is
/// an error.
void read_focal_plane_extras(const io::XmlNode& focal_plane, model::CaptureMethod& capture,
                             const ReadContext& context, Diagnostics& diagnostics);

/// Reads an `<imagefile>`. `radiometric` says whether areaunits/fluxunits apply (capture
/// method) or not (truth collection: the attributes are warned about when present).
model::ImageFile read_image_file(const io::XmlNode& node, bool radiometric,
                                 Diagnostics& diagnostics);

/// Checks that need the whole focal plane: channel centres inside the bandpass, unique
/// channel names, channel-pattern mappings naming existing channels with every filter of the
/// pattern mapped, TDI needing integration time > 0 and more than one stage.
void check_focal_plane(const model::FocalPlane& focal_plane, Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail
