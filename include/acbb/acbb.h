/* acbb — the public API in one include (the core): scenes (presets), the
 * coupled run and its snapshot, its results by name, a pool of runs, the
 * statuses, the units and the FFI entry point (ffi.h). The tools in
 * acbb/tools/ (study, accuracy, figures, plots, the JSON writer, sweeps,
 * the preset key table and the editors' preset writer, ...) serve the CLI
 * and the TUI: not installed, not exported, not a stable API. Headers
 * beside the .c files in src/ are internal. Link with `pkg-config --libs
 * acbb`. */
#ifndef ACBB_ACBB_H
#define ACBB_ACBB_H

#include "acbb/status.h"
#include "acbb/units.h"
#include "acbb/limits.h"
#include "acbb/cancel_flag.h"
#include "acbb/scene.h"
#include "acbb/loss_kinds.h"
#include "acbb/spindle.h"
#include "acbb/life.h"
#include "acbb/sim.h"
#include "acbb/outputs.h"
#include "acbb/batch.h"
#include "acbb/ffi.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifdef __cplusplus
}
#endif

#endif
