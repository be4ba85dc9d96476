// SPDX-License-Identifier: Apache-2.0
// run_process(): posix_spawn with an argv vector, stdin from /dev/null, a new process group,
// non-blocking pipes for the captured streams and a poll loop that watches the clock and the
// cancel token. find_program(): the PATH lookup.
#include "glint/process/process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "glint/core/error.h"

extern char** environ;  // NOLINT: POSIX declares it nowhere else

namespace glint::process {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kPollIntervalMs = 20;

/// Owns a file descriptor.
class Fd {
public:
    Fd() = default;
    explicit Fd(int fd) : m_fd(fd) {}
    ~Fd() { reset(); }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    int get() const { return m_fd; }
    bool open() const { return m_fd >= 0; }
    void reset() {
        if (m_fd >= 0) ::close(m_fd);
        m_fd = -1;
    }
    void assign(int fd) {
        reset();
        m_fd = fd;
    }

private:
    int m_fd = -1;
};

/// A pipe whose read end stays in the parent (non-blocking) and whose write end goes to the
/// child; both ends close on exec.
struct Pipe {
    Fd read_end;
    Fd write_end;
    void create() {
        int fds[2];
        if (::pipe2(fds, O_CLOEXEC) != 0) {
            const int code = errno;
            throw io_error("cannot create a pipe: " + errno_text(code));
        }
        read_end.assign(fds[0]);
        write_end.assign(fds[1]);
        ::fcntl(fds[0], F_SETFL, ::fcntl(fds[0], F_GETFL) | O_NONBLOCK);
    }
};

/// Collects the last `limit` bytes written to a stream.
struct BoundedBuffer {
    std::string text;
    std::size_t limit = 0;
    bool truncated = false;

    void append(const char* data, std::size_t size) {
        text.append(data, size);
        if (text.size() > 2 * limit + 1) trim();
    }
    void trim() {
        if (text.size() > limit) {
            text.erase(0, text.size() - limit);
            truncated = true;
        }
    }
};

/// Reads what is available on `fd` into `buffer`; closes `fd` at end of file or on error.
void drain(Fd& fd, BoundedBuffer& buffer) {
    std::array<char, 16384> chunk;
    while (fd.open()) {
        const ssize_t n = ::read(fd.get(), chunk.data(), chunk.size());
        if (n > 0) {
            buffer.append(chunk.data(), static_cast<std::size_t>(n));
        } else if (n == 0) {
            fd.reset();
        } else if (errno == EINTR) {
            continue;
        } else {
            if (errno != EAGAIN && errno != EWOULDBLOCK) fd.reset();
            return;
        }
    }
}

/// posix_spawn attributes and file actions, destroyed on scope exit.
struct SpawnSetup {
    posix_spawnattr_t attr;
    posix_spawn_file_actions_t actions;
    SpawnSetup() {
        posix_spawnattr_init(&attr);
        posix_spawn_file_actions_init(&actions);
    }
    ~SpawnSetup() {
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attr);
    }
    SpawnSetup(const SpawnSetup&) = delete;
    SpawnSetup& operator=(const SpawnSetup&) = delete;
};

/// The child's environment: the parent's with `overrides` applied, as "NAME=VALUE" strings.
std::vector<std::string> child_environment(
    const std::vector<std::pair<std::string, std::string>>& overrides) {
    std::vector<std::string> result;
    for (char** entry = environ; entry != nullptr && *entry != nullptr; ++entry) {
        const std::string_view text(*entry);
        const std::string_view name = text.substr(0, text.find('='));
        bool replaced = false;
        for (const auto& [key, value] : overrides) replaced = replaced || key == name;
        if (!replaced) result.emplace_back(text);
    }
    for (const auto& [key, value] : overrides) result.push_back(key + "=" + value);
    return result;
}

std::vector<char*> c_strings(std::vector<std::string>& strings) {
    std::vector<char*> result;
    result.reserve(strings.size() + 1);
    for (auto& s : strings) result.push_back(s.data());
    result.push_back(nullptr);
    return result;
}

