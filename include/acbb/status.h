/* acbb — status codes shared by every engine module.
 * Functions return an acbb_status: 0 is success, negative values are named
 * failures. A human message, where one exists, travels in an acbb_error. */
#ifndef ACBB_STATUS_H
#define ACBB_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    ACBB_OK = 0,
    ACBB_EINVAL = -1,        /* bad input value, file:line message in acbb_error */
    ACBB_EIO = -2,           /* file could not be read or written */
    ACBB_ENOMEM = -3,        /* allocation failed */
    ACBB_ILL_POSED = -4,     /* physically ill-posed scene (MODEL.md section 11) */
    ACBB_DIVERGED = -5,      /* a Newton/Brent solve did not converge */
                             /* ... or the steady polish (damped, capped; issue 18) */
    ACBB_RUNAWAY = -6,       /* thermal runaway: temperature or pressure limit */
    ACBB_CONTACT_LOST = -7,  /* every ball unloaded: no equilibrium */
    ACBB_NOT_CONVERGED = -8, /* step or time limit reached before steady state */
    ACBB_NONFINITE = -9,     /* a NaN/Inf was caught before publication */
    ACBB_SINGULAR = -10,     /* a linear system could not be factorised */
    ACBB_CANCELLED = -11,    /* the caller asked a long computation to stop */
    ACBB_UNBALANCED = -12,   /* the steady heat balance did not close (ACBB_BALANCE_TOL) */
    ACBB_WALL_LIMIT = -13    /* fidelity.max_wall_s of computing reached: last good state kept */
} acbb_status;

/* A converged run's network heat balance |in - out| must be within this
 * fraction of the heat in (MODEL.md 12 item 18: steady balance to 1e-6). */
#define ACBB_BALANCE_TOL 1e-6
/* ... or within this absolute floor, W (round-off of a network carrying no heat). */
#define ACBB_BALANCE_FLOOR_W 1e-9

/* Human-readable message buffer; the caller owns it (usually on the stack). */
typedef struct {
    char msg[512];
} acbb_error;

/* Short machine name, e.g. "diverged", "runaway" (static string). */
const char *acbb_status_name(acbb_status s);

/* printf-style setter; safe with err == NULL. Returns `code` for chaining. */
acbb_status acbb_error_set(acbb_error *err, acbb_status code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#ifdef __cplusplus
}
#endif

#endif
