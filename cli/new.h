/* acbb CLI — `acbb new DESIGNATION`: the handler (cli/new.c). */
#ifndef ACBB_CLI_NEW_H
#define ACBB_CLI_NEW_H

#include "args.h"

int acbb_cli_cmd_new(const acbb_cli_args *a);

#endif
