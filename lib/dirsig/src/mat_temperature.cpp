// SPDX-License-Identifier: Apache-2.0
// A `.mat` entry's temperature map (`TEMP_SOLVER_NAME = Map`, docs/maps.md): its
// TEMP_SOLVER block's IMAGE_FILENAME (resolved as the entry's curve files are), its
// DRAPE_PROJECTOR { INSERT_POINT, GSD, ORIGIN, FLIPX, FLIPY, EXTENDX, EXTENDY } or
// UV_PROJECTOR { ORIGIN, FLIPX, FLIPY, EXTENDX, EXTENDY }, and for an integer image the
// GAIN and BIAS that turn its counts into °C (DIRSIG's demo names a gain and a bias without
// their keys: glint's reading, said once per file). A floating-point image holds °C.
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "glint/core/text.h"
#include "map_parts.h"
#include "mat_blocks.h"

namespace glint::dirsig::detail {
namespace {

constexpr double kCelsiusToKelvin = 273.15;

std::optional<bool> boolean(const std::string& value) {
    const std::string v = to_upper(trim(value));
    if (v == "TRUE" || v == "1" || v == "YES") return true;
    if (v == "FALSE" || v == "0" || v == "NO") return false;
    return std::nullopt;
}

/// Comma- or blank-separated numbers; empty when any is not one.
std::vector<double> parse_doubles(const std::string& text) {
    std::vector<double> out;
    std::string field;
    const auto flush = [&]() -> bool {
        if (field.empty()) return true;
        const auto v = parse_double(field);
        field.clear();
        if (!v || !std::isfinite(*v)) return false;
        out.push_back(*v);
        return true;
    };
    for (const char c : text) {
        if (c == ',' || c == ' ' || c == '\t') {
            if (!flush()) return {};
        } else {
            field.push_back(c);
        }
    }
    if (!flush()) return {};
    return out;
}

}  // namespace

void MatReader::read_temperature_map(const MatBlock& solver, const std::string& path,
                                     model::Material& m) {
    warn_unknown(solver, path, {"IMAGE_FILENAME", "GAIN", "BIAS"},
                 {"DRAPE_PROJECTOR", "UV_PROJECTOR"});
    auto map = std::make_shared<model::PropertyMap>();
    map->kind = model::MapKind::temperature;
    map->name = m.name;
    map->where = at(solver.line, path);
    const std::size_t errors = diagnostics.error_count();
    const MatEntry* image = solver.find("IMAGE_FILENAME");
    if (!image || trim(image->value).empty()) {
        diagnostics.error(map->where, "missing IMAGE_FILENAME (the temperature map's image)");
        return;
    }
    map->image = options.paths.resolve(image->value, base_dir,
                                       at(image->line, path + "/IMAGE_FILENAME"), diagnostics);
    if (map->image.resolved.empty()) return;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(map->image.resolved, ec)) {
        diagnostics.error(at(image->line, path + "/IMAGE_FILENAME"),
                          "temperature map image " + quote(image->value) + " not found (" +
                              map->image.resolved.string() + ")");
        return;
    }
    // The projector.
    const MatBlock* drape = solver.find_block("DRAPE_PROJECTOR");
    const MatBlock* uv = solver.find_block("UV_PROJECTOR");
    if ((drape == nullptr) == (uv == nullptr)) {
        diagnostics.error(map->where,
                          drape ? "TEMP_SOLVER has both DRAPE_PROJECTOR and UV_PROJECTOR"
                                : "TEMP_SOLVER needs a DRAPE_PROJECTOR or a UV_PROJECTOR");
        return;
    }
    const MatBlock& p = drape ? *drape : *uv;
    const std::string pp = path + "/" + p.name;
    model::MapProjector& projector = map->projector;
    projector.uv = uv != nullptr;
    projector.where = at(p.line, pp);
    if (drape) {
        warn_unknown(p, pp,
                     {"INSERT_POINT", "GSD", "ORIGIN", "FLIPX", "FLIPY", "EXTENDX", "EXTENDY"}, {});
    } else {
        warn_unknown(p, pp, {"ORIGIN", "FLIPX", "FLIPY", "EXTENDX", "EXTENDY"}, {});
    }
    for (const MatEntry& e : p.entries) {
        const ErrorContext where = at(e.line, pp + "/" + e.key);
        const std::string value = to_upper(trim(e.value));
        if (e.key == "INSERT_POINT") {
            const std::vector<double> xyz = parse_doubles(e.value);
            if (xyz.size() < 2 || xyz.size() > 3) {
                diagnostics.error(where, "INSERT_POINT \"" + e.value + "\" is not x, y[, z]");
            } else {
                projector.insert_point_m = {xyz[0], xyz[1]};
            }
        } else if (e.key == "GSD") {
            const std::vector<double> gsd = parse_doubles(e.value);
            if ((gsd.size() != 1 && gsd.size() != 2) || !(gsd[0] > 0.0) || !(gsd.back() > 0.0)) {
                diagnostics.error(where, "GSD \"" + e.value + "\" is not one or two numbers > 0");
            } else {
                projector.gsd_m = {gsd.front(), gsd.back()};
            }
        } else if (e.key == "ORIGIN") {
            if (value != "IMAGE" && value != "CARTESIAN") {
                diagnostics.error(where,
                                  "ORIGIN \"" + e.value + "\" is neither IMAGE nor CARTESIAN");
            }
            projector.origin =
                value == "IMAGE" ? model::MapOrigin::image : model::MapOrigin::cartesian;
        } else if (e.key == "FLIPX" || e.key == "FLIPY") {
            const auto flag = boolean(e.value);
            if (!flag)
                diagnostics.error(where, e.key + " \"" + e.value + "\" is neither TRUE nor FALSE");
            (e.key == "FLIPX" ? projector.flip_x : projector.flip_y) = flag.value_or(false);
        } else if (e.key == "EXTENDX" || e.key == "EXTENDY") {
            model::MapExtend mode = model::MapExtend::none;
            if (value == "CLAMP") {
                mode = model::MapExtend::clamp;
            } else if (value == "REPEAT") {
                mode = model::MapExtend::repeat;
            } else if (value == "MIRROR") {
                mode = model::MapExtend::mirror;
            } else if (value != "NONE") {
                diagnostics.error(
                    where, e.key + " \"" + e.value + "\" is not NONE, CLAMP, REPEAT or MIRROR");
            }
            (e.key == "EXTENDX" ? projector.extend_x : projector.extend_y) = mode;
        }
    }
    if (drape && !p.find("GSD")) diagnostics.error(projector.where, "missing GSD");
    // GAIN and BIAS: °C = GAIN × value + BIAS.
    double gain = 1.0;
    double bias = 0.0;
    const MatEntry* gain_entry = solver.find("GAIN");
    const MatEntry* bias_entry = solver.find("BIAS");
    for (const auto& [entry, field] :
         {std::pair{gain_entry, &gain}, std::pair{bias_entry, &bias}}) {
        if (entry == nullptr) continue;
        const auto v = parse_double(entry->value);
        if (!v || !std::isfinite(*v)) {
            diagnostics.error(at(entry->line, path + "/" + entry->key),
                              entry->key + " \"" + entry->value + "\" is not a number");
        } else {
            *field = *v;
        }
    }
    if ((gain_entry || bias_entry) && !said_temperature_gain) {
        said_temperature_gain = true;
        const MatEntry* first = gain_entry ? gain_entry : bias_entry;
        diagnostics.warning(at(first->line, path + "/" + first->key),
                            "GAIN and BIAS read as degrees Celsius = GAIN x value + BIAS "
                            "(glint's reading of the keys DIRSIG's temperature map names; "
                            "docs/maps.md); said once per file");
    }
    if (diagnostics.error_count() != errors) return;
    std::optional<MapBrightness> values = read_brightness(*map, map->image, diagnostics);
    if (!values) return;
    if (values->integer && !gain_entry && !bias_entry) {
        diagnostics.error(at(image->line, path + "/IMAGE_FILENAME"),
                          "temperature map image " + quote(image->value) +
                              " holds integer counts: give GAIN and BIAS (degrees Celsius = "
                              "GAIN x count + BIAS), or a floating-point image of degrees "
                              "Celsius");
        return;
    }
    auto raster = std::make_shared<model::MapRaster>();
    raster->width = values->width;
    raster->height = values->height;
    raster->bands = 1;
    raster->weights.resize(values->values.size());
    for (std::size_t t = 0; t < values->values.size(); ++t) {
        const double kelvin = gain * values->values[t] + bias + kCelsiusToKelvin;
        if (!(kelvin > 0.0) || !(kelvin < 1e6)) {
            diagnostics.error(at(image->line, path + "/IMAGE_FILENAME"),
                              "temperature map image " + quote(image->value) + ": texel (" +
                                  std::to_string(t % raster->width) + ", " +
                                  std::to_string(t / raster->width) + ") is " +
                                  format_shortest(kelvin - kCelsiusToKelvin) +
                                  (kelvin > 0.0 ? " degrees Celsius, above 10^6 K"
                                                : " degrees Celsius, below absolute zero"));
            return;
        }
        raster->weights[t] = static_cast<float>(kelvin);
    }
    map->raster = raster;
    m.temperature_map = map;
}

}  // namespace glint::dirsig::detail
