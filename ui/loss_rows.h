/* acbb TUI — the loss rows a screen lists, from the engine's loss kinds
 * (loss_kinds.h), so a new kind shows without an edit in the screens. */
#ifndef ACBB_UI_LOSS_ROWS_H
#define ACBB_UI_LOSS_ROWS_H

#include <stddef.h>
#include "acbb/loss_kinds.h"

/* The kinds scene s switches on, in table order, into kinds[ACBB_LOSS_KINDS];
 * returns how many. */
int acbb_loss_rows(const acbb_scene *s, acbb_loss_kind *kinds);
/* A row's label: "  shear P_L W" (indented under the total). */
void acbb_loss_row_label(acbb_loss_kind k, char *buf, size_t n);

#endif
