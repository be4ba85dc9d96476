// SPDX-License-Identifier: Apache-2.0
// The scene as glint renders it: a geodetic origin, materials (spectral reflectance, an
// optional specular lobe, emissivity, temperature), geometry objects (an OBJ file or a
// tessellated primitive, each held as a validated triangle mesh) and their static or
// dynamic instances. Plain data in SI units (m, rad, K; wavelengths µm). The glint YAML
// scene reader (glint/yaml/scene_reader.h) fills it, as do the DIRSIG scene readers
// (glint/dirsig/scene_reader.h); docs/scene.md is the full reference.
// The YAML keys read:
//
// clang-format off
// | key | type | unit | default |
// |---|---|---|---|
// | origin/latitude, longitude | [-90, 90], [-180, 180] | deg | required in origin |
// | origin/altitude | number | m (above the WGS84 ellipsoid) | 0 |
// | materials[]/id | scalar (number or text, kept as text), unique | - | required |
// | materials[]/name | text, unique (OBJ `usemtl` binds by it) | - | the id |
// | materials[]/reflectance | {wavelengths, values, units} or {file, units}; values in [0, 1] | µm or nm | required |
// | materials[]/reflectance/units | um, nm | - | um (file: its `# units:` header, else um) |
// | materials[]/specular/fraction, roughness | [0, 1], [0, 1] | - | 0, 0 |
// | materials[]/emissivity | as reflectance; values in [0, 1] | µm or nm | 1 − reflectance |
// | materials[]/temperature | number > 0 | K | 300 |
// | objects | list of objects | - | required unless glists is given |
// | objects[]/name | text | - | "object<index>" |
// | objects[]/obj | path of a Wavefront OBJ (exclusive with primitive) | - | - |
// | objects[]/primitive | ground_plane, box, sphere, disk, cylinder (exclusive with obj) | - | - |
// | objects[]/material | material id (primitives: required; OBJ: faces before any usemtl) | - | - |
// | objects[]/size (ground_plane) | number > 0, side of the square | m | 100000 |
// | objects[]/center (ground_plane, sphere, disk, cylinder) | [x, y, z] (cylinder: centre of the base) | m | [0, 0, 0] |
// | objects[]/lower, upper (box) | [x, y, z], lower < upper on every axis | m | required |
// | objects[]/radius (sphere, disk, cylinder) | number > 0 | m | required |
// | objects[]/height (cylinder) | number > 0 | m | required |
// | objects[]/segments (sphere, disk, cylinder) | integer 3–4096 | - | 32 |
// | objects[]/rings (sphere) | integer 2–4096 | - | 16 |
// | objects[]/caps (cylinder) | bool | - | true |
// | objects[]/instances | list; absent: one identity static instance | - | [{}] |
// | instances[]/name | text | - | the object name |
// | instances[]/tags | list of text | - | [] |
// | instances[]/translation | [x, y, z] | m | [0, 0, 0] |
// | instances[]/rotation_deg | [x, y, z] | deg | [0, 0, 0] |
// | instances[]/rotation_order | permutation of xyz | - | xyz |
// | instances[]/scale | number or [x, y, z], non-zero | - | 1 |
// | instances[]/matrix | 16 numbers, row-major 4×4, last row 0 0 0 1 (exclusive with the three above) | m | - |
// | instances[]/motion | path of a .ppd or .motion (dynamic; exclusive with flex_motion and the static keys) | - | - |
// | instances[]/flex_motion | text: an inline `<motion type="flexible">` element | - | - |
// | glists[] | path of a DIRSIG .glist ($SCENE_DIR = the YAML file's folder); its objects and instances are appended after `objects`; matid and usemtl bind to materials[]/id (usemtl also to name) | - | [] |
// clang-format on
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glint/core/diagnostics.h"
#include "glint/model/common.h"
#include "glint/model/maps.h"
#include "glint/model/motion.h"

