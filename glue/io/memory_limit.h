// tiershade io: the process's memory limit for what input files ask for (docs/reliability.md).
// Readers compute what an input will take from its header (an image's w x h, an accessor's
// count) and ask here before they allocate, so a small hostile file cannot make the process
// take gigabytes. The limit is 1024 MiB unless a command sets another (`render --max-memory`).
#pragma once
#include <string>

constexpr long long kDefaultMemoryLimitMiB = 1024;

void set_memory_limit_mib(long long mib);
long long memory_limit_mib();

// True when `bytes` fit in the limit; else *why = "<what> needs N MiB, over the memory limit of
// M MiB (raise it with --max-memory MIB)" and false.
bool memory_fits(double bytes, const std::string &what, std::string *why);

// A regular file of at most max_bytes, or *why says what it is ("not a regular file (a FIFO)",
// "cannot open: ...", "file of N bytes, more than the limit of M") and false. Special files
// (FIFOs, devices such as /dev/zero, directories) would block or never end: they are refused
// before they are opened. *size gets the file's size.
bool regular_file_within(const std::string &path, long long max_bytes, long long *size, std::string *why);
