// SPDX-License-Identifier: Apache-2.0
// A bump map's tilted normal at a vertex (docs/maps.md): the surface's BSDF is evaluated and
// sampled about it, while the facet's own (geometric) normal still decides which side a
// direction leaves on — a direction that the two normals put on different sides carries no
// light (it would enter the surface, or leave it from below), so bumps never light what the
// geometry shadows.
#pragma once

#include "glint/scene/geometry_scene.h"

namespace glint::radiometry {

/// The normal the BSDF uses at `hit`, on the side of `facing` (the geometric normal turned
/// towards the outgoing direction; `back_face`: it was turned): the bump map's, else `facing`.
inline scene::Vec3 shading_normal(const scene::RayHit& hit, const scene::Vec3& facing,
                                  bool back_face) noexcept {
    if (!hit.bumped) return facing;
    return back_face ? -hit.shading_normal : hit.shading_normal;
}

/// Whether `w` lies on the same side of both normals (always, without a bump map).
inline bool same_side(const scene::Vec3& geometric, const scene::Vec3& shading,
                      const scene::Vec3& w) noexcept {
    return (dot(geometric, w) > 0.0) == (dot(shading, w) > 0.0);
}

}  // namespace glint::radiometry
