// SPDX-License-Identifier: Apache-2.0
// The measurement sequence of glint-bench and its JSON report (measurements.h).
#include "measurements.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <thread>

#include "bare_embree.h"
#include "glint/core/datetime.h"
#include "glint/core/runner.h"
#include "glint/motion/frames.h"
#include "glint/motion/scene_instances.h"
#include "glint/scene/geometry_scene.h"
#include "machine_load.h"
#include "ray_sets.h"
#include "tracer_runs.h"

namespace glint::bench {
namespace {

using Json = nlohmann::ordered_json;

/// The camera: 3 km above the terrain's centre, ±29° across, which covers about ±1.66 km.
constexpr double kCameraAltitude_m = 3000.0;
constexpr double kCameraHalfFovDeg = 29.0;
/// The band counts of the band-cost runs: 2,100 is a real hyperspectral bandpass (0.4-2.5 µm
/// at 1 nm).
constexpr unsigned kBandCounts[] = {1, 16, 256, 2100};
/// The targets of the performance requirement: the tracer's ray rate against bare Embree's
/// (primary and incoherent baselines), and the cost per path at 256 and 2,100 bands against
/// 1 band, with every band on every path and with spectral sampling.
constexpr double kRatioPrimaryTarget = 0.65;
constexpr double kRatioIncoherentTarget = 0.75;
constexpr double kBandCostTarget = 1.2;
constexpr double kHyperspectralCostTarget = 2.0;
constexpr double kScalingTarget = 0.95;
/// Above this share of the machine taken by other processes a figure is flagged unreliable.
constexpr double kQuietLimit = 0.05;

/// The share of the machine other processes took during each measurement, by name.
class Interference {
public:
    /// Runs `measure` under a LoadProbe; records the load as `name`.
    template <typename Measure>
    auto run(const std::string& name, Measure&& measure) {
        const LoadProbe probe;
        auto result = measure();
        const auto load = probe.other_load();
        m_loads[name] = load ? Json(std::round(*load * 1000.0) / 1000.0) : Json(nullptr);
        if (load) {
            m_max = std::max(m_max, *load);
            m_known = true;
        }
        return result;
    }
    double max() const noexcept { return m_max; }
    /// Whether any measurement was long enough to judge.
    bool known() const noexcept { return m_known; }
    const Json& loads() const noexcept { return m_loads; }

private:
    Json m_loads = Json::object();
    double m_max = 0.0;
    bool m_known = false;
};

/// `x` rounded to 4 significant digits (the report's figures are not more precise).
double sig4(double x) {
    if (!(x != 0.0) || !std::isfinite(x)) return x;
    const double scale = std::pow(10.0, 3 - std::floor(std::log10(std::fabs(x))));
    return std::round(x * scale) / scale;
}

double ratio(double a, double b) { return b > 0.0 ? a / b : 0.0; }

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) {
                const auto first = line.find_first_not_of(" \t", colon + 1);
                return first == std::string::npos ? "" : line.substr(first);
            }
        }
    }
    return "unknown";
}

/// The best Embree ISA the CPU supports (Embree picks it at run time when no isa= is set).
std::string cpu_isa() {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx512cd")) {
        return "avx512";
    }
    if (__builtin_cpu_supports("avx2")) return "avx2";
    if (__builtin_cpu_supports("avx")) return "avx";
    if (__builtin_cpu_supports("sse4.2")) return "sse4.2";
    return "sse2";
}

/// Fraction of rays on which the baseline and GeometryScene agree: both miss, or both hit
/// within 5 cm of each other.
double agreement(const std::vector<float>& bare, const std::vector<double>& glint) {
    if (bare.empty()) return 1.0;
    std::size_t same = 0;
    for (std::size_t i = 0; i < bare.size(); ++i) {
        const bool bare_hit = std::isfinite(bare[i]);
        const bool glint_hit = std::isfinite(glint[i]);
        if (bare_hit != glint_hit) continue;
        if (!bare_hit || std::fabs(double(bare[i]) - glint[i]) <= 0.05) ++same;
    }
    return double(same) / double(bare.size());
}

std::string hex(std::uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

Json bare_json(const BareTiming& t) {
    return {{"seconds", sig4(t.seconds)},
            {"rays", t.rays},
            {"passes", t.passes},
            {"hit_fraction", sig4(ratio(double(t.hits), double(t.rays)))},
            {"rays_per_s", sig4(t.rays_per_s())}};
}

Json tracer_json(const TracerTiming& t) {
    return {{"seconds", sig4(t.seconds)},
            {"rays", t.rays},
            {"paths", t.paths},
            {"rays_per_path", sig4(ratio(double(t.rays), double(t.paths)))},
            {"rays_per_s", sig4(t.rays_per_s())},
            {"paths_per_s", sig4(t.paths_per_s())},
            {"seconds_per_path", t.paths > 0 ? t.seconds / double(t.paths) : 0.0},
            {"radiance_hash", hex(t.radiance_hash)}};
}

Json target(double value, double goal, bool at_least) {
    return {{"value", sig4(value)},
            {"target", goal},
            {"met", at_least ? value >= goal : value <= goal}};
}

}  // namespace

