// SPDX-License-Identifier: Apache-2.0
// Point sources of a glist (`<object><basesource><pointsource matid="…">`): one
// model::PointSource per instance of the object, at the object's origin placed by that
// instance — a static instance's placement is applied to the position at once, a dynamic
// one's motion carries the source. The material must be a point-source material (a `.mat`
// entry with OPTICAL_DESCRIPTION = SOURCE). docs/scene.md ("Point sources") is the reference.
#include <cmath>

#include "glist_parts.h"

namespace glint::dirsig::detail {
namespace {

/// `m` · [p, 1].
std::array<double, 3> transform_point(const Matrix4& m, const std::array<double, 3>& p) {
    std::array<double, 3> out{};
    for (int i = 0; i < 3; ++i) {
        out[i] = m[i * 4] * p[0] + m[i * 4 + 1] * p[1] + m[i * 4 + 2] * p[2] + m[i * 4 + 3];
    }
    return out;
}

/// Reads `<pointing><vector><x/><y/><z/></vector></pointing>`: a direction that only a shaped
/// source would use; glint's sources are isotropic, so it is checked (three numbers, not all
/// zero) and, being not applied, gives one warning.
void check_pointing(const io::XmlNode& source, Diagnostics& diagnostics) {
    const auto pointing = source.child("pointing");
    if (!pointing) return;
    pointing->warn_unknown_children({"vector"}, diagnostics);
    const io::XmlNode vector = pointing->child("vector").value_or(*pointing);
    vector.warn_unknown_children({"x", "y", "z"}, diagnostics);
    const std::size_t errors = diagnostics.error_count();
    double length2 = 0.0;
    for (const char* axis : {"x", "y", "z"}) {
        const double v = vector.required_double(axis, diagnostics).value_or(0.0);
        length2 += v * v;
    }
    if (diagnostics.error_count() == errors && !(length2 > 0.0 && std::isfinite(length2))) {
        diagnostics.error(pointing->where(), "pointing vector must be finite and not zero");
        return;
    }
    diagnostics.warning(pointing->where(),
                        "<pointing> is read, not applied: glint's point "
                        "sources emit the same intensity in every direction");
}

}  // namespace

void read_base_source(const io::XmlNode& base, const std::string& object_name,
                      const std::vector<model::Instance>& instances,
                      const std::vector<MaterialScope>& within, model::Scene& scene,
                      const SceneLoad& load, Diagnostics& diagnostics) {
    base.warn_unknown_children({"pointsource"}, diagnostics);
    const auto kids = base.children();
    if (kids.size() != 1 || kids.front().name() != "pointsource") {
        diagnostics.error(base.where(), "expected exactly one <pointsource>, got " +
                                            std::to_string(kids.size()) + " elements");
        return;
    }
    const io::XmlNode& source = kids.front();
    source.warn_unknown_children({"pointing", "matid"}, diagnostics);
    check_pointing(source, diagnostics);
    // DIRSIG writes the material as an attribute; the element form of basegeometry is
    // accepted too.
    std::optional<std::string> id = source.attribute("matid");
    ErrorContext id_where = source.where_attribute("matid");
    if (!id) {
        id = source.optional_text("matid");
        if (id) id_where = source.child("matid")->where();
    }
    if (!id || id->empty()) {
        diagnostics.error(source.where(), "missing matid (a point-source material's id)");
        return;
    }
    const auto material = material_by_id(*id, scene, load, within);
    if (!material) {
        diagnostics.error(id_where, "unknown material id \"" + *id + "\"");
        return;
    }
    if (!scene.materials[*material].point_source) {
        diagnostics.error(id_where, "material \"" + *id +
                                        "\" is not a point-source material (a .mat entry with "
                                        "OPTICAL_DESCRIPTION = SOURCE and INTENSITY_FILENAME)");
        return;
    }
    for (const model::Instance& in : instances) {
        model::PointSource s;
        s.name = in.name.empty() ? object_name : in.name;
        s.material = *material;
        s.where = in.where;
        if (in.dynamic()) {
            s.motion = in.motion;
            s.motion_file = in.motion_file;
        } else {
            s.position_m = transform_point(to_matrix(in.transform), {0.0, 0.0, 0.0});
        }
        scene.point_sources.push_back(std::move(s));
    }
}

void place_nested_sources(const std::vector<model::PointSource>& inner,
                          const std::vector<model::Instance>& outer, model::Scene& scene,
                          Diagnostics& diagnostics) {
    for (const model::Instance& o : outer) {
        const Matrix4 outer_matrix = to_matrix(o.transform);
        for (const model::PointSource& s : inner) {
            model::PointSource placed = s;
            if (s.dynamic() && (o.dynamic() || !is_identity(outer_matrix))) {
                diagnostics.error(s.where,
                                  "a moving point source in a nested glist cannot be "
                                  "placed again by " +
                                      o.where.element);
                continue;
            }
            if (o.dynamic()) {
                // The glist's frame is the vehicle's: the source rides at its glist position.
                placed.motion = o.motion;
                placed.motion_file = o.motion_file;
            } else if (!s.dynamic()) {
                placed.position_m = transform_point(outer_matrix, s.position_m);
            }
            scene.point_sources.push_back(std::move(placed));
        }
    }
}

}  // namespace glint::dirsig::detail
