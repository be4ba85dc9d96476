// SPDX-License-Identifier: Apache-2.0
// Cooperative cancellation: long-running library code polls a CancelToken and unwinds with
// a `cancelled` glint::Error, so that destructors remove half-written outputs.
#pragma once

#include <atomic>
#include <memory>

namespace glint {

/// A shared flag that the tool runner raises on SIGINT. Copies observe the same flag.
class CancelToken {
public:
    CancelToken() : m_flag(std::make_shared<std::atomic<bool>>(false)) {}

    bool cancelled() const { return m_flag->load(std::memory_order_relaxed); }
    void cancel() const { m_flag->store(true, std::memory_order_relaxed); }
    /// Throws glint::Error(cancelled, "interrupted") once the flag is raised.
    void throw_if_cancelled() const;
    /// The flag itself, for the tool runner's signal handler (lock-free atomic store).
    std::atomic<bool>* flag_for_signal_handler() const { return m_flag.get(); }

private:
    std::shared_ptr<std::atomic<bool>> m_flag;
};

}  // namespace glint
