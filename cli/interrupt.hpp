// How a command of `circles` ends on SIGINT (Ctrl-C), SIGTERM (a CI time-out, kill) or SIGHUP (a closed
// terminal): at once, leaving nothing behind.
//
// The handler removes the temporary files of the outputs being written and stops the programs writing them
// (formats::remove_temporary_files: a trace, a video and its ffmpeg, a frame, a report), erases the progress
// line of a terminal, says "circles run: interrupted by SIGINT" on stderr and exits with 128 + the signal's
// number, the status a shell gives a command that a signal ended. Files already complete (frames written
// before the signal) stay; an output written in place (a pipe, a device) has what reached it. A signal that was
// ignored when the program started (nohup, a background job of a shell without job control) stays ignored.
#pragma once

#include <string>

namespace circles::cli {

// Installs the handler for SIGINT, SIGTERM and SIGHUP; `command` ("circles run") opens its message.
// With `wind_down` (conform::interrupt, for `circles conform`), the first signal calls it instead, and the
// command ends itself as it says (stopping its programs, writing its reports); a second signal ends it at once.
// `wind_down` runs in a signal handler: it must be async-signal-safe.
void end_cleanly_on_interrupt(const std::string& command, void (*wind_down)(int) noexcept = nullptr);

}  // namespace circles::cli
