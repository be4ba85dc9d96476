// SPDX-License-Identifier: Apache-2.0
// The glint YAML scene's geometry objects (OBJ file or primitive) and their static or
// dynamic instances.
#include "glint/core/text.h"
#include "scene_parts.h"

namespace glint::yaml::yaml_scene {
namespace {

// ---- objects and instances ------------------------------------------------------------------

std::optional<model::PrimitiveKind> primitive_kind(const std::string& text) {
    using K = model::PrimitiveKind;
    static const std::map<std::string, K> kinds{{"ground_plane", K::ground_plane},
                                                {"box", K::box},
                                                {"sphere", K::sphere},
                                                {"disk", K::disk},
                                                {"cylinder", K::cylinder}};
    const auto it = kinds.find(text);
    return it == kinds.end() ? std::nullopt : std::optional(it->second);
}

/// Reads the motion of a dynamic instance from an inline FlexMotion text block, mapping
/// the XML lines of its diagnostics onto lines of the YAML file.
model::PlatformMotion read_inline_motion(Reader& r, const YAML::Node& node,
                                         const std::string& path) {
    model::PlatformMotion motion;
    motion.file = r.file;
    Diagnostics local;
    // A block scalar ("|") starts on the line after its indicator; a plain one on its own.
    const std::string& text = node.Scalar();
    const int first_line = node.Mark().line + (node.Tag() == "!" ? 2 : 1);
    try {
        const io::XmlDocument document = io::XmlDocument::parse(text, r.file);
        const io::XmlNode root = document.root("motion");
        const MotionReadContext context{r.options, r.base_dir, text};
        // As in a .motion file, the type is optional here but must be flexible when given.
        if (const auto type = root.attribute("type"); type && to_lower(trim(*type)) != "flexible") {
            local.error(root.where_attribute("type"),
                        "motion type \"" + *type + "\" is not supported, expected flexible");
        }
        motion.flexible = read_flex_motion(root, context, local);
        document.warn_unread(local);
    } catch (const Error& error) {
        local.add(error);
    }
    for (const Diagnostic& d : local.items()) {
        ErrorContext where = d.where;
        if (where.file == r.file) {
            where.line = where.line > 0 ? where.line + first_line - 1 : first_line - 1;
            where.element = path + (where.element.empty() ? "" : " " + where.element);
        }
        r.diagnostics.copy(d, std::move(where));
    }
    return motion;
}

model::Instance read_instance(Reader& r, const YAML::Node& node, const std::string& path,
                              std::size_t object_index, const std::string& object_name) {
    model::Instance in;
    in.object_index = object_index;
    in.where = r.where(node, path);
    in.name = object_name;
    if (node.IsNull()) return in;
    if (!r.expect_map(node, path)) return in;
    r.warn_unknown(node, path,
                   {"name", "tags", "translation", "rotation_deg", "rotation_order", "scale",
                    "matrix", "motion", "flex_motion"});
    in.name = r.text_key(node, path, "name", false).value_or(object_name);
    if (const YAML::Node tags = node["tags"]) {
        if (!tags.IsSequence()) {
            r.error(tags, Reader::join(path, "tags"), "expected a list of text");
        } else {
            for (std::size_t i = 0; i < tags.size(); ++i) {
                if (tags[i].IsScalar() && !tags[i].Scalar().empty()) {
                    in.tags.push_back(tags[i].Scalar());
                } else {
                    r.error(tags[i], Reader::join(path, "tags") + "[" + std::to_string(i) + "]",
                            "expected non-empty text");
                }
            }
        }
    }
    const auto starts_important = [](const std::string& s) {
        return s.rfind(model::kImportantLabel, 0) == 0;
    };
    in.important = starts_important(in.name);
    for (const std::string& tag : in.tags) in.important = in.important || starts_important(tag);

    const bool has_static =
        node["translation"] || node["rotation_deg"] || node["rotation_order"] || node["scale"];
    const bool dynamic = node["motion"] || node["flex_motion"];
    if (node["motion"] && node["flex_motion"]) {
        r.error(node, path, "give either motion or flex_motion, not both");
        return in;
    }
    if (dynamic && (has_static || node["matrix"])) {
        r.error(node, path,
                "a dynamic instance (motion, flex_motion) takes no static "
                "transform keys");
        return in;
    }
    if (node["matrix"] && has_static) {
        r.error(node, path,
                "give either matrix or translation, rotation_deg, rotation_order and scale");
        return in;
    }
    auto& t = in.transform;
    if (auto v = r.triple_key(node, path, "translation")) t.translation_m = *v;
    if (auto v = r.triple_key(node, path, "rotation_deg")) {
        for (int k = 0; k < 3; ++k) t.rotation_rad[k] = (*v)[k] * kDegToRad;
    }
    if (const auto order = r.text_key(node, path, "rotation_order", false)) {
        std::string sorted = to_lower(*order);
        std::sort(sorted.begin(), sorted.end());
        if (sorted != "xyz") {
            r.error(node["rotation_order"], Reader::join(path, "rotation_order"),
                    "rotation order \"" + *order + "\" is not a permutation of xyz");
        } else {
            t.rotation_order = to_lower(*order);
        }
    }
    if (const YAML::Node scale = node["scale"]) {
        const std::string sp = Reader::join(path, "scale");
        if (scale.IsScalar()) {
            if (const auto s = r.number(scale, sp)) t.scale = {*s, *s, *s};
        } else if (const auto s = r.triple_key(node, path, "scale")) {
            t.scale = *s;
        }
        for (const double s : t.scale) {
            if (s == 0.0) {
                r.error(scale, sp, "scale must be non-zero");
                break;
            }
        }
    }
    if (const YAML::Node matrix = node["matrix"]) {
        const std::string mp = Reader::join(path, "matrix");
        const std::size_t errors = r.diagnostics.error_count();
        const std::vector<double> values = r.numbers(matrix, mp);
        if (r.diagnostics.error_count() == errors) {
            if (values.size() != 16) {
                r.error(matrix, mp,
                        "matrix has " + std::to_string(values.size()) + " values, expected 16");
            } else if (values[12] != 0.0 || values[13] != 0.0 || values[14] != 0.0 ||
                       values[15] != 1.0) {
                r.error(matrix, mp, "matrix last row must be 0 0 0 1");
            } else {
                std::array<double, 16> m{};
                std::copy(values.begin(), values.end(), m.begin());
                t.matrix = m;
            }
        }
    }
    if (const YAML::Node motion = node["motion"]) {
        if (const auto text = r.text_key(node, path, "motion", true)) {
            in.motion_file = r.options.paths.resolve(
                *text, r.base_dir, r.where(motion, Reader::join(path, "motion")), r.diagnostics);
            if (!in.motion_file.resolved.empty()) {
                in.motion = std::make_shared<const model::PlatformMotion>(
                    read_motion(in.motion_file.resolved, r.options, r.diagnostics));
            }
        }
    } else if (const YAML::Node flex = node["flex_motion"]) {
        if (r.text_key(node, path, "flex_motion", true)) {
            in.motion = std::make_shared<const model::PlatformMotion>(
                read_inline_motion(r, flex, Reader::join(path, "flex_motion")));
        }
    }
    return in;
}

/// Reads the primitive parameters of `node` into `p` (kind already set).
void read_primitive(Reader& r, const YAML::Node& node, const std::string& path,
                    model::Primitive& p) {
    using K = model::PrimitiveKind;
    const bool round = p.kind == K::sphere || p.kind == K::disk || p.kind == K::cylinder;
    if (p.kind != K::box) {
        if (auto v = r.triple_key(node, path, "center")) p.center_m = *v;
    }
    if (p.kind == K::ground_plane) {
        if (auto v = r.number_key(node, path, "size", false)) p.size_m = *v;
    }
    if (p.kind == K::box) {
        if (!node["lower"]) r.error(node, path, "missing required key \"lower\"");
        if (!node["upper"]) r.error(node, path, "missing required key \"upper\"");
        if (auto v = r.triple_key(node, path, "lower")) p.lower_m = *v;
        if (auto v = r.triple_key(node, path, "upper")) p.upper_m = *v;
    }
    if (round) {
        if (auto v = r.number_key(node, path, "radius", true)) p.radius_m = *v;
        if (auto v = r.integer_key(node, path, "segments")) p.segments = static_cast<int>(*v);
    }
    if (p.kind == K::sphere) {
        if (auto v = r.integer_key(node, path, "rings")) p.rings = static_cast<int>(*v);
    }
    if (p.kind == K::cylinder) {
        if (auto v = r.number_key(node, path, "height", true)) p.height_m = *v;
        if (const YAML::Node caps = node["caps"]) {
            const auto value = caps.IsScalar() ? parse_bool(caps.Scalar()) : std::nullopt;
            if (value) {
                p.caps = *value;
            } else {
                r.error(caps, Reader::join(path, "caps"), "expected true or false");
            }
        }
    }
}

/// Keys an object of each kind takes.
std::vector<std::string_view> object_keys(std::optional<model::PrimitiveKind> kind) {
    using K = model::PrimitiveKind;
    std::vector<std::string_view> keys{"name", "obj", "primitive", "material", "instances"};
    if (!kind) return keys;
    if (*kind != K::box) keys.push_back("center");
    if (*kind == K::ground_plane) keys.push_back("size");
    if (*kind == K::box) keys.insert(keys.end(), {"lower", "upper"});
    if (*kind == K::sphere || *kind == K::disk || *kind == K::cylinder) {
        keys.insert(keys.end(), {"radius", "segments"});
    }
    if (*kind == K::sphere) keys.push_back("rings");
    if (*kind == K::cylinder) keys.insert(keys.end(), {"height", "caps"});
    return keys;
}

}  // namespace

void read_object(Reader& r, const YAML::Node& node, const std::string& path, model::Scene& scene) {
    model::GeometryObject object;
    object.where = r.where(node, path);
    object.name = "object" + std::to_string(scene.objects.size());
    if (!r.expect_map(node, path)) return;
    object.name = r.text_key(node, path, "name", false).value_or(object.name);
    const std::size_t errors = r.diagnostics.error_count();

    std::optional<model::PrimitiveKind> kind;
    if (node["primitive"] && node["obj"]) {
        r.error(node, path, "give either obj or primitive, not both");
    } else if (!node["primitive"] && !node["obj"]) {
        r.error(node, path, "missing required key \"obj\" or \"primitive\"");
    } else if (node["primitive"]) {
        if (const auto text = r.text_key(node, path, "primitive", true)) {
            kind = primitive_kind(*text);
            if (!kind) {
                r.error(node["primitive"], Reader::join(path, "primitive"),
                        "unknown primitive \"" + *text +
                            "\", expected ground_plane, box, sphere, disk or cylinder");
            }
        }
    }
    {
        const std::vector<std::string_view> keys = object_keys(kind);
        for (const auto& entry : node) {
            const std::string key = entry.first.Scalar();
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
                r.diagnostics.warning(r.where(entry.first, Reader::join(path, key)),
                                      "unknown key \"" + key + "\" (ignored)");
            }
        }
    }

