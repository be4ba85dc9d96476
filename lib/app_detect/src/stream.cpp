// SPDX-License-Identifier: Apache-2.0
// glint-detect's line loop (stream.h). Blocks of lines are double-buffered: while the
// threads convert block k, the calling thread first writes block k − 1 and reads block k + 1,
// then joins the conversion; lines are handed out one at a time from an atomic counter.
// Each line's output depends only on its own input and key, so the bytes do not depend on
// which thread converted it.
#include "stream.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

#include "glint/core/error.h"

namespace glint::app_detect::internal {
namespace {

constexpr std::size_t kLinesPerThread = 32;
constexpr std::size_t kMaxBlockBytes = 64u << 20;  // input + output values of one block

/// The first failure seen by one thread: the line it happened on and the exception.
struct Failure {
    std::size_t line = 0;
    std::exception_ptr error;
};

/// One block of lines: its first line, its count, and its input and output values.
struct Block {
    std::size_t first = 0;
    std::size_t count = 0;
    std::vector<double> in;
    std::vector<double> out;
};

}  // namespace

void stream_lines(io::EnviReader& reader, io::EnviWriter& writer,
                  const detect::DetectionChain& chain, const CaptureMap& map, unsigned threads,
                  Context& ctx) {
    const std::size_t lines = reader.header().lines;
    const std::size_t in_values = chain.input_values_per_line();
    const std::size_t out_values = chain.output_values_per_line();
    unsigned workers = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    const std::size_t line_bytes = (in_values + out_values) * sizeof(double);
    const std::size_t memory_lines = std::max<std::size_t>(1, kMaxBlockBytes / 2 / line_bytes);
    const std::size_t block_lines =
        std::max<std::size_t>(1, std::min({lines, memory_lines, workers * kLinesPerThread}));
    workers = static_cast<unsigned>(std::min<std::size_t>(workers, block_lines));

    Block blocks[2];
    for (Block& b : blocks) {
        b.in.resize(block_lines * in_values);
        b.out.resize(block_lines * out_values);
    }
    auto read_block = [&](Block& b, std::size_t first) {
        b.first = first;
        b.count = std::min(block_lines, lines - first);
        for (std::size_t i = 0; i < b.count; ++i) {
            reader.read_line(first + i, std::span<double>(b.in).subspan(i * in_values, in_values));
        }
    };
    auto write_block = [&](const Block& b) {
        for (std::size_t i = 0; i < b.count; ++i) {
            writer.write_line(std::span<const double>(b.out).subspan(i * out_values, out_values));
        }
        ctx.progress.update("detect", b.first + b.count, lines);
    };

    std::vector<Failure> failures(workers);
    const std::size_t block_count = (lines + block_lines - 1) / block_lines;
    read_block(blocks[0], 0);
    for (std::size_t k = 0; k < block_count; ++k) {
        ctx.cancel.throw_if_cancelled();
        Block& current = blocks[k % 2];
        Block& other = blocks[(k + 1) % 2];
        std::atomic<std::size_t> next{0};
        auto convert = [&](unsigned worker) {
            for (std::size_t i = next.fetch_add(1); i < current.count; i = next.fetch_add(1)) {
                const std::size_t y = current.first + i;
                try {
                    const detect::LineKey key{map.indices[y / map.lines_per_capture],
                                              map.first_line + y % map.lines_per_capture};
                    chain.process_line(
                        key, std::span<const double>(current.in).subspan(i * in_values, in_values),
                        std::span<double>(current.out).subspan(i * out_values, out_values));
                } catch (...) {
                    Failure& f = failures[worker];
                    if (!f.error || y < f.line) f = {y, std::current_exception()};
                }
            }
        };
        std::vector<std::thread> pool;
        pool.reserve(workers - 1);
        try {
            for (unsigned w = 1; w < workers; ++w) pool.emplace_back(convert, w);
            // The calling thread's I/O overlaps the others' conversion, then it converts too.
            if (k > 0) write_block(other);
            if (k + 1 < block_count) read_block(other, (k + 1) * block_lines);
        } catch (...) {
            next.store(current.count);  // stop the conversion, then report the I/O error
            for (std::thread& t : pool) t.join();
            throw;
        }
        convert(0);
        for (std::thread& t : pool) t.join();

        const Failure* first_failure = nullptr;
        for (const Failure& f : failures) {
            if (f.error && (first_failure == nullptr || f.line < first_failure->line)) {
                first_failure = &f;
            }
        }
        if (first_failure != nullptr) {
            const std::size_t line = first_failure->line;
            try {
                std::rethrow_exception(first_failure->error);
            } catch (const Error& e) {
                throw Error(e.category(), "line " + std::to_string(line) + ", " + e.message(),
                            e.context());
            }
        }
    }
    if (block_count > 0) write_block(blocks[(block_count - 1) % 2]);
    ctx.progress.finish("detect", lines);
}

}  // namespace glint::app_detect::internal
