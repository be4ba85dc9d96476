// SPDX-License-Identifier: Apache-2.0
// The noisy path of DetectionChain::process_line, in batches of draws: the means; the first
// Philox block of every draw at once (RandomStream::blocks_at); the samplers' constants and
// first proposals side by side (so that their square roots and divisions overlap); then
// each draw's decisions. The few draws that the first block leaves undecided continue with
// the samplers from the next word. Every value equals detect_value's (sample_poisson, then
// sample_standard_normal, from the draw's word position), which determinism_test checks.
#include <algorithm>
#include <cmath>

#include "glint/detect/adc.h"
#include "glint/detect/chain.h"
#include "glint/detect/noise.h"

namespace glint::detect {

void DetectionChain::process_noisy(RandomStream& stream, const int* cfa_row,
                                   std::uint64_t first_pixel, std::span<const double> in,
                                   std::span<double> out) const {
    constexpr std::size_t kBatch = 16;
    const std::size_t channels = m_settings.channels();
    const std::size_t draws = cfa_row != nullptr ? m_samples : m_samples * channels;
    const detail::ZigguratTable& zig = detail::ziggurat_table();
    const Adc adc = m_adc;
    const io::EnviDataType type = m_settings.data_type;
    const bool counts = m_settings.output == DetectOutput::counts;
    const double sigma = m_read_sigma_e;

    double mean[kBatch], u[kBatch], v[kBatch], us[kBatch], candidate[kBatch];
    detail::PtrsConstants ptrs[kBatch];
    std::uint64_t position[kBatch], word0[kBatch], word1[kBatch];
    PhiloxCounter block[kBatch];
    for (std::size_t begin = 0; begin < draws; begin += kBatch) {
        const std::size_t n = std::min(kBatch, draws - begin);
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t i = begin + j;
            std::size_t x = i, c = 0;
            if (cfa_row != nullptr) {
                c = static_cast<std::size_t>(cfa_row[i % m_cfa_period]);
            } else {
                x = i / channels;
                c = i % channels;
            }
            mean[j] = checked_mean(in[x * channels + c], c, x);
            position[j] = ((first_pixel + x) * channels + c) << kWordsPerDrawLog2;
        }
        stream.blocks_at(std::span<const std::uint64_t>(position, n),
                         std::span<PhiloxCounter>(block, n));
        // The stream's first two 64-bit draws at each position (low word first), and PTRS's
        // constants and first proposal (used only for means >= 10).
        for (std::size_t j = 0; j < n; ++j) {
            word0[j] = block[j][0] | static_cast<std::uint64_t>(block[j][1]) << 32;
            word1[j] = block[j][2] | static_cast<std::uint64_t>(block[j][3]) << 32;
        }
        for (std::size_t j = 0; j < n; ++j) {
            ptrs[j] = detail::ptrs_constants(mean[j]);
            u[j] = detail::ptrs_u(word0[j]);
            v[j] = detail::ptrs_v(word0[j]);
            us[j] = 0.5 - std::fabs(u[j]);
            candidate[j] = detail::ptrs_candidate(ptrs[j], mean[j], u[j], us[j]);
        }
        for (std::size_t j = 0; j < n; ++j) {
            const double mu = mean[j];
            double k = 0.0;
            std::uint64_t normal_word = word0[j];
            std::uint64_t poisson_words = 2;  // 32-bit words the Poisson draw took
            bool poisson_decided = true;
            if (mu == 0.0) {
                poisson_words = 0;
            } else if (mu < detail::kPoissonInversionLimit) {
                k = detail::poisson_inversion(mu, word0[j]);
                normal_word = word1[j];
            } else {
                const detail::PtrsProposal p{u[j], v[j], us[j], detail::floor_value(candidate[j]),
                                             us[j] >= 0.07 && v[j] <= ptrs[j].v_r};
                k = p.k;
                poisson_decided = p.fast_accept || detail::ptrs_slow_accept(ptrs[j], mu, p);
                normal_word = word1[j];
            }
            double electrons = k;
            if (!poisson_decided) {
                // The first proposal was rejected: the second is the block's second word;
                // after that PTRS goes on from the next block.
                const detail::PtrsProposal p = detail::ptrs_proposal(ptrs[j], mu, word1[j]);
                stream.skip_to(position[j] + 4);
                electrons = p.fast_accept || detail::ptrs_slow_accept(ptrs[j], mu, p)
                                ? p.k
                                : static_cast<double>(detail::ptrs_from(stream, mu));
                if (sigma > 0.0) electrons += sigma * sample_standard_normal(stream);
            } else if (sigma > 0.0) {
                double z = 0.0;
                if (!detail::normal_fast(zig, normal_word, z)) {
                    stream.skip_to(position[j] + poisson_words);
                    z = sample_standard_normal(stream);
                }
                electrons += sigma * z;
            }
            out[begin + j] = counts ? stored_count(adc.count(electrons), type) : electrons;
        }
    }
}

}  // namespace glint::detect
