// SPDX-License-Identifier: Apache-2.0
// Internal interface between the files of the `.platform` reader's tree half:
// platform_reader.cpp (file, metadata, clock table, attachments, affine transforms),
// mount_reader.cpp (mounts and their jitter), instrument_reader.cpp (instruments, focal
// planes, truth) and array_clock_reader.cpp (detector arrays and clocks). The capture-method
// half is behind platform_parts.h.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "glint/core/diagnostics.h"
#include "glint/io/xml.h"
#include "glint/model/instrument.h"
#include "glint/model/platform.h"
#include "platform_parts.h"

namespace glint::dirsig::detail {

/// Radians per unit of `@angularunits` on `node` (degrees, the default, or radians); an
/// unknown unit is an error and reads as degrees.
double angular_unit_factor(const io::XmlNode& node, Diagnostics& diagnostics);

/// `@rotationorder` on `node`: any permutation of "xyz" (any case; stored lower case),
/// default "xyz"; anything else is an error and reads as "xyz".
std::string read_rotation_order(const io::XmlNode& node, Diagnostics& diagnostics);

/// Three numbers from the children named `names` (each optional, default 0), times `factor`.
std::array<double, 3> read_triplet(const io::XmlNode& node,
                                   const std::array<std::string_view, 3>& names, double factor,
                                   Diagnostics& diagnostics);

/// A value that may be spelled two ways (`xtranslate` / `xtranslation`, `stddev` / `sigma`):
/// the number in whichever child is present; both present is an error.
std::optional<double> read_either(const io::XmlNode& node, std::string_view first,
                                  std::string_view second, Diagnostics& diagnostics,
                                  io::NumberRule rule = io::NumberRule::any());

/// A warning for an element glint reads past: "<name> is parsed but not used yet".
void warn_not_used(const io::XmlNode& node, Diagnostics& diagnostics);

/// `text` trimmed of blanks.
std::string trimmed(std::string_view text);

/// `text` trimmed of blanks and lower-cased (for keyword attributes).
std::string lower_trimmed(std::string_view text);

/// Shortest round-trip text of a number for messages ("5e-06", "0.5", "12").
std::string number_text(double value);

/// `<attachment>` (recursing into mounts and instruments).
model::Attachment read_attachment(const io::XmlNode& node, const ReadContext& context,
                                  Diagnostics& diagnostics);

/// `<mount>` (recursing into its attachments).
model::Mount read_mount(const io::XmlNode& node, const ReadContext& context,
                        Diagnostics& diagnostics);

/// `<rotationdeviates>`: per-axis pointing jitter of a mount.
model::RotationDeviates read_rotation_deviates(const io::XmlNode& node, const ReadContext& context,
                                               Diagnostics& diagnostics);

/// `<instrument>` with its properties and focal planes.
model::Instrument read_instrument(const io::XmlNode& node, const ReadContext& context,
                                  Diagnostics& diagnostics);

/// `<detectorarray>` with its clock and rolling readout.
model::DetectorArray read_detector_array(const io::XmlNode& node, const ReadContext& context,
                                         Diagnostics& diagnostics);

/// A focal plane's `<clock>`.
model::Clock read_clock(const io::XmlNode& node, const ReadContext& context,
                        Diagnostics& diagnostics);

/// A `<clocktable>` `<clock>` (a master clock: named, independent).
model::MasterClock read_master_clock(const io::XmlNode& node, Diagnostics& diagnostics);

}  // namespace glint::dirsig::detail
