// SPDX-License-Identifier: Apache-2.0
// Nested glists (`<basegeometry><glist>`): each is read once per scene load and material
// scope, and its instances are placed once per including instance. A static including
// instance composes its matrix with each inner one; a dynamic one (a moving vehicle made of
// parts) gives its motion to every part, whose placement inside the glist is baked into a
// copy of the part's mesh, since a model::Instance is either static or moving.
#include <algorithm>
#include <cmath>

#include "glist_parts.h"

namespace glint::dirsig::detail {
namespace {

/// Deepest nesting of glist base geometry accepted.
constexpr int kMaxGlistDepth = 16;

double determinant3(const Matrix4& m) {
    return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
           m[2] * (m[4] * m[9] - m[5] * m[8]);
}

/// The index of a copy of object `index` with `m` applied to its vertices (made once per
/// load); nullopt after an error at `where` when `m` is singular or not finite.
std::optional<std::size_t> baked_object(std::size_t index, const Matrix4& m,
                                        const ErrorContext& where, model::Scene& scene,
                                        SceneLoad& load, Diagnostics& diagnostics) {
    const auto key = std::make_pair(index, m);
    if (const auto found = load.baked.find(key); found != load.baked.end()) return found->second;
    const double det = determinant3(m);
    bool finite = std::isfinite(det);
    for (const double v : m) finite = finite && std::isfinite(v);
    if (!finite || det == 0.0) {
        diagnostics.error(where, "the placement of this part of a moving glist is " +
                                     std::string(finite ? "singular" : "not finite"));
        return std::nullopt;
    }
    model::GeometryObject copy = scene.objects[index];
    // Each vertex placed in double (from the mesh's origin), then stored relative to the
    // placed mesh's own origin (model::mesh_origin_for its first vertex).
    const std::array<double, 3> from = copy.mesh.origin_m;
    bool first = true;
    for (std::array<float, 3>& v : copy.mesh.vertices_m) {
        std::array<double, 3> q{};
        for (int i = 0; i < 3; ++i) q[i] = from[i] + v[i];
        std::array<double, 3> p{};
        for (int i = 0; i < 3; ++i) {
            p[i] = m[i * 4] * q[0] + m[i * 4 + 1] * q[1] + m[i * 4 + 2] * q[2] + m[i * 4 + 3];
        }
        if (first) copy.mesh.origin_m = model::mesh_origin_for(p);
        first = false;
        for (int i = 0; i < 3; ++i) v[i] = static_cast<float>(p[i] - copy.mesh.origin_m[i]);
    }
    if (det < 0.0) {  // a mirroring placement: keep the front faces counter-clockwise
        for (auto& t : copy.mesh.triangles) std::swap(t[1], t[2]);
    }
    scene.objects.push_back(std::move(copy));
    load.baked.emplace(key, scene.objects.size() - 1);
    return scene.objects.size() - 1;
}

}  // namespace

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
    Matrix4 c{};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            for (int k = 0; k < 4; ++k) c[i * 4 + j] += a[i * 4 + k] * b[k * 4 + j];
        }
    }
    return c;
}

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

bool is_identity(const Matrix4& m) {
    for (int i = 0; i < 16; ++i) {
        if (m[i] != (i % 5 == 0 ? 1.0 : 0.0)) return false;
    }
    return true;
}

void place_nested(const model::FileRef& ref, const std::vector<model::Instance>& outer,
                  const ReadOptions& options, model::Scene& scene, SceneLoad& load,
                  const std::vector<MaterialScope>& scopes, Diagnostics& diagnostics) {
    const auto path = ref.resolved.lexically_normal();
    if (std::find(load.chain.begin(), load.chain.end(), path) != load.chain.end()) {
        diagnostics.error(ref.where, "glist " + ref.text + " includes itself");
        return;
    }
    if (static_cast<int>(load.chain.size()) >= kMaxGlistDepth) {
        diagnostics.error(
            ref.where, "glist nesting deeper than " + std::to_string(kMaxGlistDepth) + " levels");
        return;
    }
    std::string scope_key;
    for (const MaterialScope& scope : scopes) scope_key += scope.key;
    auto cached = load.nested.find({path, scope_key});
    if (cached == load.nested.end()) {
        // Its objects join the scene's (indices stay absolute); its instances are kept apart.
        model::Scene sub;
        sub.materials = std::move(scene.materials);
        sub.objects = std::move(scene.objects);
        read_glist_file(ref.resolved, options, sub, diagnostics, load, scopes);
        scene.materials = std::move(sub.materials);
        scene.objects = std::move(sub.objects);
        cached = load.nested
                     .emplace(std::make_pair(path, scope_key),
                              NestedGlist{std::move(sub.instances), std::move(sub.point_sources)})
                     .first;
    }
    const std::vector<model::Instance>& inner_instances = cached->second.instances;
    // Count before building: every including instance places every instance (and point
    // source) of the glist.
    const std::uint64_t adding =
        static_cast<std::uint64_t>(outer.size()) *
        static_cast<std::uint64_t>(inner_instances.size() + cached->second.sources.size());
    const std::uint64_t total = static_cast<std::uint64_t>(scene.instances.size()) +
                                static_cast<std::uint64_t>(scene.point_sources.size()) + adding;
    if (total > options.max_instances) {
        diagnostics.error(ref.where,
                          "glist " + ref.text + " (" + std::to_string(inner_instances.size()) +
                              " instances) placed by " + std::to_string(outer.size()) +
                              " instances would bring this glist to " + std::to_string(total) +
                              " instances, more than the " + std::to_string(options.max_instances) +
                              " allowed (--max-instances raises the limit)");
        return;
    }
    for (const model::Instance& o : outer) {
        const Matrix4 outer_matrix = to_matrix(o.transform);
        const bool identity = !o.dynamic() && is_identity(outer_matrix);
        for (const model::Instance& inner : inner_instances) {
            model::Instance in = inner;
            in.tags.insert(in.tags.begin(), o.tags.begin(), o.tags.end());
            in.important = in.important || o.important;
            if (o.dynamic()) {
                if (inner.dynamic()) {
                    diagnostics.error(inner.where,
                                      "a dynamic instance in a nested glist cannot be moved by a "
                                      "dynamicinstance (" +
                                          o.where.element + ")");
                    continue;
                }
                const Matrix4 m = to_matrix(inner.transform);
                if (!is_identity(m)) {
                    const auto baked =
                        baked_object(inner.object_index, m, inner.where, scene, load, diagnostics);
                    if (!baked) continue;
                    in.object_index = *baked;
                }
                in.transform = model::StaticTransform{};
                in.motion = o.motion;
                in.motion_file = o.motion_file;
            } else if (!identity) {
                if (inner.dynamic()) {
                    diagnostics.error(inner.where,
                                      "a dynamic instance in a nested glist cannot be placed by "
                                      "a non-identity static instance (" +
                                          o.where.element + ")");
                    continue;
                }
                in.transform = model::StaticTransform{};
                in.transform.matrix = multiply(outer_matrix, to_matrix(inner.transform));
            }
            scene.instances.push_back(std::move(in));
        }
    }
    place_nested_sources(cached->second.sources, outer, scene, diagnostics);
}

}  // namespace glint::dirsig::detail
