// SPDX-License-Identifier: Apache-2.0
// CaptureMethod of a focal plane: output file, spectral response, sampling, temporal
// integration, detector model, convergence, PSF, active area and processing tasks.
//
// clang-format off
// | element / attribute | type | unit | default |
// |---|---|---|---|
// | capturemethod@type | simple, raw, lidar | - | simple |
// | capturemethod@name | text | - | "" |
// | samplestrategy@type | text (central seen) | - | central |
// | samplestrategy/hypersamplingmultiplier | number >= 1 | - | 1 |
// | imagefile@areaunits | cm2, m2 | - | cm2 |
// | imagefile@fluxunits | watts, milliwatts, microwatts, photonspersecond, electronspersecond | - | watts |
// | imagefile (simple, raw: required; lidar: optional) | | | |
// | imagefile/basename, extension | non-empty text | - | required, img |
// | imagefile/schedule | simulation, task, capture | - | simulation |
// | imagefile/datatype | ENVI code 1, 2, 3, 4, 5, 12, 13, 14, 15 | - | 5 |
// | spatialresponse@spatialsampling, @spectralunits | text (DIRSIG4; parsed, ignored with a warning) | - | "" |
// | spatialresponse@xsubelements, @ysubelements | integer >= 1 (ignored) | - | 1 |
// | spatialresponse/entry@type, spectralpoint, xwidth, ywidth, totalweight | text, numbers; widths and weight >= 0 (ignored) | -, spectralunits, -, -, - | "", 0, 1, 1, 1 |
// | temporalintegration@tdi | bool; true needs time > 0 and yelementcount > 1 | - | false |
// | temporalintegration/time | number >= 0 (0 = instantaneous) | s | 0 |
// | temporalintegration/samples | integer >= 1 (DIRSIG4; ignored, warning when > 1) | - | 1 |
// | detectormodel | only with capturemethod type simple | | |
// | detectormodel/quantumefficiency | number in [0, 1] | - | required |
// | detectormodel/readnoise | number >= 0 | electrons | 0 |
// | detectormodel/darkcurrentdensity | number >= 0 | A/m² | 0 |
// | detectormodel/minelectrons, maxelectrons | numbers >= 0, min < max | electrons | required |
// | detectormodel/bitdepth | integer 1–32 | bits | required |
// | convergence/minimumsamples, maximumsamples | integers 1–10⁹, min <= max | paths | required |
// | convergence/threshold | number >= 0 | W/(cm² sr µm) | required |
// | psf/width | number > 0 (Gaussian σ); exclusive with image + scale | pixels | - |
// | psf/image, psf/scale | grey image file (path resolved, existence checked later); number > 0 (image extent); both required together | -, pixels | - |
// | activearea/image | 8-bit grey mask of one pixel (path resolved, existence checked later) | - | required in activearea |
// | processing/task@schedule | collection_started, task_started, capture_started, capture_completed, task_completed, collection_completed | - | required |
// | processing/task/message, program, argument*, removefile | text, non-empty text, text without whitespace, bool | - | "", required, -, false |
// | signalgate (lidar only; required there) | | | |
// | signalgate/start, stop | numbers, 0 <= start < stop | s after the pulse | required |
// | signalgate/binwidth | number > 0, (stop − start) / binwidth whole (to 1e-6) | s | required |
// | signalgate/samplespertimebin | integer 1–1024 | - | 1 |
// (psf, activearea, convergence, processing and detectormodel are also accepted directly in
// focalplane; giving one in both places is an error. docs/formats.md has the details.)
// clang-format on
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "glint/model/common.h"
#include "glint/model/spectral_response.h"

