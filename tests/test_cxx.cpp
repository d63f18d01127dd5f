// The public headers from C++ (issue 28 item 5): <acbb/acbb.h> compiles
// as C++ (extern "C" linkage, no C11 _Atomic in a public type), links
// against the C library, and a C++ std::atomic<int> cancel flag is the
// flag acbb polls: a run with the flag already set ends ACBB_CANCELLED,
// one without converges to the same loss as a plain C run. TAP.
// The tools headers (include/acbb/tools/, issue 27 item 5) serve the CLI
// and the TUI, not installed, but keep the same guards: all compile as
// C++ here and one of their functions links with C linkage.
#include <acbb/acbb.h>
#include <acbb/tools/accuracy.h>
#include <acbb/tools/branches.h>
#include <acbb/tools/contact_study.h>
#include <acbb/tools/designation.h>
#include <acbb/tools/fidelity.h>
#include <acbb/tools/figures.h>
#include <acbb/tools/history.h>
#include <acbb/tools/json.h>
#include <acbb/tools/life_eval.h>
#include <acbb/tools/lubricant.h>
#include <acbb/tools/measure.h>
#include <acbb/tools/outfile.h>
#include <acbb/tools/physics_profile.h>
#include <acbb/tools/plot.h>
#include <acbb/tools/preload_map.h>
#include <acbb/tools/preset_info.h>
#include <acbb/tools/scene_edit.h>
#include <acbb/tools/scene_inactive.h>
#include <acbb/tools/scene_schema.h>
#include <acbb/tools/schedule.h>
#include <acbb/tools/sensitivity.h>
#include <acbb/tools/set.h>
#include <acbb/tools/study.h>
#include <acbb/tools/surroundings.h>
#include <acbb/tools/sweep.h>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>

static int n = 0, failed = 0;
static void ok(bool c, const char *what)
{
    std::printf("%s %d - %s\n", c ? "ok" : "not ok", ++n, what);
    if (!c) failed++;
}

static acbb_status run(const acbb_scene *s, const acbb_atomic_int *flag, double *total)
{
    acbb_sim *sim = nullptr;
    acbb_error err = {};
    acbb_sim_opts opts = {};
    opts.cancel = flag;
    acbb_status rc = acbb_sim_create(s, &opts, &sim, &err);
    if (rc == ACBB_OK) {
        acbb_run_ctl ctl = {nullptr, nullptr, flag};
        rc = acbb_sim_drive(sim, &ctl);
        acbb_snapshot *snap = new acbb_snapshot();
        acbb_sim_snapshot(sim, snap);
        *total = snap->losses.total;
        delete snap;
    }
    acbb_sim_free(sim);
    return rc;
}

int main()
{
    acbb_scene s;
    acbb_error err = {};
    ok(acbb_scene_load("presets/7008C.ini", &s, &err) == ACBB_OK, "7008C loads from C++");
    s.heating = false; // isothermal: one mechanics solve, quick
    std::atomic<int> flag(0);
    double P = NAN, P_cancel = NAN;
    ok(run(&s, &flag, &P) == ACBB_OK && std::isfinite(P) && P > 0.0,
       "an isothermal run converges with a C++ flag left clear");
    flag.store(1);
    acbb_status rc = run(&s, &flag, &P_cancel);
    ok(rc == ACBB_CANCELLED, "the same run with the C++ flag set ends ACBB_CANCELLED");
    double v[3] = {3.0, 1.0, 2.0};
    ok(acbb_median(v, 3) == 2.0, "a tools function (acbb_median, acbb/tools/measure.h) links from C++");
    // A key set by name through the core (scene.h), read back through the
    // key table the editors use (acbb/tools/scene_schema.h).
    size_t k = 0;
    while (k < acbb_scene_field_count() && std::strcmp(acbb_scene_field(k)->key, "inner_speed_rpm"))
        k++;
    char buf[64] = "";
    ok(acbb_scene_set(&s, "operating.inner_speed_rpm", "12000", &err) == ACBB_OK
           && k < acbb_scene_field_count()
           && (acbb_scene_field_format(&s, k, buf, sizeof buf), !std::strcmp(buf, "12000")),
       "a key set by name (scene.h) reads back through the key table (tools/scene_schema.h)");
    std::printf("1..%d\n", n);
    return failed ? 1 : 0;
}
