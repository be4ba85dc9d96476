// SPDX-License-Identifier: Apache-2.0
// Checks on triangle meshes shared by the mesh and scene reader tests: a mesh's bounds and
// the outward orientation of its triangles.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "glint/model/scene.h"

namespace glint::test {

/// An axis-aligned box, m.
struct Bounds {
    std::array<float, 3> lo{1e30f, 1e30f, 1e30f};
    std::array<float, 3> hi{-1e30f, -1e30f, -1e30f};
};

/// The axis-aligned box of a mesh's used vertices.
inline Bounds bounds_of(const model::Mesh& mesh) {
    Bounds b;
    for (const auto& tri : mesh.triangles) {
        for (const auto index : tri) {
            for (int k = 0; k < 3; ++k) {
                b.lo[k] = std::min(b.lo[k], mesh.vertices_m[index][k]);
                b.hi[k] = std::max(b.hi[k], mesh.vertices_m[index][k]);
            }
        }
    }
    return b;
}

/// Every triangle's normal points away from `inside`.
inline void expect_outward(const model::Mesh& mesh, std::array<double, 3> inside) {
    for (const auto& tri : mesh.triangles) {
        std::array<double, 3> p[3];
        for (int k = 0; k < 3; ++k) {
            for (int a = 0; a < 3; ++a) p[k][a] = mesh.vertices_m[tri[k]][a];
        }
        const std::array<double, 3> e0{p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        const std::array<double, 3> e1{p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        const std::array<double, 3> n{e0[1] * e1[2] - e0[2] * e1[1], e0[2] * e1[0] - e0[0] * e1[2],
                                      e0[0] * e1[1] - e0[1] * e1[0]};
        const std::array<double, 3> c{(p[0][0] + p[1][0] + p[2][0]) / 3 - inside[0],
                                      (p[0][1] + p[1][1] + p[2][1]) / 3 - inside[1],
                                      (p[0][2] + p[1][2] + p[2][2]) / 3 - inside[2]};
        EXPECT_GT(n[0] * c[0] + n[1] * c[1] + n[2] * c[2], 0.0);
    }
}

}  // namespace glint::test
