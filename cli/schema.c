/* acbb CLI — `acbb schema`: the JSON Schema of the JSON documents
 * (docs/schema/acbb.schema.json, installed to DATADIR/acbb/schema/),
 * compiled in by meson (schema_text.c) so the binary prints the very file
 * it was built with, wherever it is installed. */
#include <stdio.h>
#include "commands.h"
#include "common.h"

extern const char acbb_cli_schema_text[];

int acbb_cli_cmd_schema(const acbb_cli_args *a)
{
    (void)a;
    fputs(acbb_cli_schema_text, stdout);
    return acbb_cli_stdout_check(0);
}
