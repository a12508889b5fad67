// tiershade budget: capture of Mesa's ST_DEBUG=nir dump (see nir_capture.h).
#include "budget/nir_capture.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "budget/budget.h"
#include "conform/conform.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/common_interface_defs.h>
#endif

namespace {

// ---------------------------------------------------------------------------
// Emergency path: if the process dies (fatal signal, termination signal,
// sanitizer report, exit()) while fd 2 is redirected, put the real stderr back,
// copy the tail of what was captured there, and remove the temp files.  Only
// async-signal-safe calls below.
// ---------------------------------------------------------------------------
const int kSignals[] = {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT, SIGINT, SIGTERM, SIGHUP, SIGPIPE};
constexpr int kNumSignals = sizeof kSignals / sizeof kSignals[0];
constexpr off_t kTailBytes = 8192;

struct Emergency {
  volatile sig_atomic_t active = 0;
  int saved_fd = -1;  // the real stderr, dup()ed
  int capture_fd = -1;  // the temp file (also on fd 2 while active)
  char file[PATH_MAX] = {0};
  char dir[PATH_MAX] = {0};
  struct sigaction old[kNumSignals];
};
Emergency g_em;

void write_all(int fd, const char *p, size_t n) {
  while (n > 0) {
    const ssize_t w = write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return;
    p += w;
    n -= static_cast<size_t>(w);
  }
}
void write_str(int fd, const char *s) { write_all(fd, s, strlen(s)); }

void emergency_restore(const char *why) {
  if (!g_em.active) return;
  g_em.active = 0;
  const int saved_errno = errno;
  dup2(g_em.saved_fd, 2);
  write_str(2, "tiershade: ");
  write_str(2, why);
  write_str(2, " while stderr was redirected to capture Mesa's NIR dump; the last bytes written to stderr were:\n");
  struct stat st;
  if (fstat(g_em.capture_fd, &st) == 0) {
    off_t pos = st.st_size > kTailBytes ? st.st_size - kTailBytes : 0;
    char buf[1024];
    while (pos < st.st_size) {
      const ssize_t n = pread(g_em.capture_fd, buf, sizeof buf, pos);
      if (n <= 0) break;
      write_all(2, buf, static_cast<size_t>(n));
      pos += n;
    }
  }
  write_str(2, "\n(end of captured stderr)\n");
  unlink(g_em.file);
  rmdir(g_em.dir);
  errno = saved_errno;
}

void on_signal(int sig, siginfo_t *info, void *) {
  emergency_restore(sig == SIGINT || sig == SIGTERM || sig == SIGHUP || sig == SIGPIPE ? "terminated by a signal"
                                                                                       : "fatal signal");
  for (int i = 0; i < kNumSignals; ++i)
    if (kSignals[i] == sig) sigaction(sig, &g_em.old[i], nullptr);
  // A hardware fault repeats when we return, now under the previous handler (e.g. the
  // sanitizer's, which reports it).  A sent signal (kill, raise, abort) is raised again;
  // it is blocked in this handler and delivered under the previous disposition on return.
  const bool fault = sig == SIGSEGV || sig == SIGBUS || sig == SIGILL || sig == SIGFPE;
  if (!fault || !info || info->si_code <= 0) raise(sig);
}

void at_exit() { emergency_restore("the process exited"); }
#if defined(__SANITIZE_ADDRESS__)
void on_sanitizer_death() { emergency_restore("a sanitizer report ended the process"); }
#endif

void register_once() {
  static bool done = false;
  if (done) return;
  done = true;
  atexit(at_exit);
#if defined(__SANITIZE_ADDRESS__)
  __sanitizer_set_death_callback(on_sanitizer_death);
#endif
}

void block_signals(bool block, sigset_t *old) {
  sigset_t set;
  sigemptyset(&set);
  for (int s : kSignals)
    if (s != SIGSEGV && s != SIGBUS && s != SIGILL && s != SIGFPE) sigaddset(&set, s);
  if (block)
    sigprocmask(SIG_BLOCK, &set, old);
  else
    sigprocmask(SIG_SETMASK, old, nullptr);
}

std::string errno_text(const std::string &what) { return what + ": " + strerror(errno); }

// Redirects fd 2 to a temp file; end() restores it and returns what was written.
class Fd2Capture {
 public:
  ~Fd2Capture() {
    if (!armed_) return;
    // Unwinding (an exception from fn): restore, and pass on what was captured.
    std::string text, err;
    end(&text, &err);
    std::string nir, other;
    nir_split_stderr(text, &nir, &other);
    fwrite(other.data(), 1, other.size(), stderr);
  }

  bool begin(std::string *err) {
    register_once();
    const char *tmp = getenv("TMPDIR");
    const std::string dir_t = std::string(tmp && *tmp ? tmp : "/tmp") + "/tiershade_nir.XXXXXX";
    if (dir_t.size() + 16 >= sizeof g_em.dir) {
      *err = "temp directory path too long: " + dir_t;
      return false;
    }
    std::vector<char> dir(dir_t.begin(), dir_t.end());
    dir.push_back('\0');
    if (!mkdtemp(dir.data())) {
      *err = errno_text("mkdtemp " + dir_t);
      return false;
    }
    dir_ = dir.data();
    std::vector<char> file;
    const std::string file_t = dir_ + "/stderr.XXXXXX";
    file.assign(file_t.begin(), file_t.end());
    file.push_back('\0');
    fd_ = mkstemp(file.data());
    if (fd_ < 0) {
      *err = errno_text("mkstemp " + file_t);
      rmdir(dir_.c_str());
      return false;
    }
    file_ = file.data();
    fcntl(fd_, F_SETFD, FD_CLOEXEC);
    fflush(stderr);
    saved_ = fcntl(2, F_DUPFD_CLOEXEC, 3);
    if (saved_ < 0) {
      *err = errno_text("dup of fd 2");
      cleanup_files();
      return false;
    }
    // Arm the emergency path before fd 2 moves.
    g_em.saved_fd = saved_;
    g_em.capture_fd = fd_;
    snprintf(g_em.file, sizeof g_em.file, "%s", file_.c_str());
    snprintf(g_em.dir, sizeof g_em.dir, "%s", dir_.c_str());
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_sigaction = on_signal;
    sa.sa_flags = SA_SIGINFO;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < kNumSignals; ++i) sigaction(kSignals[i], &sa, &g_em.old[i]);
    g_em.active = 1;
    armed_ = true;
    if (dup2(fd_, 2) < 0) {
      const int e = errno;
      std::string ignored;
      end(nullptr, &ignored);
      errno = e;
      *err = errno_text("dup2 onto fd 2");
      return false;
    }
    return true;
  }

