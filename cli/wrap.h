/* Word wrapping for the CLI's text (cli/wrap.c). */
#ifndef ACBB_CLI_WRAP_H
#define ACBB_CLI_WRAP_H
#include <stddef.h>
#include <stdio.h>

/* `text` word-wrapped to 79 columns, continuation lines indented by
 * `indent`; `col` is where the cursor stands. Returns the new column. */
size_t acbb_cli_wrap(FILE *f, const char *text, size_t col, size_t indent);

#endif
