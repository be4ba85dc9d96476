#include "glint/core/text.h"
// SPDX-License-Identifier: Apache-2.0
#include "glint/core/text.h"
// The glint YAML scene's geometry objects (OBJ file or primitive) and their static or
#include "glint/core/text.h"
// dynamic instances.
#include "glint/core/text.h"
#include "scene_parts.h"
namespace glint::yaml::yaml_scene {
#include "glint/core/text.h"
namespace {
#include "glint/core/text.h"
// ---- objects and instances ------------------------------------------------------------------
#include "glint/core/text.h"
std::optional<model::PrimitiveKind> primitive_kind(const std::string& text) {
#include "glint/core/text.h"
    using K = model::PrimitiveKind;
#include "glint/core/text.h"
    static const std::map<std::string, K> kinds{{"ground_plane", K::ground_plane},
#include "glint/core/text.h"
                                                {"box", K::box},
#include "glint/core/text.h"
                                                {"sphere", K::sphere},
#include "glint/core/text.h"
                                                {"disk", K::disk},
#include "glint/core/text.h"
                                                {"cylinder", K::cylinder}};
#include "glint/core/text.h"
    const auto it = kinds.find(text);
#include "glint/core/text.h"
    return it == kinds.end() ? std::nullopt : std::optional(it->second);
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// Reads the motion of a dynamic instance from an inline FlexMotion text block, mapping
#include "glint/core/text.h"
/// the XML lines of its diagnostics onto lines of the YAML file.
#include "glint/core/text.h"
model::PlatformMotion read_inline_motion(Reader& r, const YAML::Node& node,
#include "glint/core/text.h"
                                         const std::string& path) {
#include "glint/core/text.h"
    model::PlatformMotion motion;
#include "glint/core/text.h"
    motion.file = r.file;
#include "glint/core/text.h"
    Diagnostics local;
#include "glint/core/text.h"
    // A block scalar ("|") starts on the line after its indicator; a plain one on its own.
#include "glint/core/text.h"
    const std::string& text = node.Scalar();
#include "glint/core/text.h"
    const int first_line = node.Mark().line + (node.Tag() == "!" ? 2 : 1);
#include "glint/core/text.h"
    try {
#include "glint/core/text.h"
        const io::XmlDocument document = io::XmlDocument::parse(text, r.file);
#include "glint/core/text.h"
        const io::XmlNode root = document.root("motion");
#include "glint/core/text.h"
        const MotionReadContext context{r.options, r.base_dir, text};
#include "glint/core/text.h"
        motion.flexible = read_flex_motion(root, context, local);
#include "glint/core/text.h"
    } catch (const Error& error) {
#include "glint/core/text.h"
        local.add(error);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    for (const Diagnostic& d : local.items()) {
#include "glint/core/text.h"
        ErrorContext where = d.where;
#include "glint/core/text.h"
        if (where.file == r.file) {
#include "glint/core/text.h"
            where.line = where.line > 0 ? where.line + first_line - 1 : first_line - 1;
#include "glint/core/text.h"
            where.element = path + (where.element.empty() ? "" : " " + where.element);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        if (d.severity == Diagnostic::Severity::error) {
#include "glint/core/text.h"
            r.diagnostics.error(where, d.message);
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            r.diagnostics.warning(where, d.message);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return motion;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
model::Instance read_instance(Reader& r, const YAML::Node& node, const std::string& path,
#include "glint/core/text.h"
                              std::size_t object_index, const std::string& object_name) {
#include "glint/core/text.h"
    model::Instance in;
#include "glint/core/text.h"
    in.object_index = object_index;
#include "glint/core/text.h"
    in.where = r.where(node, path);
#include "glint/core/text.h"
    in.name = object_name;
#include "glint/core/text.h"
    if (node.IsNull()) return in;
#include "glint/core/text.h"
    if (!r.expect_map(node, path)) return in;
#include "glint/core/text.h"
    r.warn_unknown(node, path,
#include "glint/core/text.h"
                   {"name", "tags", "translation", "rotation_deg", "rotation_order", "scale",
#include "glint/core/text.h"
                    "matrix", "motion", "flex_motion"});
#include "glint/core/text.h"
    in.name = r.text_key(node, path, "name", false).value_or(object_name);
#include "glint/core/text.h"
    if (const YAML::Node tags = node["tags"]) {
#include "glint/core/text.h"
        if (!tags.IsSequence()) {
#include "glint/core/text.h"
            r.error(tags, Reader::join(path, "tags"), "expected a list of text");
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            for (std::size_t i = 0; i < tags.size(); ++i) {
#include "glint/core/text.h"
                if (tags[i].IsScalar() && !tags[i].Scalar().empty()) {
#include "glint/core/text.h"
                    in.tags.push_back(tags[i].Scalar());
#include "glint/core/text.h"
                } else {
#include "glint/core/text.h"
                    r.error(tags[i], Reader::join(path, "tags") + "[" + std::to_string(i) + "]",
#include "glint/core/text.h"
                            "expected non-empty text");
#include "glint/core/text.h"
                }
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const auto starts_important = [](const std::string& s) {
#include "glint/core/text.h"
        return s.rfind(model::kImportantLabel, 0) == 0;
#include "glint/core/text.h"
    };
#include "glint/core/text.h"
    in.important = starts_important(in.name);
#include "glint/core/text.h"
    for (const std::string& tag : in.tags) in.important = in.important || starts_important(tag);
#include "glint/core/text.h"
    const bool has_static =
#include "glint/core/text.h"
        node["translation"] || node["rotation_deg"] || node["rotation_order"] || node["scale"];
#include "glint/core/text.h"
    const bool dynamic = node["motion"] || node["flex_motion"];
#include "glint/core/text.h"
    if (node["motion"] && node["flex_motion"]) {
#include "glint/core/text.h"
        r.error(node, path, "give either motion or flex_motion, not both");
#include "glint/core/text.h"
        return in;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (dynamic && (has_static || node["matrix"])) {
#include "glint/core/text.h"
        r.error(node, path,
#include "glint/core/text.h"
                "a dynamic instance (motion, flex_motion) takes no static "
#include "glint/core/text.h"
                "transform keys");
#include "glint/core/text.h"
        return in;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (node["matrix"] && has_static) {
#include "glint/core/text.h"
        r.error(node, path,
#include "glint/core/text.h"
                "give either matrix or translation, rotation_deg, rotation_order and scale");
#include "glint/core/text.h"
        return in;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    auto& t = in.transform;
#include "glint/core/text.h"
    if (auto v = r.triple_key(node, path, "translation")) t.translation_m = *v;
#include "glint/core/text.h"
    if (auto v = r.triple_key(node, path, "rotation_deg")) {
#include "glint/core/text.h"
        for (int k = 0; k < 3; ++k) t.rotation_rad[k] = (*v)[k] * kDegToRad;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const auto order = r.text_key(node, path, "rotation_order", false)) {
#include "glint/core/text.h"
        std::string sorted = to_lower(*order);
#include "glint/core/text.h"
        std::sort(sorted.begin(), sorted.end());
#include "glint/core/text.h"
        if (sorted != "xyz") {
#include "glint/core/text.h"
            r.error(node["rotation_order"], Reader::join(path, "rotation_order"),
#include "glint/core/text.h"
                    "rotation order \"" + *order + "\" is not a permutation of xyz");
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            t.rotation_order = to_lower(*order);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const YAML::Node scale = node["scale"]) {
#include "glint/core/text.h"
        const std::string sp = Reader::join(path, "scale");
#include "glint/core/text.h"
        if (scale.IsScalar()) {
#include "glint/core/text.h"
            if (const auto s = r.number(scale, sp)) t.scale = {*s, *s, *s};
#include "glint/core/text.h"
        } else if (const auto s = r.triple_key(node, path, "scale")) {
#include "glint/core/text.h"
            t.scale = *s;
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        for (const double s : t.scale) {
#include "glint/core/text.h"
            if (s == 0.0) {
#include "glint/core/text.h"
                r.error(scale, sp, "scale must be non-zero");
#include "glint/core/text.h"
                break;
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const YAML::Node matrix = node["matrix"]) {
#include "glint/core/text.h"
        const std::string mp = Reader::join(path, "matrix");
#include "glint/core/text.h"
        const std::size_t errors = r.diagnostics.error_count();
#include "glint/core/text.h"
        const std::vector<double> values = r.numbers(matrix, mp);
#include "glint/core/text.h"
        if (r.diagnostics.error_count() == errors) {
#include "glint/core/text.h"
            if (values.size() != 16) {
#include "glint/core/text.h"
                r.error(matrix, mp,
#include "glint/core/text.h"
                        "matrix has " + std::to_string(values.size()) + " values, expected 16");
#include "glint/core/text.h"
            } else if (values[12] != 0.0 || values[13] != 0.0 || values[14] != 0.0 ||
#include "glint/core/text.h"
                       values[15] != 1.0) {
#include "glint/core/text.h"
                r.error(matrix, mp, "matrix last row must be 0 0 0 1");
#include "glint/core/text.h"
            } else {
#include "glint/core/text.h"
                std::array<double, 16> m{};
#include "glint/core/text.h"
                std::copy(values.begin(), values.end(), m.begin());
#include "glint/core/text.h"
                t.matrix = m;
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (const YAML::Node motion = node["motion"]) {
#include "glint/core/text.h"
        if (const auto text = r.text_key(node, path, "motion", true)) {
#include "glint/core/text.h"
            in.motion_file = r.options.paths.resolve(
#include "glint/core/text.h"
                *text, r.base_dir, r.where(motion, Reader::join(path, "motion")), r.diagnostics);
#include "glint/core/text.h"
            if (!in.motion_file.resolved.empty()) {
#include "glint/core/text.h"
                in.motion = read_motion(in.motion_file.resolved, r.options, r.diagnostics);
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    } else if (const YAML::Node flex = node["flex_motion"]) {
#include "glint/core/text.h"
        if (r.text_key(node, path, "flex_motion", true)) {
#include "glint/core/text.h"
            in.motion = read_inline_motion(r, flex, Reader::join(path, "flex_motion"));
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    return in;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// Reads the primitive parameters of `node` into `p` (kind already set).
#include "glint/core/text.h"
void read_primitive(Reader& r, const YAML::Node& node, const std::string& path,
#include "glint/core/text.h"
                    model::Primitive& p) {
#include "glint/core/text.h"
    using K = model::PrimitiveKind;
#include "glint/core/text.h"
    const bool round = p.kind == K::sphere || p.kind == K::disk || p.kind == K::cylinder;
#include "glint/core/text.h"
    if (p.kind != K::box) {
#include "glint/core/text.h"
        if (auto v = r.triple_key(node, path, "center")) p.center_m = *v;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (p.kind == K::ground_plane) {
#include "glint/core/text.h"
        if (auto v = r.number_key(node, path, "size", false)) p.size_m = *v;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (p.kind == K::box) {
#include "glint/core/text.h"
        if (!node["lower"]) r.error(node, path, "missing required key \"lower\"");
#include "glint/core/text.h"
        if (!node["upper"]) r.error(node, path, "missing required key \"upper\"");
#include "glint/core/text.h"
        if (auto v = r.triple_key(node, path, "lower")) p.lower_m = *v;
#include "glint/core/text.h"
        if (auto v = r.triple_key(node, path, "upper")) p.upper_m = *v;
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (round) {
#include "glint/core/text.h"
        if (auto v = r.number_key(node, path, "radius", true)) p.radius_m = *v;
#include "glint/core/text.h"
        if (auto v = r.integer_key(node, path, "segments")) p.segments = static_cast<int>(*v);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (p.kind == K::sphere) {
#include "glint/core/text.h"
        if (auto v = r.integer_key(node, path, "rings")) p.rings = static_cast<int>(*v);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (p.kind == K::cylinder) {
#include "glint/core/text.h"
        if (auto v = r.number_key(node, path, "height", true)) p.height_m = *v;
#include "glint/core/text.h"
        if (const YAML::Node caps = node["caps"]) {
#include "glint/core/text.h"
            const auto value = caps.IsScalar() ? parse_bool(caps.Scalar()) : std::nullopt;
#include "glint/core/text.h"
            if (value) {
#include "glint/core/text.h"
                p.caps = *value;
#include "glint/core/text.h"
            } else {
#include "glint/core/text.h"
                r.error(caps, Reader::join(path, "caps"), "expected true or false");
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
}
#include "glint/core/text.h"
/// Keys an object of each kind takes.
#include "glint/core/text.h"
std::vector<std::string_view> object_keys(std::optional<model::PrimitiveKind> kind) {
#include "glint/core/text.h"
    using K = model::PrimitiveKind;
#include "glint/core/text.h"
    std::vector<std::string_view> keys{"name", "obj", "primitive", "material", "instances"};
#include "glint/core/text.h"
    if (!kind) return keys;
#include "glint/core/text.h"
    if (*kind != K::box) keys.push_back("center");
#include "glint/core/text.h"
    if (*kind == K::ground_plane) keys.push_back("size");
#include "glint/core/text.h"
    if (*kind == K::box) keys.insert(keys.end(), {"lower", "upper"});
#include "glint/core/text.h"
    if (*kind == K::sphere || *kind == K::disk || *kind == K::cylinder) {
#include "glint/core/text.h"
        keys.insert(keys.end(), {"radius", "segments"});
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (*kind == K::sphere) keys.push_back("rings");
#include "glint/core/text.h"
    if (*kind == K::cylinder) keys.insert(keys.end(), {"height", "caps"});
#include "glint/core/text.h"
    return keys;
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace
#include "glint/core/text.h"
void read_object(Reader& r, const YAML::Node& node, const std::string& path, model::Scene& scene) {
#include "glint/core/text.h"
    model::GeometryObject object;
#include "glint/core/text.h"
    object.where = r.where(node, path);
#include "glint/core/text.h"
    object.name = "object" + std::to_string(scene.objects.size());
#include "glint/core/text.h"
    if (!r.expect_map(node, path)) return;
#include "glint/core/text.h"
    object.name = r.text_key(node, path, "name", false).value_or(object.name);
#include "glint/core/text.h"
    const std::size_t errors = r.diagnostics.error_count();
#include "glint/core/text.h"
    std::optional<model::PrimitiveKind> kind;
#include "glint/core/text.h"
    if (node["primitive"] && node["obj"]) {
#include "glint/core/text.h"
        r.error(node, path, "give either obj or primitive, not both");
#include "glint/core/text.h"
    } else if (!node["primitive"] && !node["obj"]) {
#include "glint/core/text.h"
        r.error(node, path, "missing required key \"obj\" or \"primitive\"");
#include "glint/core/text.h"
    } else if (node["primitive"]) {
#include "glint/core/text.h"
        if (const auto text = r.text_key(node, path, "primitive", true)) {
#include "glint/core/text.h"
            kind = primitive_kind(*text);
#include "glint/core/text.h"
            if (!kind) {
#include "glint/core/text.h"
                r.error(node["primitive"], Reader::join(path, "primitive"),
#include "glint/core/text.h"
                        "unknown primitive \"" + *text +
#include "glint/core/text.h"
                            "\", expected ground_plane, box, sphere, disk or cylinder");
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    {
#include "glint/core/text.h"
        const std::vector<std::string_view> keys = object_keys(kind);
#include "glint/core/text.h"
        for (const auto& entry : node) {
#include "glint/core/text.h"
            const std::string key = entry.first.Scalar();
#include "glint/core/text.h"
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
#include "glint/core/text.h"
                r.diagnostics.warning(r.where(entry.first, Reader::join(path, key)),
#include "glint/core/text.h"
                                      "unknown key \"" + key + "\" (ignored)");
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    std::optional<std::uint32_t> material;
#include "glint/core/text.h"
    if (const auto id = r.text_key(node, path, "material", kind.has_value())) {
#include "glint/core/text.h"
        object.material_id = *id;
#include "glint/core/text.h"
        for (std::size_t i = 0; i < scene.materials.size(); ++i) {
#include "glint/core/text.h"
            if (scene.materials[i].id == *id) material = static_cast<std::uint32_t>(i);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
        if (!material) {
#include "glint/core/text.h"
            r.error(node["material"], Reader::join(path, "material"),
#include "glint/core/text.h"
                    "unknown material id \"" + *id + "\"");
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    if (kind) {
#include "glint/core/text.h"
        object.primitive = model::Primitive{};
#include "glint/core/text.h"
        object.primitive->kind = *kind;
#include "glint/core/text.h"
        read_primitive(r, node, path, *object.primitive);
#include "glint/core/text.h"
        if (material && r.diagnostics.error_count() == errors) {
#include "glint/core/text.h"
            object.mesh =
#include "glint/core/text.h"
                mesh::tessellate_primitive(*object.primitive, *material, object.where,
                                           r.diagnostics);
#include "glint/core/text.h"
            mesh::validate_mesh(object.mesh, scene.materials.size(), object.where, r.diagnostics);
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    } else if (node["obj"] && r.diagnostics.error_count() == errors) {
#include "glint/core/text.h"
        if (const auto text = r.text_key(node, path, "obj", true)) {
#include "glint/core/text.h"
            object.obj_file = r.options.paths.resolve(
#include "glint/core/text.h"
                *text, r.base_dir, r.where(node["obj"], Reader::join(path, "obj")), r.diagnostics);
#include "glint/core/text.h"
            if (!object.obj_file.resolved.empty()) {
#include "glint/core/text.h"
                const auto by_name = [&scene](const std::string& name) {
#include "glint/core/text.h"
                    std::optional<std::uint32_t> found;
#include "glint/core/text.h"
                    for (std::size_t i = 0; i < scene.materials.size() && !found; ++i) {
#include "glint/core/text.h"
                        if (scene.materials[i].name == name) {
#include "glint/core/text.h"
                            found = static_cast<std::uint32_t>(i);
#include "glint/core/text.h"
                        }
#include "glint/core/text.h"
                    }
#include "glint/core/text.h"
                    return found;
#include "glint/core/text.h"
                };
#include "glint/core/text.h"
                object.mesh =
#include "glint/core/text.h"
                    dirsig::load_obj_mesh(object.obj_file.resolved,
                                          object.obj_file.resolved.string(),
#include "glint/core/text.h"
                                          r.options, by_name, material, scene.materials.size(),
#include "glint/core/text.h"
                                          r.diagnostics);
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    const std::size_t object_index = scene.objects.size();
#include "glint/core/text.h"
    if (const YAML::Node instances = node["instances"]) {
#include "glint/core/text.h"
        const std::string ip = Reader::join(path, "instances");
#include "glint/core/text.h"
        if (!instances.IsSequence()) {
#include "glint/core/text.h"
            r.error(instances, ip, "expected a list of instances");
#include "glint/core/text.h"
        } else if (instances.size() == 0) {
#include "glint/core/text.h"
            r.diagnostics.warning(r.where(instances, ip),
#include "glint/core/text.h"
                                  "object \"" + object.name + "\" has no instances");
#include "glint/core/text.h"
        } else {
#include "glint/core/text.h"
            for (std::size_t i = 0; i < instances.size(); ++i) {
#include "glint/core/text.h"
                scene.instances.push_back(read_instance(r, instances[i],
#include "glint/core/text.h"
                                                        ip + "[" + std::to_string(i) + "]",
#include "glint/core/text.h"
                                                        object_index, object.name));
#include "glint/core/text.h"
            }
#include "glint/core/text.h"
        }
#include "glint/core/text.h"
    } else {
#include "glint/core/text.h"
        model::Instance in;
#include "glint/core/text.h"
        in.object_index = object_index;
#include "glint/core/text.h"
        in.name = object.name;
#include "glint/core/text.h"
        in.important = object.name.rfind(model::kImportantLabel, 0) == 0;
#include "glint/core/text.h"
        in.where = object.where;
#include "glint/core/text.h"
        scene.instances.push_back(in);
#include "glint/core/text.h"
    }
#include "glint/core/text.h"
    scene.objects.push_back(std::move(object));
#include "glint/core/text.h"
}
#include "glint/core/text.h"
}  // namespace glint::yaml::yaml_scene
