// SPDX-License-Identifier: Apache-2.0
// Mie's solution for a homogeneous sphere: extinction, scattering and backscattering
// efficiencies, the asymmetry parameter and the scattering amplitudes S1, S2, by the classical
// series (C. F. Bohren, D. R. Huffman, "Absorption and Scattering of Light by Small
// Particles", Wiley, 1983, chapter 4 and Appendix A) with W. J. Wiscombe's stability measures
// and, a little extended, his number of terms ("Improved Mie scattering algorithms", Applied
// Optics 19, 1980, 1505–1509). Checked against Wiscombe's and Bohren & Huffman's published test
// cases (tests/unit/atmosphere/mie_test.cpp).
#pragma once

#include <complex>
#include <span>
#include <vector>

namespace glint::atmosphere {

/// The optics of one sphere. Efficiencies are cross sections over the geometric π r².
struct MieResult {
    double q_ext = 0.0;
    double q_sca = 0.0;
    double q_back = 0.0;     ///< 4 |S1(180°)|² / x² (Bohren & Huffman's definition)
    double asymmetry = 0.0;  ///< g = ⟨cos Θ⟩ of the scattered light
    /// The amplitudes at the requested cos Θ, in Bohren & Huffman's convention (time
    /// dependence e^(−iωt); W. J. Wiscombe's MIEV0 gives their complex conjugates). The
    /// unpolarised phase function is (|S1|² + |S2|²)/2 up to normalisation:
    /// dC_sca/dΩ = (|S1|² + |S2|²) / (2 k²), and ∫ (|S1|² + |S2|²)/2 dcos Θ = Q_sca x²/2.
    std::vector<std::complex<double>> s1, s2;
};

/// The sphere of size parameter `size_parameter` (x = 2π r/λ, in (0, 20000]) and relative
/// refractive index `m` (n + i k, finite, n > 0, k ≥ 0 with k > 0 absorbing, |m| in
/// [0.001, 1000]), with its amplitudes at each cos Θ of `cos_angles` (in [−1, 1]; may be
/// empty). Throws glint::Error (input) for values outside those ranges. Accuracy, measured
/// against a 40-digit evaluation of the series (x ≤ 300) and a longer series (to x = 2e4), for
/// x in [1e-3, 2e4] and |m| up to 15: 2e-9 relative on Q_ext, Q_sca and g, 4e-7 on Q_back and
/// the amplitudes (relative to the rms of |S1| and |S2|). g, of order x² for small spheres,
/// loses digits as x → 0 and m → 1 together (2e-6 at x = 1e-3, m = 1.0001; 1e-15/x² below
/// x = 1e-3); below x ≈ 1e-50 the efficiencies underflow towards 0, never to NaN.
MieResult mie_sphere(double size_parameter, std::complex<double> m,
                     std::span<const double> cos_angles = {});

/// The number of terms of the series for size parameter x: x + 5 x^(1/3) + 2, Wiscombe's
/// count (x + 4.05 x^(1/3) + 2, Applied Optics 19, 1980) and x^(1/3) more. His count converges
/// Q_ext, Q_sca and g to 1e-9 but leaves up to 3e-4 in the backward amplitudes of nearly
/// matched large spheres (x = 1500, m = 1.1); the extra terms bring that below 4e-7. x
/// outside (0, 20000] counts as the nearer end.
int mie_terms(double size_parameter) noexcept;

}  // namespace glint::atmosphere
