// SPDX-License-Identifier: Apache-2.0
// Small value types for motion and rendering geometry: a 3-vector, a 3×3 matrix and a unit
// quaternion, all in double precision, without heap allocation and without Eigen (so the
// public headers need nothing beyond the standard library). Conventions used throughout
// glint::motion:
//   - vectors are columns; a matrix acts on the left (v' = M · v); Mat3 is stored row-major;
//   - rotations are active and right-handed: rotation_z(+90°) takes +X to +Y;
//   - quaternions are Hamilton quaternions (w, x, y, z) with ij = k; a unit quaternion q
//     rotates v as q · v · q*, and to_matrix(q) is the same rotation as a matrix;
//   - composition reads right to left: (a * b) applies b first, then a (matrices and
//     quaternions alike).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace glint::motion {

/// A 3-vector (position in metres, direction, or angle triple, depending on use).
/// Aggregate: Vec3{1, 2, 3}; v[0..2] index x, y, z.
struct Vec3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;

    constexpr double& operator[](std::size_t i) noexcept { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double operator[](std::size_t i) const noexcept {
        return i == 0 ? x : (i == 1 ? y : z);
    }
    friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
};

/// Converts the std::array triples used by glint::model into a Vec3.
constexpr Vec3 to_vec3(const std::array<double, 3>& a) noexcept { return {a[0], a[1], a[2]}; }
/// Converts a Vec3 into the std::array triple used by glint::model.
constexpr std::array<double, 3> to_array(const Vec3& v) noexcept { return {v.x, v.y, v.z}; }

