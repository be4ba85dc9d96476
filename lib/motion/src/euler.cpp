// SPDX-License-Identifier: Apache-2.0
// Euler (Tait–Bryan) angles in the six DIRSIG rotation orders: composition into matrices and
// quaternions, and the inverse (angles from a matrix) for every order through one formula
// parameterised by the axis permutation and its parity.
#include "glint/motion/euler.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>

#include "glint/core/units.h"

namespace glint::motion {
namespace {

/// The axes of an order in application order, and +1 for an even (cyclic) permutation.
struct OrderAxes {
    std::size_t first;
    std::size_t second;
    std::size_t third;
    double parity;
};

constexpr OrderAxes axes_of(EulerOrder order) noexcept {
    switch (order) {
        case EulerOrder::xyz:
            return {0, 1, 2, +1.0};
        case EulerOrder::xzy:
            return {0, 2, 1, -1.0};
        case EulerOrder::yxz:
            return {1, 0, 2, -1.0};
        case EulerOrder::yzx:
            return {1, 2, 0, +1.0};
        case EulerOrder::zxy:
            return {2, 0, 1, +1.0};
        case EulerOrder::zyx:
            return {2, 1, 0, -1.0};
    }
    return {0, 1, 2, +1.0};
}

Mat3 elementary_matrix(std::size_t axis, double angle_rad) noexcept {
    switch (axis) {
        case 0:
            return rotation_x(angle_rad);
        case 1:
            return rotation_y(angle_rad);
        default:
            return rotation_z(angle_rad);
    }
}

Quaternion elementary_quaternion(std::size_t axis, double angle_rad) noexcept {
    const double c = std::cos(0.5 * angle_rad), s = std::sin(0.5 * angle_rad);
    switch (axis) {
        case 0:
            return {c, s, 0.0, 0.0};
        case 1:
            return {c, 0.0, s, 0.0};
        default:
            return {c, 0.0, 0.0, s};
    }
}

}  // namespace

std::optional<EulerOrder> parse_euler_order(std::string_view text) noexcept {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
        text.remove_prefix(1);
    }
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
        text.remove_suffix(1);
    }
    if (text.size() != 3) return std::nullopt;
    char lower[3];
    for (std::size_t i = 0; i < 3; ++i) {
        lower[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
    }
    const std::string_view name(lower, 3);
    for (const EulerOrder order : kAllEulerOrders) {
        if (name == to_string(order)) return order;
    }
    return std::nullopt;
}

std::string_view to_string(EulerOrder order) noexcept {
    switch (order) {
        case EulerOrder::xyz:
            return "xyz";
        case EulerOrder::xzy:
            return "xzy";
        case EulerOrder::yxz:
            return "yxz";
        case EulerOrder::yzx:
            return "yzx";
        case EulerOrder::zxy:
            return "zxy";
        case EulerOrder::zyx:
            return "zyx";
    }
    return "xyz";
}

Vec3 euler_deg_to_rad(const Vec3& angles_deg) noexcept {
    return {deg_to_rad(angles_deg.x), deg_to_rad(angles_deg.y), deg_to_rad(angles_deg.z)};
}

Vec3 euler_rad_to_deg(const Vec3& angles_rad) noexcept {
    return {rad_to_deg(angles_rad.x), rad_to_deg(angles_rad.y), rad_to_deg(angles_rad.z)};
}

Mat3 euler_to_matrix(const Vec3& angles_rad, EulerOrder order) noexcept {
    const OrderAxes a = axes_of(order);
    return elementary_matrix(a.third, angles_rad[a.third]) *
           elementary_matrix(a.second, angles_rad[a.second]) *
           elementary_matrix(a.first, angles_rad[a.first]);
}

Quaternion euler_to_quaternion(const Vec3& angles_rad, EulerOrder order) noexcept {
    const OrderAxes a = axes_of(order);
    return elementary_quaternion(a.third, angles_rad[a.third]) *
           elementary_quaternion(a.second, angles_rad[a.second]) *
           elementary_quaternion(a.first, angles_rad[a.first]);
}

Vec3 matrix_to_euler(const Mat3& m, EulerOrder order) noexcept {
    // With R = R_k(c) · R_j(b) · R_i(a) (i applied first) and s the permutation's parity:
    //   R[k][i] = −s·sin b,   R[k][j] =  s·sin a·cos b,  R[k][k] = cos a·cos b,
    //   R[j][i] =  s·sin c·cos b,   R[i][i] = cos c·cos b.
    // At cos b = 0 only a ± c is defined: set a = 0, then R[i][j] = −s·sin c, R[j][j] = cos c.
    const OrderAxes ax = axes_of(order);
    const std::size_t i = ax.first, j = ax.second, k = ax.third;
    const double s = ax.parity;
    const double cos_b = std::hypot(m(i, i), m(j, i));
    Vec3 angles;
    angles[j] = std::atan2(-s * m(k, i), cos_b);
    if (cos_b > 1e-12) {
        angles[i] = std::atan2(s * m(k, j), m(k, k));
        angles[k] = std::atan2(s * m(j, i), m(i, i));
    } else {
        angles[i] = 0.0;
        angles[k] = std::atan2(-s * m(i, j), m(j, j));
    }
    return angles;
}

Vec3 quaternion_to_euler(const Quaternion& q, EulerOrder order) noexcept {
    return matrix_to_euler(to_matrix(normalized(q)), order);
}

}  // namespace glint::motion
