// The watertight triangle test's ray (geometry/triangle.hpp): the axes it shears along, chosen without
// branches, for every kind of direction a ray may have.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "glint/geometry/triangle.hpp"

namespace glint {
namespace {

// Directions with components from a set that holds ties, both zeros, both signs and a NaN.
TEST(WatertightRay, ShearsAlongTheLargestComponentAndKeepsTheWinding) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double values[] = {-2, -1, -0.0, 0, 0.5, 1, 2, nan};
    int checked = 0;
    for (double x : values) {
        for (double y : values) {
            for (double z : values) {
                const Vec3 d{x, y, z};
                const Vec3 o{10.0 + checked, 20.0 - checked, 0.5 * checked};
                const WatertightRay ray({o, d});
                SCOPED_TRACE(testing::Message() << "direction " << x << " " << y << " " << z);
                // A permutation of the three axes.
                ASSERT_EQ((1 << ray.kx) | (1 << ray.ky) | (1 << ray.kz), 7);
                // kz: the largest |component|; a tie goes to z before x and y, then to y before x
                // (which axis a tie takes changes no hit's answer, only which bits a render gets).
                const double ax = std::abs(x), ay = std::abs(y), az = std::abs(z);
                const int largest = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
                EXPECT_EQ(ray.kz, largest);
                // (kx, ky, kz) is a cyclic order of (x, y, z) unless the ray runs along −kz, which
                // swaps kx and ky: the sign of a triangle's determinant then means the same side.
                const bool along_minus = d[ray.kz] < 0;
                EXPECT_EQ(ray.kx, along_minus ? (ray.kz + 2) % 3 : (ray.kz + 1) % 3);
                EXPECT_EQ(ray.ky, along_minus ? (ray.kz + 1) % 3 : (ray.kz + 2) % 3);
                // The shear and the permuted origin, to the bit (a NaN stays a NaN).
                const auto same = [](double a, double b) {
                    return a == b || (std::isnan(a) && std::isnan(b));
                };
                EXPECT_TRUE(same(ray.shear_x, d[ray.kx] / d[ray.kz]));
                EXPECT_TRUE(same(ray.shear_y, d[ray.ky] / d[ray.kz]));
                EXPECT_TRUE(same(ray.shear_z, 1.0 / d[ray.kz]));
                EXPECT_EQ(ray.origin_x, o[ray.kx]);
                EXPECT_EQ(ray.origin_y, o[ray.ky]);
                EXPECT_EQ(ray.origin_z, o[ray.kz]);
                ++checked;
            }
        }
    }
    EXPECT_EQ(checked, 512);
}

// A triangle seen along each axis, from both sides: hit at the same t whichever axis the ray shears
// along, with its own vertex order either way.
TEST(WatertightRay, HitsATriangleAlongEveryAxisFromBothSides) {
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {1.0, -1.0}) {
            const auto at = [&](double u, double v, double w) {
                Vec3 p;
                p[axis] = w;
                p[(axis + 1) % 3] = u;
                p[(axis + 2) % 3] = v;
                return p;
            };
            const Vec3 v0 = at(-1, -1, 0), v1 = at(2, -1, 0), v2 = at(-1, 2, 0);
            Vec3 direction;
            direction[axis] = sign;
            direction[(axis + 1) % 3] = 0.01;  // slightly off the axis
            const Ray ray{at(0, 0, -5 * sign), direction};
            TriangleHit hit;
            ASSERT_TRUE(intersect_triangle(WatertightRay(ray), v0, v1, v2, kInf, hit))
                << "axis " << axis << " sign " << sign;
            EXPECT_DOUBLE_EQ(hit.t, 5.0);
            EXPECT_NEAR(hit.b0 + hit.b1 + hit.b2, 1.0, 1e-15);
            TriangleHit reversed;
            ASSERT_TRUE(intersect_triangle(WatertightRay(ray), v0, v2, v1, kInf, reversed));
            EXPECT_EQ(reversed.t, hit.t);
        }
    }
}

}  // namespace
}  // namespace glint