BenchOptions quick_options() {
    BenchOptions o;
    o.image_size = 48;
    o.min_bare_seconds = 0.05;
    o.scene.terrain_quads = 64;
    o.scene.buildings = 64;
    return o;
}

Json run_benchmark(const BenchOptions& options, const Context& context) {
    const Log& log = context.log;
    const unsigned threads =
        context.threads != 0 ? context.threads : std::max(1u, std::thread::hardware_concurrency());
    using Clock = std::chrono::steady_clock;

    // The scene, twice.
    log.info("building the procedural scene");
    const ProceduralScene procedural = build_procedural_scene(options.scene);
    const model::Scene& scene = procedural.scene;
    const auto trajectories =
        motion::make_instance_trajectories(scene, motion::SceneFrame(), DateTime{}, log);
    const auto build_start = Clock::now();
    const scene::GeometryScene geometry =
        scene::GeometryScene::build(scene, trajectories, scene::BuildOptions{}, log);
    const double glint_build_s = std::chrono::duration<double>(Clock::now() - build_start).count();
    const BareEmbreeScene bare(scene, geometry.device().config);

    // The rays: the camera's primary rays as solve() draws them, and one diffuse bounce each.
    const NadirCamera camera(options.image_size, options.image_size, kCameraAltitude_m,
                             kCameraHalfFovDeg * std::acos(-1.0) / 180.0);
    radiometry::StreamKey key;
    key.seed = context.seed;
    const std::uint64_t problems = camera.problems();
    const auto primary = primary_rays(camera, problems, options.samples, key);
    const auto incoherent = incoherent_rays(geometry, primary, context.seed, threads);
    const auto bare_primary = to_bare(primary);
    const auto bare_incoherent = to_bare(incoherent);
    const double primary_agreement = agreement(intersect_distances(bare, bare_primary, threads),
                                               scene_distances(geometry, primary, threads));

    // Bare Embree, N threads then 1.
    Interference interference;
    const auto bare_run = [&](const std::string& name, const std::vector<BareRay>& rays,
                              unsigned n) {
        return interference.run(name, [&] {
            return time_intersect(bare, rays, n, options.min_bare_seconds, options.repeats);
        });
    };
    log.info("timing bare rtcIntersect1 on " + std::to_string(threads) + " thread(s)");
    const BareTiming bare_primary_n = bare_run("bare_primary", bare_primary, threads);
    const BareTiming bare_incoherent_n = bare_run("bare_incoherent", bare_incoherent, threads);
    log.info("timing bare rtcIntersect1 on 1 thread");
    const BareTiming bare_primary_1 =
        threads > 1 ? bare_run("bare_primary_one_thread", bare_primary, 1) : bare_primary_n;
    const BareTiming bare_incoherent_1 =
        threads > 1 ? bare_run("bare_incoherent_one_thread", bare_incoherent, 1)
                    : bare_incoherent_n;

    // The tracer at every band count on N threads, then the main band count on 1 thread.
    std::map<unsigned, std::unique_ptr<TracerRig>> rigs;
    for (const unsigned b : kBandCounts) rigs[b] = std::make_unique<TracerRig>(scene, geometry, b);
    if (!rigs.contains(options.bands)) {
        rigs[options.bands] = std::make_unique<TracerRig>(scene, geometry, options.bands);
    }
    const TracerRig& main_rig = *rigs.at(options.bands);
    log.info("warming up the tracer");
    time_tracer(main_rig.tracer, camera, std::min<std::uint64_t>(problems, 4096), options.samples,
                options.tile, key, threads, 1, context);
    std::map<unsigned, TracerTiming> by_bands;
    std::map<unsigned, TracerTiming> trace_only;
    for (const auto& [b, rig] : rigs) {
        log.info("timing the tracer at " + std::to_string(b) + " band(s) on " +
                 std::to_string(threads) + " thread(s)");
        const std::string name = "tracer_" + std::to_string(b) + "_bands";
        by_bands[b] = interference.run(name, [&] {
            return time_tracer(rig->tracer, camera, problems, options.samples, options.tile, key,
                               threads, options.repeats, context);
        });
        trace_only[b] = interference.run(name + "_trace_only", [&] {
            return time_trace_only(rig->tracer, camera, problems, options.samples, key, threads,
                                   options.repeats);
        });
    }
    // The render's way (solve_each, each spectrum integrated and dropped): every band, then
    // spectral_samples wavelengths per path.
    radiometry::TracerSettings sampled_settings;
    sampled_settings.spectral_samples = options.spectral_samples;
    std::map<unsigned, TracerTiming> reduced;
    std::map<unsigned, TracerTiming> sampled;
    for (const unsigned b : kBandCounts) {
        log.info("timing the render's reduction at " + std::to_string(b) + " band(s)");
        reduced[b] = interference.run("reduced_" + std::to_string(b) + "_bands", [&] {
            return time_reduced(rigs.at(b)->tracer, camera, problems, options.samples, options.tile,
                                key, threads, options.repeats, context);
        });
        const TracerRig sampled_rig(scene, geometry, b, sampled_settings);
        sampled[b] = interference.run("sampled_" + std::to_string(b) + "_bands", [&] {
            return time_reduced(sampled_rig.tracer, camera, problems, options.samples, options.tile,
                                key, threads, options.repeats, context);
        });
    }
    const TracerTiming& tracer_n = by_bands.at(options.bands);
    log.info("timing the tracer on 1 thread");
    const TracerTiming tracer_1 =
        threads > 1 ? interference.run("tracer_one_thread",
                                       [&] {
                                           return time_tracer(main_rig.tracer, camera, problems,
                                                              options.samples, options.tile, key, 1,
                                                              options.repeats, context);
                                       })
                    : tracer_n;
    const TracerTiming trace_only_1 =
        threads > 1
            ? interference.run("tracer_trace_only_one_thread",
                               [&] {
                                   return time_trace_only(main_rig.tracer, camera, problems,
                                                          options.samples, key, 1, options.repeats);
                               })
            : trace_only.at(options.bands);
    const bool quiet = interference.max() <= kQuietLimit;
    if (!quiet) {
        log.warning("other processes took up to " +
                    std::to_string(int(std::round(interference.max() * 100.0))) +
                    " % of the machine during a measurement; the figures are not reliable");
    }

    // The report.
    const double ratio_primary = ratio(tracer_n.rays_per_s(), bare_primary_n.rays_per_s());
    const double ratio_incoherent = ratio(tracer_n.rays_per_s(), bare_incoherent_n.rays_per_s());
    const double speedup_bare = ratio(bare_primary_n.rays_per_s(), bare_primary_1.rays_per_s());
    const double speedup_bare_incoherent =
        ratio(bare_incoherent_n.rays_per_s(), bare_incoherent_1.rays_per_s());
    const double speedup_tracer = ratio(tracer_1.seconds, tracer_n.seconds);
    const double relative_scaling = ratio(speedup_tracer, speedup_bare);
    const auto per_path = [](const TracerTiming& t) {
        return t.paths > 0 ? t.seconds / double(t.paths) : 0.0;
    };
    const double one_band_per_path = per_path(by_bands.at(1));
    const double trace_only_one_band = per_path(trace_only.at(1));

    Json report;
    report["format"] = "glint-bench";
    report["schema_version"] = 1;
    report["provenance"] = {{"tool", "glint-bench"},
                            {"version", glint::version()},
                            {"arguments", options.command_line},
                            {"seed", context.seed}};
    report["machine"] = {{"cpu", cpu_model()},
                         {"hardware_threads", std::thread::hardware_concurrency()}};
    report["embree"] = {
        {"version", geometry.device().embree_version},
        {"device_config", geometry.device().config},
        {"isa", cpu_isa()},
        {"isa_source", "the best ISA the CPU supports; Embree 3 selects it at run time"},
        {"native_packet_width", bare.native_packet_width()}};
    report["threads"] = threads;
    report["interference"] = {
        {"quiet", interference.known() ? Json(quiet) : Json(nullptr)},
        {"max_other_load", sig4(interference.max())},
        {"other_load", interference.loads()},
        {"note",
         "share of all cores' time that other processes (and hypervisor steal) took during "
         "each measurement; above 0.05 the figures measure the neighbours too"}};
    report["scene"] = {
        {"triangles", procedural.unique_triangles()},
        {"instanced_triangles", geometry.instanced_triangle_count()},
        {"terrain_triangles", procedural.terrain_triangles},
        {"terrain_quads_per_side", options.scene.terrain_quads},
        {"buildings", options.scene.buildings},
        {"triangles_per_building", procedural.building_triangles},
        {"instances", scene.instances.size()},
        {"build_seconds",
         {{"geometry_scene", sig4(glint_build_s)}, {"bare_embree", sig4(bare.build_seconds())}}}};
    report["rays"] = {
        {"camera", "nadir pinhole, " + std::to_string(options.image_size) + " x " +
                       std::to_string(options.image_size) + " pixels, 3000 m above the terrain, " +
                       "+/-29 deg"},
        {"samples_per_pixel", options.samples},
        {"tile_problems", options.tile},
        {"primary_rays", primary.size()},
        {"incoherent_rays", incoherent.size()},
        {"incoherent", "one cosine-distributed ray from each primary hit, about its normal"},
        {"primary_hits_agree", sig4(primary_agreement)}};
    report["bare_embree"] = {
        {"primary_rays_per_s", sig4(bare_primary_n.rays_per_s())},
        {"incoherent_rays_per_s", sig4(bare_incoherent_n.rays_per_s())},
        {"primary", bare_json(bare_primary_n)},
        {"incoherent", bare_json(bare_incoherent_n)},
        {"one_thread",
         {{"primary", bare_json(bare_primary_1)}, {"incoherent", bare_json(bare_incoherent_1)}}}};
    report["tracer"] = tracer_json(tracer_n);
    report["tracer"]["bands"] = options.bands;
    report["tracer"]["one_thread"] = tracer_json(tracer_1);
    report["tracer"]["same_radiance_on_1_and_n_threads"] =
        tracer_1.radiance_hash == tracer_n.radiance_hash;
    report["ratio"] = {
        {"primary", sig4(ratio_primary)},
        {"incoherent", sig4(ratio_incoherent)},
        {"primary_one_thread", sig4(ratio(tracer_1.rays_per_s(), bare_primary_1.rays_per_s()))},
        {"note",
         "tracer rays/s over bare rtcIntersect1 rays/s; the tracer's rays include incoherent "
         "bounce rays and shadow rays, the primary baseline only coherent camera rays, so "
         "ratio.primary is conservative"}};
    report["scaling"] = {{"threads", {1, threads}},
                         {"bare", sig4(speedup_bare)},
                         {"bare_incoherent", sig4(speedup_bare_incoherent)},
                         {"tracer", sig4(speedup_tracer)},
                         {"relative", sig4(relative_scaling)},
                         {"tracer_trace_only",
                          sig4(ratio(trace_only_1.seconds, trace_only.at(options.bands).seconds))}};
    Json bands;
    for (const unsigned b : kBandCounts) {
        const TracerTiming& t = by_bands.at(b);
        const TracerTiming& bare_trace = trace_only.at(b);
        bands[std::to_string(b)] = {
            {"seconds", sig4(t.seconds)},
            {"seconds_per_path", per_path(t)},
            {"relative", sig4(ratio(per_path(t), one_band_per_path))},
            {"rays", t.rays},
            {"rays_per_s", sig4(t.rays_per_s())},
            {"trace_only_seconds_per_path", per_path(bare_trace)},
            {"trace_only_rays", bare_trace.rays},
            {"trace_only_relative", sig4(ratio(per_path(bare_trace), trace_only_one_band))}};
    }
    report["bands"] = bands;
    const double one_band_reduced = per_path(reduced.at(1));
    Json render_path;
    for (const unsigned b : kBandCounts) {
        const TracerTiming& every = reduced.at(b);
        const TracerTiming& some = sampled.at(b);
        render_path[std::to_string(b)] = {
            {"seconds_per_path", per_path(every)},
            {"relative", sig4(ratio(per_path(every), one_band_reduced))},
            {"sampled_seconds_per_path", per_path(some)},
            {"sampled_relative", sig4(ratio(per_path(some), one_band_reduced))},
            {"sampled_rays", some.rays}};
    }
    render_path["spectral_samples"] = options.spectral_samples;
    render_path["note"] =
        "solve_each() as glint-render calls it, each pixel's spectrum integrated into one value "
        "and dropped; relative: per path over the one-band figure; sampled: each path follows "
        "spectral_samples wavelengths (the reference band and the rest drawn), unbiased but "
        "noisier per band";
    report["render_path"] = render_path;
    const double band_cost = ratio(per_path(by_bands.at(256)), one_band_per_path);
    const double hyperspectral_cost = ratio(per_path(by_bands.at(2100)), one_band_per_path);
    const double sampled_band_cost = ratio(per_path(sampled.at(256)), one_band_reduced);
    const double sampled_cost = ratio(per_path(sampled.at(2100)), one_band_reduced);
    report["targets"] = {
        {"ratio_primary", target(ratio_primary, kRatioPrimaryTarget, true)},
        {"ratio_incoherent", target(ratio_incoherent, kRatioIncoherentTarget, true)},
        {"band_cost_256", target(band_cost, kBandCostTarget, false)},
        {"band_cost_256_sampled", target(sampled_band_cost, kBandCostTarget, false)},
        {"band_cost_2100", target(hyperspectral_cost, kHyperspectralCostTarget, false)},
        {"band_cost_2100_sampled", target(sampled_cost, kHyperspectralCostTarget, false)},
        {"thread_scaling", target(relative_scaling, kScalingTarget, true)}};
    return report;
}

}  // namespace glint::bench
