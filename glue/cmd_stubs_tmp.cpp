#include "cli.h"
int cmd_fold(int, char **) { return 3; }
