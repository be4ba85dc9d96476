// SPDX-License-Identifier: Apache-2.0
// Reader of DIRSIG `.glist` geometry lists into model::Scene: `object` elements with one
// `basegeometry` (obj, glist, box, sphere, groundplane, disk, cylinder), static instances
// (translation, rotation, scale or a 16-value matrix), dynamic instances (generic motion
// from a .ppd/.motion file or inline flexible motion), tags, `search_paths`, and the
// `localmaterials`/`assign` material scopes (glist_materials.cpp) and `basesource` point
// sources (glist_sources.cpp). Nested glists are flattened by glist_nested.cpp. GDB/ODB
// geometry is an error.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <set>

#include "glint/core/text.h"
#include "glint/dirsig/motion_reader.h"
#include "glint/dirsig/scene_reader.h"
#include "glint/io/xml.h"
#include "glist_parts.h"

namespace glint::dirsig {
namespace detail {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

bool starts_important(const std::string& s) { return s.rfind(model::kImportantLabel, 0) == 0; }

/// Everything the element readers of one glist file share.
struct GlistReader {
    std::string file;
    std::filesystem::path base_dir;
    std::string source_text;
    const ReadOptions& options;
    Diagnostics& diagnostics;
    model::Scene& scene;
    SceneLoad& load;
    std::vector<MaterialScope> scopes;  ///< material scopes in force, outermost first

    /// x, y, z of `parent/name/inner` (or `parent/name/x..z` without the inner element).
    std::optional<std::array<double, 3>> triple(const io::XmlNode& parent, std::string_view name,
                                                std::string_view inner) {
        const auto outer = parent.child(name);
        if (!outer) return std::nullopt;
        const io::XmlNode node = outer->child(inner).value_or(*outer);
        const std::size_t errors = diagnostics.error_count();
        std::array<double, 3> v{};
        for (int k = 0; k < 3; ++k) {
            const std::string axis(1, static_cast<char>('x' + k));
            v[k] = node.required_double(axis, diagnostics).value_or(0.0);
        }
        if (diagnostics.error_count() != errors) return std::nullopt;
        return v;
    }

    /// The material index of `matid` (required) in `within` (local materials, then the
    /// scene's); an error when unknown.
    std::optional<std::uint32_t> material(const io::XmlNode& node, std::string& id,
                                          const std::vector<MaterialScope>& within) {
        id = node.required_text("matid", diagnostics);
        if (id.empty()) return std::nullopt;
        if (const auto index = material_by_id(id, scene, load, within)) return index;
        diagnostics.error(node.child("matid")->where(), "unknown material id \"" + id + "\"");
        return std::nullopt;
    }

    std::vector<std::string> tags(const io::XmlNode& node) {
        std::vector<std::string> out;
        const auto list = node.child("tags");
        if (!list) return out;
        list->warn_unknown_children({"tag"}, diagnostics);
        const auto items = list->children("tag");
        if (items.empty()) return split_list(list->text());
        for (const io::XmlNode& tag : items) {
            if (tag.text().empty()) {
                diagnostics.error(tag.where(), "empty tag");
            } else {
                out.push_back(tag.text());
            }
        }
        return out;
    }

