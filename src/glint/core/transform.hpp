// Affine transforms of 3-D space: a 3×3 linear part and a translation, kept with their inverse so that
// points, directions and normals move either way without inverting per ray.
#pragma once

#include <array>
#include <optional>

#include "glint/core/bounds.hpp"

namespace glint {

class Transform {
  public:
    using Matrix = std::array<std::array<double, 4>, 3>;  // rows of [linear | translation]

    Transform() : forward_(identity_matrix()), inverse_(identity_matrix()) {}

    // The transform x ↦ M x, given as 3 rows of 4 (the last column the translation), or nothing when
    // M cannot be inverted: its determinant is zero, or negligible next to the size of its rows (a
    // flattened space, whose normals are undefined), which does not depend on the overall scale.
    static std::optional<Transform> from_matrix(const Matrix& m) {
        const double det = determinant(m);
        const double row_scale = row_length(m, 0) * row_length(m, 1) * row_length(m, 2);
        if (!(std::abs(det) > 1e-12 * row_scale) || !std::isfinite(det)) {
            return std::nullopt;
        }
        Transform t;
        t.forward_ = m;
        t.inverse_ = invert(m, det);
        return t;
    }
    static Transform translate(const Vec3& v) {
        return *from_matrix({{{1, 0, 0, v.x}, {0, 1, 0, v.y}, {0, 0, 1, v.z}}});
    }
    // Scale factors must be non-zero (from_matrix is the checked path).
    static std::optional<Transform> scale(const Vec3& s) {
        return from_matrix({{{s.x, 0, 0, 0}, {0, s.y, 0, 0}, {0, 0, s.z, 0}}});
    }
    // A rotation by `degrees` about the unit `axis`, counter-clockwise looking down the axis
    // (right-hand rule; Rodrigues' formula).
    static Transform rotate(const Vec3& axis, double degrees) {
        const Vec3 a = normalize(axis);
        const double c = std::cos(radians(degrees)), s = std::sin(radians(degrees)), k = 1 - c;
        Transform t;
        t.forward_ = {{{c + a.x * a.x * k, a.x * a.y * k - a.z * s, a.x * a.z * k + a.y * s, 0},
                       {a.y * a.x * k + a.z * s, c + a.y * a.y * k, a.y * a.z * k - a.x * s, 0},
                       {a.z * a.x * k - a.y * s, a.z * a.y * k + a.x * s, c + a.z * a.z * k, 0}}};
        // A rotation's inverse is its transpose.
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                t.inverse_[i][j] = t.forward_[j][i];
            }
            t.inverse_[i][3] = 0;
        }
        return t;
    }

    // This transform followed by `next`: (next ∘ this)(x) = next(this(x)).
    Transform then(const Transform& next) const {
        Transform t;
        t.forward_ = multiply(next.forward_, forward_);
        t.inverse_ = multiply(inverse_, next.inverse_);
        return t;
    }
    Transform inverse() const {
        Transform t;
        t.forward_ = inverse_;
        t.inverse_ = forward_;
        return t;
    }

    Vec3 point(const Vec3& p) const { return apply(forward_, p) + column(forward_, 3); }
    Vec3 vector(const Vec3& v) const { return apply(forward_, v); }
    // The inverse map, without building the inverse Transform.
    Vec3 inverse_point(const Vec3& p) const { return apply(inverse_, p) + column(inverse_, 3); }
    Vec3 inverse_vector(const Vec3& v) const { return apply(inverse_, v); }
    // Normals move by the inverse transpose, so they stay perpendicular to transformed tangents. The
    // result is not unit length.
    Vec3 normal(const Vec3& n) const { return apply_transposed(inverse_, n); }

    // A box holding the transformed box (its eight corners); infinite stays infinite.
    Bounds3 bounds(const Bounds3& b) const {
        if (!b.is_finite()) {
            return b.empty() ? b : Bounds3::infinite();
        }
        Bounds3 out;
        for (int corner = 0; corner < 8; ++corner) {
            out.grow(point(
                {corner & 1 ? b.hi.x : b.lo.x, corner & 2 ? b.hi.y : b.lo.y, corner & 4 ? b.hi.z : b.lo.z}));
        }
        return out;
    }

    // Σ_j |M_ij| per row i: how much an error bound in each input axis can grow in output axis i.
    Vec3 row_abs_sums() const {
        return {std::abs(forward_[0][0]) + std::abs(forward_[0][1]) + std::abs(forward_[0][2]),
                std::abs(forward_[1][0]) + std::abs(forward_[1][1]) + std::abs(forward_[1][2]),
                std::abs(forward_[2][0]) + std::abs(forward_[2][1]) + std::abs(forward_[2][2])};
    }
    Vec3 translation() const { return column(forward_, 3); }
    // If the linear part is a rotation times a uniform scale s (possibly a mirror), s; else nothing.
    // Such transforms keep areas in the ratio s² and uniform densities uniform.
    std::optional<double> uniform_scale() const {
        const Vec3 c0 = column(forward_, 0), c1 = column(forward_, 1), c2 = column(forward_, 2);
        const double s2 = dot(c0, c0);
        const double tolerance = 1e-9 * s2;
        if (std::abs(dot(c1, c1) - s2) > tolerance || std::abs(dot(c2, c2) - s2) > tolerance ||
            std::abs(dot(c0, c1)) > tolerance || std::abs(dot(c1, c2)) > tolerance ||
            std::abs(dot(c0, c2)) > tolerance) {
            return std::nullopt;
        }
        return std::sqrt(s2);
    }
    const Matrix& matrix() const { return forward_; }
    const Matrix& inverse_matrix() const { return inverse_; }

  private:
    static Matrix identity_matrix() { return {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}}; }
    static Vec3 column(const Matrix& m, int j) { return {m[0][j], m[1][j], m[2][j]}; }
    static Vec3 apply(const Matrix& m, const Vec3& v) {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    static Vec3 apply_transposed(const Matrix& m, const Vec3& v) {
        return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z, m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
                m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
    }
    static double row_length(const Matrix& m, int i) { return std::hypot(m[i][0], m[i][1], m[i][2]); }
    static double determinant(const Matrix& m) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    }
    // The inverse of x ↦ A x + b is x ↦ A⁻¹ x − A⁻¹ b, A⁻¹ = adjugate / det.
    static Matrix invert(const Matrix& m, double det) {
        Matrix r{};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                // Cofactor of m[j][i] (transposed), by cyclic indices.
                const int j1 = (j + 1) % 3, j2 = (j + 2) % 3, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
                r[i][j] = (m[j1][i1] * m[j2][i2] - m[j1][i2] * m[j2][i1]) / det;
            }
        }
        const Vec3 b = column(m, 3);
        const Vec3 inv_b = apply(r, b);
        r[0][3] = -inv_b.x;
        r[1][3] = -inv_b.y;
        r[2][3] = -inv_b.z;
        return r;
    }
    // The composition a ∘ b of two affine maps.
    static Matrix multiply(const Matrix& a, const Matrix& b) {
        Matrix r{};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 4; ++j) {
                r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + (j == 3 ? a[i][3] : 0);
            }
        }
        return r;
    }

    Matrix forward_, inverse_;
};

}  // namespace glint
