/* acbb — engine limits, defined once. */
#ifndef ACBB_LIMITS_H
#define ACBB_LIMITS_H

#define ACBB_MAX_BALLS 64      /* balls per bearing */
#define ACBB_MAX_NODES 48      /* thermal network nodes */

#endif