    void read_transform(const io::XmlNode& node, model::StaticTransform& t) {
        const bool has_parts =
            node.child("translation") || node.child("rotation") || node.child("scale");
        if (auto v = triple(node, "translation", "point")) t.translation_m = *v;
        if (auto v = triple(node, "rotation", "cartesiantriple")) {
            for (int k = 0; k < 3; ++k) t.rotation_rad[k] = (*v)[k] * kDegToRad;
        }
        if (const auto rotation = node.child("rotation")) {
            if (const auto order = rotation->attribute("order")) {
                std::string sorted = *order;
                std::sort(sorted.begin(), sorted.end());
                if (sorted != "xyz") {
                    diagnostics.error(
                        rotation->where_attribute("order"),
                        "rotation order \"" + *order + "\" is not a permutation of xyz");
                } else {
                    t.rotation_order = *order;
                }
            }
        }
        if (auto v = triple(node, "scale", "cartesiantriple")) {
            if ((*v)[0] == 0.0 || (*v)[1] == 0.0 || (*v)[2] == 0.0) {
                diagnostics.error(node.child("scale")->where(), "scale must be non-zero");
            } else {
                t.scale = *v;
            }
        }
        const auto matrix = node.child("matrix");
        if (!matrix) return;
        if (has_parts) {
            diagnostics.error(matrix->where(),
                              "give either matrix or translation, rotation and scale");
            return;
        }
        std::string text = matrix->text();
        for (char& c : text) {
            if (std::isspace(static_cast<unsigned char>(c))) c = ',';
        }
        const std::vector<std::string> items = split_list(text);
        if (items.size() != 16) {
            diagnostics.error(matrix->where(), "matrix has " + std::to_string(items.size()) +
                                                   " values, expected 16");
            return;
        }
        Matrix4 m{};
        for (std::size_t i = 0; i < 16; ++i) {
            const auto v = parse_double(items[i]);
            if (!v) {
                diagnostics.error(matrix->where(), "matrix value " + std::to_string(i + 1) + " \"" +
                                                       items[i] + "\" is not a number");
                return;
            }
            m[i] = *v;
        }
        if (m[12] != 0.0 || m[13] != 0.0 || m[14] != 0.0 || m[15] != 1.0) {
            diagnostics.error(matrix->where(), "matrix last row must be 0 0 0 1");
            return;
        }
        t.matrix = m;
    }

    model::Instance read_instance(const io::XmlNode& node, const std::string& object_name,
                                  const std::vector<std::string>& object_tags) {
        model::Instance in;
        in.where = node.where();
        in.name = node.attribute("name").value_or(object_name);
        in.tags = object_tags;
        for (std::string& tag : tags(node)) in.tags.push_back(std::move(tag));
        in.important = starts_important(in.name);
        for (const std::string& tag : in.tags) in.important = in.important || starts_important(tag);
        if (node.name() == "staticinstance") {
            node.warn_unknown_children({"translation", "rotation", "scale", "matrix", "tags"},
                                       diagnostics);
            read_transform(node, in.transform);
            return in;
        }
        node.warn_unknown_children({"motion", "tags"}, diagnostics);
        const auto motion = node.child("motion");
        if (!motion) {
            diagnostics.error(node.where(), "missing required element <motion>");
            return in;
        }
        const auto type = motion->attribute_enum("type", {"generic", "flexible"}, diagnostics);
        if (!type) {
            if (!motion->attribute("type")) {
                diagnostics.error(motion->where(), "missing attribute type (generic or flexible)");
            }
            return in;
        }
        if (*type == "flexible" && !motion->child("filename")) {
            model::PlatformMotion m;
            m.file = file;
            const MotionReadContext context{options, base_dir, source_text};
            m.flexible = read_flex_motion(*motion, context, diagnostics);
            in.motion = std::make_shared<const model::PlatformMotion>(std::move(m));
            return in;
        }
        motion->warn_unknown_children({"filename"}, diagnostics);
        const std::string text = motion->required_text("filename", diagnostics);
        if (text.empty()) return in;
        in.motion_file = find_file(text, base_dir, true, FileKind::plain, "motion file",
                                   motion->child("filename")->where(), options, load, diagnostics);
        if (!in.motion_file.resolved.empty()) {
            in.motion = std::make_shared<const model::PlatformMotion>(
                read_motion(in.motion_file.resolved, options, diagnostics));
        }
        return in;
    }

    /// An error for each point-source material `object`'s surfaces use: a source has no
    /// surface to render.
    void refuse_source_surfaces(const model::GeometryObject& object) {
        std::set<std::uint32_t> seen;
        for (const std::uint32_t m : object.mesh.triangle_materials) {
            if (m >= scene.materials.size() || !scene.materials[m].point_source) continue;
            if (!seen.insert(m).second) continue;
            diagnostics.error(object.where, "object \"" + object.name +
                                                "\" uses point-source material \"" +
                                                scene.materials[m].id +
                                                "\" on a surface; only a <pointsource> may "
                                                "name it");
        }
    }

