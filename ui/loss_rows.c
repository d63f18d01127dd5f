/* acbb TUI — the loss rows a screen lists (see loss_rows.h). */
#include <stdio.h>
#include "loss_rows.h"

int acbb_loss_rows(const acbb_scene *s, acbb_loss_kind *kinds)
{
    int n = 0;
    for (int k = 0; k < ACBB_LOSS_KINDS; k++)
        if (acbb_loss_enabled(s, (acbb_loss_kind)k)) kinds[n++] = (acbb_loss_kind)k;
    return n;
}

void acbb_loss_row_label(acbb_loss_kind k, char *buf, size_t n)
{
    snprintf(buf, n, "  %s %s W", acbb_loss_name(k), acbb_loss_symbol(k));
}
