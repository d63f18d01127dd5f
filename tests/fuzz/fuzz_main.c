/* libFuzzer harness, built twice (tests/fuzz/meson.build): with
 * -DACBB_FUZZ_TARGET=acbb_fuzz_preset the input is a preset file
 * (acbb_scene_load), with acbb_fuzz_set it is `--set` edits
 * (acbb_scene_apply_edits, acbb_scene_set). Only with clang and
 * -Dfuzz=true. A broken invariant (fuzz_entry.h) aborts, which libFuzzer
 * reports as a crash. */
#include <stdio.h>
#include <stdlib.h>
#ifdef ACBB_FUZZ_HEADER
#include ACBB_FUZZ_HEADER
#else
#include "fuzz_entry.h"
#endif

#ifndef ACBB_FUZZ_TARGET
#error "define ACBB_FUZZ_TARGET (acbb_fuzz_preset or acbb_fuzz_set)"
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char why[1024];
    if (ACBB_FUZZ_TARGET(data, size, why, sizeof why) == ACBB_FUZZ_BROKEN) {
        fprintf(stderr, "acbb fuzz: %s\n", why);
        abort();
    }
    return 0;
}