/// Kills the child's group and reaps the child unless release() was called: a thrown
/// exception never leaves a running child behind.
class ChildGuard {
public:
    explicit ChildGuard(pid_t pid) : m_pid(pid) {}
    ~ChildGuard() {
        if (m_pid <= 0) return;
        ::kill(-m_pid, SIGKILL);
        int status = 0;
        while (::waitpid(m_pid, &status, 0) < 0 && errno == EINTR) {
        }
    }
    ChildGuard(const ChildGuard&) = delete;
    ChildGuard& operator=(const ChildGuard&) = delete;
    void release() { m_pid = -1; }

private:
    pid_t m_pid;
};

bool is_executable_file(const std::filesystem::path& path) {
    struct stat info {};
    return ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
           ::access(path.c_str(), X_OK) == 0;
}

}  // namespace

std::string ProcessResult::describe() const {
    char text[160];
    if (timed_out) {
        std::snprintf(text, sizeof text, "timed out (time limit %.3g s)", timeout_s);
    } else if (signal != 0) {
        const char* name = ::strsignal(signal);
        std::snprintf(text, sizeof text, "killed by signal %d (%s)", signal,
                      name != nullptr ? name : "unknown");
    } else {
        std::snprintf(text, sizeof text, "exited with status %d", exit_code);
    }
    return text;
}

std::optional<std::filesystem::path> find_program(std::string_view name, const char* path_env) {
    if (name.empty()) return std::nullopt;
    if (name.find('/') != std::string_view::npos) {
        std::filesystem::path path{std::string(name)};
        if (is_executable_file(path)) return path;
        return std::nullopt;
    }
    const char* path = path_env != nullptr ? path_env : std::getenv("PATH");
    const std::string_view dirs = path != nullptr ? std::string_view(path) : "/usr/bin:/bin";
    std::size_t begin = 0;
    while (begin <= dirs.size()) {
        std::size_t end = dirs.find(':', begin);
        if (end == std::string_view::npos) end = dirs.size();
        const std::string_view dir = dirs.substr(begin, end - begin);
        const std::filesystem::path candidate =
            std::filesystem::path(dir.empty() ? std::string(".") : std::string(dir)) /
            std::string(name);
        if (is_executable_file(candidate)) return candidate;
        begin = end + 1;
    }
    return std::nullopt;
}