    std::optional<std::uint32_t> material;
    if (const auto id = r.text_key(node, path, "material", kind.has_value())) {
        object.material_id = *id;
        for (std::size_t i = 0; i < scene.materials.size(); ++i) {
            if (scene.materials[i].id == *id) material = static_cast<std::uint32_t>(i);
        }
        if (!material) {
            r.error(node["material"], Reader::join(path, "material"),
                    "unknown material id \"" + *id + "\"");
        }
    }

    if (kind) {
        object.primitive = model::Primitive{};
        object.primitive->kind = *kind;
        read_primitive(r, node, path, *object.primitive);
        if (material && r.diagnostics.error_count() == errors) {
            object.mesh = mesh::tessellate_primitive(*object.primitive, *material, object.where,
                                                     r.diagnostics);
            mesh::validate_mesh(object.mesh, scene.materials.size(), object.where, r.diagnostics);
        }
    } else if (node["obj"] && r.diagnostics.error_count() == errors) {
        if (const auto text = r.text_key(node, path, "obj", true)) {
            object.obj_file = r.options.paths.resolve(
                *text, r.base_dir, r.where(node["obj"], Reader::join(path, "obj")), r.diagnostics);
            if (!object.obj_file.resolved.empty()) {
                const auto by_name = [&scene](const std::string& name) {
                    std::optional<std::uint32_t> found;
                    for (std::size_t i = 0; i < scene.materials.size() && !found; ++i) {
                        if (scene.materials[i].name == name) {
                            found = static_cast<std::uint32_t>(i);
                        }
                    }
                    return found;
                };
                object.mesh = dirsig::load_obj_mesh(
                    object.obj_file.resolved, object.obj_file.resolved.string(), r.options, by_name,
                    material, scene.materials.size(), r.diagnostics);
            }
        }
    }

    const std::size_t object_index = scene.objects.size();
    if (const YAML::Node instances = node["instances"]) {
        const std::string ip = Reader::join(path, "instances");
        if (!instances.IsSequence()) {
            r.error(instances, ip, "expected a list of instances");
        } else if (instances.size() == 0) {
            r.diagnostics.warning(r.where(instances, ip),
                                  "object \"" + object.name + "\" has no instances");
        } else {
            for (std::size_t i = 0; i < instances.size(); ++i) {
                scene.instances.push_back(read_instance(r, instances[i],
                                                        ip + "[" + std::to_string(i) + "]",
                                                        object_index, object.name));
            }
        }
    } else {
        model::Instance in;
        in.object_index = object_index;
        in.name = object.name;
        in.important = object.name.rfind(model::kImportantLabel, 0) == 0;
        in.where = object.where;
        scene.instances.push_back(in);
    }
    scene.objects.push_back(std::move(object));
}

}  // namespace glint::yaml::yaml_scene
