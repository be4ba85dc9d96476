// SPDX-License-Identifier: Apache-2.0
// THERM in a render (docs/thermal.md, "THERM in the renderer"): every triangle of a static
// instance whose material uses THERM, cut into cells of at most kCellSize_m, is solved once
// per cell before the first capture, at the captures' times (mid-window, rounded to
// kTimeStep_s), its sunlit share over the 24 h before traced against the scene itself; the
// scene then reports those temperatures at its hits.
// The weather's hours are local time: hour 24 is the local midnight that starts the day of
// the first capture.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "glint/core/error.h"
#include "glint/core/text.h"
#include "glint/thermal/therm.h"
#include "render_parts.h"

namespace glint::render::detail {

namespace {

/// The captures' times are rounded to this step: a pushbroom's lines share a solution.
constexpr double kTimeStep_s = 60.0;
/// A facet is cut into cells at most this long (its longest edge / n, n² cells), so that a
/// large facet (a ground plane) carries its shadows; at most kMaxCuts cuts per edge, and for
/// a sliver (the long narrow side of a kerb or a road slab) no more than makes its cells'
/// mean area (kCellSize_m / kSliverCuts)²: a 300 m × 2 cm face gets 7 cuts, not 256.
constexpr double kCellSize_m = 1.0;
constexpr std::size_t kMaxCuts = 256;
constexpr double kSliverCuts = 4.0;

/// The broadband optical properties THERM uses where the .mat gives none: 1 − the mean
/// reflectance over 0.3-2.5 µm (every 10 nm), the mean emissivity over 8-14 µm.
thermal::ThermFacet optics(const model::Material& m, const model::ThermProperties& t) {
    thermal::ThermFacet f;
    const auto mean = [](const model::SpectralTable& table, double lo, double hi) {
        if (table.wavelengths_um.empty()) return -1.0;
        double sum = 0.0;
        int count = 0;
        for (double wl = lo; wl <= hi + 1e-9; wl += 0.01) {
            sum += model::sample_held(table, wl);
            ++count;
        }
        return sum / count;
    };
    const double reflectance = mean(m.reflectance, 0.3, 2.5);
    f.solar_absorptance = t.solar_absorptance.value_or(
        reflectance >= 0.0 ? std::clamp(1.0 - reflectance, 0.0, 1.0) : 0.7);
    double emissivity = mean(m.emissivity, 8.0, 14.0);
    if (emissivity < 0.0) {
        const double r = mean(m.reflectance, 8.0, 14.0);
        emissivity = r >= 0.0 ? 1.0 - r : 0.9;
    }
    f.thermal_emissivity = t.thermal_emissivity.value_or(std::clamp(emissivity, 0.0, 1.0));
    return f;
}

}  // namespace

bool uses_therm(const model::Scene& scene) noexcept {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [](const model::Material& m) { return bool(m.therm); });
}