namespace glint::model {

enum class CaptureMethodType { simple, raw, lidar };
enum class ImageSchedule { simulation, task, capture };
enum class FluxUnits { watts, milliwatts, microwatts, photons_per_second, electrons_per_second };
enum class AreaUnits { cm2, m2 };

/// `<imagefile>`: the output file of a capture method or truth collection.
struct ImageFile {
    std::string basename;
    std::string extension = "img";
    ImageSchedule schedule = ImageSchedule::simulation;
    int datatype = 5;  ///< ENVI data type code
    AreaUnits area_units = AreaUnits::cm2;
    FluxUnits flux_units = FluxUnits::watts;
    ErrorContext where;
};

struct SampleStrategy {
    std::string type = "central";
    double hypersampling_multiplier = 1.0;
};

struct TemporalIntegration {
    double time_s = 0.0;  ///< integration window length; 0 = instantaneous
    int samples = 1;      ///< DIRSIG4 temporal sample count, ignored by glint (as DIRSIG5)
    bool tdi = false;     ///< Y dimension of the array = TDI stages
    ErrorContext where;
};

/// The internal detector model (the nine steps of the DIRSIG5 BasicPlatform manual).
struct DetectorModel {
    double quantum_efficiency = 1.0;
    double read_noise_e = 0.0;
    double dark_current_density_a_per_m2 = 0.0;
    double min_electrons = 0.0;
    double max_electrons = 0.0;
    int bit_depth = 12;
    ErrorContext where;
};

/// Per-focal-plane convergence (overrides the command line's --convergence).
struct Convergence {
    std::int64_t minimum_samples = 0;
    std::int64_t maximum_samples = 0;
    double threshold = 0.0;  ///< W/(cm² sr µm) at the reference wavelength
    ErrorContext where;
};

/// The values of a grey image used as sampling weights (a PSF or active-area image), as the
/// readers (glint/inputs/load.h, read_weight_image) read it: its first channel, integer codes
/// divided by the type's largest code, line 0 at the top.
struct WeightImage {
    std::size_t width = 0;
    std::size_t height = 0;
    std::vector<double> values;  ///< width × height, row-major
    bool empty() const noexcept { return values.empty(); }
};

/// Point spread function: a Gaussian of σ `width_px` pixels, or an image spanning `scale_px`.
struct Psf {
    std::optional<double> width_px;
    FileRef image;
    WeightImage weights;  ///< the image's values (read with the platform); empty: not read
    double scale_px = 0.0;
    ErrorContext where;
};

enum class ProcessingSchedule {
    collection_started,
    task_started,
    capture_started,
    capture_completed,
    task_completed,
    collection_completed,
};

/// An external program run on a schedule event (`$$IMG_BASENAME$$` substituted later).
struct ProcessingTask {
    ProcessingSchedule schedule = ProcessingSchedule::capture_completed;
    std::string message;
    std::string program;
    std::vector<std::string> arguments;
    bool remove_file = false;
    ErrorContext where;
};

/// One `<entry>` of a DIRSIG4 `<spatialresponse>` (values as written, never used).
struct SpatialResponseEntry {
    std::string type;             ///< @type, e.g. "uniform"
    double spectral_point = 0.0;  ///< in the block's @spectralunits
    double x_width = 1.0;
    double y_width = 1.0;
    double total_weight = 1.0;
    ErrorContext where;
};

/// The DIRSIG4 `<spatialresponse>` block: parsed so nothing is lost, never used.
struct SpatialResponse {
    std::string spatial_sampling;  ///< @spatialsampling
    std::string spectral_units;    ///< @spectralunits, as written
    int x_sub_elements = 1;
    int y_sub_elements = 1;
    std::vector<SpatialResponseEntry> entries;
    ErrorContext where;
};

/// A lidar capture's range gate (`<signalgate>`, docs/lidar.md): the receiver records
/// photons from `start_s` to `stop_s` after each pulse in bins of `bin_width_s`.
struct SignalGate {
    double start_s = 0.0;
    double stop_s = 0.0;
    double bin_width_s = 0.0;
    std::uint32_t samples_per_bin = 1;
    ErrorContext where;

    /// Bins in the gate: (stop − start) / bin width, rounded (the reader checks it is whole).
    std::uint64_t bin_count() const;
};

/// `<capturemethod>`.
struct CaptureMethod {
    CaptureMethodType type = CaptureMethodType::simple;
    std::string name;
    SampleStrategy sample_strategy;
    ImageFile image_file;
    SpectralResponse spectral_response;
    std::optional<SpatialResponse> spatial_response;
    TemporalIntegration temporal_integration;
    std::optional<DetectorModel> detector_model;
    std::optional<Convergence> convergence;
    std::optional<Psf> psf;
    FileRef active_area_image;  ///< empty = full pixel
    WeightImage active_area;    ///< its values (read with the platform); empty: not read
    std::vector<ProcessingTask> processing;
    std::optional<SignalGate> signal_gate;  ///< lidar captures only
    ErrorContext where;
};

}  // namespace glint::model