namespace glint::model {

/// The label that marks an instance for hypersampling when its name or one of its tags
/// starts with it.
inline constexpr std::string_view kImportantLabel = "::IMPORTANT::";

/// Side of the default ground plane square.
inline constexpr double kDefaultGroundPlaneSize_m = 100'000.0;
/// Default longitude segments of spheres, disks and cylinders.
inline constexpr int kDefaultSegments = 32;
/// Default latitude rings of spheres.
inline constexpr int kDefaultRings = 16;
/// Default material temperature.
inline constexpr double kDefaultTemperature_k = 300.0;
/// How far emissivity + reflectance may exceed 1 unnoticed: rounding in curves written as
/// decimals (0.90 + 0.10); the renderer lowers ρ to 1 − ε within it.
inline constexpr double kEmissivityReflectanceSlack = 1e-6;

/// The geodetic origin of the scene's ENU frame (WGS84).
struct SceneOrigin {
    double latitude_deg = 0.0;
    double longitude_deg = 0.0;
    double altitude_m = 0.0;  ///< height above the ellipsoid
    ErrorContext where;
};

/// A spectral quantity tabulated at strictly increasing wavelengths, linearly interpolated
/// between them (as glint::SpectralCurve, which the radiometry builds from it).
struct SpectralTable {
    std::vector<double> wavelengths_um;
    std::vector<double> values;
    FileRef file;  ///< the two-column file it came from; empty when given inline
    ErrorContext where;

