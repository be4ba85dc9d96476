// SPDX-License-Identifier: Apache-2.0
// The non-inline parts of the geometry value types: matrix → quaternion (Shepperd), slerp and
// the angle between two rotations.
#include "glint/motion/geometry.h"

#include <algorithm>
#include <cmath>

namespace glint::motion {

Quaternion quaternion_from_matrix(const Mat3& m) noexcept {
    // Shepperd (1978): pick the largest of 4w², 4x², 4y², 4z² to divide by.
    const double trace = m(0, 0) + m(1, 1) + m(2, 2);
    Quaternion q;
    if (trace >= m(0, 0) && trace >= m(1, 1) && trace >= m(2, 2)) {
        const double s = 2.0 * std::sqrt(std::max(0.0, 1.0 + trace));  // 4w
        q = {0.25 * s, (m(2, 1) - m(1, 2)) / s, (m(0, 2) - m(2, 0)) / s, (m(1, 0) - m(0, 1)) / s};
    } else if (m(0, 0) >= m(1, 1) && m(0, 0) >= m(2, 2)) {
        const double s = 2.0 * std::sqrt(std::max(0.0, 1.0 + m(0, 0) - m(1, 1) - m(2, 2)));  // 4x
        q = {(m(2, 1) - m(1, 2)) / s, 0.25 * s, (m(0, 1) + m(1, 0)) / s, (m(0, 2) + m(2, 0)) / s};
    } else if (m(1, 1) >= m(2, 2)) {
        const double s = 2.0 * std::sqrt(std::max(0.0, 1.0 + m(1, 1) - m(0, 0) - m(2, 2)));  // 4y
        q = {(m(0, 2) - m(2, 0)) / s, (m(0, 1) + m(1, 0)) / s, 0.25 * s, (m(1, 2) + m(2, 1)) / s};
    } else {
        const double s = 2.0 * std::sqrt(std::max(0.0, 1.0 + m(2, 2) - m(0, 0) - m(1, 1)));  // 4z
        q = {(m(1, 0) - m(0, 1)) / s, (m(0, 2) + m(2, 0)) / s, (m(1, 2) + m(2, 1)) / s, 0.25 * s};
    }
    if (q.w < 0.0) q = {-q.w, -q.x, -q.y, -q.z};
    return normalized(q);
}

Quaternion slerp(const Quaternion& a, const Quaternion& b_in, double t) noexcept {
    Quaternion b = b_in;
    if (dot(a, b) < 0.0) b = {-b.w, -b.x, -b.y, -b.z};  // q ≡ −q: take the shorter arc
    // θ = 2·atan2(|a − b|, |a + b|) is accurate for small and large angles alike (acos is
    // not near 1).
    const Quaternion d{a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z};
    const Quaternion s{a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
    const double theta = 2.0 * std::atan2(norm(d), norm(s));
    double wa = 1.0 - t;
    double wb = t;
    if (theta > 1e-9) {
        const double sin_theta = std::sin(theta);
        wa = std::sin((1.0 - t) * theta) / sin_theta;
        wb = std::sin(t * theta) / sin_theta;
    }
    return normalized(
        {wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z});
}

double angle_between(const Quaternion& a, const Quaternion& b) noexcept {
    // The relative rotation r = b · a*; its angle is 2·atan2(|vector part|, |w|).
    const Quaternion r = b * conjugate(a);
    const double v = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    return 2.0 * std::atan2(v, std::abs(r.w));
}

}  // namespace glint::motion
