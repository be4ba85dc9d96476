// SPDX-License-Identifier: Apache-2.0
// Tests of the material scattering shape (glint/radiometry/bsdf.h): the chi-square fit of
// Bsdf::sample over the whole sphere (20 θ × 20 φ cells from 0 to π: reflected and
// transmitted draws together, so the side probability is tested with the lobes) for each
// reflection model with and without a transmission; the weights (shape |cos| / pdf over the
// side's probability); the mirror (delta draws, reflection() without the delta); the
// DirectionalAlbedo table against independent estimates (Lambertian 1 exactly, GGX and Ward
// by quadrature within 2e-3, Ross–Li by quadrature); the anisotropic shading frame.
#include "glint/radiometry/bsdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "chi_square.h"
#include "glint/core/error.h"
#include "glint/core/rng.h"

namespace glint::radiometry {
namespace bsdf_test {

using testing::chi_square_direction_test;
using testing::DirectionHistogram;
using testing::integrate_upper_hemisphere;
using testing::kChiSquarePValueThreshold;
using testing::local_direction;

constexpr std::uint64_t kSeed = 20261129;

struct Case {
    std::string name;
    Bsdf bsdf;
};

std::vector<Case> cases() {
    return {
        {"lambertian", Bsdf(SurfaceBrdf(1.0, 0.0, 0.0), 0.0)},
        {"leaf", Bsdf(SurfaceBrdf(1.0, 0.0, 0.0), 0.45)},
        {"ggx leaf", Bsdf(SurfaceBrdf(1.0, 0.3, 0.4), 0.3)},
        {"ward", Bsdf(WardBrdf(0.6, 0.4, 0.2, 0.2), 0.0)},
        {"anisotropic ward sheet", Bsdf(WardBrdf(0.5, 0.5, 0.3, 0.1), 0.2)},
        {"ross-li", Bsdf(RossLiBrdf(0.5, 0.1), 0.0)},
        {"ross-li sheet", Bsdf(RossLiBrdf(0.5, 0.1), 0.4)},
    };
}

TEST(Bsdf, ChiSquareOverTheSphere) {
    std::uint64_t stream = 1;
    for (const Case& c : cases()) {
        for (double theta_o : {15.0, 60.0}) {
            const Vec3 wo = local_direction(theta_o, 70.0);
            RandomStream extra(kSeed, {stream + 500});
            DirectionHistogram sphere;
            sphere.theta_bins = 20;
            sphere.theta_max_rad = kPi;
            const auto r = chi_square_direction_test(
                sphere, 200000,
                [&](double u1, double u2) -> std::optional<Vec3> {
                    const auto s = c.bsdf.sample(wo, extra.uniform(), extra.uniform(), u1, u2);
                    if (!s) return std::nullopt;
                    return s->wi;
                },
                [&](const Vec3& wi) { return c.bsdf.pdf_per_sr(wo, wi); }, kSeed, stream++, 24);
            EXPECT_GT(r.p_value, kChiSquarePValueThreshold)
                << c.name << " theta_o " << theta_o << " chi2 " << r.statistic << " dof " << r.dof;
        }
    }
}

TEST(Bsdf, WeightIsShapeTimesCosineOverPdf) {
    RandomStream rng(kSeed, {2});
    for (const Case& c : cases()) {
        const Vec3 wo = local_direction(40.0, 10.0);
        for (int i = 0; i < 500; ++i) {
            const auto s =
                c.bsdf.sample(wo, rng.uniform(), rng.uniform(), rng.uniform(), rng.uniform());
            if (!s) continue;
            ASSERT_FALSE(s->delta);
            const bool through = s->side == ScatterSide::transmitted;
            EXPECT_EQ(through, s->wi.z < 0.0) << c.name;
            const double shape = through ? Bsdf::transmission() : c.bsdf.reflection(wo, s->wi);
            EXPECT_NEAR(s->pdf_per_sr, c.bsdf.pdf_per_sr(wo, s->wi), 1e-9 * s->pdf_per_sr);
            // The weight divides by the side's probability; the pdf includes it.
            EXPECT_NEAR(s->weight, shape * std::abs(s->wi.z) / s->pdf_per_sr,
                        1e-9 * (1.0 + s->weight))
                << c.name;
        }
    }
}

TEST(Bsdf, TransmitsWithItsProbabilityAndOpaqueDrawsNoSide) {
    const Bsdf leaf(SurfaceBrdf(1.0, 0.0, 0.0), 0.25);
    const Vec3 wo = local_direction(30.0, 0.0);
    const auto through = leaf.sample(wo, 0.2, 0.5, 0.3, 0.6);
    ASSERT_TRUE(through);
    EXPECT_EQ(through->side, ScatterSide::transmitted);
    EXPECT_DOUBLE_EQ(through->weight, 4.0);
    const auto back = leaf.sample(wo, 0.3, 0.5, 0.3, 0.6);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->side, ScatterSide::reflected);
    EXPECT_DOUBLE_EQ(back->weight, 1.0 / 0.75);
    // An opaque shape gives exactly its lobe's draw, whatever u_side.
    const SurfaceBrdf lobe(1.0, 0.3, 0.4);
    const Bsdf opaque(lobe, 0.0);
    const auto a = opaque.sample(wo, 0.0, 0.1, 0.3, 0.6);
    const auto b = lobe.sample(wo, 0.1, 0.3, 0.6);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->weight, b->weight);
    EXPECT_EQ(a->wi.x, b->wi.x);
    EXPECT_THROW(Bsdf(lobe, 1.5), Error);
}