std::shared_ptr<const scene::FacetTemperatures> solve_therm(const RenderPlan& plan,
                                                            const scene::GeometryScene& geometry,
                                                            const Context& context) {
    const RenderInputs& in = plan.inputs;
    std::vector<std::uint32_t> therm;
    for (std::size_t i = 0; i < in.scene.materials.size(); ++i) {
        if (in.scene.materials[i].therm) therm.push_back(static_cast<std::uint32_t>(i));
    }
    if (therm.empty() || plan.captures.empty()) return nullptr;
    if (in.weather.empty()) {
        throw input_error("material \"" + in.scene.materials[therm.front()].name +
                              "\" uses THERM but the simulation names no weather (a ThermWeather "
                              "plugin's filename, a .atm's "
                              "<uniformweather><classicdata><filename>, or a YAML atmosphere's "
                              "'weather')",
                          in.scene.materials[therm.front()].therm->where);
    }
    // The captures' times, in the rays' clock (the first platform's tasks reference).
    const auto& plugins = in.schedule->plugins();
    const DateTime reference = plugins.front().tasks.reference;
    std::set<double> rounded;
    for (const PlannedCapture& p : plan.captures) {
        const auto& source = in.schedule->sources()[p.capture.source];
        const DateTime own = plugins[source.plugin].tasks.reference;
        if (own != reference) {
            throw input_error("THERM needs every platform's tasks on one reference time (" +
                              format_iso8601_utc(reference) + " and " + format_iso8601_utc(own) +
                              ")");
        }
        const double mid = 0.5 * (p.capture.t0_s + p.capture.t1_s);
        rounded.insert(std::round(mid / kTimeStep_s) * kTimeStep_s);
    }
    const std::vector<double> times_s(rounded.begin(), rounded.end());
    // The history is anchored on the whole run's first capture (its start, rounded), not on
    // this run's: a shard (--schedule) solves the same temperatures.
    const std::optional<schedule::Capture> first = in.schedule->captures().next();
    const double anchor_s =
        std::min(times_s.front(),
                 std::round((first ? first->t0_s : times_s.front()) / kTimeStep_s) * kTimeStep_s);

    // Local time: the offset the tasks' time was written with, else the longitude's zone.
    const double longitude = in.frame.origin().longitude_deg;
    const bool written = reference.utc_offset_min != 0;
    const double offset_s =
        written ? 60.0 * reference.utc_offset_min : 3600.0 * std::round(longitude / 15.0);
    if (!written && std::round(longitude / 15.0) != 0.0) {
        context.log.warning(
            "THERM: the tasks' time has no UTC offset: the weather's local time "
            "is taken as UTC" +
            std::string(offset_s >= 0.0 ? "+" : "") + format_shortest(offset_s / 3600.0) +
            " h (the longitude's zone)");
    }
    // Weather hour of a ray-clock time t: 24 + hours since the local midnight of the first
    // capture's day.
    const DateTime first_local = add_seconds(add_seconds(reference, anchor_s), offset_s);
    const double since_midnight_s =
        static_cast<double>(((first_local.unix_s % 86'400) + 86'400) % 86'400) +
        first_local.fraction_s;
    const double hour_of_first = 24.0 + since_midnight_s / 3600.0;
    const auto weather_hour = [&](double t_s) { return hour_of_first + (t_s - anchor_s) / 3600.0; };
    const auto ray_time = [&](double hour) { return anchor_s + (hour - hour_of_first) * 3600.0; };
    thermal::ThermSettings settings;
    settings.start_h = hour_of_first;
    std::vector<double> hours;
    for (double t : times_s) hours.push_back(weather_hour(t));

    const std::vector<scene::GeometryScene::Facet> facets = geometry.static_facets(
        [&](std::uint32_t m) { return std::find(therm.begin(), therm.end(), m) != therm.end(); });
    {
        // Instances THERM leaves at their materials' constant temperature: those that move.
        std::set<std::uint32_t> solved;
        for (const auto& f : facets) solved.insert(f.instance);
        std::vector<std::string> kept;
        ErrorContext first_kept;
        for (std::size_t i = 0; i < in.scene.instances.size(); ++i) {
            const model::Instance& instance = in.scene.instances[i];
            if (!instance.dynamic() || solved.count(static_cast<std::uint32_t>(i)) != 0) continue;
            const auto& materials = in.scene.objects[instance.object_index].mesh.triangle_materials;
            if (std::any_of(materials.begin(), materials.end(), [&](std::uint32_t m) {
                    return std::find(therm.begin(), therm.end(), m) != therm.end();
                })) {
                if (kept.empty()) first_kept = instance.where;
                kept.push_back("\"" + instance.name + "\"");
            }
        }
        if (!kept.empty()) {
            const std::size_t count = kept.size();
            constexpr std::size_t kNamed = 5;
            if (count > kNamed) {
                kept.resize(kNamed);
                kept.push_back(std::to_string(count - kNamed) + " more");
            }
            const bool many = count > 1;
            context.log.warning(format_located(
                first_kept, "THERM is solved for what stays put: the moving instance" +
                                std::string(many ? "s " : " ") + join(kept, ", ", " and ") +
                                (many ? " keep their" : " keeps its") +
                                " THERM materials' constant TEMPERATURE and cast" +
                                (many ? "" : "s") + " no shadow in THERM's sun history"));
        }
    }
    // A property map decides a hit's material by texel, THERM a facet's temperature by its
    // own material: where the two meet, one warning per map says what is used.
    const auto is_therm = [&](std::uint32_t m) {
        return std::find(therm.begin(), therm.end(), m) != therm.end();
    };
    for (const model::PropertyMap& map : in.scene.maps) {
        std::vector<std::uint32_t> gives = map.slot_materials;
        for (const model::TextureClasses& classes : map.texture_classes) {
            gives.insert(gives.end(), classes.materials.begin(), classes.materials.end());
        }
        std::vector<std::string> placed;  // THERM materials the map puts on other facets
        for (std::uint32_t m : gives) {
            if (is_therm(m) && std::find(map.applies_to.begin(), map.applies_to.end(), m) ==
                                   map.applies_to.end()) {
                placed.push_back("\"" + in.scene.materials[m].name + "\"");
            }
        }
        std::sort(placed.begin(), placed.end());
        placed.erase(std::unique(placed.begin(), placed.end()), placed.end());
        const bool over_therm = std::any_of(map.applies_to.begin(), map.applies_to.end(), is_therm);
        if (placed.empty() && !over_therm) continue;
        std::string message = "THERM solves each facet with its own material:";
        if (over_therm) {
            message += " the materials it puts on a THERM facet take that facet's temperature";
        }
        if (!placed.empty()) {
            message += std::string(over_therm ? ";" : "") + " where it puts " +
                       join(placed, ", ", " or ") +
                       " on a facet of another material, the constant TEMPERATURE is used";
        }
        context.log.warning(format_located(map.where, message));
    }
    context.log.info("THERM: " + std::to_string(facets.size()) + " facets at " +
                     std::to_string(times_s.size()) + " time(s), weather " + in.weather.file +
                     " from hour " + format_shortest(std::round(hours.front() * 100.0) / 100.0));
    // Each facet's cuts and its cells: (facet, cell slot, the cell's centroid).
    struct Cell {
        std::size_t facet = 0;
        std::size_t slot = 0;
        motion::Vec3 point_m;
    };
    std::vector<std::size_t> cuts(facets.size(), 1);
    std::vector<Cell> cells;
    for (std::size_t k = 0; k < facets.size(); ++k) {
        const auto& c = facets[k].corners_m;
        const double longest = std::max({norm(c[1] - c[0]), norm(c[2] - c[1]), norm(c[0] - c[2])});
        const double area_m2 = 0.5 * norm(cross(c[1] - c[0], c[2] - c[0]));
        const double by_area = std::ceil(kSliverCuts * std::sqrt(area_m2) / kCellSize_m);
        const double wanted = std::min(std::ceil(longest / kCellSize_m), by_area);
        const std::size_t n =
            std::clamp(static_cast<std::size_t>(wanted), std::size_t{1}, kMaxCuts);
        cuts[k] = n;
        const double step = 1.0 / static_cast<double>(n);
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = 0; i + j < n; ++j) {
                for (const bool upper : {false, true}) {
                    if (upper && i + j + 1 >= n) continue;
                    const double third = upper ? 2.0 / 3.0 : 1.0 / 3.0;
                    const double u = (static_cast<double>(i) + third) * step;
                    const double v = (static_cast<double>(j) + third) * step;
                    cells.push_back({k, scene::FacetTemperatures::cell_index(n, i, j, upper),
                                     c[0] + (c[1] - c[0]) * u + (c[2] - c[0]) * v});
                }
            }
        }
    }
    context.log.info("THERM: " + std::to_string(cells.size()) + " cells of at most " +
                     format_shortest(kCellSize_m) + " m");
    // The sun's direction every kSunStep_h over the spin-up and the captures, once for every
    // cell (the ephemeris is the costly part of a step), linear between (it moves 0.25° a
    // minute: the chord's error is below 10⁻⁶ rad).
    constexpr double kSunStep_h = 1.0 / 60.0;
    const double sun_from_h = settings.start_h - settings.spin_up_h - kSunStep_h;
    std::vector<std::array<double, 3>> sun_table;
    for (double h = sun_from_h; h <= hours.back() + 2.0 * kSunStep_h; h += kSunStep_h) {
        const motion::SunPosition p = in.light->sun_at(add_seconds(reference, ray_time(h)));
        sun_table.push_back({p.direction_enu.x, p.direction_enu.y, p.direction_enu.z});
    }
    const auto sun = [&](double hour) {
        const double position = std::clamp((hour - sun_from_h) / kSunStep_h, 0.0,
                                           static_cast<double>(sun_table.size() - 2));
        const auto i = static_cast<std::size_t>(position);
        const double f = position - static_cast<double>(i);
        std::array<double, 3> d{};
        double length = 0.0;
        for (std::size_t k = 0; k < 3; ++k) {
            d[k] = (1.0 - f) * sun_table[i][k] + f * sun_table[i + 1][k];
            length += d[k] * d[k];
        }
        for (double& x : d) x /= std::sqrt(length);
        return d;
    };
    // Facets that store heat step on THERM's grid; faces without storage balance at the
    // times themselves. Each plan says where a cell's sunlit share is needed.
    const thermal::ThermPlan slab_plan = thermal::therm_plan(true, hours, settings);
    const thermal::ThermPlan face_plan = thermal::therm_plan(false, hours, settings);
    const std::vector<double> slab_times = slab_plan.forcing_times_h();
    const std::vector<double> face_times = face_plan.forcing_times_h();
    const auto stores = [&](const Cell& cell) {
        return thermal::stores_heat(*in.scene.materials[facets[cell.facet].material].therm);
    };
    tbb::task_arena arena(context.threads == 0 ? tbb::task_arena::automatic
                                               : static_cast<int>(context.threads));
    // Pass 1: each cell's shadow history, one bit per forcing time: a shadow ray from its
    // centroid towards the sun where the sun is up and in front of the face.
    std::vector<std::vector<std::uint64_t>> lit(cells.size());
    const auto trace_history = [&](std::size_t index) {
        const Cell& cell = cells[index];
        const scene::GeometryScene::Facet& f = facets[cell.facet];
        const std::vector<double>& at = stores(cell) ? slab_times : face_times;
        std::vector<std::uint64_t> bits((at.size() + 63) / 64, 0);
        const motion::Vec3 origin = cell.point_m + f.normal * f.spawn_offset_m;
        for (std::size_t i = 0; i < at.size(); ++i) {
            const std::array<double, 3> s = sun(at[i]);
            const motion::Vec3 to_sun{s[0], s[1], s[2]};
            if (s[2] <= 0.0 || dot(to_sun, f.normal) <= 0.0) continue;
            if (!geometry.occluded(origin, to_sun, ray_time(at[i]))) {
                bits[i / 64] |= std::uint64_t{1} << (i % 64);
            }
        }
        lit[index] = std::move(bits);
    };
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, cells.size(), [&](std::size_t i) { trace_history(i); });
    });
    // Cells of one material with the same normal and shadow history have the same forcing at
    // every step, so the same temperatures: each such group is solved once, numbered in cell
    // order (a ground plane's open cells are one group; the shaded ones split by history).
    const auto same = [&](std::size_t a, std::size_t b) {
        const auto& fa = facets[cells[a].facet];
        const auto& fb = facets[cells[b].facet];
        return fa.material == fb.material && fa.normal.x == fb.normal.x &&
               fa.normal.y == fb.normal.y && fa.normal.z == fb.normal.z && lit[a] == lit[b];
    };
    const auto hash = [&](std::size_t index) {
        const auto& f = facets[cells[index].facet];
        std::size_t h = std::hash<std::uint32_t>{}(f.material);
        const auto mix = [&h](std::size_t v) {
            h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        };
        for (const double c : {f.normal.x, f.normal.y, f.normal.z}) mix(std::hash<double>{}(c));
        for (const std::uint64_t word : lit[index]) mix(std::hash<std::uint64_t>{}(word));
        return h;
    };
    std::unordered_map<std::size_t, std::size_t, decltype(hash), decltype(same)> groups(
        cells.size() / 4 + 1, hash, same);
    std::vector<std::size_t> group_of(cells.size());
    std::vector<std::size_t> first_cell;  // of each group
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const auto [it, added] = groups.try_emplace(i, first_cell.size());
        if (added) first_cell.push_back(i);
        group_of[i] = it->second;
    }
    context.log.info("THERM: " + std::to_string(first_cell.size()) +
                     " distinct (material, normal, shadow history) solved");
    // Pass 2: one slab per group.
    std::vector<std::vector<double>> solved(first_cell.size());
    const auto solve_group = [&](std::size_t g) {
        const std::size_t index = first_cell[g];
        const scene::GeometryScene::Facet& f = facets[cells[index].facet];
        const model::Material& material = in.scene.materials[f.material];
        thermal::ThermFacet facet = optics(material, *material.therm);
        facet.normal = {f.normal.x, f.normal.y, f.normal.z};
        const bool slab = stores(cells[index]);
        const std::size_t count = (slab ? slab_times : face_times).size();
        std::vector<double> shares(count, 0.0);
        for (std::size_t i = 0; i < count; ++i) {
            if ((lit[index][i / 64] >> (i % 64)) & 1U) shares[i] = 1.0;
        }
        solved[g] = thermal::therm_temperatures_k(*material.therm, facet, in.weather, sun, shares,
                                                  slab ? slab_plan : face_plan);
    };
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, first_cell.size(),
                          [&](std::size_t g) { solve_group(g); });
    });
    auto table = std::make_shared<scene::FacetTemperatures>(times_s);
    std::size_t next = 0;
    for (std::size_t k = 0; k < facets.size(); ++k) {
        const std::size_t n = cuts[k];
        std::vector<double> rows(scene::FacetTemperatures::cell_slots(n) * times_s.size(), 0.0);
        for (; next < cells.size() && cells[next].facet == k; ++next) {
            const std::vector<double>& temperatures = solved[group_of[next]];
            std::copy(
                temperatures.begin(), temperatures.end(),
                rows.begin() + static_cast<std::ptrdiff_t>(cells[next].slot * times_s.size()));
        }
        table->add(facets[k].instance, facets[k].triangle, n, rows);
    }
    return table;
}

}  // namespace glint::render::detail
