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
#include <filesystem>
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

namespace {

// The text of <pre id="out"> in Chromium's --dump-dom output, its HTML escapes undone.
bool page_output(const std::string &dom, std::string *text) {
  const std::string open = "<pre id=\"out\">";
  const size_t a = dom.find(open);
  if (a == std::string::npos) return false;
  const size_t b = dom.find("</pre>", a);
  if (b == std::string::npos) return false;
  const std::string raw = dom.substr(a + open.size(), b - a - open.size());
  text->clear();
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] != '&') {
      *text += raw[i];
      continue;
    }
    static const std::pair<const char *, char> kEsc[] = {{"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}, {"&quot;", '"'},
                                                         {"&#39;", '\''}, {"&nbsp;", ' '}};
    bool done = false;
    for (const auto &e : kEsc) {
      const size_t n = strlen(e.first);
      if (raw.compare(i, n, e.first) == 0) {
        *text += e.second;
        i += n - 1;
        done = true;
        break;
      }
    }
    if (!done) *text += '&';
  }
  return true;
}

}  // namespace

bool chromium_run_page(const std::vector<std::pair<std::string, std::string>> &files, const std::string &html,
                       int timeout_s, std::string *text, std::string *err) {
  const char *tmp = getenv("TMPDIR");
  std::string dir = std::string(tmp && *tmp ? tmp : "/tmp") + "/tiershade_webgl.XXXXXX";
  if (!mkdtemp(&dir[0])) {
    *err = dir + ": " + strerror(errno);
    return false;
  }
  struct Cleanup {
    std::string d;
    ~Cleanup() {
      std::error_code ec;
      std::filesystem::remove_all(d, ec);
    }
  } cleanup{dir};
  for (const auto &f : files) {
    std::ofstream o(dir + "/" + f.first, std::ios::binary);
    o << f.second;
    if (!o.good()) {
      *err = dir + "/" + f.first + ": cannot write";
      return false;
    }
  }
  std::string dom;
  if (!chromium_dump_dom(dir + "/" + html, dir, timeout_s, &dom, err)) return false;
  if (!page_output(dom, text)) {
    *err = "the page " + html + " wrote no <pre id=\"out\"> (Chromium's DOM is " + std::to_string(dom.size()) + " bytes)";
    return false;
  }
  return true;
}
