// tiershade browser: running headless Chromium (see chromium.h).
#include "browser/chromium.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

namespace {

bool executable(const std::string &p) {
  struct stat st;
  return stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && access(p.c_str(), X_OK) == 0;
}

std::string read_all(const std::string &path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::string tail_lines(const std::string &s, int n) {
  size_t pos = s.size();
  for (int k = 0; k <= n && pos > 0; ++k) {
    const size_t p = s.rfind('\n', pos - 1);
    if (p == std::string::npos) return s;
    pos = p;
  }
  return s.substr(pos + 1);
}

}  // namespace

bool find_chromium(std::string *path, std::string *err) {
  if (const char *env = getenv("TIERSHADE_CHROMIUM")) {
    if (executable(env)) {
      *path = env;
      return true;
    }
    *err = std::string("$TIERSHADE_CHROMIUM (") + env + ") is not an executable file";
    return false;
  }
  const char *pathvar = getenv("PATH");
  std::string dirs = pathvar ? pathvar : "/usr/bin:/bin";
  for (const char *name : {"chromium", "chromium-browser"}) {
    std::istringstream ss(dirs);
    std::string d;
    while (std::getline(ss, d, ':')) {
      if (d.empty()) continue;
      const std::string p = d + "/" + name;
      if (executable(p)) {
        *path = p;
        return true;
      }
    }
  }
  *err = "no Chromium found (chromium or chromium-browser on PATH, or $TIERSHADE_CHROMIUM): make deps installs it";
  return false;
}

bool chromium_dump_dom(const std::string &html, const std::string &scratch_dir, int timeout_s, std::string *dom,
                       std::string *err) {
  std::string exe;
  if (!find_chromium(&exe, err)) return false;
  const std::string profile = scratch_dir + "/profile", out_path = scratch_dir + "/dom.txt",
                    err_path = scratch_dir + "/chromium.log";
  if (mkdir(profile.c_str(), 0700) != 0 && errno != EEXIST) {
    *err = profile + ": " + strerror(errno);
    return false;
  }
  std::vector<std::string> args = {exe,
                                   "--headless=new",
                                   "--no-sandbox",
                                   "--use-angle=swiftshader",
                                   "--enable-unsafe-swiftshader",
                                   "--disable-gpu-sandbox",
                                   "--disable-background-networking",
                                   "--disable-component-update",
                                   "--disable-sync",
                                   "--no-first-run",
                                   "--user-data-dir=" + profile,
                                   "--dump-dom",
                                   "file://" + html};
  std::vector<char *> argv;
  for (auto &a : args) argv.push_back(&a[0]);
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    *err = std::string("fork: ") + strerror(errno);
    return false;
  }
  if (pid == 0) {
    setpgid(0, 0);  // its own process group: the timeout kills the browser's helpers too
    const int o = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int e = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int in = open("/dev/null", O_RDONLY);
    if (o < 0 || e < 0 || in < 0) _exit(126);
    dup2(in, 0);
    dup2(o, 1);
    dup2(e, 2);
    execv(argv[0], argv.data());
    _exit(127);
  }
  setpgid(pid, pid);
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  for (;;) {
    const pid_t r = waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) {
      *err = std::string("waitpid: ") + strerror(errno);
      kill(-pid, SIGKILL);
      return false;
    }
    if (std::chrono::steady_clock::now() - t0 > std::chrono::seconds(timeout_s)) {
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      *err = exe + " did not finish " + html + " within " + std::to_string(timeout_s) + " s (killed)";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(-pid, SIGKILL);  // whatever the browser left behind
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    *err = exe + " on " + html + ": " +
           (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                              : "killed by signal " + std::to_string(WTERMSIG(status))) +
           "; its stderr ends:\n" + tail_lines(read_all(err_path), 8);
    return false;
  }
  *dom = read_all(out_path);
  return true;
}
