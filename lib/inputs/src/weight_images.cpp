// SPDX-License-Identifier: Apache-2.0
// The PSF and active-area images a `.platform` names, read with the platform
// (glint/inputs/load.h, read_weight_images), so a render and glint-platform2jsim --check
// refuse the same images with the same messages.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/inputs/load.h"
#include "glint/io/image.h"

namespace glint::inputs {
namespace {

void read_attachment_images(std::vector<model::Attachment>& attachments, Diagnostics& diagnostics) {
    for (model::Attachment& attachment : attachments) {
        for (model::Instrument& instrument : attachment.instruments) {
            for (model::FocalPlane& plane : instrument.focal_planes) {
                if (!plane.enabled) continue;
                model::CaptureMethod& capture = plane.capture_method;
                if (capture.psf && !capture.psf->width_px && !capture.psf->image.empty()) {
                    if (auto weights =
                            read_weight_image(capture.psf->image, "<psf><image>",
                                              capture.psf->where, INFINITY, diagnostics)) {
                        capture.psf->weights = std::move(*weights);
                    }
                }
                if (!capture.active_area_image.empty()) {
                    if (auto mask =
                            read_weight_image(capture.active_area_image, "<activearea><image>",
                                              capture.active_area_image.where, 1.0, diagnostics)) {
                        capture.active_area = std::move(*mask);
                    }
                }
            }
        }
        for (model::Mount& mount : attachment.mounts) {
            read_attachment_images(mount.attachments, diagnostics);
        }
    }
}

}  // namespace

std::optional<model::WeightImage> read_weight_image(const model::FileRef& image,
                                                    const std::string& element,
                                                    const ErrorContext& where, double max_value,
                                                    Diagnostics& diagnostics) {
    std::optional<std::string> problem;
    io::GreyImage grey;
    try {
        grey = io::read_grey_image(image.resolved);
        problem = io::weight_image_problem(grey, max_value);
    } catch (const Error& e) {
        if (e.category() != ErrorCategory::input && e.category() != ErrorCategory::io) throw;
        problem = e.message();
    }
    if (problem) {
        diagnostics.error(where, element + " " + quote(image.text) + ": " + *problem);
        return std::nullopt;
    }
    return model::WeightImage{grey.width, grey.height, std::move(grey.values)};
}

void read_weight_images(model::Platform& platform, Diagnostics& diagnostics) {
    read_attachment_images(platform.attachments, diagnostics);
}

}  // namespace glint::inputs
