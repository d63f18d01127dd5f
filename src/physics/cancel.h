/* acbb — the one test of a caller's cancel flag (acbb_run_ctl.cancel,
 * acbb_batch_opts.cancel): NULL never cancels. Internal. */
#ifndef ACBB_CANCEL_H
#define ACBB_CANCEL_H

#include <stdatomic.h>

static inline int acbb_cancelled(const atomic_int *cancel)
{
    return cancel && atomic_load_explicit(cancel, memory_order_relaxed);
}

#endif
