// SPDX-License-Identifier: Apache-2.0
// Checks of a `.platform` focal plane that need all of it (platform_parts.h,
// check_focal_plane): the spectral response against the capture type, TDI's integration time
// and stages, channel names and channel-pattern mappings.
#include <set>
#include <string>

#include "glint/core/text.h"
#include "platform_parts.h"
#include "spectral_reader.h"

namespace glint::dirsig::detail {

void check_focal_plane(const model::FocalPlane& focal_plane, Diagnostics& diagnostics) {
    const auto& capture = focal_plane.capture_method;
    capture_io::check_spectral_response(capture.spectral_response, capture.type, diagnostics);

    const auto& integration = capture.temporal_integration;
    if (integration.tdi) {
        if (!(integration.time_s > 0.0)) {
            diagnostics.error(integration.where,
                              "tdi=\"true\" needs an integration time, expected <time> > 0");
        }
        const std::size_t stages = focal_plane.detector_array.y_count;
        if (stages == 1) {
            diagnostics.error(integration.where,
                              "tdi=\"true\" uses the array's rows as TDI stages, expected "
                              "<yelementcount> > 1 in <detectorarray> (it is 1)");
        }
    }
    if (capture.detector_model && capture.type == model::CaptureMethodType::raw) {
        diagnostics.error(capture.detector_model->where,
                          "the detector model needs capturemethod type simple, expected no "
                          "<detectormodel> in a raw capture");
    }
    if (capture.type == model::CaptureMethodType::lidar) {
        // A pulse is one instant for every pixel and each pixel is one problem.
        if (integration.tdi) {
            diagnostics.error(integration.where,
                              "tdi=\"true\" needs capturemethod type simple (a lidar receiver "
                              "records every pixel at each pulse)");
        }
        if (focal_plane.detector_array.rolling_line_time_s) {
            diagnostics.warning(focal_plane.detector_array.where,
                                "rollingreadout is read, not applied on a lidar receiver: every "
                                "row records the same pulse");
        }
        if (capture.sample_strategy.hypersampling_multiplier > 1.0) {
            diagnostics.warning(capture.where,
                                "<hypersamplingmultiplier> is read, not applied on a lidar "
                                "receiver: its returns take the convergence maximum of samples "
                                "in every pixel");
        }
    }
    if (capture.type == model::CaptureMethodType::lidar && integration.time_s > 0.0) {
        diagnostics.warning(integration.where,
                            "<temporalintegration> does not apply to a lidar capture (the "
                            "signal gate sets its times, and the passive term is a rate); "
                            "ignored");
    }
    // A raw capture is the bandpass-sampled radiance for an external detection model: the
    // TDI accumulation of the in-render detection is not for it (a <channelpattern> on it is
    // refused by check_spectral_response).
    if (capture.type == model::CaptureMethodType::raw && integration.tdi) {
        diagnostics.error(integration.where,
                          "tdi=\"true\" needs capturemethod type simple (TDI stages are "
                          "accumulated by detection, which a raw capture leaves to an external "
                          "model)");
    }
    if (capture.type == model::CaptureMethodType::raw &&
        !capture.spectral_response.channels.empty()) {
        diagnostics.warning(capture.spectral_response.channels.front().where,
                            "the <channel>s of a raw capture are read, not applied: raw writes "
                            "one band per bandpass sample");
    }
    const model::DetectorArray& array = focal_plane.detector_array;
    if ((array.x_oversample > 1 || array.y_oversample > 1) &&
        capture.type != model::CaptureMethodType::raw) {
        diagnostics.warning(array.oversample_where,
                            "<xoversample>/<yoversample> are read, not applied: they oversample "
                            "a raw capture only (a simple capture samples each element's area)");
    } else if (array.y_oversample > 1 && array.rolling_line_time_s) {
        diagnostics.error(array.oversample_where,
                          "<yoversample> with rollingreadout: the sub-rows of a raw capture have "
                          "no readout time of their own, expected one of the two");
    }
    if (integration.tdi && focal_plane.detector_array.y_count > 1 &&
        focal_plane.detector_array.rolling_line_time_s) {
        diagnostics.warning(focal_plane.detector_array.where,
                            "rollingreadout is read, not applied on a TDI array: its stages are "
                            "read once per capture");
    }
    if (capture.detector_model && capture.type == model::CaptureMethodType::simple) {
        for (const model::Channel& channel : capture.spectral_response.channels) {
            if (channel.normalize) {
                diagnostics.warning(channel.where,
                                    "normalize of channel \"" + channel.name +
                                        "\" is ignored with a detector model (detection counts "
                                        "photons through the channel's response)");
            }
        }
    }
    const auto& file = capture.image_file;
    if (capture.detector_model &&
        (file.area_units != model::AreaUnits::cm2 || file.flux_units != model::FluxUnits::watts)) {
        diagnostics.warning(file.where,
                            "areaunits and fluxunits are ignored when the detector model is "
                            "enabled (the output is in digital counts)");
    }
}

}  // namespace glint::dirsig::detail
