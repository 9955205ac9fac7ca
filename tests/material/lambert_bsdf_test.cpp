// LambertBsdf, the path tracer's inline Lambert lobe for a Matte of constant albedo, against the Bsdf
// that Matte itself makes: the same values to the bit, for directions on both sides and in frames
// turned every way, and a Material::constant_lambert() only where that lobe is the whole BSDF.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>

#include "glint/material/matte.hpp"
#include "glint/material/phong.hpp"
#include "glint/texture/checker.hpp"
#include "material/bsdf_checks.hpp"

namespace glint {
namespace {

using testing::test_point;

void expect_same_bits(const Rgb& a, const Rgb& b) {
    EXPECT_EQ(a.r, b.r);
    EXPECT_EQ(a.g, b.g);
    EXPECT_EQ(a.b, b.b);
}

TEST(LambertBsdf, OnlyAMatteOfConstantAlbedoHasAConstantLambertLobe) {
    const Matte matte(Rgb(0.2, 0.5, 0.7));
    ASSERT_NE(matte.constant_lambert(), nullptr);
    expect_same_bits(*matte.constant_lambert(), Rgb(0.2, 0.5, 0.7));

    const auto checker = std::make_shared<CheckerTexture>(std::make_shared<ConstantTexture>(Rgb(0.1)),
                                                          std::make_shared<ConstantTexture>(Rgb(0.9)), 1.0,
                                                          CheckerTexture::Space::Solid);
    EXPECT_EQ(Matte(checker).constant_lambert(), nullptr);  // a texture: looked up per hit
    EXPECT_EQ(
        Phong(std::make_shared<ConstantTexture>(Rgb(0.5)), std::make_shared<ConstantTexture>(Rgb(0.3)), 20)
            .constant_lambert(),
        nullptr);  // a diffuse part, and a lobe besides
}

TEST(LambertBsdf, GivesTheBitsOfMattesOwnBsdf) {
    const Matte matte(Rgb(0.25, 0.5, 0.8));
    int samples_compared = 0;
    for (std::uint32_t frame_index = 0; frame_index < 64; ++frame_index) {
        // Shading normals all over the sphere, so that both branches of the frame's construction run.
        const Point2 n = test_point(11, frame_index);
        const double z = 1 - 2 * n.x;
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        const Hit hit =
            testing::test_hit(normalize(Vec3{r * std::cos(2 * kPi * n.y), r * std::sin(2 * kPi * n.y), z}));
        const Bsdf bsdf = matte.bsdf(hit);
        const LambertBsdf lambert(Frame::from_normal(hit.shading_normal), *matte.constant_lambert());
        for (std::uint32_t i = 0; i < 32; ++i) {
            // wo and wi on either side of the surface (a reflection or a transmission).
            const Point2 a = test_point(frame_index + 100, 2 * i);
            const Point2 b = test_point(frame_index + 100, 2 * i + 1);
            const Vec3 wo =
                normalize(Vec3{2 * a.x - 1, 2 * a.y - 1, (i % 2 == 0 ? 1 : -1) * (0.05 + a.x * a.y)});
            const Vec3 wi = normalize(Vec3{2 * b.x - 1, 2 * b.y - 1, (i % 3 == 0 ? -1 : 1) * (0.05 + b.y)});
            expect_same_bits(lambert.evaluate_local(wo, wi), bsdf.evaluate_local(wo, wi));
            EXPECT_EQ(lambert.pdf_local(wo, wi), bsdf.pdf_local(wo, wi));

            const Point2 u = test_point(frame_index + 1000, i);
            const std::optional<BsdfSample> mine = lambert.sample_from_local(wo, u);
            const std::optional<BsdfSample> theirs = bsdf.sample_from_local(wo, u);
            ASSERT_EQ(mine.has_value(), theirs.has_value());
            if (mine) {
                EXPECT_EQ(mine->wi.x, theirs->wi.x);
                EXPECT_EQ(mine->wi.y, theirs->wi.y);
                EXPECT_EQ(mine->wi.z, theirs->wi.z);
                expect_same_bits(mine->f, theirs->f);
                expect_same_bits(mine->weight, theirs->weight);
                EXPECT_EQ(mine->pdf, theirs->pdf);
                EXPECT_EQ(mine->delta, theirs->delta);
                ++samples_compared;
            }
        }
        for (const auto& [mine, theirs] :
             {std::pair{lambert.frame().s, bsdf.frame().s}, std::pair{lambert.frame().t, bsdf.frame().t},
              std::pair{lambert.frame().n, bsdf.frame().n}}) {
            EXPECT_EQ(mine.x, theirs.x);
            EXPECT_EQ(mine.y, theirs.y);
            EXPECT_EQ(mine.z, theirs.z);
        }
    }
    EXPECT_GT(samples_compared, 1000);
}

}  // namespace
}  // namespace glint
