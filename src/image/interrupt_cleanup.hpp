// No signal that ends clrt may leave an AtomicFile's temporary behind. SIGINT, SIGTERM, SIGHUP,
// SIGQUIT, SIGALRM, SIGPIPE, SIGUSR1, SIGUSR2 and SIGXFSZ are blocked in every thread and taken
// by one thread of ours with sigwait(), which removes every temporary that exists at that
// moment, then ends the process by the same signal with its default action, so a shell sees the
// conventional status (128 + the signal's number) and stops a loop running it. One ignored when
// the process starts (nohup ignores SIGHUP) stays ignored.
//
// Why a thread rather than handlers: LLVM, inside PoCL, installs handlers of its own for most of
// these signals whenever it compiles (which PoCL also does in the middle of a render) and then
// swallows SIGQUIT, SIGUSR1 and SIGXFSZ. A blocked signal never reaches any handler, whoever
// installed it, so sigwait() gets it.
#pragma once

#include <functional>
#include <string>

namespace clrt {

// Blocks the signals and starts the thread (once per process; later calls do nothing). Call it
// first thing in main(), before any thread exists: threads inherit the blocked set.
void remove_temporaries_on_signal();

// A failed write may have raised SIGPIPE (a pipe without reader) or SIGXFSZ (past the file size
// limit) for the writing thread, where it waits, blocked. If one does, ends the process by it as
// the thread would have; otherwise returns. Call it before reporting a failure.
void end_by_pending_signal();

// Whether a first SIGINT or SIGTERM asks to stop (true) or ends the process (false, as at start).
void accept_stop_requests(bool accept);
// The signal that asked to stop, or 0.
int stop_request();
// Ends the process by the signal that asked to stop, removing any temporary; returns at once
// when none did.
void end_by_stop_request();

// For the tests that stop a render: when CLRT_TEST_HOLD_AFTER_ROUND is "K:FIFO" and
// `rounds_done` is K (the rounds of samples clrt has run, over every frame), writes "round K"
// and a newline to the FIFO, then waits until a stop is requested. Otherwise does nothing.
void hold_after_round_for_tests(unsigned rounds_done);

namespace image_detail {

// Runs `step`, which creates, renames or removes the temporary at `path` and returns whether the
// temporary exists afterwards, while no signal can end the process; the temporaries removed on a
// signal are exactly those that exist. Safe from any thread.
void change_temporary(const std::string& path, const std::function<bool()>& step);

// For the test that signals clrt in the middle of a write: when CLRT_TEST_HOLD_BEFORE_COMMIT
// names a FIFO, writes `temp_path` and a newline to it, then waits for a signal forever.
// Without the variable it does nothing.
void hold_before_commit_for_tests(const std::string& temp_path);

}  // namespace image_detail
}  // namespace clrt
