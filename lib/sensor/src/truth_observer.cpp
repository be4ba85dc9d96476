// SPDX-License-Identifier: Apache-2.0
// The truth observer: per-pixel accumulators over a problem's samples (glint/sensor/truth.h).
#include <cmath>
#include <limits>
#include <utility>

#include "glint/sensor/truth.h"

namespace glint::sensor {
namespace {

using Q = model::TruthQuantity;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

// A named namespace, not an anonymous one: Recorder, a member of a class with external
// linkage, holds Tallies (GCC's -Wsubobject-linkage in a unity build).
namespace truth_detail {

/// Σ w per index, the index with the most (ties: the lowest).
class Tally {
public:
    void clear() noexcept { m_weights.clear(); }
    void add(std::uint32_t index, double weight) {
        for (auto& [i, w] : m_weights) {
            if (i == index) {
                w += weight;
                return;
            }
        }
        m_weights.emplace_back(index, weight);
    }
    double most_common() const noexcept {
        if (m_weights.empty()) return kNaN;
        std::pair<std::uint32_t, double> best = m_weights.front();
        for (const auto& [i, w] : m_weights) {
            if (w > best.second || (w == best.second && i < best.first)) best = {i, w};
        }
        return static_cast<double>(best.first);
    }

private:
    std::vector<std::pair<std::uint32_t, double>> m_weights;
};

}  // namespace truth_detail

class TruthObserver::Recorder final : public radiometry::SampleRecorder {
public:
    explicit Recorder(const TruthObserver& owner)
        : m_owner(owner),
          m_targets(owner.m_layout.targets.size()),
          m_channels(owner.m_channel ? 1 : owner.m_context.units->channels()),
          m_moments(m_channels),
          m_channel_values(m_channels),
          m_scaled(owner.m_bands.count) {}

    void begin(std::uint64_t) override {
        m_weight = m_weight_sq = m_hit_weight = 0.0;
        m_point = m_normal = {};
        m_distance = m_shadow = m_temperature = m_reflectance = 0.0;
        m_materials.clear();
        m_instances.clear();
        m_objects.clear();
        std::fill(m_targets.begin(), m_targets.end(), 0.0);
        std::fill(m_moments.begin(), m_moments.end(), radiometry::WeightedMoments{});
    }

    void add(const radiometry::SampleRay& ray, std::span<const double> radiance,
             const radiometry::FirstHit* hit) override {
        const double w = ray.weight;
        m_weight += w;
        m_weight_sq += w * w;
        add_channels(radiance, w);
        if (hit == nullptr || !hit->hit) return;
        const TruthContext& c = m_owner.m_context;
        m_hit_weight += w;
        m_point = m_point + w * hit->position_m;
        m_normal = m_normal + w * hit->normal;
        m_distance += w * hit->distance_m;
        if (hit->sun_blocked) m_shadow += w;
        // A mixture map's texel counts each of its materials by its weight (the abundance
        // of a mixed texel is the weight, not the material this sample drew).
        const std::uint32_t single = hit->material;
        const float one = 1.0f;
        const std::span<const std::uint32_t> materials =
            hit->mix.materials.empty() ? std::span<const std::uint32_t>(&single, 1)
                                       : hit->mix.materials;
        const std::span<const float> weights =
            hit->mix.materials.empty() ? std::span<const float>(&one, 1) : hit->mix.weights;
        const auto& targets = m_owner.m_layout.targets;
        for (std::size_t k = 0; k < materials.size(); ++k) {
            const double wk = w * weights[k];
            if (!(wk > 0.0)) continue;
            const std::uint32_t m = materials[k];
            m_temperature += wk * (hit->temperature_k > 0.0 ? hit->temperature_k
                                                            : c.scene->materials[m].temperature_k);
            m_reflectance += wk * c.materials->reflectance(m)[c.reflectance_band];
            // A texture class counts as the material it is a class of.
            const std::uint32_t reported = c.scene->materials[m].texture_parent.value_or(m);
            m_materials.add(reported, wk);
            for (std::size_t t = 0; t < targets.size(); ++t) {
                if (!targets[t].is_tag && targets[t].matches[reported] != 0) m_targets[t] += wk;
            }
        }
        m_instances.add(hit->instance, w);
        m_objects.add(static_cast<std::uint32_t>(c.scene->instances[hit->instance].object_index),
                      w);
        for (std::size_t t = 0; t < targets.size(); ++t) {
            if (targets[t].is_tag && targets[t].matches[hit->instance] != 0) m_targets[t] += w;
        }
    }

