// SPDX-License-Identifier: Apache-2.0
// The simpleradiativetransfer subset of a DIRSIG `.atm` file (glint/dirsig/atm_reader.h),
// read with glint::io::XmlNode.
#include "glint/dirsig/atm_reader.h"

#include "glint/io/xml.h"

namespace glint::dirsig {
namespace {

/// How to run a simulation whose atmosphere glint cannot read.
constexpr const char* kAtmosphereOverrideHint =
    "to render without it, give glint-render --atmosphere none|parametric|FILE (FILE: a glint "
    "YAML atmosphere, e.g. model tabulated with a MODTRAN table)";

}  // namespace

model::Atmosphere parse_atm(std::string_view text, const std::string& file,
                            Diagnostics& diagnostics) {
    model::Atmosphere atmosphere;
    const io::XmlDocument doc = io::XmlDocument::parse(text, file);
    const io::XmlNode root = doc.root("atmosphericconditions");
    atmosphere.where = root.where();
    bool found = false;
    for (const io::XmlNode& child : root.children()) {
        const std::string& name = child.name();
        if (name == "metadata") continue;
        if (name == "simpleradiativetransfer") {
            if (found) {
                diagnostics.error(child.where(), "more than one radiative-transfer block");
                continue;
            }
            found = true;
            atmosphere.kind = model::AtmosphereKind::simple;
            atmosphere.where = child.where();
            if (auto t = child.optional_double("apparentskytemperature", diagnostics,
                                               io::NumberRule::non_negative())) {
                atmosphere.simple.apparent_sky_temperature_k = *t;
            }
            child.warn_unknown_children({"apparentskytemperature"}, diagnostics);
        } else if (name == "uniformradiativetransfer" || name == "classicradiativetransfer") {
            found = true;
            const char* built_by = name == "classicradiativetransfer"
                                       ? " (a MODTRAN-built atmosphere)"
                                       : " (a uniform atmosphere)";
            diagnostics.error(child.where(), "atmosphere kind <" + name + ">" + built_by +
                                                 " is not supported: glint reads "
                                                 "<simpleradiativetransfer> or a glint YAML "
                                                 "atmosphere; " +
                                                 kAtmosphereOverrideHint);
        } else if (name == "uniformweather") {
            // <uniformweather><classicdata><filename>: a .wth weather history (the nesting of
            // DIRSIG's demos as glint reads it; docs/formats.md).
            const std::optional<io::XmlNode> data = child.child("classicdata");
            const std::optional<io::XmlNode> file_node =
                data ? data->child("filename") : std::nullopt;
            if (!file_node || file_node->text().empty()) {
                diagnostics.warning(child.where(),
                                    "<uniformweather> without <classicdata><filename> ignored "
                                    "(glint reads a .wth weather history named there)");
            } else {
                atmosphere.weather_file = file_node->text();
                atmosphere.weather_where = file_node->where();
                child.warn_unknown_children({"classicdata"}, diagnostics);
                data->warn_unknown_children({"filename"}, diagnostics);
            }
        } else if (name == "weather" || name == "classicweather") {
            diagnostics.warning(child.where(), "<" + name +
                                                   "> ignored (glint reads the weather of "
                                                   "<uniformweather><classicdata><filename>)");
        } else {
            diagnostics.warning(child.where(), "unknown element <" + name + "> ignored");
        }
    }
    if (!found) {
        diagnostics.error(root.where(), std::string("missing a radiative-transfer block "
                                                    "(<simpleradiativetransfer>); ") +
                                            kAtmosphereOverrideHint);
    }
    doc.warn_unread(diagnostics);
    return atmosphere;
}

}  // namespace glint::dirsig
