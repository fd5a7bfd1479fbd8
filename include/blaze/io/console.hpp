// Console output of the programs: stdout line-buffered, so a run that is killed (SIGKILL, a job
// scheduler's time limit, an out-of-memory kill) has printed every line it reached: the banner,
// notes, warnings and the guard's report. By default stdout into a file or a pipe is block-buffered
// and a killed run lost up to 4 KiB of it. stderr (errors, the progress line) is unbuffered.
#pragma once
#include <cstdio>

namespace blaze {

inline void line_buffered_output() { std::setvbuf(stdout, nullptr, _IOLBF, 0); }

}  // namespace blaze