TEST(Bsdf, AClearSheetTransmitsStraightThrough) {
    const Bsdf pane(SurfaceBrdf(1.0, 1.0, 0.0), 0.9, true);
    EXPECT_TRUE(pane.straight());
    const Vec3 wo = local_direction(25.0, 40.0);
    const auto through = pane.sample(wo, 0.5, 0.5, 0.2, 0.3);
    ASSERT_TRUE(through);
    EXPECT_TRUE(through->delta);
    EXPECT_EQ(through->side, ScatterSide::transmitted);
    EXPECT_DOUBLE_EQ(through->wi.x, -wo.x);
    EXPECT_DOUBLE_EQ(through->wi.z, -wo.z);
    EXPECT_DOUBLE_EQ(through->weight, 1.0 / 0.9);
    EXPECT_EQ(pane.pdf_per_sr(wo, Vec3{0.0, 0.0, -1.0}), 0.0);
    // An opaque shape cannot be straight.
    EXPECT_FALSE(Bsdf(SurfaceBrdf(1.0, 0.0, 0.0), 0.0, true).straight());
}

TEST(Bsdf, MirrorDrawsTheReflectionAsADelta) {
    const Bsdf water(SurfaceBrdf(1.0, 0.7, 0.0), 0.0);
    EXPECT_TRUE(water.has_mirror());
    EXPECT_FALSE(water.glossy());
    EXPECT_TRUE(water.unit_albedo());
    const Vec3 wo = local_direction(35.0, 20.0);
    const auto m = water.sample(wo, 1.0, 0.5, 0.1, 0.9);
    ASSERT_TRUE(m);
    EXPECT_TRUE(m->delta);
    EXPECT_NEAR(m->wi.x, -wo.x, 1e-15);
    EXPECT_NEAR(m->wi.y, -wo.y, 1e-15);
    EXPECT_NEAR(m->wi.z, wo.z, 1e-15);
    EXPECT_DOUBLE_EQ(m->weight, 1.0);
    const auto d = water.sample(wo, 1.0, 0.8, 0.1, 0.9);
    ASSERT_TRUE(d);
    EXPECT_FALSE(d->delta);
    EXPECT_NEAR(d->weight, 1.0, 1e-12);
    // reflection() holds the diffuse 30 % only, as does the pdf.
    EXPECT_NEAR(water.reflection(wo, local_direction(10, 0)), 0.3 / kPi, 1e-15);
    EXPECT_NEAR(
        integrate_upper_hemisphere([&](const Vec3& w) { return water.pdf_per_sr(wo, w); }, 4), 0.3,
        1e-6);
}

TEST(DirectionalAlbedo, AgreesWithQuadrature) {
    // Lambertian: 1 at every node (each weight is exactly 1).
    const DirectionalAlbedo lambert(SurfaceBrdf(1.0, 0.0, 0.0));
    for (double c : {0.0, 0.3, 1.0}) EXPECT_DOUBLE_EQ(lambert.at(c), 1.0);
    const std::vector<std::pair<std::string, Bsdf::Reflection>> lobes = {
        {"ggx", SurfaceBrdf(1.0, 0.6, 0.5)},
        {"ward", WardBrdf(0.3, 0.7, 0.2, 0.2)},
        {"ross-li", RossLiBrdf(0.6, 0.15)},
    };
    for (const auto& [name, lobe] : lobes) {
        const DirectionalAlbedo table(lobe);
        const Bsdf bsdf(lobe, 0.0);
        for (double theta_o : {0.0, 41.4, 75.5}) {
            const Vec3 wo = local_direction(theta_o, 0.0);
            const double reference = integrate_upper_hemisphere(
                [&](const Vec3& wi) { return bsdf.reflection(wo, wi) * wi.z; }, 24);
            // 2e-3: the 64 × 64 stratified estimate's error on these smooth lobes, plus the
            // table's linear interpolation between nodes 1/32 apart in cos θo.
            EXPECT_NEAR(table.at(wo.z), reference, 2e-3) << name << " theta_o " << theta_o;
            if (name == "ross-li") {
                // An independent NumPy midpoint quadrature (1600 × 3200 cells) of
                // max(0, 1 + 0.6 K_vol + 0.15 K_geo) with zeniths limited to 80° gives
                // 0.8063390, 0.8572857 and 1.1036582.
                const double numpy = theta_o == 0.0 ? 0.8063390
                                     : theta_o < 50 ? 0.8572857
                                                    : 1.1036582;
                EXPECT_NEAR(table.at(wo.z), numpy, 5e-4) << theta_o;
            }
        }
    }
}

TEST(ShadingFrame, AnisotropicLobesTakeEastAsTheirXAxis) {
    const Bsdf ward(WardBrdf(0.5, 0.5, 0.3, 0.1), 0.0);
    ASSERT_TRUE(ward.anisotropic());
    const Vec3 n = normalized(Vec3{0.0, 0.3, 1.0});
    const Frame f = shading_frame(ward, n);
    EXPECT_NEAR(f.s.x, 1.0, 1e-12);
    EXPECT_NEAR(dot(f.s, n), 0.0, 1e-12);
    EXPECT_NEAR(dot(f.t, n), 0.0, 1e-12);
    EXPECT_NEAR(dot(cross(f.s, f.t), n), 1.0, 1e-12);
    // A wall facing east: north is x.
    const Frame w = shading_frame(ward, Vec3{1.0, 0.0, 0.0});
    EXPECT_NEAR(w.s.y, 1.0, 1e-12);
    // Isotropic lobes keep the usual frame.
    const Bsdf lambert(SurfaceBrdf(1.0, 0.0, 0.0), 0.0);
    const Frame l = shading_frame(lambert, n);
    const Frame d = Frame::from_normal(n);
    EXPECT_EQ(l.s.x, d.s.x);
    EXPECT_EQ(l.t.y, d.t.y);
}

}  // namespace bsdf_test
}  // namespace glint::radiometry
