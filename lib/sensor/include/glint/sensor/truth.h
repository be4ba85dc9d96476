// SPDX-License-Identifier: Apache-2.0
// Truth collection (docs/truth.md): what a focal plane's `<truthcollection>`s ask for, laid
// out as bands, and the sample observer that fills them from the very samples the radiance is
// made of. Each truth file is a float cube, one band per individual collector (one per
// abundance target, one per output channel for the standard error), the collection's bands
// in the order its collectors name them (a band named twice is written once).
//
// Per pixel, over its samples (weights w as the radiance's):
//   - the most common first-hit material, instance and object (Σ w per index; ties: the
//     lowest index);
//   - abundance: Σ w over samples whose first hit counts for the target / Σ w over all
//     samples (a sample that hits nothing counts for no target);
//   - scene point, normal (renormalized), distance, temperature, reflectance: Σ w x / Σ w
//     over samples that hit; shadow: the same of 1 for a first hit the sun does not light;
//     latitude, longitude, altitude: of the mean scene point;
//   - sample count: the paths traced (all spectral states);
//   - standard error: each channel's weighted standard error (problem.h), in the channel's
//     radiometric units (before any detection).
// A quantity undefined without a hit is NaN (the no-data value) for a pixel none of whose
// samples hit. With split channels the first-hit quantities come from the first spectral state
// alone, each channel's standard error from its own state.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "glint/core/log.h"
#include "glint/core/spectral.h"
#include "glint/io/envi.h"
#include "glint/model/instrument.h"
#include "glint/model/scene.h"
#include "glint/model/truth.h"
#include "glint/motion/frames.h"
#include "glint/radiometry/materials.h"
#include "glint/radiometry/problem.h"
#include "glint/sensor/output_units.h"

namespace glint::sensor {

/// One band of truth.
struct TruthBand {
    model::TruthQuantity quantity = model::TruthQuantity::material_index;
    /// The abundance target (index into TruthLayout::targets) or the standard error's channel.
    std::size_t index = 0;
    std::string name;   ///< the ENVI band name
    std::string units;  ///< what its values are in
};

/// The bands of one truth file.
struct TruthFileLayout {
    std::size_t collection = 0;      ///< index into the focal plane's truth_collections
    std::vector<std::size_t> bands;  ///< into TruthLayout::bands, in the file's band order
};

/// Every truth band of a focal plane, shared by its files.
struct TruthLayout {
    std::vector<TruthBand> bands;
    std::vector<model::AbundanceTarget> targets;
    std::vector<TruthFileLayout> files;  ///< one per collection that writes a file, in order
    bool needs_first_hit = false;        ///< some band is not sample count or standard error

    bool empty() const noexcept { return files.empty(); }
};

/// The layout of focal plane `fp`'s collections that write a file (model::writes_truth), for
/// a render whose output channels are `units`'s. Warns (log, at the collector) about an
/// abundance tag no instance carries and a collector whose bands all appear before it in its
/// collection. Throws glint::Error (input, at the collector) for an unknown collector name
/// and what model::resolve_abundance throws.
TruthLayout make_truth_layout(const model::FocalPlane& fp, const model::Scene& scene,
                              const OutputUnits& units, const Log& log);

/// The header of truth file `file` of `layout`: `base`'s provenance keys (its `glint ...`
/// keys but for those describing the radiometric image), the band names, the float type of
/// the collection's `<imagefile>`, `data ignore value = NaN`, and `glint band units`,
/// `glint material ids` / `names` (when a band holds a material index), `glint instance
/// names` and `glint object names` (when a band holds such an index, at most 100,000
/// names).
io::EnviHeader truth_header(const io::EnviHeader& base, const model::FocalPlane& fp,
                            const TruthLayout& layout, const TruthFileLayout& file,
                            const model::Scene& scene);

/// What a truth observer needs besides the layout.
struct TruthContext {
    const model::Scene* scene = nullptr;
    const radiometry::MaterialTable* materials = nullptr;  ///< on the focal plane's grid
    const motion::SceneFrame* frame = nullptr;
    const OutputUnits* units = nullptr;
    std::size_t reflectance_band = 0;  ///< the focal plane's reference band
    double radiance_share = 1.0;       ///< the active area's mean sensitivity (or 1)
};

/// Fills a capture's truth values (problems × layout.bands.size(), pixel after pixel;
/// zeroed by the caller before the first spectral state) from the samples of one spectral
/// state: `bands` of the focal plane's grid, rendering `channel` alone when split (none:
/// every channel). Only the first state (`first_state`) records first-hit quantities.
class TruthObserver final : public radiometry::SampleObserver {
public:
    TruthObserver(const TruthLayout& layout, const TruthContext& context, BandRange bands,
                  std::optional<std::size_t> channel, bool first_state, std::uint64_t first_problem,
                  std::span<double> values);
    bool wants_first_hit() const noexcept override;
    std::unique_ptr<radiometry::SampleRecorder> make_recorder() const override;

private:
    class Recorder;
    const TruthLayout& m_layout;
    TruthContext m_context;
    BandRange m_bands;
    std::optional<std::size_t> m_channel;
    bool m_first_state;
    std::uint64_t m_first_problem;
    std::span<double> m_values;
};

/// The values of truth file `file` from a capture's truth values (pixel after pixel, the
/// file's bands only).
std::vector<double> truth_file_values(const TruthLayout& layout, const TruthFileLayout& file,
                                      std::span<const double> values);

}  // namespace glint::sensor