  // Restores fd 2 (unless the emergency path already did), reads and removes the file.
  bool end(std::string *text, std::string *err) {
    if (!armed_) return true;
    armed_ = false;
    fflush(stderr);
    sigset_t old;
    block_signals(true, &old);
    bool ok = true;
    if (g_em.active) {
      g_em.active = 0;
      if (dup2(saved_, 2) < 0) {
        ok = false;
        *err = errno_text("restoring fd 2");
      }
    }
    for (int i = 0; i < kNumSignals; ++i) sigaction(kSignals[i], &g_em.old[i], nullptr);
    block_signals(false, &old);
    close(saved_);
    saved_ = -1;
    if (text) {
      text->clear();
      char buf[65536];
      off_t pos = 0;
      for (;;) {
        const ssize_t n = pread(fd_, buf, sizeof buf, pos);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
          ok = false;
          *err = errno_text("reading the captured stderr");
        }
        if (n <= 0) break;
        text->append(buf, static_cast<size_t>(n));
        pos += n;
      }
    }
    cleanup_files();
    return ok;
  }

 private:
  void cleanup_files() {
    if (fd_ >= 0) close(fd_);
    fd_ = -1;
    if (!file_.empty()) unlink(file_.c_str());
    if (!dir_.empty()) rmdir(dir_.c_str());
    file_.clear();
    dir_.clear();
  }
  bool armed_ = false;
  int fd_ = -1, saved_ = -1;
  std::string dir_, file_;
};

bool has_fragment_section(const std::string &nir) {
  return nir.find("shader: MESA_SHADER_FRAGMENT") != std::string::npos;
}

void forward(const std::string &other) {
  if (other.empty()) return;
  fwrite(other.data(), 1, other.size(), stderr);
  fflush(stderr);
}

}  // namespace

void nir_capture_setup_env() {
  setenv("ST_DEBUG", "nir", 1);
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
}

bool capture_fd2(const std::function<void()> &fn, std::string *captured, std::string *err) {
  captured->clear();
  Fd2Capture cap;
  if (!cap.begin(err)) return false;
  fn();  // no tiershade output to stderr in here: it would be captured
  return cap.end(captured, err);
}

void nir_split_stderr(const std::string &captured, std::string *nir, std::string *other) {
  nir->clear();
  other->clear();
  enum { Out, In, After } state = Out;  // After: just past a column-0 "}"
  size_t pos = 0;
  while (pos < captured.size()) {
    size_t nl = captured.find('\n', pos);
    const size_t end = nl == std::string::npos ? captured.size() : nl + 1;
    const std::string line = captured.substr(pos, end - pos);
    pos = end;
    std::string t = line;
    while (!t.empty() && (t.back() == '\n' || t.back() == '\r')) t.pop_back();
    const bool header = t == "NIR before handing off to driver:";
    if (state == After) {
      if (t.empty()) {
        *nir += line;
        continue;
      }
      state = (header || t.rfind("impl ", 0) == 0) ? In : Out;  // another function of the shader
    }
    if (state == Out && header) state = In;
    if (state == Out) {
      *other += line;
      continue;
    }
    *nir += line;
    if (t == "}") state = After;
  }
}

bool nir_count_production(GlRenderer &r, Api api, const Variant &v, NirCounts *out, std::string *err) {
  *out = NirCounts();
  std::string build_err, captured, nir, other;
  GLuint prog = 0;
  if (!capture_fd2([&] { prog = build_production_program(r, api, v, &build_err); }, &captured, err)) return false;
  nir_split_stderr(captured, &nir, &other);
  forward(other);
  if (!prog) {
    *err = build_err;
    return false;
  }
  out->printed_at = "link";
  if (!has_fragment_section(nir)) {
    // Not printed at link time: the driver compiles at the first draw.
    bool drew = false;
    std::string draw_err, nir2;
    const bool cap_ok = capture_fd2(
        [&] {
          ImageF img;
          drew = r.draw(prog, {}, 1, 1, &img, &draw_err);
        },
        &captured, err);
    r.delete_program(prog);
    if (!cap_ok) return false;
    nir_split_stderr(captured, &nir2, &other);
    forward(other);
    if (!drew) {
      *err = "drawing to trigger the NIR dump: " + draw_err;
      return false;
    }
    nir += nir2;
    out->printed_at = "draw";
  } else {
    r.delete_program(prog);
  }
  out->dump_bytes = nir.size();
  if (!has_fragment_section(nir)) {
    const char *st = getenv("ST_DEBUG");
    *err = std::string("Mesa printed no fragment NIR while linking and drawing the program (ST_DEBUG=") +
        (st ? st : "<unset>") + "); ST_DEBUG=nir must be set before the process creates its first GL context";
    return false;
  }
  return budget_count_nir_text(nir, &out->alu, &out->tex, err);
}
