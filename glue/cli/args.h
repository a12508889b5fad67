// tiershade cli: command-line parsing shared by the subcommands.
// Every bad argument gives "tiershade <cmd>: <what is wrong>" and exit status 2.
#pragma once
#include <map>
#include <string>
#include <vector>

struct CliError {
  std::string message;
};

class Args {
 public:
  // flags: options that take no value; opts: options that take a value.
  Args(const std::string &cmd, int argc, char **argv, const std::vector<std::string> &flags,
       const std::vector<std::string> &opts);
  bool flag(const std::string &name) const { return flags_.count(name) > 0; }
  bool has(const std::string &name) const { return opts_.count(name) > 0; }
  std::string get(const std::string &name, const std::string &def = "") const;
  std::vector<std::string> all(const std::string &name) const;
  int get_int(const std::string &name, int def, int lo, int hi) const;
  // A finite decimal number in [lo, hi] (strtod syntax, nothing after it).
  double get_number(const std::string &name, double def, double lo, double hi) const;
  const std::vector<std::string> &positional() const { return pos_; }
  // --help given: prints text (and a newline) and returns true (the command then exits 0).
  bool help(const char *text) const;
  // Fails with "unexpected argument 'X'" on the first positional argument, if any.
  void no_positional() const;
  [[noreturn]] void fail(const std::string &msg) const;
  const std::string &cmd() const { return cmd_; }

 private:
  std::string cmd_;
  std::map<std::string, int> flags_;
  std::multimap<std::string, std::string> opts_;
  std::vector<std::string> pos_;
};

// Parses "WxH" strictly: two decimal integers (digits only: no sign, spaces or other text)
// joined by 'x' or 'X', each in [lo, hi]; overflow is refused. False on anything else.
bool parse_wxh(const std::string &s, int lo, int hi, int *w, int *h);

// Subcommands (glue/cmd_*.cpp). Each returns the process exit status.
int cmd_variants(int argc, char **argv);
int cmd_budget(int argc, char **argv);
int cmd_conform(int argc, char **argv);
int cmd_probe(int argc, char **argv);
int cmd_assemble(int argc, char **argv);
int cmd_demo(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_render(int argc, char **argv);
int cmd_bake(int argc, char **argv);
int cmd_light(int argc, char **argv);
int cmd_fold(int argc, char **argv);
int cmd_lut(int argc, char **argv);
int cmd_check_bundle(int argc, char **argv);
int cmd_web(int argc, char **argv);