ProcessResult run_process(const ProcessOptions& options) {
    if (options.argv.empty() || options.argv.front().empty()) {
        throw usage_error("no program to run");
    }
    for (std::size_t i = 0; i < options.argv.size(); ++i) {
        // The kernel would cut the argument at the NUL: the program would see another one.
        if (options.argv[i].find('\0') != std::string::npos) {
            throw input_error((i == 0 ? std::string("the program name") : "argument " + std::to_string(i)) +
                              " holds a NUL byte, which no program can be given");
        }
    }
    const std::string& program_name = options.argv.front();
    const auto program = find_program(program_name);
    if (!program) {
        throw io_error(program_name.find('/') != std::string::npos
                           ? "program not found or not executable"
                           : "program not found on PATH",
                       program_name);
    }

    Pipe err_pipe;
    Pipe out_pipe;
    err_pipe.create();
    if (options.stdout_mode == OutputMode::capture) out_pipe.create();

    SpawnSetup setup;
    posix_spawn_file_actions_addopen(&setup.actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    if (options.stdout_mode == OutputMode::discard) {
        posix_spawn_file_actions_addopen(&setup.actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    } else if (options.stdout_mode == OutputMode::capture) {
        posix_spawn_file_actions_adddup2(&setup.actions, out_pipe.write_end.get(), STDOUT_FILENO);
    }
    posix_spawn_file_actions_adddup2(&setup.actions, err_pipe.write_end.get(), STDERR_FILENO);
    if (!options.working_directory.empty()) {
        posix_spawn_file_actions_addchdir_np(&setup.actions, options.working_directory.c_str());
    }
    sigset_t empty_mask;
    sigemptyset(&empty_mask);
    sigset_t defaults;
    sigemptyset(&defaults);
    for (int sig : {SIGINT, SIGTERM, SIGQUIT, SIGHUP, SIGPIPE, SIGCHLD, SIGUSR1, SIGUSR2, SIGALRM,
                    SIGTSTP, SIGTTIN, SIGTTOU}) {
        sigaddset(&defaults, sig);
    }
    posix_spawnattr_setsigmask(&setup.attr, &empty_mask);
    posix_spawnattr_setsigdefault(&setup.attr, &defaults);
    posix_spawnattr_setpgroup(&setup.attr, 0);
    posix_spawnattr_setflags(
        &setup.attr,
        static_cast<short>(POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF));

    std::vector<std::string> args = options.argv;
    std::vector<std::string> env = child_environment(options.environment);
    std::vector<char*> c_args = c_strings(args);
    std::vector<char*> c_env = c_strings(env);

    pid_t pid = -1;
    const int spawn_error = ::posix_spawn(&pid, program->c_str(), &setup.actions, &setup.attr,
                                          c_args.data(), c_env.data());
    if (spawn_error != 0) {
        throw io_error("cannot run program: " + errno_text(spawn_error), program_name);
    }
    ChildGuard guard(pid);
    err_pipe.write_end.reset();
    out_pipe.write_end.reset();

    ProcessResult result;
    if (options.timeout) result.timeout_s = static_cast<double>(options.timeout->count()) / 1e3;
    BoundedBuffer err_buffer{{}, options.capture_limit_bytes, false};
    BoundedBuffer out_buffer{{}, options.capture_limit_bytes, false};
    const auto start = Clock::now();
    bool kill_pending = false;
    Clock::time_point kill_at = start;
    int status = 0;

    for (;;) {
        std::array<pollfd, 2> fds{};
        nfds_t count = 0;
        if (err_pipe.read_end.open()) fds[count++] = pollfd{err_pipe.read_end.get(), POLLIN, 0};
        if (out_pipe.read_end.open()) fds[count++] = pollfd{out_pipe.read_end.get(), POLLIN, 0};
        if (::poll(count > 0 ? fds.data() : nullptr, count, kPollIntervalMs) < 0 &&
            errno != EINTR) {
            const int code = errno;
            throw io_error("poll failed: " + errno_text(code), program_name);
        }
        drain(err_pipe.read_end, err_buffer);
        drain(out_pipe.read_end, out_buffer);

        // Peek (WNOWAIT) so that the group can still be signalled before the child is reaped.
        siginfo_t info{};
        if (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) != 0) {
            if (errno != EINTR) {
                const int code = errno;
                throw io_error("waitid failed: " + errno_text(code), program_name);
            }
        } else if (info.si_pid == pid) {
            break;
        }
        if (options.cancel && options.cancel->cancelled()) {
            // ChildGuard kills the group and reaps the child while this unwinds.
            throw Error(ErrorCategory::cancelled, "interrupted while running " + program_name);
        }
        const auto now = Clock::now();
        if (options.timeout && !result.timed_out && now - start >= *options.timeout) {
            result.timed_out = true;
            ::kill(-pid, SIGTERM);
            kill_at = now + options.kill_grace;
            kill_pending = true;
        }
        if (kill_pending && now >= kill_at) {
            ::kill(-pid, SIGKILL);
            kill_pending = false;
        }
    }
    if (result.timed_out) ::kill(-pid, SIGKILL);  // whatever the child left in its group
    while (::waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            const int code = errno;
            guard.release();
            throw io_error("waitpid failed: " + errno_text(code), program_name);
        }
    }
    guard.release();

    // The child is gone; take what it (or a descendant still holding the pipe) left.
    drain(err_pipe.read_end, err_buffer);
    drain(out_pipe.read_end, out_buffer);
    err_buffer.trim();
    out_buffer.trim();

    if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    result.stderr_text = std::move(err_buffer.text);
    result.stderr_truncated = err_buffer.truncated;
    result.stdout_text = std::move(out_buffer.text);
    result.stdout_truncated = out_buffer.truncated;
    return result;
}

}  // namespace glint::process
