// SPDX-License-Identifier: Apache-2.0
// Platform (a `.platform` file): metadata, the clock table, and the attachment tree
// platform > attachment > mount > attachment > instrument (mounts nest). An instrument's
// pose relative to the vehicle is the composition, outermost first, of the attachment
// transforms and mount rotations on its path.
//
// | element / attribute | type | unit | default |
// |---|---|---|---|
// | metadata/entry/name, value | text | - | - |
// | clocktable/clock@name (+ clock fields) | master clocks | - | - |
// | attachment/affinetransform | empty = identity; xtranslate… zrotate or matrix (see
// docs/formats.md) | m, rad | identity | | mount@type | static, commanded, tabulated, whisk,
// tracking (lemniscate, line, scripted: warned) | - | static | | mount/data@angularunits,
// @rotationorder | degrees/radians; xyz… | - | degrees, xyz | | mount/data/xrotation, yrotation,
// zrotation | number | angularunits | 0 | | mount/data/entry (commanded, tabulated) | datetime,
// x/y/zrotation, x/y/ztranslation | s, angularunits, m | - | | mount/rotationdeviates | per-axis
// jitter (see docs/formats.md); empty = none | angularunits | none |
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "glint/model/common.h"
#include "glint/model/instrument.h"
#include "glint/model/jitter.h"

namespace glint::model {

/// `<affinetransform>`: a placement on the parent. Identity when empty.
struct AffineTransform {
    std::array<double, 3> translation_m{0, 0, 0};
    std::array<double, 3> rotation_rad{0, 0, 0};
    std::string rotation_order = "xyz";
    /// A full 4×4 row-major matrix, when the file gives one (translation in m).
    std::optional<std::array<double, 16>> matrix;
    ErrorContext where;

    bool is_identity() const;
};

enum class MountType { static_mount, commanded, tabulated, whisk, tracking, other };

/// One pointing entry of a commanded or tabulated mount.
struct MountEntry {
    double time_s = 0.0;  ///< relative to the reference date-time (absolute ones converted)
    std::array<double, 3> rotation_rad{0, 0, 0};
    std::array<double, 3> translation_m{0, 0, 0};
    ErrorContext where;
};

/// Scan of a whisk (sinusoidal/line scanning) mount about one axis.
struct WhiskScan {
    enum class Axis { across_track, along_track };  ///< about Y, about X
    Axis axis = Axis::across_track;
    double min_angle_rad = 0.0;
    double max_angle_rad = 0.0;
    double rate_hz = 0.0;  ///< full scan cycles per second
    double phase_rad = 0.0;
    bool sinusoidal = true;  ///< false: linear (sawtooth) sweep
};

/// Target of a tracking mount.
struct TrackingTarget {
    std::string name;  ///< named scene target (instance name)
    std::array<double, 3> offset_m{0, 0, 0};
    std::optional<std::array<double, 3>> point_m;  ///< a fixed scene point instead of a name
};

/// `<rotationdeviates>`: jitter about x, y, z (empty element = none), each axis a JitterSpec
/// in radians (mean, stddev; a PSD in rad²/Hz).
struct RotationDeviates {
    std::array<JitterSpec, 3> axes;
    ErrorContext where;
    bool any() const;
};

struct Attachment;

/// `<mount>`.
struct Mount {
    std::string name;
    MountType type = MountType::static_mount;
    std::string type_text = "static";  ///< as written
    std::string rotation_order = "xyz";
    std::array<double, 3> rotation_rad{0, 0, 0};  ///< static
    std::vector<MountEntry> entries;              ///< commanded, tabulated
    std::optional<double> period_s;               ///< tabulated: repeat period
    std::optional<WhiskScan> whisk;
    std::optional<TrackingTarget> tracking;
    RotationDeviates deviates;
    std::vector<Attachment> attachments;
    ErrorContext where;
};

/// `<attachment>`: a placement and what sits there (mounts and/or instruments).
struct Attachment {
    AffineTransform transform;
    std::vector<Mount> mounts;
    std::vector<Instrument> instruments;
    ErrorContext where;
};

/// A `.platform` file.
struct Platform {
    std::string file;  ///< as named to the reader
    Metadata metadata;
    std::vector<MasterClock> clock_table;
    std::vector<Attachment> attachments;
};

/// An instrument with the chain of attachments and mounts that holds it, outermost first.
struct InstrumentPath {
    const Instrument* instrument = nullptr;
    std::vector<const Attachment*> attachments;  ///< one more than mounts
    std::vector<const Mount*> mounts;
};

/// Every instrument of the platform in document order (the instrument index of the
/// schedule and of output naming).
std::vector<InstrumentPath> list_instruments(const Platform& platform);

}  // namespace glint::model
