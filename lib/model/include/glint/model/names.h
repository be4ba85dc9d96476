// SPDX-License-Identifier: Apache-2.0
// The spelling of every model enumeration as the DIRSIG XML writes it ("generic",
// "photonspersecond", "capture_completed", ...), for JSON outputs and messages.
#pragma once

#include "glint/model/capture.h"
#include "glint/model/instrument.h"
#include "glint/model/platform.h"
#include "glint/model/spectral_response.h"

namespace glint::model {

/// The XML spelling of an enumeration value.
const char* name_of(InstrumentType type);
const char* name_of(MountType type);
const char* name_of(CaptureMethodType type);
const char* name_of(ImageSchedule schedule);
const char* name_of(FluxUnits units);
const char* name_of(AreaUnits units);
const char* name_of(ProcessingSchedule schedule);
const char* name_of(ChannelShape shape);
const char* name_of(ChannelPatternKind kind);
const char* name_of(ClockType type);
const char* name_of(JitterSpec::Kind kind);
const char* name_of(WhiskScan::Axis axis);

}  // namespace glint::model
