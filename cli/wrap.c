/* Word wrapping for the CLI's text: help pages, lists, the run summary. */
#include <stdio.h>
#include <string.h>
#include "wrap.h"

size_t acbb_cli_wrap(FILE *f, const char *text, size_t col, size_t indent)
{
    while (*text) {
        size_t word = strcspn(text, " ");
        if (col > indent && col + 1 + word > 79) {
            fprintf(f, "\n%*s", (int)indent, "");
            col = indent;
        } else if (col > indent) {
            fputc(' ', f);
            col++;
        }
        fprintf(f, "%.*s", (int)word, text);
        col += word;
        text += word;
        text += strspn(text, " ");
    }
    return col;
}
