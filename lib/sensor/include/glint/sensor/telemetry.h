// SPDX-License-Identifier: Apache-2.0
// Data recorders (the DIRSIG5 BasicPlatform manual's "Data Recorder Instrument": GPS/IMU-like
// telemetry). A `type="datarecorder"` instrument samples its own pose at the ticks of its
// clock inside the task windows: position (scene ENU, ECEF, geodetic), velocity, orientation
// (quaternion and Euler angles in the platform's rotation order), body angular rates, with
// optional Gaussian noise drawn from streams keyed by (seed, plugin, instrument, tick), and
// glint-render writes them as CSV and JSON lines. docs/data-recorder.md is the reference.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "glint/core/datetime.h"
#include "glint/model/instrument.h"
#include "glint/model/platform.h"
#include "glint/model/tasks.h"
#include "glint/motion/euler.h"
#include "glint/motion/frames.h"
#include "glint/motion/pose_service.h"

namespace glint::sensor {

/// One sample of a data recorder.
struct TelemetryRecord {
    std::uint64_t task = 0;     ///< task index in the tasks file
    double time_s = 0.0;        ///< s after the tasks reference time
    motion::Vec3 position_enu_m;
    motion::Vec3 position_ecef_m;
    motion::Geodetic geodetic;  ///< WGS84
    motion::Vec3 velocity_enu_m_s;
    motion::Quaternion orientation;  ///< instrument frame → scene ENU (w ≥ 0)
    motion::Vec3 euler_deg;          ///< the same rotation, Euler angles (x, y, z) in `order`
    motion::Vec3 angular_rate_deg_s;  ///< in the instrument frame
};

/// The clock a data recorder samples at: its `<clock>`, else its first enabled focal plane's
/// clock; nullptr when it has neither.
const model::Clock* recorder_clock(const model::Instrument& recorder);

/// One sample of instrument `instrument` of `poses` at `time_s` in task `task`: the pose from
/// the pose service, the velocity and body rates by central differences over ±1 ms, and the
/// recorder's noise from the stream keyed by (seed, plugin_index, instrument, `index`), the
/// sample's index among all the recorder's samples.
TelemetryRecord record_sample(const motion::PoseService& poses, std::size_t instrument,
                              std::uint64_t task, double time_s, std::uint64_t index,
                              const motion::SceneFrame& frame, const model::TelemetryNoise& noise,
                              std::uint64_t seed, std::uint64_t plugin_index);

/// The times a data recorder samples: the ticks of its `<clock>` (else of its first enabled
/// focal plane's clock) in each task window, with the task's index; empty when it has no
/// clock. Throws glint::Error (input, at the clock) as schedule::ClockTicks does.
std::vector<std::pair<std::uint64_t, double>> recorder_times_s(
    const model::Instrument& recorder, const model::Platform& platform,
    const model::TaskList& tasks);

/// Samples instrument `instrument` of `poses` at `times` (recorder_times_s), each as
/// record_sample does with its index in `times`.
std::vector<TelemetryRecord> record_telemetry(
    const motion::PoseService& poses, std::size_t instrument,
    const std::vector<std::pair<std::uint64_t, double>>& times, const motion::SceneFrame& frame,
    const model::TelemetryNoise& noise, std::uint64_t seed, std::uint64_t plugin_index);

/// What the files' headers say besides the records.
struct TelemetryHeader {
    std::string instrument;
    std::string platform_file;
    std::uint64_t plugin_index = 0;
    motion::Geodetic scene_origin;
    motion::EulerOrder order = motion::EulerOrder::xyz;
    DateTime reference;  ///< the tasks reference time
    model::TelemetryNoise noise;
    std::string tool;  ///< provenance: tool, version, command line
    std::string version;
    std::string command_line;
    std::uint64_t seed = 0;
};

/// The records as CSV: `#` comment lines naming the instrument, frames, units and noise, then
/// a header row and one row per record (numbers with 17 significant digits).
std::string telemetry_csv(const TelemetryHeader& header, const std::vector<TelemetryRecord>& records);

/// The records as JSON lines: a header object (format "glint-telemetry", version, units,
/// frames, noise, provenance), then one object per record.
std::string telemetry_jsonl(const TelemetryHeader& header,
                            const std::vector<TelemetryRecord>& records);

/// The same files a piece at a time, for writing them as the samples are made: the CSV's
/// comment lines and header row, one CSV row, the JSON lines' header object, one record's
/// object (each ending in a newline).
std::string telemetry_csv_head(const TelemetryHeader& header);
std::string telemetry_csv_row(const TelemetryHeader& header, const TelemetryRecord& record);
std::string telemetry_jsonl_head(const TelemetryHeader& header);
std::string telemetry_jsonl_row(const TelemetryHeader& header, const TelemetryRecord& record);

}  // namespace glint::sensor
