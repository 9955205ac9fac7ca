// The convergence study measures what theory predicts: random sampling's error falls as n^−1/2,
// stratified patterns' as n^−3/4 on an edge; and the test integrands' closed forms are right.
#include "glint/sampling/convergence.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

double midpoint_integral(const TestIntegrand& integrand, int grid) {
    double sum = 0;
    for (int y = 0; y < grid; ++y) {
        for (int x = 0; x < grid; ++x) {
            sum += integrand.f({(x + 0.5) / grid, (y + 0.5) / grid});
        }
    }
    return sum / (static_cast<double>(grid) * grid);
}

TEST(Convergence, IntegrandsClosedFormsAgreeWithQuadrature) {
    EXPECT_NEAR(midpoint_integral(edge_integrand(), 2000), edge_integrand().integral, 1e-4);
    EXPECT_NEAR(midpoint_integral(smooth_integrand(), 500), smooth_integrand().integral, 1e-6);
}

TEST(Convergence, LogLogSlopeOfAPowerLaw) {
    EXPECT_NEAR(log_log_slope({1, 4, 16, 64}, {1, 0.125, 1.0 / 64, 1.0 / 512}, 1), -1.5, 1e-12);
    EXPECT_NEAR(log_log_slope({1, 4, 16, 64}, {9, 1, 0.5, 0.25}, 4), -0.5, 1e-12);  // fits from 4 only
}

TEST(Convergence, RandomHalfJitteredThreeQuartersOnAnEdge) {
    const auto curves =
        convergence_study({"random", "jittered", "sobol"}, {edge_integrand()}, {16, 64, 256}, 128, 1, 16);
    ASSERT_EQ(curves.size(), 3u);
    EXPECT_NEAR(curves[0].slope, -0.5, 0.12) << "random";
    EXPECT_NEAR(curves[1].slope, -0.75, 0.12) << "jittered";
    EXPECT_NEAR(curves[2].slope, -0.75, 0.15) << "sobol";
    EXPECT_LT(curves[1].rmse.back(), 0.5 * curves[0].rmse.back());
}

}  // namespace
}  // namespace glint
