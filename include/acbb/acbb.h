/* acbb — the public API in one include: scenes (presets), the coupled run,
 * its results, the batch commands built on it, the run as JSON and the
 * FFI entry point (ffi.h). Headers beside the .c files in src/ are
 * internal. Link with `pkg-config --libs acbb`. */
#ifndef ACBB_ACBB_H
#define ACBB_ACBB_H

#include "acbb/status.h"
#include "acbb/units.h"
#include "acbb/limits.h"
#include "acbb/scene.h"
#include "acbb/set.h"
#include "acbb/schedule.h"
#include "acbb/preset_info.h"
#include "acbb/designation.h"
#include "acbb/fidelity.h"
#include "acbb/physics_profile.h"
#include "acbb/loss_kinds.h"
#include "acbb/spindle.h"
#include "acbb/sim.h"
#include "acbb/branches.h"
#include "acbb/history.h"
#include "acbb/outputs.h"
#include "acbb/measure.h"
#include "acbb/outfile.h"
#include "acbb/batch.h"
#include "acbb/sweep.h"
#include "acbb/sensitivity.h"
#include "acbb/study.h"
#include "acbb/accuracy.h"
#include "acbb/figures.h"
#include "acbb/plot.h"
#include "acbb/json.h"
#include "acbb/ffi.h"
#include "acbb/life.h"
#include "acbb/life_eval.h"
#include "acbb/preload_map.h"
#include "acbb/contact_study.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifdef __cplusplus
}
#endif

#endif
