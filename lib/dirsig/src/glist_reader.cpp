// SPDX-License-Identifier: Apache-2.0
// Reader of DIRSIG `.glist` geometry lists into model::Scene: `object` elements with one
// `basegeometry` (obj, glist, box, sphere, groundplane, disk, cylinder), static instances
// (translation, rotation, scale or a 16-value matrix), dynamic instances (generic motion
// from a .ppd/.motion file or inline flexible motion) and tags. Nested glists are flattened
// by composing their static instances with the including one. GDB/ODB geometry is an error.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>

#include "glint/core/text.h"
#include "glint/dirsig/motion_reader.h"
#include "glint/dirsig/scene_reader.h"
#include "glint/io/xml.h"

namespace glint::dirsig {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
/// Deepest nesting of glist base geometry accepted.
constexpr int kMaxGlistDepth = 16;

using Matrix4 = std::array<double, 16>;

/// A nested glist as read once per read_glist: its objects were appended to the scene at
/// `object_offset`, and `instances` (object indices relative to those objects) are placed
/// again for every instance that includes it — a glist named by ten objects is parsed once
/// and its meshes are stored once.
struct NestedGlist {
    std::size_t object_offset = 0;
    std::vector<model::Instance> instances;
};

/// The nested glists read so far, by absolute normalised path.
using GlistCache = std::map<std::filesystem::path, NestedGlist>;

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
    Matrix4 c{};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            for (int k = 0; k < 4; ++k) c[i * 4 + j] += a[i * 4 + k] * b[k * 4 + j];
        }
    }
    return c;
}

/// The 4×4 of a static transform (scene.h: p' = t + R · (s ∘ p)).
Matrix4 to_matrix(const model::StaticTransform& t) {
    if (t.matrix) return *t.matrix;
    Matrix4 r{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    for (const char axis : t.rotation_order) {
        const int k = axis - 'x';
        const double c = std::cos(t.rotation_rad[k]);
        const double s = std::sin(t.rotation_rad[k]);
        Matrix4 step{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        const int a = (k + 1) % 3;
        const int b = (k + 2) % 3;
        step[a * 4 + a] = c;
        step[a * 4 + b] = -s;
        step[b * 4 + a] = s;
        step[b * 4 + b] = c;
        r = multiply(step, r);  // first letter applied first
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) r[i * 4 + j] *= t.scale[j];
        r[i * 4 + 3] = t.translation_m[i];
    }
    return r;
}

bool is_identity(const model::StaticTransform& t) {
    const Matrix4 m = to_matrix(t);
    for (int i = 0; i < 16; ++i) {
        if (m[i] != (i % 5 == 0 ? 1.0 : 0.0)) return false;
    }
    return true;
}

bool starts_important(const std::string& s) { return s.rfind(model::kImportantLabel, 0) == 0; }

/// Everything the element readers of one glist file share.
struct GlistReader {
    std::string file;
    std::filesystem::path base_dir;
    std::string source_text;
    const ReadOptions& options;
    Diagnostics& diagnostics;
    model::Scene& scene;
    std::vector<std::filesystem::path>& chain;  ///< glists being read, outermost first
    GlistCache& cache;                          ///< nested glists already read

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

    /// The material index of `matid` (required); an error when unknown.
    std::optional<std::uint32_t> material(const io::XmlNode& node, std::string& id) {
        id = node.required_text("matid", diagnostics);
        if (id.empty()) return std::nullopt;
        for (std::size_t i = 0; i < scene.materials.size(); ++i) {
            if (scene.materials[i].id == id) return static_cast<std::uint32_t>(i);
        }
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
        in.motion_file =
            options.paths.resolve(text, base_dir, motion->child("filename")->where(), diagnostics);
        if (!in.motion_file.resolved.empty()) {
            in.motion = std::make_shared<const model::PlatformMotion>(
                read_motion(in.motion_file.resolved, options, diagnostics));
        }
        return in;
    }

    /// Reads a nested glist and places its instances with each of `outer`.
    void place_nested(const model::FileRef& ref, const std::vector<model::Instance>& outer);

    void read_object(const io::XmlNode& node);
};

/// Reads one glist file into `scene` (the recursive step behind read_glist).
void read_glist_file(const std::filesystem::path& path, const ReadOptions& options,
                     model::Scene& scene, Diagnostics& diagnostics,
                     std::vector<std::filesystem::path>& chain, GlistCache& cache) {
    const std::string name = path.string();
    const std::size_t depth = chain.size();
    try {
        const std::string text = options.read_text(path, name);
        const io::XmlDocument document = io::XmlDocument::parse(text, name);
        const io::XmlNode root = document.root("geometrylist");
        if (root.attribute_bool("enabled", diagnostics) == false) return;
        root.warn_unknown_children({"object"}, diagnostics);
        chain.push_back(std::filesystem::absolute(path).lexically_normal());
        GlistReader reader{
            name, std::filesystem::absolute(path).parent_path(), text, options, diagnostics, scene,
            chain, cache};
        for (const io::XmlNode& object : root.children("object")) reader.read_object(object);
        document.warn_unread(diagnostics);
    } catch (const Error& error) {
        diagnostics.add(error);
    }
    chain.resize(depth);
}

void GlistReader::place_nested(const model::FileRef& ref,
                               const std::vector<model::Instance>& outer) {
    const auto key = ref.resolved.lexically_normal();
    if (std::find(chain.begin(), chain.end(), key) != chain.end()) {
        diagnostics.error(ref.where, "glist " + ref.text + " includes itself");
        return;
    }
    if (static_cast<int>(chain.size()) >= kMaxGlistDepth) {
        diagnostics.error(
            ref.where, "glist nesting deeper than " + std::to_string(kMaxGlistDepth) + " levels");
        return;
    }
    auto cached = cache.find(key);
    if (cached == cache.end()) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(ref.resolved, ec)) {
            diagnostics.error(ref.where,
                              "glist " + ref.text + " not found (" + ref.resolved.string() + ")");
            return;
        }
        model::Scene sub;
        sub.materials = scene.materials;
        read_glist_file(ref.resolved, options, sub, diagnostics, chain, cache);
        NestedGlist nested;
        nested.object_offset = scene.objects.size();
        nested.instances = std::move(sub.instances);
        for (model::GeometryObject& object : sub.objects) {
            scene.objects.push_back(std::move(object));
        }
        cached = cache.emplace(key, std::move(nested)).first;
    }
    const NestedGlist& sub = cached->second;
    // Count before building: every including instance places every instance of the glist.
    const std::uint64_t adding =
        static_cast<std::uint64_t>(outer.size()) * static_cast<std::uint64_t>(sub.instances.size());
    const std::uint64_t total = static_cast<std::uint64_t>(scene.instances.size()) + adding;
    if (total > options.max_instances) {
        diagnostics.error(ref.where,
                          "glist " + ref.text + " (" + std::to_string(sub.instances.size()) +
                              " instances) placed by " + std::to_string(outer.size()) +
                              " instances would bring this glist to " + std::to_string(total) +
                              " instances, more than the " +
                              std::to_string(options.max_instances) +
                              " allowed (--max-instances raises the limit)");
        return;
    }
    for (const model::Instance& o : outer) {
        if (o.dynamic()) {
            diagnostics.error(o.where, "a dynamicinstance of glist base geometry (" + ref.text +
                                           ") is not supported");
            continue;
        }
        const bool identity = is_identity(o.transform);
        for (const model::Instance& inner : sub.instances) {
            model::Instance in = inner;
            in.object_index += sub.object_offset;
            in.tags.insert(in.tags.begin(), o.tags.begin(), o.tags.end());
            in.important = in.important || o.important;
            if (!identity) {
                if (inner.dynamic()) {
                    diagnostics.error(inner.where,
                                      "a dynamic instance in a nested glist cannot be placed by "
                                      "a non-identity static instance (" +
                                          o.where.element + ")");
                    continue;
                }
                in.transform = model::StaticTransform{};
                in.transform.matrix = multiply(to_matrix(o.transform), to_matrix(inner.transform));
            }
            scene.instances.push_back(std::move(in));
        }
    }
}