    void read_object(const io::XmlNode& node);
    void read_obj(const io::XmlNode& g, const model::FileRef& ref,
                  const std::vector<MaterialScope>& within, model::GeometryObject& object);
};

}  // namespace

void read_glist_file(const std::filesystem::path& path, const ReadOptions& options,
                     model::Scene& scene, Diagnostics& diagnostics, SceneLoad& load,
                     const std::vector<MaterialScope>& scopes) {
    const std::string name = path.string();
    const std::size_t depth = load.chain.size();
    try {
        const std::string text = options.read_text(path, name);
        const io::XmlDocument document = io::XmlDocument::parse(text, name);
        const io::XmlNode root = document.root("geometrylist");
        if (root.attribute_bool("enabled", diagnostics) == false) return;
        root.warn_unknown_children({"object"}, diagnostics);
        load.chain.push_back(std::filesystem::absolute(path).lexically_normal());
        GlistReader reader{name,        std::filesystem::absolute(path).parent_path(),
                           text,        options,
                           diagnostics, scene,
                           load,        scopes};
        for (const io::XmlNode& object : root.children("object")) reader.read_object(object);
        document.warn_unread(diagnostics);
    } catch (const Error& error) {
        diagnostics.add(error);
    }
    load.chain.resize(depth);
}

void GlistReader::read_obj(const io::XmlNode& g, const model::FileRef& ref,
                           const std::vector<MaterialScope>& within,
                           model::GeometryObject& object) {
    std::optional<std::uint32_t> fallback;
    if (g.child("matid")) fallback = material(g, object.material_id, within);
    const auto lookup = [this, &within](const std::string& name) {
        return material_for_usemtl(name, scene, load, within);
    };
    object.obj_file = ref;
    std::string text;
    try {
        text = options.read_text(ref.resolved, ref.resolved.string());
    } catch (const Error& error) {
        // At the element that names the file, which a bare "cannot open" would not say.
        diagnostics.error(ref.where, "obj file " + ref.text + ": " + error.message() + " (" +
                                         ref.resolved.string() + ")");
        return;
    }
    object.mesh = mesh::parse_obj_mesh(text, ref.resolved.string(), lookup, fallback,
                                       scene.materials.size(), diagnostics);
}

void GlistReader::read_object(const io::XmlNode& node) {
    if (node.attribute_bool("enabled", diagnostics) == false) return;
    node.warn_unknown_children({"basegeometry", "basesource", "staticinstance", "dynamicinstance",
                                "tags", "localmaterials", "assign", "name"},
                               diagnostics);
    const bool local = search_paths_local(node, diagnostics);
    model::GeometryObject object;
    object.where = node.where();
    object.name = node.attribute("name").value_or(
        node.optional_text("name").value_or("object" + std::to_string(scene.objects.size())));
    const std::vector<std::string> object_tags = tags(node);
    std::vector<model::Instance> instances;
    for (const io::XmlNode& child : node.children()) {
        if (child.name() == "staticinstance" || child.name() == "dynamicinstance") {
            instances.push_back(read_instance(child, object.name, object_tags));
        }
    }
    if (instances.empty()) {
        diagnostics.warning(node.where(), "object \"" + object.name + "\" has no instances");
    }
    const auto base = node.child("basegeometry");
    std::optional<io::XmlNode> obj;
    if (base) obj = base->child("obj");
    // The object's localmaterials and assign entries hold for its base geometry.
    std::vector<MaterialScope> within = scopes;
    if (auto scope = read_material_scope(node, obj, base_dir, local, options, scene, load, scopes,
                                         diagnostics)) {
        within.push_back(std::move(*scope));
    }
    if (const auto source = node.child("basesource")) {
        if (base) {
            diagnostics.error(source->where(), "give either <basegeometry> or <basesource>");
            return;
        }
        read_base_source(*source, object.name, instances, within, scene, load, diagnostics);
        return;
    }
    if (!base) {
        diagnostics.error(node.where(),
                          "missing required element <basegeometry> (or "
                          "<basesource>)");
        return;
    }
    const auto kids = base->children();
    if (kids.size() != 1) {
        diagnostics.error(base->where(), "expected exactly one geometry element, got " +
                                             std::to_string(kids.size()));
        return;
    }
    const io::XmlNode& g = kids.front();
    const std::string kind = g.name();
    if (kind == "gdb" || kind == "odb") {
        diagnostics.error(g.where(), kind + " geometry (" +
                                         g.optional_text("filename").value_or("") +
                                         ") is not supported; convert it to OBJ");
        return;
    }
    if (kind == "obj" || kind == "glist") {
        g.warn_unknown_children({"filename", "matid", "assign"}, diagnostics);
        const std::string text = g.required_text("filename", diagnostics);
        if (text.empty()) return;
        const model::FileRef ref =
            find_file(text, base_dir, local, kind == "glist" ? FileKind::glist : FileKind::geometry,
                      kind == "glist" ? "glist" : "obj file", g.child("filename")->where(), options,
                      load, diagnostics);
        if (ref.resolved.empty()) return;
        if (kind == "glist") {
            place_nested(ref, instances, options, scene, load, within, diagnostics);
            return;
        }
        read_obj(g, ref, within, object);
    } else {
        using K = model::PrimitiveKind;
        model::Primitive p;
        if (kind == "box") {
            p.kind = K::box;
            g.warn_unknown_children({"matid", "lowerextent", "upperextent"}, diagnostics);
        } else if (kind == "sphere" || kind == "disk" || kind == "cylinder") {
            p.kind = kind == "sphere" ? K::sphere : kind == "disk" ? K::disk : K::cylinder;
            g.warn_unknown_children(
                {"matid", "center", "radius", "height", "segments", "rings", "caps"}, diagnostics);
        } else if (kind == "groundplane") {
            p.kind = K::ground_plane;
            g.warn_unknown_children({"matid", "center", "size"}, diagnostics);
        } else {
            diagnostics.error(g.where(),
                              "unknown basegeometry <" + kind +
                                  ">, expected obj, glist, box, sphere, groundplane, disk or "
                                  "cylinder");
            return;
        }
        const std::size_t errors = diagnostics.error_count();
        const auto mat = material(g, object.material_id, within);
        if (p.kind == K::box) {
            if (!g.child("lowerextent")) diagnostics.error(g.where(), "missing <lowerextent>");
            if (!g.child("upperextent")) diagnostics.error(g.where(), "missing <upperextent>");
            p.lower_m = triple(g, "lowerextent", "point").value_or(p.lower_m);
            p.upper_m = triple(g, "upperextent", "point").value_or(p.upper_m);
        } else {
            p.center_m = triple(g, "center", "point").value_or(p.center_m);
        }
        if (p.kind == K::ground_plane) {
            p.size_m = g.optional_double("size", diagnostics, io::NumberRule::positive())
                           .value_or(p.size_m);
        }
        if (p.kind == K::sphere || p.kind == K::disk || p.kind == K::cylinder) {
            p.radius_m =
                g.required_double("radius", diagnostics, io::NumberRule::positive()).value_or(0.0);
            p.segments = static_cast<int>(
                g.optional_int("segments", diagnostics, 3, 4096).value_or(p.segments));
        }
        if (p.kind == K::sphere) {
            p.rings =
                static_cast<int>(g.optional_int("rings", diagnostics, 2, 4096).value_or(p.rings));
        }
        if (p.kind == K::cylinder) {
            p.height_m =
                g.required_double("height", diagnostics, io::NumberRule::positive()).value_or(0.0);
            p.caps = g.optional_bool("caps", diagnostics).value_or(true);
        }
        object.primitive = p;
        if (mat && diagnostics.error_count() == errors) {
            object.mesh = mesh::tessellate_primitive(p, *mat, g.where(), diagnostics);
            mesh::validate_mesh(object.mesh, scene.materials.size(), g.where(), diagnostics);
        }
    }
    refuse_source_surfaces(object);
    const std::size_t object_index = scene.objects.size();
    for (model::Instance& in : instances) {
        in.object_index = object_index;
        scene.instances.push_back(std::move(in));
    }
    scene.objects.push_back(std::move(object));
}

}  // namespace detail

void read_glist(const std::filesystem::path& file, const ReadOptions& options, model::Scene& scene,
                Diagnostics& diagnostics) {
    detail::SceneLoad load;
    load.global_materials = scene.materials.size();
    detail::read_glist_file(file, options, scene, diagnostics, load, {});
}

}  // namespace glint::dirsig
