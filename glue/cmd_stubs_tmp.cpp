#include "cli.h"
int cmd_demo(int, char **) { return 3; }
int cmd_bench(int, char **) { return 3; }
int cmd_fold(int, char **) { return 3; }