void GlistReader::read_object(const io::XmlNode& node) {
    if (node.attribute_bool("enabled", diagnostics) == false) return;
    node.warn_unknown_children(
        {"basegeometry", "staticinstance", "dynamicinstance", "tags", "localmaterials", "name"},
        diagnostics);
    if (node.child("localmaterials")) {
        diagnostics.warning(node.child("localmaterials")->where(),
                            "localmaterials are not supported (ignored)");
    }
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
    if (!base) {
        diagnostics.error(node.where(), "missing required element <basegeometry>");
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
        g.warn_unknown_children({"filename", "matid"}, diagnostics);
        const std::string text = g.required_text("filename", diagnostics);
        if (text.empty()) return;
        model::FileRef ref =
            options.paths.resolve(text, base_dir, g.child("filename")->where(), diagnostics);
        if (ref.resolved.empty()) return;
        if (kind == "glist") {
            place_nested(ref, instances);
            return;
        }
        std::optional<std::uint32_t> fallback;
        if (g.child("matid")) fallback = material(g, object.material_id);
        const auto by_name = [this](const std::string& name) {
            std::optional<std::uint32_t> found;
            for (std::size_t i = 0; i < scene.materials.size() && !found; ++i) {
                if (scene.materials[i].id == name) found = static_cast<std::uint32_t>(i);
            }
            for (std::size_t i = 0; i < scene.materials.size() && !found; ++i) {
                if (scene.materials[i].name == name) found = static_cast<std::uint32_t>(i);
            }
            return found;
        };
        object.obj_file = ref;
        object.mesh = load_obj_mesh(ref.resolved, ref.resolved.string(), options, by_name, fallback,
                                    scene.materials.size(), diagnostics);
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
        const auto mat = material(g, object.material_id);
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
    const std::size_t object_index = scene.objects.size();
    for (model::Instance& in : instances) {
        in.object_index = object_index;
        scene.instances.push_back(std::move(in));
    }
    scene.objects.push_back(std::move(object));
}

}  // namespace

void read_glist(const std::filesystem::path& file, const ReadOptions& options, model::Scene& scene,
                Diagnostics& diagnostics) {
    std::vector<std::filesystem::path> chain;
    GlistCache cache;
    read_glist_file(file, options, scene, diagnostics, chain, cache);
}

}  // namespace glint::dirsig