    bool empty() const { return wavelengths_um.empty(); }
};

/// The specular part of a material's reflectance: `fraction` of the reflectance goes into
/// a lobe of the given roughness (0 = mirror); the rest is Lambertian.
struct SpecularLobe {
    double fraction = 0.0;
    double roughness = 0.0;
};

/// The reflection model of a material (docs/materials.md). `lambertian`: ρ(λ) spread as a
/// Lambertian lobe, with the SpecularLobe's share in a GGX lobe or a mirror.
enum class ReflectionModel { lambertian, ward, ross_li };

/// DIRSIG's Ward BRDF, f = ρd/π + ρs f_Ward(αx, αy) (spectrally constant): the diffuse and
/// specular weights and the widths (σ, the rms slope) along the surface's x and y axes.
struct WardParameters {
    double diffuse = 0.0;
    double specular = 0.0;
    double alpha_x = 0.0;
    double alpha_y = 0.0;
};

/// The Ross–Li kernel weights relative to the isotropic one (f_vol/f_iso, f_geo/f_iso); the
/// material's reflectance curve is f_iso(λ).
struct RossLiParameters {
    double volumetric = 0.0;
    double geometric = 0.0;
};

/// The thermal parameters of DIRSIG's THERM surface energy balance (`TEMP_SOLVER_NAME =
/// Therm`), in SI units (the `.mat`'s own units are converted by its reader;
/// docs/thermal.md, "Surface temperatures").
struct ThermProperties {
    double specific_heat_j_per_kg_k = 0.0;
    double density_kg_per_m3 = 0.0;
    double conductivity_w_per_m_k = 0.0;
    /// Broadband absorptance of sunlight; empty: 1 − the reflectance's mean over the sun's
    /// spectrum (worked out by the solver).
    std::optional<double> solar_absorptance;
    /// Broadband longwave emissivity; empty: the emissivity's mean over 8-14 µm.
    std::optional<double> thermal_emissivity;
    /// Share of the facet exchanging heat with the air, [0, 1] (the magnitude of DIRSIG's
    /// −1 … 1 EXPOSED_AREA).
    double exposed_area = 1.0;
    /// Slab thickness; 0 (or a zero conductivity): a face without heat storage, in balance
    /// with its forcing at every instant.
    double thickness_m = 0.0;
    ErrorContext where;  ///< the TEMP_SOLVER block
};

/// A surface material: opaque, or a thin two-sided sheet (a leaf) when it has a transmittance.
struct Material {
    std::string id;    ///< as written (a number is kept as its text)
    std::string name;  ///< OBJ `usemtl` names bind to it; defaults to the id
    SpectralTable reflectance;
    SpecularLobe specular;
    /// The reflection lobe's shape; with `ward`, `reflectance` is the constant ρd + ρs.
    ReflectionModel model = ReflectionModel::lambertian;
    WardParameters ward;
    RossLiParameters ross_li;
    /// Diffuse (Lambertian) transmittance τ of a thin sheet, the same from either side: the
    /// share of the irradiance on one face that leaves the other, spread as f = τ/π. Empty:
    /// opaque (τ = 0).
    SpectralTable transmittance;
    /// The transmittance passes straight through (a clear pane: the direction unchanged, as
    /// a delta lobe) instead of diffusely.
    bool straight_transmission = false;
    /// False: only the front face (counter-clockwise seen from it) has these properties; the
    /// back face is black — it neither reflects, transmits nor emits (it still casts shadows).
    /// A single-sided material cannot have a transmittance.
    bool double_sided = true;
    /// Emissivity; when not given it is 1 − reflectance − transmittance (Kirchhoff) at the
    /// curves' wavelengths and `emissivity_is_default` is true.
    SpectralTable emissivity;
    bool emissivity_is_default = true;
    double temperature_k = kDefaultTemperature_k;
    /// A temperature map (`TEMP_SOLVER_NAME = Map`): the temperature where it covers the
    /// surface (elsewhere temperature_k). Shared by the material's copies.
    std::shared_ptr<const PropertyMap> temperature_map;
    /// THERM's parameters (`TEMP_SOLVER_NAME = Therm`); empty for any other solver.
    std::optional<ThermProperties> therm;
    /// Texture classes (docs/maps.md): every curve of a classic `.ems` holding several, the
    /// first (this material's own) included, in file order; emissivities when
    /// `texture_curves_are_emissivity`, else reflectances. A `<texturemap>` selects among them.
    std::vector<SpectralTable> texture_curves;
    bool texture_curves_are_emissivity = true;
    /// The reflectance was made from the emissivity (1 − ε − τ: a `.mat` entry with only an
    /// emissivity curve).
    bool reflectance_from_emissivity = false;
    /// A texture class made from another material's texture_curves: that material (index into
    /// Scene::materials), which truth reports in its place.
    std::optional<std::uint32_t> texture_parent;
    /// A point-source material (a DIRSIG `.mat` entry with `OPTICAL_DESCRIPTION = SOURCE`):
    /// only a PointSource may name it; its surface curves are black (ρ = 0, ε = 0).
    bool point_source = false;
    /// A point-source material's spectral radiant intensity, W/(sr µm); 0 beyond its ends.
    SpectralTable intensity_w_per_sr_um;
    ErrorContext where;
};

/// A triangle mesh in object coordinates, validated: finite vertices, indices in range, no
/// degenerate triangles, at least one triangle, every triangle with a material.
struct Mesh {
    /// Vertex positions, object coordinates, relative to `origin_m` (single precision).
    std::vector<std::array<float, 3>> vertices_m;
    /// What the vertices are measured from (object coordinates, m): vertex i lies at
    /// origin_m + vertices_m[i]. 0 unless the mesh lies far from its object's origin
    /// (mesh_origin_for), where float coordinates would lose millimetres: at 4,000,000 m a
    /// float steps by 0.25 m.
    std::array<double, 3> origin_m{};
    /// Vertex indices, counter-clockwise seen from the front (outside) of the surface.
    std::vector<std::array<std::uint32_t, 3>> triangles;
    /// Per triangle: index into Scene::materials.
    std::vector<std::uint32_t> triangle_materials;
    /// Per triangle, its corners' texture coordinates (OBJ `vt`: u0 v0 u1 v1 u2 v2), for maps
    /// projected through them; empty when no face gives any, NaN for a face that gives none.
    std::vector<std::array<float, 6>> triangle_uvs;
};

/// Beyond this distance from the object's origin (any coordinate, m) a mesh's vertices are
/// stored relative to an origin of their own: a float there steps by 8 mm or more.
inline constexpr double kMeshOriginBeyond_m = 65536.0;

/// The origin a mesh whose first vertex is `first_m` stores its vertices from: that vertex
/// rounded to whole metres when it lies beyond kMeshOriginBeyond_m, else 0 (small meshes keep
/// their coordinates as written).
inline std::array<double, 3> mesh_origin_for(const std::array<double, 3>& first_m) noexcept {
    for (const double c : first_m) {
        if (c > kMeshOriginBeyond_m || c < -kMeshOriginBeyond_m) {
            return {std::round(first_m[0]), std::round(first_m[1]), std::round(first_m[2])};
        }
    }
    return {};
}

enum class PrimitiveKind { ground_plane, box, sphere, disk, cylinder };

/// A primitive's parameters as written; only those of `kind` are meaningful. docs/scene.md
/// gives the exact tessellation.
struct Primitive {
    PrimitiveKind kind = PrimitiveKind::box;
    double size_m = kDefaultGroundPlaneSize_m;  ///< ground_plane: side of the square
    std::array<double, 3> center_m{};           ///< ground_plane, sphere, disk; cylinder base
    std::array<double, 3> lower_m{};            ///< box
    std::array<double, 3> upper_m{};            ///< box
    double radius_m = 0.0;                      ///< sphere, disk, cylinder
    double height_m = 0.0;                      ///< cylinder, along +z
    int segments = kDefaultSegments;            ///< sphere, disk, cylinder
    int rings = kDefaultRings;                  ///< sphere
    bool caps = true;                           ///< cylinder: close both ends
};

/// One piece of geometry, instanced zero or more times.
struct GeometryObject {
    std::string name;
    FileRef obj_file;                    ///< an OBJ object; empty for a primitive
    std::optional<Primitive> primitive;  ///< a primitive object
    std::string material_id;             ///< primitives: their material; OBJ: faces before usemtl
    Mesh mesh;
    ErrorContext where;
};

/// A static placement: p' = translation + R · (scale ∘ p), R the rotations about x, y, z
/// applied in `rotation_order` (first letter first), or p' = matrix · [p, 1] when given.
struct StaticTransform {
    std::array<double, 3> translation_m{};
    std::array<double, 3> rotation_rad{};
    std::string rotation_order = "xyz";
    std::array<double, 3> scale{1.0, 1.0, 1.0};
    std::optional<std::array<double, 16>> matrix;  ///< row-major 4×4
};

/// A placement of an object: static (`transform`) or dynamic (`motion`).
struct Instance {
    std::size_t object_index = 0;  ///< into Scene::objects
    std::string name;
    std::vector<std::string> tags;
    bool important = false;  ///< name or a tag starts with kImportantLabel
    StaticTransform transform;
    /// Dynamic instances: the motion read from `motion_file` or from an inline FlexMotion;
    /// shared by the copies a nested glist makes (an inline PlatformMotion is 6 KB, and a
    /// scene may place 10⁶ instances).
    std::shared_ptr<const PlatformMotion> motion;
    FileRef motion_file;  ///< empty for static and inline-FlexMotion instances
    ErrorContext where;

