// SPDX-License-Identifier: Apache-2.0
// Instrument, its focal planes, their detector arrays, clocks and truth collections.
//
// | element / attribute | type | unit | default |
// |---|---|---|---|
// | instrument@type | generic, lidar, datarecorder | - | generic |
// | instrument@name | text | - | "" |
// | properties/focallength | number > 0 | mm (stored m) | required for generic |
// | properties/aperturediameter | number > 0 | m | none (no aperture) |
// | properties/aperturethroughput | number in (0, 1] | - | 1 |
// | properties/focusdistance | number > 0; needs aperturediameter | m | none (infinity) |
// | properties/distortion/k1 k2 k3 p1 p2 | numbers | focal lengths | 0 |
// | focalplane@enabled, @name | bool, text | - | true, "" |
// | detectorarray@spatialunits | microns, millimeters, meters (also um, mm, m) | - | microns |
// | detectorarray/xelementcount, yelementcount | integer 1–1,000,000; product ≤ 2^31 | pixels |
// required | | detectorarray/xelementsize, yelementsize | number > 0 | spatialunits | = spacing |
// | detectorarray/xelementspacing, yelementspacing | number > 0, >= size | spatialunits | required
// | | detectorarray/xarrayoffset, yarrayoffset | number | spatialunits | 0 | |
// detectorarray/xflipaxis, yflipaxis | bool (0/1) | - | false | | detectorarray/clock@type |
// independent, synchronous, external (see docs/formats.md) | - | required | | clock@temporalunits,
// rate, offset | hertz; number > 0; number | Hz, s | hertz, required, 0 | |
// truthcollection/enabled, name, imagefile, collectorlist/collector/name, materials, tags | | | |
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "glint/model/capture.h"
#include "glint/model/common.h"

