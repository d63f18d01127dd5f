/* acbb — status names and the error-message setter. */
#include <stdarg.h>
#include <stdio.h>
#include "acbb/status.h"

const char *acbb_status_name(acbb_status s)
{
    switch (s) {
    case ACBB_OK: return "ok";
    case ACBB_EINVAL: return "bad_input";
    case ACBB_EIO: return "io_error";
    case ACBB_ENOMEM: return "out_of_memory";
    case ACBB_ILL_POSED: return "ill_posed";
    case ACBB_DIVERGED: return "diverged";
    case ACBB_RUNAWAY: return "runaway";
    case ACBB_CONTACT_LOST: return "contact_lost";
    case ACBB_NOT_CONVERGED: return "not_converged";
    case ACBB_NONFINITE: return "nonfinite";
    case ACBB_SINGULAR: return "singular";
    case ACBB_CANCELLED: return "cancelled";
    case ACBB_UNBALANCED: return "unbalanced";
    case ACBB_WALL_LIMIT: return "wall_limit";
    }
    return "unknown";
}

acbb_status acbb_error_set(acbb_error *err, acbb_status code, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->msg, sizeof err->msg, fmt, ap);
        va_end(ap);
    }
    return code;
}
