/* acbb — the type of the cancel flags the long computations poll: C11's
 * atomic_int in C, std::atomic<int> in C++ (the same object on every
 * compiler acbb supports: GCC and Clang lay std::atomic<int> out as
 * _Atomic int), so a C++ host can include the public headers and pass its
 * own flag. The caller owns the flag; acbb only reads it. */
#ifndef ACBB_CANCEL_FLAG_H
#define ACBB_CANCEL_FLAG_H

#ifdef __cplusplus
#include <atomic>
typedef std::atomic<int> acbb_atomic_int;
#else
#include <stdatomic.h>
typedef atomic_int acbb_atomic_int;
#endif

#endif