    void end(std::uint64_t problem, std::uint64_t samples) override {
        const TruthLayout& layout = m_owner.m_layout;
        const std::size_t stride = layout.bands.size();
        double* out = m_owner.m_values.data() + (problem - m_owner.m_first_problem) * stride;
        for (std::size_t b = 0; b < stride; ++b) {
            const TruthBand& band = layout.bands[b];
            if (band.quantity == Q::sample_count) {
                out[b] += static_cast<double>(samples);
            } else if (band.quantity == Q::standard_error) {
                const std::size_t first = m_owner.m_channel.value_or(0);
                if (band.index >= first && band.index - first < m_channels) {
                    out[b] = m_moments[band.index - first].standard_error(m_weight, m_weight_sq);
                }
            } else if (m_owner.m_first_state) {
                out[b] = first_hit_value(band);
            }
        }
    }

private:
    /// One sample's channel values into the standard-error moments.
    void add_channels(std::span<const double> radiance, double w) {
        const TruthContext& c = m_owner.m_context;
        for (std::size_t b = 0; b < radiance.size(); ++b) {
            m_scaled[b] = radiance[b] * c.radiance_share;
        }
        if (m_owner.m_channel) {
            m_channel_values[0] =
                c.units->channel_value(*m_owner.m_channel, m_owner.m_bands.first, m_scaled);
        } else {
            c.units->apply(m_scaled, m_channel_values);
        }
        for (std::size_t k = 0; k < m_channels; ++k) {
            m_moments[k].add(m_channel_values[k], w, m_weight);
        }
    }

    double first_hit_value(const TruthBand& band) const {
        if (band.quantity == Q::abundance) {
            return m_weight > 0.0 ? m_targets[band.index] / m_weight : 0.0;
        }
        if (!(m_hit_weight > 0.0)) return kNaN;
        const double h = m_hit_weight;
        const motion::Vec3 point = (1.0 / h) * m_point;
        switch (band.quantity) {
            case Q::material_index:
                return m_materials.most_common();
            case Q::instance_index:
                return m_instances.most_common();
            case Q::object_index:
                return m_objects.most_common();
            case Q::scene_x:
                return point.x;
            case Q::scene_y:
                return point.y;
            case Q::scene_z:
                return point.z;
            case Q::latitude:
                return geodetic(point).latitude_deg;
            case Q::longitude:
                return geodetic(point).longitude_deg;
            case Q::altitude:
                return geodetic(point).altitude_m;
            case Q::normal_x:
                return unit_normal().x;
            case Q::normal_y:
                return unit_normal().y;
            case Q::normal_z:
                return unit_normal().z;
            case Q::distance:
                return m_distance / h;
            case Q::shadow:
                return m_shadow / h;
            case Q::temperature:
                return m_temperature / h;
            case Q::reflectance:
                return m_reflectance / h;
            default:
                return kNaN;
        }
    }

    motion::Geodetic geodetic(const motion::Vec3& point) const {
        return motion::ecef_to_geodetic(m_owner.m_context.frame->enu_to_ecef(point));
    }

    motion::Vec3 unit_normal() const {
        const double length = motion::norm(m_normal);
        if (!(length > 0.0)) return {kNaN, kNaN, kNaN};
        return (1.0 / length) * m_normal;
    }

    const TruthObserver& m_owner;
    double m_weight = 0.0;
    double m_weight_sq = 0.0;
    double m_hit_weight = 0.0;
    motion::Vec3 m_point;
    motion::Vec3 m_normal;
    double m_distance = 0.0;
    double m_shadow = 0.0;
    double m_temperature = 0.0;
    double m_reflectance = 0.0;
    truth_detail::Tally m_materials;
    truth_detail::Tally m_instances;
    truth_detail::Tally m_objects;
    std::vector<double> m_targets;  ///< Σ w per abundance target
    std::size_t m_channels;         ///< channels this state's standard errors cover
    std::vector<radiometry::WeightedMoments> m_moments;
    std::vector<double> m_channel_values;
    std::vector<double> m_scaled;  ///< one sample's radiance × the active area's share
};

TruthObserver::TruthObserver(const TruthLayout& layout, const TruthContext& context,
                             BandRange bands, std::optional<std::size_t> channel, bool first_state,
                             std::uint64_t first_problem, std::span<double> values)
    : m_layout(layout),
      m_context(context),
      m_bands(bands),
      m_channel(channel),
      m_first_state(first_state),
      m_first_problem(first_problem),
      m_values(values) {}

bool TruthObserver::wants_first_hit() const noexcept {
    return m_first_state && m_layout.needs_first_hit;
}

std::unique_ptr<radiometry::SampleRecorder> TruthObserver::make_recorder() const {
    return std::make_unique<Recorder>(*this);
}

}  // namespace glint::sensor
