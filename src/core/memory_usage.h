#pragma once
// How much memory the process holds, for reports that show whether repeated work leaks.
#include <cstdint>

namespace hipr {

// Resident set size in bytes (Linux: /proc/self/statm); 0 where it cannot be read.
uint64_t resident_bytes();
// The most the process has held at once so far (Linux: getrusage's ru_maxrss); 0 where unknown.
uint64_t peak_resident_bytes();

}  // namespace hipr
