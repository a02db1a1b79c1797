// When processes started, from the kernel's record (/proc/PID/stat): the render job reports
// its time to the first pass from its own start (so the dynamic loader and static initialisers
// count), and atomic files tell a dead writer's temporaries from a live one's.
#pragma once

namespace penumbra {

// When process PID started, in clock ticks since boot (/proc/PID/stat field 22), or -1 when
// unknown.
double processStartTicks(long pid);

// Milliseconds since this process started (its start against CLOCK_BOOTTIME; known to a clock
// tick, 10 ms on Linux), or -1 when unknown.
double processAgeMs();

}  // namespace penumbra