namespace glint::model {

enum class ClockType { independent, synchronous, external_trigger };

/// What starts a focal plane's captures.
struct Clock {
    ClockType type = ClockType::independent;
    std::string temporal_units = "hertz";
    double rate_hz = 0.0;           ///< independent
    double offset_s = 0.0;          ///< independent: time of the first tick
    std::string master;             ///< synchronous: name of a clock in the platform's clocktable
    std::int64_t divider = 1;       ///< synchronous: one tick every `divider` master ticks
    std::int64_t offset_count = 0;  ///< synchronous: master ticks before the first tick
    FileRef trigger_file;           ///< external: text file of trigger times (s after reference)
    /// external: the trigger file's times (s after reference), as the input loader
    /// (glint/inputs) read them; empty until then.
    std::vector<double> trigger_times_s;
    ErrorContext where;
};

/// A named clock of the platform's `<clocktable>` (a master for synchronous clocks).
struct MasterClock {
    std::string name;
    double rate_hz = 0.0;
    double offset_s = 0.0;
    ErrorContext where;
};

/// `<detectorarray>`. Sizes in m.
struct DetectorArray {
    std::string spatial_units = "microns";  ///< as written
    std::size_t x_count = 0;                ///< columns (ENVI samples)
    std::size_t y_count = 0;                ///< rows (ENVI lines), or TDI stages
    double x_size_m = 0.0;                  ///< active element size
    double y_size_m = 0.0;
    double x_spacing_m = 0.0;  ///< pitch
    double y_spacing_m = 0.0;
    double x_offset_m = 0.0;  ///< array centre relative to the optical axis
    double y_offset_m = 0.0;
    bool x_flip = false;
    bool y_flip = false;
    Clock clock;
    /// Rolling readout: time between the readout of consecutive rows; none = global shutter.
    std::optional<double> rolling_line_time_s;
    /// `<xoversample>`, `<yoversample>`: sub-pixels per element along each axis, written as
    /// their own pixels by a raw capture (1: none).
    std::size_t x_oversample = 1;
    std::size_t y_oversample = 1;
    ErrorContext oversample_where;  ///< the first oversample element, when given
    ErrorContext where;
};

/// One truth collector: a DIRSIG4 set name or a DIRSIG5 collector name, with the optional
/// abundance targets.
struct TruthCollector {
    std::string name;
    std::vector<std::string> materials;  ///< material ids or labels (abundance)
    std::vector<std::string> tags;       ///< geometry tags (abundance)
    ErrorContext where;
};

/// `<truthcollection>`: several per focal plane allowed, each to its own file.
struct TruthCollection {
    bool enabled = true;
    std::string name;
    ImageFile image_file;
    std::vector<TruthCollector> collectors;
    ErrorContext where;
};

/// `<focalplane>`.
struct FocalPlane {
    bool enabled = true;
    std::string name;
    CaptureMethod capture_method;
    DetectorArray detector_array;
    std::vector<TruthCollection> truth_collections;
    ErrorContext where;
};

/// Five-parameter Brown lens distortion (coordinates in focal lengths).
struct Distortion {
    double k1 = 0, k2 = 0, k3 = 0, p1 = 0, p2 = 0;
};

/// `<properties>` of an instrument. Lengths in m (focal length converted from mm).
struct InstrumentProperties {
    std::optional<double> focal_length_m;
    std::optional<double> aperture_diameter_m;
    double aperture_throughput = 1.0;
    std::optional<double> focus_distance_m;
    std::optional<Distortion> distortion;
    ErrorContext where;
};

enum class InstrumentType { generic, lidar, data_recorder };

/// `<instrument>`.
/// Optional GPS/IMU-style noise of a data recorder (`<noise>`): the standard deviation of a
/// zero-mean Gaussian added to each recorded component; unset: none.
struct TelemetryNoise {
    std::optional<double> position_m;          ///< each ENU axis
    std::optional<double> velocity_m_s;        ///< each ENU axis
    std::optional<double> orientation_deg;     ///< each Euler angle
    std::optional<double> angular_rate_deg_s;  ///< each body axis
    ErrorContext where;
};

/// What a data recorder instrument (`type="datarecorder"`) records (docs/data-recorder.md).
struct DataRecorder {
    /// The instrument-level `<clock>`; unset: its first enabled focal plane's clock.
    std::optional<Clock> clock;
    std::string basename;  ///< `<output><basename>`; default: the instrument's name
    TelemetryNoise noise;
    ErrorContext where;
};

/// A tabulated pulse shape: relative power against time (s after the pulse's firing time).
struct PulseShapeTable {
    std::vector<double> time_s;
    std::vector<double> power;
    ErrorContext where;  ///< the file, line of its first row
};

/// A lidar instrument's laser (`<transmitter>`, docs/lidar.md). It sits at the instrument's
/// frame and fires along its boresight (−Z), one pulse per tick of the receiver's clock.
struct Transmitter {
    double wavelength_um = 0.0;
    double spectral_width_um = 0.0;  ///< FWHM of the laser line
    double pulse_energy_j = 0.0;
    double pulse_duration_s = 0.0;  ///< FWHM of the temporal shape
    FileRef pulse_shape_file;       ///< tabulated shape (time s, relative power); empty: Gaussian
    /// The tabulated shape, as the input loader (glint/inputs) read it; empty until then.
    PulseShapeTable pulse_shape;
    double beam_divergence_rad = 0.0;  ///< full angle at 1/e² of a Gaussian beam
    /// `<pulserate>` (Hz), the pulse repetition frequency: the receiver's clock fires the
    /// pulses, so this must agree with an independent receiver clock's rate; unset: the
    /// clock's.
    std::optional<double> pulse_rate_hz;
    ErrorContext where;
};

struct Instrument {
    InstrumentType type = InstrumentType::generic;
    std::string type_text = "generic";  ///< as written
    std::string name;
    InstrumentProperties properties;
    std::vector<FocalPlane> focal_planes;
    DataRecorder recorder;                   ///< data recorders only
    std::optional<Transmitter> transmitter;  ///< lidar instruments only
    ErrorContext where;
};

}  // namespace glint::model