    bool dynamic() const { return motion != nullptr; }
};

/// A point source (a DIRSIG glist `<basesource><pointsource>`): an isotropic emitter of its
/// material's spectral intensity. A static source sits at `position_m` in scene coordinates;
/// a moving one at `position_m` in the frame its `motion` moves (vehicle coordinates).
struct PointSource {
    std::string name;
    std::uint32_t material = 0;  ///< into Scene::materials, a point_source material
    std::array<double, 3> position_m{};
    std::shared_ptr<const PlatformMotion> motion;  ///< none: static
    FileRef motion_file;                           ///< empty for static and inline motion
    ErrorContext where;

    bool dynamic() const { return motion != nullptr; }
};

/// A whole scene.
struct Scene {
    std::string file;  ///< as named to the reader
    std::optional<SceneOrigin> origin;
    std::vector<Material> materials;
    std::vector<GeometryObject> objects;
    std::vector<Instance> instances;
    std::vector<PointSource> point_sources;
    /// The enabled property maps, in the order they apply (docs/maps.md).
    std::vector<PropertyMap> maps;
};

/// A grey material of constant `reflectance` over 0.1–100 µm, at `temperature_k`, with
/// emissivity `emissivity` when given (else 1 − reflectance − transmittance,
/// emissivity_is_default), the `specular` lobe and, when `transmittance` > 0, that constant
/// diffuse transmittance: scenes built in code (tests, benchmarks, plugins).
Material flat_material(const std::string& id, double reflectance,
                       double temperature_k = kDefaultTemperature_k,
                       std::optional<double> emissivity = std::nullopt, SpecularLobe specular = {},
                       double transmittance = 0.0);

/// `table` at `wavelength_um`: linear between its points, held constant beyond its ends
/// (how the renderer samples material curves on its spectral grid). `table` is not empty.
double sample_held(const SpectralTable& table, double wavelength_um);

/// The wavelengths where all of a material's given curves are measured: the overlap of
/// the reflectance's and (when given) the transmittance's and the emissivity's ranges, µm;
/// empty (lo > hi) when they do not overlap.
std::pair<double, double> measured_range_um(const Material& material);

/// The physical checks of a material every tool applies alike (glint-platform2jsim --check
/// as glint-render): reflectance given, temperature finite and > 0, reflectance,
/// transmittance and emissivity within [0, 1] at every point of any curve, and emissivity +
/// reflectance + transmittance ≤ 1 + kEmissivityReflectanceSlack at every such point inside
/// measured_range_um (all are linear between their points, so a sum within 1 there is within
/// 1 on any grid; beyond it the renderer lowers the held emissivity, see physics.md).
/// Problems go to `diagnostics` at the material's `where`.
void check_material(const Material& material, Diagnostics& diagnostics);

/// Kirchhoff's emissivity of `material`, ε = max(0, 1 − ρ − τ), at every wavelength of its
/// reflectance and transmittance curves (so that it is exact between them too), located at
/// the reflectance curve.
SpectralTable kirchhoff_emissivity(const Material& material);

}  // namespace glint::model
