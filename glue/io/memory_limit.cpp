// tiershade io: the memory limit for inputs and the regular-file check (io/memory_limit.h).
#include "io/memory_limit.h"

#include <sys/stat.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>

namespace {
std::atomic<long long> g_limit_mib{kDefaultMemoryLimitMiB};

std::string mib(double bytes) { return std::to_string(static_cast<long long>(std::ceil(bytes / 1048576.0))); }
}  // namespace

void set_memory_limit_mib(long long v) { g_limit_mib = v; }
long long memory_limit_mib() { return g_limit_mib; }

bool memory_fits(double bytes, const std::string &what, std::string *why) {
  const double limit = static_cast<double>(g_limit_mib.load()) * 1048576.0;
  if (bytes <= limit) return true;
  if (why)
    *why = what + " needs " + mib(bytes) + " MiB, over the memory limit of " + std::to_string(g_limit_mib.load()) +
        " MiB (raise it with --max-memory MIB)";
  return false;
}

bool regular_file_within(const std::string &path, long long max_bytes, long long *size, std::string *why) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) {
    *why = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    const char *kind = S_ISFIFO(st.st_mode)  ? "a FIFO"
        : S_ISDIR(st.st_mode)                ? "a directory"
        : S_ISCHR(st.st_mode)                ? "a character device"
        : S_ISBLK(st.st_mode)                ? "a block device"
        : S_ISSOCK(st.st_mode)               ? "a socket"
                                             : "a special file";
    *why = std::string("not a regular file (") + kind + ")";
    return false;
  }
  if (st.st_size > max_bytes) {
    *why = "file of " + std::to_string(static_cast<long long>(st.st_size)) + " bytes, more than the limit of " +
        std::to_string(max_bytes) + " bytes";
    return false;
  }
  if (size) *size = static_cast<long long>(st.st_size);
  return true;
}