constexpr Vec3 operator+(const Vec3& a, const Vec3& b) noexcept {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
constexpr Vec3 operator-(const Vec3& a, const Vec3& b) noexcept {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
constexpr Vec3 operator-(const Vec3& a) noexcept { return {-a.x, -a.y, -a.z}; }
constexpr Vec3 operator*(const Vec3& a, double s) noexcept { return {a.x * s, a.y * s, a.z * s}; }
constexpr Vec3 operator*(double s, const Vec3& a) noexcept { return a * s; }
constexpr Vec3 operator/(const Vec3& a, double s) noexcept { return {a.x / s, a.y / s, a.z / s}; }
constexpr Vec3& operator+=(Vec3& a, const Vec3& b) noexcept { return a = a + b; }
constexpr Vec3& operator-=(Vec3& a, const Vec3& b) noexcept { return a = a - b; }
constexpr Vec3& operator*=(Vec3& a, double s) noexcept { return a = a * s; }

/// Dot product.
constexpr double dot(const Vec3& a, const Vec3& b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
/// Cross product a × b (right-handed).
constexpr Vec3 cross(const Vec3& a, const Vec3& b) noexcept {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// Euclidean length.
inline double norm(const Vec3& a) noexcept { return std::sqrt(dot(a, a)); }
/// `a` scaled to unit length; the zero vector stays zero.
inline Vec3 normalized(const Vec3& a) noexcept {
    const double n = norm(a);
    return n > 0.0 ? a / n : a;
}

/// A 3×3 matrix, row-major: m[row][column]. Value-initialised to zero; use identity().
struct Mat3 {
    std::array<std::array<double, 3>, 3> m{};

    constexpr double& operator()(std::size_t row, std::size_t col) noexcept { return m[row][col]; }
    constexpr double operator()(std::size_t row, std::size_t col) const noexcept {
        return m[row][col];
    }
    /// The identity matrix.
    static constexpr Mat3 identity() noexcept { return {{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}; }
    /// The matrix whose rows are r0, r1, r2.
    static constexpr Mat3 from_rows(const Vec3& r0, const Vec3& r1, const Vec3& r2) noexcept {
        return {{{{r0.x, r0.y, r0.z}, {r1.x, r1.y, r1.z}, {r2.x, r2.y, r2.z}}}};
    }
    /// The matrix whose columns are c0, c1, c2 (e.g. the images of the basis vectors).
    static constexpr Mat3 from_columns(const Vec3& c0, const Vec3& c1, const Vec3& c2) noexcept {
        return {{{{c0.x, c1.x, c2.x}, {c0.y, c1.y, c2.y}, {c0.z, c1.z, c2.z}}}};
    }
    /// Row `i` (0-2).
    constexpr Vec3 row(std::size_t i) const noexcept { return {m[i][0], m[i][1], m[i][2]}; }
    /// Column `j` (0-2).
    constexpr Vec3 column(std::size_t j) const noexcept { return {m[0][j], m[1][j], m[2][j]}; }
    friend constexpr bool operator==(const Mat3&, const Mat3&) = default;
};

/// Matrix product a · b (b is applied first when acting on a vector).
constexpr Mat3 operator*(const Mat3& a, const Mat3& b) noexcept {
    Mat3 r;
    for (std::size_t i = 0; i < 3; ++i) {
        for (std::size_t j = 0; j < 3; ++j) {
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
        }
    }
    return r;
}
/// Matrix times column vector.
constexpr Vec3 operator*(const Mat3& a, const Vec3& v) noexcept {
    return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
            a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
            a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}
/// Transpose (the inverse of a rotation matrix).
constexpr Mat3 transpose(const Mat3& a) noexcept {
    return Mat3::from_columns(a.row(0), a.row(1), a.row(2));
}
/// Determinant (+1 for a proper rotation).
constexpr double determinant(const Mat3& a) noexcept {
    return dot(a.row(0), cross(a.row(1), a.row(2)));
}

/// Active right-handed rotation by `angle_rad` about +X: takes +Y towards +Z.
inline Mat3 rotation_x(double angle_rad) noexcept {
    const double c = std::cos(angle_rad), s = std::sin(angle_rad);
    return {{{{1, 0, 0}, {0, c, -s}, {0, s, c}}}};
}
/// Active right-handed rotation by `angle_rad` about +Y: takes +Z towards +X.
inline Mat3 rotation_y(double angle_rad) noexcept {
    const double c = std::cos(angle_rad), s = std::sin(angle_rad);
    return {{{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}}};
}
/// Active right-handed rotation by `angle_rad` about +Z: takes +X towards +Y.
inline Mat3 rotation_z(double angle_rad) noexcept {
    const double c = std::cos(angle_rad), s = std::sin(angle_rad);
    return {{{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}}};
}

/// A Hamilton quaternion w + xi + yj + zk. Rotations use unit quaternions; q and −q are the
/// same rotation. Default-constructed it is the identity rotation.
struct Quaternion {
    double w = 1.0;
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;

    /// The identity rotation.
    static constexpr Quaternion identity() noexcept { return {1.0, 0.0, 0.0, 0.0}; }
    friend constexpr bool operator==(const Quaternion&, const Quaternion&) = default;
};

/// Hamilton product a · b (as rotations: b first, then a).
constexpr Quaternion operator*(const Quaternion& a, const Quaternion& b) noexcept {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
/// Conjugate (the inverse rotation for a unit quaternion).
constexpr Quaternion conjugate(const Quaternion& q) noexcept { return {q.w, -q.x, -q.y, -q.z}; }
/// Four-dimensional dot product.
constexpr double dot(const Quaternion& a, const Quaternion& b) noexcept {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}
/// Euclidean norm (1 for a rotation).
inline double norm(const Quaternion& q) noexcept { return std::sqrt(dot(q, q)); }
/// `q` scaled to unit norm; the zero quaternion becomes the identity.
inline Quaternion normalized(const Quaternion& q) noexcept {
    const double n = norm(q);
    if (!(n > 0.0)) return Quaternion::identity();
    return {q.w / n, q.x / n, q.y / n, q.z / n};
}
/// The rotation by `angle_rad` (right-handed) about `axis` (need not be unit length; a zero
/// axis gives the identity).
inline Quaternion quaternion_from_axis_angle(const Vec3& axis, double angle_rad) noexcept {
    const double n = norm(axis);
    if (!(n > 0.0)) return Quaternion::identity();
    const double s = std::sin(0.5 * angle_rad) / n;
    return {std::cos(0.5 * angle_rad), axis.x * s, axis.y * s, axis.z * s};
}
/// Rotates `v` by the unit quaternion `q` (q v q*), without forming a matrix.
constexpr Vec3 rotate(const Quaternion& q, const Vec3& v) noexcept {
    // v' = v + 2w (u × v) + 2 u × (u × v), u = (x, y, z).
    const Vec3 u{q.x, q.y, q.z};
    const Vec3 t = 2.0 * cross(u, v);
    return v + q.w * t + cross(u, t);
}
/// The rotation matrix of the unit quaternion `q` (same rotation as rotate(q, ·)).
constexpr Mat3 to_matrix(const Quaternion& q) noexcept {
    const double xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const double xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const double wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    return {{{{1 - 2 * (yy + zz), 2 * (xy - wz), 2 * (xz + wy)},
              {2 * (xy + wz), 1 - 2 * (xx + zz), 2 * (yz - wx)},
              {2 * (xz - wy), 2 * (yz + wx), 1 - 2 * (xx + yy)}}}};
}
/// The unit quaternion of a rotation matrix (Shepperd's method, stable for every rotation),
/// with w ≥ 0. `m` should be orthonormal with determinant +1; the result is normalised.
Quaternion quaternion_from_matrix(const Mat3& m) noexcept;
/// Spherical linear interpolation between unit quaternions along the shorter arc:
/// t = 0 gives a, t = 1 gives b (or −b, the same rotation), constant angular speed between.
/// Uses linear interpolation (then normalises) when a and b are within 1e-9 rad.
Quaternion slerp(const Quaternion& a, const Quaternion& b, double t) noexcept;
/// The angle in radians (0..π) of the rotation that takes a to b.
double angle_between(const Quaternion& a, const Quaternion& b) noexcept;

}  // namespace glint::motion
