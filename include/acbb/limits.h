/* acbb — engine limits, defined once. */
#ifndef ACBB_LIMITS_H
#define ACBB_LIMITS_H

#ifdef __cplusplus
extern "C" {
#endif

#define ACBB_MAX_BALLS 64      /* balls per bearing */
#define ACBB_MAX_NODES 48      /* thermal network nodes */
#define ACBB_MAX_SET 4         /* bearings in a set (MODEL.md 14) */

#ifdef __cplusplus
}
#endif

#endif
