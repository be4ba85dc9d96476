// SPDX-License-Identifier: Apache-2.0
// The spelling of every model enumeration as the DIRSIG XML writes it.
#include "glint/model/names.h"

namespace glint::model {

const char* name_of(InstrumentType type) {
    switch (type) {
        case InstrumentType::generic:
            return "generic";
        case InstrumentType::lidar:
            return "lidar";
        case InstrumentType::data_recorder:
            return "datarecorder";
    }
    return "generic";
}

const char* name_of(MountType type) {
    switch (type) {
        case MountType::static_mount:
            return "static";
        case MountType::commanded:
            return "commanded";
        case MountType::tabulated:
            return "tabulated";
        case MountType::whisk:
            return "whisk";
        case MountType::tracking:
            return "tracking";
        case MountType::other:
            return "other";
    }
    return "other";
}

const char* name_of(CaptureMethodType type) {
    switch (type) {
        case CaptureMethodType::simple:
            return "simple";
        case CaptureMethodType::raw:
            return "raw";
        case CaptureMethodType::lidar:
            return "lidar";
    }
    return "simple";
}

const char* name_of(ImageSchedule schedule) {
    switch (schedule) {
        case ImageSchedule::simulation:
            return "simulation";
        case ImageSchedule::task:
            return "task";
        case ImageSchedule::capture:
            return "capture";
    }
    return "simulation";
}

const char* name_of(FluxUnits units) {
    switch (units) {
        case FluxUnits::watts:
            return "watts";
        case FluxUnits::milliwatts:
            return "milliwatts";
        case FluxUnits::microwatts:
            return "microwatts";
        case FluxUnits::photons_per_second:
            return "photonspersecond";
        case FluxUnits::electrons_per_second:
            return "electronspersecond";
    }
    return "watts";
}

const char* name_of(AreaUnits units) { return units == AreaUnits::m2 ? "m2" : "cm2"; }

const char* name_of(ProcessingSchedule schedule) {
    switch (schedule) {
        case ProcessingSchedule::collection_started:
            return "collection_started";
        case ProcessingSchedule::task_started:
            return "task_started";
        case ProcessingSchedule::capture_started:
            return "capture_started";
        case ProcessingSchedule::capture_completed:
            return "capture_completed";
        case ProcessingSchedule::task_completed:
            return "task_completed";
        case ProcessingSchedule::collection_completed:
            return "collection_completed";
    }
    return "capture_completed";
}

const char* name_of(ChannelShape shape) {
    switch (shape) {
        case ChannelShape::gaussian:
            return "gaussian";
        case ChannelShape::tabulated:
            return "tabulated";
        case ChannelShape::tophat:
            return "tophat";
        case ChannelShape::triangle:
            return "triangle";
    }
    return "gaussian";
}

const char* name_of(ChannelPatternKind kind) {
    return kind == ChannelPatternKind::truesense ? "truesense" : "bayer";
}

const char* name_of(ClockType type) {
    switch (type) {
        case ClockType::independent:
            return "independent";
        case ClockType::synchronous:
            return "synchronous";
        case ClockType::external_trigger:
            return "external";
    }
    return "independent";
}

const char* name_of(JitterSpec::Kind kind) {
    switch (kind) {
        case JitterSpec::Kind::none:
            return "none";
        case JitterSpec::Kind::normal:
            return "normal";
        case JitterSpec::Kind::psd:
            return "psd";
    }
    return "none";
}

const char* name_of(WhiskScan::Axis axis) {
    return axis == WhiskScan::Axis::along_track ? "along_track" : "across_track";
}

}  // namespace glint::model
