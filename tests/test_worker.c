/* Tests of the TUI's curses-free parts: the worker thread hand-off (also
 * run under ThreadSanitizer), the layout function for several terminal
 * sizes, the progress estimate, the chart raster and the editor model;
 * the accuracy screen's pieces: the engine's cancel hook, the benchmark
 * thread (bench.c) and the log-log chart model (acc_chart.c). */
#include <dirent.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <time.h>
#include <unistd.h>

#include "tap.h"
#include "acc_chart.h"
#include "bench.h"
#include "chart.h"
#include "editor.h"
#include "layout.h"
#include "progress.h"
#include "worker.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void sleep_ms(int ms)
{
    struct timespec ts = { ms / 1000, (long)(ms % 1000) * 1000000L };
    nanosleep(&ts, NULL);
}

/* ---- layout ---- */

static void check_layout(int rows, int cols)
{
    acbb_layout l;
    int rc = acbb_layout_compute(rows, cols, &l);
    ok(rc == 0 && !l.too_small, "%dx%d: usable", cols, rows);
    ok(l.title.y == 0 && l.title.h == 1 && l.body.y == 1 && l.body.h == rows - 3 &&
           l.status.y == rows - 2 && l.message.y == rows - 1,
       "%dx%d: title, body, status, message stack over all %d rows", cols, rows, rows);
    const acbb_rect p[4] = { l.temps, l.losses, l.mech, l.chart };
    int inside = 1, apart = 1, area = 0;
    for (int i = 0; i < 4; i++) {
        inside &= acbb_rect_inside(p[i], rows, cols) && p[i].y >= l.body.y &&
                  p[i].y + p[i].h <= l.body.y + l.body.h;
        area += p[i].h * p[i].w;
        for (int j = i + 1; j < 4; j++) apart &= !acbb_rect_overlap(p[i], p[j]);
    }
    ok(inside, "%dx%d: overview panels inside the body", cols, rows);
    ok(apart, "%dx%d: overview panels do not overlap", cols, rows);
    ok(area == l.body.h * l.body.w, "%dx%d: overview panels tile the body (%d of %d cells)", cols,
       rows, area, l.body.h * l.body.w);
    ok(l.temps.w >= 40 && l.losses.w >= 40, "%dx%d: temperature and loss panels >= 40 wide", cols, rows);
    ok(l.chart.h >= 5, "%dx%d: overview chart keeps >= 5 rows (got %d)", cols, rows, l.chart.h);
    int sum = 0, stacked = 1;
    for (int i = 0; i < ACBB_LAYOUT_CHARTS; i++) {
        sum += l.charts[i].h;
        if (i > 0) stacked &= l.charts[i].y == l.charts[i - 1].y + l.charts[i - 1].h;
    }
    ok(sum == l.body.h && stacked && l.charts[0].y == l.body.y,
       "%dx%d: history charts stack over the body", cols, rows);
    int want_cols = cols / ACBB_LAYOUT_NODE_COL_W > 4 ? 4 : cols / ACBB_LAYOUT_NODE_COL_W;
    ok(l.node_columns == want_cols && l.node_columns * ACBB_LAYOUT_NODE_COL_W <= cols,
       "%dx%d: %d node-table columns fit", cols, rows, l.node_columns);
    ok(l.table_rows == rows - 4, "%dx%d: table rows = rows - 4", cols, rows);
}

static void test_layout(void)
{
    check_layout(24, 80);
    check_layout(30, 100);
    check_layout(60, 200);
    acbb_layout l;
    /* 80x24: two columns of 40; 8-row top panels, 4-row mechanics, 9-row chart. */
    acbb_layout_compute(24, 80, &l);
    ok(l.temps.w == 40 && l.losses.x == 40 && l.mech.y == 9 && l.chart.y == 13 && l.chart.h == 9,
       "80x24: panels at the planned places");
    acbb_layout_compute(60, 200, &l);
    ok(l.mech.y == l.temps.y && l.mech.x > l.losses.x, "200x60: mechanics is a third column");
    const int small[][2] = { { 10, 40 }, { 24, 79 }, { 23, 80 }, { 0, 0 } };
    for (int i = 0; i < 4; i++) {
        int rc = acbb_layout_compute(small[i][0], small[i][1], &l);
        ok(rc == -1 && l.too_small, "%dx%d: terminal too small", small[i][1], small[i][0]);
    }
    acbb_layout_compute(10, 40, &l);
    ok(l.message.y == 9 && l.message.w == 40, "40x10: the notice row is still the bottom row");
}

/* ---- progress ---- */

static void test_progress(void)
{
    acbb_progress p;
    acbb_progress_reset(&p);
    ok(!p.valid && p.eta_s < 0, "progress: unknown before the first residual");
    acbb_progress_update(&p, 1.0, 0.0, 1e-4);
    is_close(p.fraction, 0.0, 0, 1e-15, "progress: 0 at the first residual");
    /* r: 1 -> 1e-2 in 2 s; tol 1e-4: half way on the log scale,
     * ln(1e-2/1e-4) / (ln(1/1e-2) / 2 s) = 2 s left. */
    acbb_progress_update(&p, 1e-2, 2.0, 1e-4);
    is_close(p.fraction, 0.5, 1e-12, 0, "progress: ln(1/1e-2)/ln(1/1e-4) = 0.5");
    is_close(p.eta_s, 2.0, 1e-12, 0, "progress: ETA extrapolates the log decay rate (2 s)");
    acbb_progress_update(&p, 1e-5, 5.0, 1e-4);
    ok(p.fraction == 1.0 && p.eta_s == 0.0, "progress: clamps at 1 below tolerance");
}

/* ---- chart raster ---- */

static void test_chart(void)
{
    static acbb_chart c;
    char g[8];
    const double x[2] = { 0, 1 }, y[2] = { 1, 1 };
    acbb_chart_init(&c, 2, 1, 0, 1, 0, 1);
    acbb_chart_plot(&c, x, y, 2, 0);
    /* y = ymax is the top dot row: bits 0x01 | 0x08 in both cells = U+2809. */
    ok(c.dots[0][0] == 0x09 && c.dots[0][1] == 0x09, "chart: a line at ymax lights the top dots");
    acbb_chart_cell(&c, 0, 0, 1, g);
    ok(strcmp(g, "\xe2\xa0\x89") == 0, "chart: cell drawn as braille U+2809");
    int owner = acbb_chart_cell(&c, 0, 1, 0, g);
    ok(strcmp(g, "'") == 0 && owner == 0, "chart: ASCII fallback draws top dots as ' (series 0)");
    /* A flat series widens the range by 5 % and sits mid-height:
     * dot row round(0.5 * 3) = 2 -> bits 0x04 | 0x20, ASCII '.'. */
    const double y5[2] = { 5, 5 };
    acbb_chart_init(&c, 1, 1, 0, 1, 5, 5);
    is_close(c.ymax - c.ymin, 0.5, 1e-12, 0, "chart: flat range widened by +-5 %");
    acbb_chart_plot(&c, x, y5, 2, 1);
    ok(c.dots[0][0] == 0x24, "chart: a flat line sits on dot row 2");
    acbb_chart_cell(&c, 0, 0, 0, g);
    ok(strcmp(g, ".") == 0, "chart: ASCII '.' for bottom-half dots");
    /* A diagonal is joined: every dot column of a 4x2 chart has a dot. */
    acbb_chart_init(&c, 4, 2, 0, 1, 0, 1);
    acbb_chart_plot(&c, x, x, 2, 0);
    int cols_lit = 0;
    for (int dx = 0; dx < 8; dx++) {
        int lit = 0;
        for (int row = 0; row < 2; row++)
            for (int dr = 0; dr < 4; dr++) {
                static const unsigned char bit[4][2] = { { 1, 8 }, { 2, 16 }, { 4, 32 }, { 64, 128 } };
                lit |= (c.dots[row][dx / 2] & bit[dr][dx % 2]) != 0;
            }
        cols_lit += lit;
    }
    ok(cols_lit == 8, "chart: a diagonal is drawn without gaps (%d of 8 dot columns)", cols_lit);
}

/* ---- editor model ---- */

static void test_editor(void)
{
    static acbb_editor e;
    acbb_error err = { { 0 } };
    size_t idiam = 0, iload = 0;
    for (size_t i = 0; i < acbb_scene_field_count(); i++) {
        if (strcmp(acbb_scene_field(i)->key, "ball_diameter_mm") == 0) idiam = i;
        if (strcmp(acbb_scene_field(i)->key, "axial_load_N") == 0) iload = i;
    }
    ok(acbb_editor_open(&e, "presets/7008C.ini", &err) == ACBB_OK, "editor: opens 7008C (%s)", err.msg);
    double D = e.scene.ball_diameter;
    ok(acbb_editor_set(&e, idiam, "-3", &err) == ACBB_EINVAL, "editor: ball_diameter_mm = -3 refused");
    has_substr(err.msg, "ball_diameter_mm = -3: must be > 0", "editor: the engine's message");
    ok(e.scene.ball_diameter == D && !e.modified && e.undo_n == 0,
       "editor: a refused value is not applied and not undoable");
    ok(acbb_editor_set(&e, iload, "500", &err) == ACBB_OK && e.scene.axial_load == 500.0 && e.modified,
       "editor: axial_load_N = 500 accepted, marked modified");
    ok(acbb_editor_set(&e, iload, "700", &err) == ACBB_OK && e.undo_n == 2, "editor: second edit stacked");
    ok(acbb_editor_undo(&e) && e.scene.axial_load == 500.0 && e.modified, "editor: undo restores 500");
    ok(acbb_editor_undo(&e) && e.scene.axial_load == 1000.0 && !e.modified,
       "editor: undo back to the file clears the marker");
    ok(!acbb_editor_undo(&e), "editor: nothing left to undo");
    acbb_editor_set(&e, iload, "450", &err);
    char path[] = "/tmp/acbb-test-editor-XXXXXX";
    int fd = mkstemp(path);
    close(fd);
    ok(acbb_editor_save(&e, path, &err) == ACBB_OK && !e.modified && strcmp(e.path, path) == 0,
       "editor: save-as writes, clears the marker, adopts the path");
    acbb_scene back;
    ok(acbb_scene_load(path, &back, &err) == ACBB_OK && back.axial_load == 450.0,
       "editor: the saved file loads back with axial_load_N = 450");
    unlink(path);
}

/* ---- worker ---- */

typedef struct {
    acbb_worker *w;
    _Atomic int stop;
    _Atomic int violations;
    _Atomic long reads;
} reader_arg;

/* Plays the UI: copies the state out in a loop and checks that within one
 * run the iteration never goes back and the history stays bounded. */
static void *reader(void *p)
{
    reader_arg *r = p;
    static acbb_worker_state st;
    static acbb_history h;
    unsigned long run = 0, pubs = 0;
    long it = -1;
    while (!atomic_load(&r->stop)) {
        acbb_worker_read(r->w, &st, &h);
        if (st.publications < pubs) atomic_fetch_add(&r->violations, 1);
        if (st.run_id == run && st.snap.iteration < it) atomic_fetch_add(&r->violations, 1);
        if (h.n > ACBB_HISTORY_CAP) atomic_fetch_add(&r->violations, 1);
        for (size_t k = 1; k < h.n; k++)
            if (h.p[k].iteration <= h.p[k - 1].iteration) {
                atomic_fetch_add(&r->violations, 1);
                break;
            }
        run = st.run_id;
        it = st.snap.iteration;
        pubs = st.publications;
        atomic_fetch_add(&r->reads, 1);
        sleep_ms(1);
    }
    return NULL;
}

static acbb_worker_state st; /* test scratch, main thread only */
static acbb_history hist;

static int wait_phase(acbb_worker *w, acbb_worker_phase p, double timeout_s)
{
    double end = now_s() + timeout_s;
    do {
        acbb_worker_read(w, &st, NULL);
        if (st.phase == p) return 1;
        sleep_ms(2);
    } while (now_s() < end);
    return 0;
}

static unsigned long post_wait(acbb_worker *w, acbb_worker_cmd c, const acbb_scene *s, int warm)
{
    unsigned long seq = acbb_worker_post(w, c, s, warm);
    if (seq == 0 || !acbb_worker_wait_done(w, seq, 10000)) return 0;
    acbb_worker_read(w, &st, &hist);
    return seq;
}

static long progress_over(acbb_worker *w, int ms)
{
    acbb_worker_read(w, &st, NULL);
    long a = st.snap.iteration;
    sleep_ms(ms);
    acbb_worker_read(w, &st, NULL);
    return st.snap.iteration - a;
}

/* SigBlk of every thread but the main one must hold INT, TERM, HUP, WINCH. */
static int worker_threads_block_signals(void)
{
    DIR *d = opendir("/proc/self/task");
    if (!d) return -1;
    struct dirent *e;
    int checked = 0, good = 1;
    pid_t self = getpid();
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.' || atol(e->d_name) == self) continue;
        char path[300], line[256];
        snprintf(path, sizeof path, "/proc/self/task/%s/status", e->d_name);
        FILE *f = fopen(path, "r");
        if (!f) continue;
        while (fgets(line, sizeof line, f))
            if (strncmp(line, "SigBlk:", 7) == 0) {
                unsigned long long m = strtoull(line + 7, NULL, 16);
                const int sigs[] = { 1, 2, 15, 28 }; /* HUP INT TERM WINCH on Linux */
                for (int i = 0; i < 4; i++) good &= (int)((m >> (sigs[i] - 1)) & 1);
                checked++;
            }
        fclose(f);
    }
    closedir(d);
    return checked ? good : -1;
}

static void test_worker_basics(const acbb_scene *s0)
{
    acbb_worker *w = NULL;
    acbb_error err = { { 0 } };
    ok(acbb_worker_new(s0, 0, &w, &err) == ACBB_OK, "worker: starts (%s)", err.msg);
    ok(wait_phase(w, ACBB_WORKER_IDLE, 10) && st.has_snapshot && st.snap.iteration == 0,
       "worker: initial Sim ready at iteration 0");
    ok(st.snap.T_outer_ring == s0->ambient_C, "worker: initial temperatures at ambient");
    int sb = worker_threads_block_signals();
    ok(sb == 1, "worker: thread blocks SIGINT/SIGTERM/SIGHUP/SIGWINCH (%d)", sb);

    /* The wake-up pipe: readable after a publication, empty once drained. */
    unsigned long seq = acbb_worker_post(w, ACBB_CMD_RESET, NULL, 0);
    acbb_worker_wait_done(w, seq, 10000);
    sleep_ms(20); /* the worker pokes the pipe just after marking the command done */
    fd_set rf;
    struct timeval tv = { 1, 0 };
    FD_ZERO(&rf);
    FD_SET(acbb_worker_wake_fd(w), &rf);
    ok(select(acbb_worker_wake_fd(w) + 1, &rf, NULL, NULL, &tv) == 1, "worker: wake fd readable after publishing");
    acbb_worker_drain_wake(w);
    tv.tv_sec = 0;
    tv.tv_usec = 50000;
    FD_ZERO(&rf);
    FD_SET(acbb_worker_wake_fd(w), &rf);
    ok(select(acbb_worker_wake_fd(w) + 1, &rf, NULL, NULL, &tv) == 0, "worker: idle worker stays quiet after drain");

    /* Flat out to steady state equals a direct acbb_sim_run of the scene. */
    acbb_sim *ref = NULL;
    acbb_snapshot rs;
    acbb_sim_new(s0, &ref, &err);
    acbb_sim_run(ref);
    acbb_sim_snapshot(ref, &rs);
    acbb_sim_free(ref);
    post_wait(w, ACBB_CMD_START, s0, 0);
    ok(wait_phase(w, ACBB_WORKER_DONE, 60), "worker: flat-out run ends");
    acbb_worker_read(w, &st, &hist);
    ok(st.snap.state == ACBB_RUN_CONVERGED, "worker: run converged (%s)", st.snap.message);
    ok(st.snap.iteration == rs.iteration && st.snap.T_outer_ring == rs.T_outer_ring &&
           st.snap.losses.total == rs.losses.total,
       "worker: same steady state as acbb_sim_run (%ld steps, T5 %.6f, P %.6f)", st.snap.iteration,
       st.snap.T_outer_ring, st.snap.losses.total);
    ok(hist.n == (size_t)rs.iteration + 1 && hist.p[hist.n - 1].iteration == rs.iteration &&
           hist.p[0].iteration == 0,
       "worker: history holds steps 0..%ld (%zu points)", rs.iteration, hist.n);

    /* Paced run: ~50 steps/s. */
    acbb_worker_set_pace(w, 50);
    ok(acbb_worker_pace(w) == 50, "worker: pace reads back");
    post_wait(w, ACBB_CMD_START, s0, 0);
    long adv = progress_over(w, 400);
    ok(adv >= 5 && adv <= 40, "worker: paced at 50/s advances %ld steps in 0.4 s", adv);
    post_wait(w, ACBB_CMD_PAUSE, NULL, 0);
    ok(st.phase == ACBB_WORKER_PAUSED, "worker: paused");
    ok(progress_over(w, 50) == 0, "worker: paused means no progress over 50 ms");
    post_wait(w, ACBB_CMD_RESUME, NULL, 0);
    ok(st.phase == ACBB_WORKER_RUNNING && progress_over(w, 200) > 0, "worker: resumed run progresses");
    /* Pause/resume does not restart: the run id is unchanged. */
    unsigned long run = st.run_id;
    post_wait(w, ACBB_CMD_STOP, NULL, 0);
    ok(st.phase == ACBB_WORKER_STOPPED && st.run_id == run, "worker: stopped, same run");
    ok(progress_over(w, 50) == 0, "worker: stopped means no progress");
    double T_hot = st.snap.T_outer_ring;

    /* Warm vs cold apply, at 1 step/s so the state right after is visible. */
    acbb_worker_set_pace(w, 1);
    acbb_scene s = *s0;
    s.axial_load = 500.0;
    post_wait(w, ACBB_CMD_APPLY, &s, 1);
    ok(st.phase == ACBB_WORKER_RUNNING && st.run_id == run + 1 && st.snap.iteration <= 1,
       "worker: apply starts a new run");
    is_close(st.snap.reaction_x, 500.0, 1e-6, 0, "worker: applied axial load visible (reaction_x)");
    ok(st.scene.axial_load == 500.0, "worker: published scene is the applied one");
    ok(fabs(st.snap.T_outer_ring - T_hot) < 0.5 && T_hot - s0->ambient_C > 0.5,
       "worker: warm apply keeps temperatures (%.3f vs %.3f)", st.snap.T_outer_ring, T_hot);
    s.axial_load = 800.0;
    post_wait(w, ACBB_CMD_APPLY, &s, 0);
    ok(fabs(st.snap.T_outer_ring - s0->ambient_C) < 0.5, "worker: cold apply starts from ambient (%.3f)",
       st.snap.T_outer_ring);
    is_close(st.snap.reaction_x, 800.0, 1e-6, 0, "worker: cold apply: reaction_x = 800 N");

    /* A bad scene is refused; the current run is untouched. */
    acbb_scene bad = *s0;
    bad.ball_diameter = -1e-3;
    run = st.run_id;
    seq = post_wait(w, ACBB_CMD_APPLY, &bad, 0);
    ok(st.err_cmd == seq && st.last_error != ACBB_OK && st.message[0] && st.run_id == run &&
           st.scene.axial_load == 800.0,
       "worker: bad scene refused (%s)", st.message);

    post_wait(w, ACBB_CMD_RESET, NULL, 0);
    ok(st.phase == ACBB_WORKER_IDLE && st.snap.iteration == 0 && hist.n == 1 &&
           st.snap.T_outer_ring == s0->ambient_C,
       "worker: reset back to ambient, iteration 0, history 1 point");

    /* TE vs WTE in the worker. */
    acbb_worker_set_pace(w, 0);
    post_wait(w, ACBB_CMD_COMPARE, s0, 0);
    double end = now_s() + 60;
    do {
        acbb_worker_read(w, &st, NULL);
        sleep_ms(5);
    } while (st.compare.phase != ACBB_CMP_DONE && now_s() < end);
    ok(st.compare.phase == ACBB_CMP_DONE && st.compare.ok[0] && st.compare.ok[1],
       "worker: TE and WTE both ran");
    ok(st.compare.snap[0].T_outer_ring == rs.T_outer_ring, "worker: TE result equals the plain run");
    ok(st.compare.snap[1].exp_outer == 0.0 && st.compare.snap[0].exp_outer > 0.0,
       "worker: WTE has no expansion, TE has");
    ok(st.phase == ACBB_WORKER_IDLE, "worker: comparison leaves the main run alone");

    /* Quitting joins promptly even from a 1 step/s wait. */
    acbb_worker_set_pace(w, 1);
    post_wait(w, ACBB_CMD_START, s0, 0);
    double t0 = now_s();
    acbb_worker_free(w);
    ok(now_s() - t0 < 0.5, "worker: free joins a paced worker promptly (%.3f s)", now_s() - t0);
}

static int phase_after_ok(acbb_worker_cmd c, acbb_worker_phase before, acbb_worker_phase after)
{
    switch (c) {
    case ACBB_CMD_START: case ACBB_CMD_APPLY:
        return after == ACBB_WORKER_RUNNING || after == ACBB_WORKER_DONE;
    case ACBB_CMD_PAUSE:
        return before == ACBB_WORKER_RUNNING ? after == ACBB_WORKER_PAUSED || after == ACBB_WORKER_DONE
                                             : after == before || after == ACBB_WORKER_DONE;
    case ACBB_CMD_RESUME:
        return before == ACBB_WORKER_PAUSED ? after == ACBB_WORKER_RUNNING || after == ACBB_WORKER_DONE
                                            : after == before || after == ACBB_WORKER_DONE;
    case ACBB_CMD_STOP:
        return (before == ACBB_WORKER_RUNNING || before == ACBB_WORKER_PAUSED)
                   ? after == ACBB_WORKER_STOPPED || after == ACBB_WORKER_DONE
                   : after == before || after == ACBB_WORKER_DONE;
    case ACBB_CMD_RESET: return after == ACBB_WORKER_IDLE;
    default: return 1;
    }
}

static void test_worker_cycles(const acbb_scene *s0, int cycles)
{
    acbb_worker *w = NULL;
    acbb_error err = { { 0 } };
    acbb_worker_new(s0, 0, &w, &err);
    wait_phase(w, ACBB_WORKER_IDLE, 10);
    reader_arg ra = { .w = w };
    atomic_init(&ra.stop, 0);
    atomic_init(&ra.violations, 0);
    atomic_init(&ra.reads, 0);
    pthread_t rt;
    pthread_create(&rt, NULL, reader, &ra);

    const acbb_worker_cmd seqc[] = { ACBB_CMD_START, ACBB_CMD_PAUSE, ACBB_CMD_RESUME, ACBB_CMD_STOP,
                                     ACBB_CMD_APPLY, ACBB_CMD_PAUSE, ACBB_CMD_APPLY, ACBB_CMD_RESET };
    int bad_phase = 0, bad_scene = 0, lost = 0, bad_hist = 0;
    for (int c = 0; c < cycles; c++) {
        acbb_worker_set_pace(w, c % 3 == 0 ? 0 : 2000);
        for (size_t k = 0; k < sizeof seqc / sizeof seqc[0]; k++) {
            acbb_scene s = *s0;
            s.axial_load = 200.0 + 100.0 * (double)((c + (int)k) % 9);
            acbb_worker_read(w, &st, NULL);
            acbb_worker_phase before = st.phase;
            int warm = (int)k == 4;
            if (!post_wait(w, seqc[k], seqc[k] == ACBB_CMD_APPLY || seqc[k] == ACBB_CMD_START ? &s : NULL,
                           warm)) {
                lost++;
                continue;
            }
            if (!phase_after_ok(seqc[k], before, st.phase)) bad_phase++;
            if ((seqc[k] == ACBB_CMD_APPLY || seqc[k] == ACBB_CMD_START) &&
                (st.scene.axial_load != s.axial_load || fabs(st.snap.reaction_x - s.axial_load) > 1e-6 * s.axial_load))
                bad_scene++;
            if (hist.n > ACBB_HISTORY_CAP || hist.n == 0) bad_hist++;
            if (k % 2 == 0) sleep_ms(1);
        }
    }
    ok(lost == 0, "cycles: every command handled within 10 s (%d lost)", lost);
    ok(bad_phase == 0, "cycles: phase after each command as specified (%d wrong)", bad_phase);
    ok(bad_scene == 0, "cycles: start/apply publish the new scene's load (%d wrong)", bad_scene);
    ok(bad_hist == 0, "cycles: history within 1..capacity (%d wrong)", bad_hist);

    /* Posting faster than the worker drains: the queue refuses, never blocks. */
    int refused = 0, accepted = 0;
    acbb_worker_set_pace(w, 0);
    for (int i = 0; i < 200; i++) {
        if (acbb_worker_post(w, i % 2 ? ACBB_CMD_PAUSE : ACBB_CMD_RESUME, NULL, 0)) accepted++;
        else refused++;
    }
    ok(accepted >= 16 && accepted + refused == 200, "cycles: burst of 200 posts: %d queued, %d refused",
       accepted, refused);

    atomic_store(&ra.stop, 1);
    pthread_join(rt, NULL);
    ok(atomic_load(&ra.violations) == 0 && atomic_load(&ra.reads) > 10,
       "cycles: concurrent reader saw monotone iterations and bounded history (%ld reads, %d violations)",
       atomic_load(&ra.reads), atomic_load(&ra.violations));
    double t0 = now_s();
    acbb_worker_free(w);
    ok(now_s() - t0 < 2.0, "cycles: free joins (%.3f s)", now_s() - t0);
}

/* ---- accuracy screen: layout, chart model, formats ---- */

static void check_acc_layout(int rows, int cols)
{
    acbb_layout l;
    acbb_layout_compute(rows, cols, &l);
    const acbb_rect p[3] = { l.acc_table, l.acc_frontier, l.acc_chart };
    int inside = 1, apart = 1, area = 0;
    for (int i = 0; i < 3; i++) {
        /* Below the screen's title and progress rows, inside the body. */
        inside &= acbb_rect_inside(p[i], rows, cols) && p[i].y >= l.body.y + 2 &&
                  p[i].y + p[i].h <= l.body.y + l.body.h;
        area += p[i].h * p[i].w;
        for (int j = i + 1; j < 3; j++) apart &= !acbb_rect_overlap(p[i], p[j]);
    }
    ok(inside && apart, "%dx%d: accuracy table, frontier, chart inside the body, apart", cols, rows);
    /* Wide: a one-column gap between table and chart; else they tile. */
    int gap = cols >= ACBB_LAYOUT_ACC_WIDE_COLS ? l.body.h - 2 : 0;
    ok(area + gap == (l.body.h - 2) * l.body.w, "%dx%d: accuracy panels fill the body below its 2 rows",
       cols, rows);
    ok(l.acc_table.w >= ACBB_LAYOUT_ACC_TABLE_W && l.acc_chart.h >= 7 && l.acc_table.h >= 6,
       "%dx%d: table %d wide x %d rows, chart %d rows", cols, rows, l.acc_table.w, l.acc_table.h,
       l.acc_chart.h);
}

static void test_acc_layout(void)
{
    check_acc_layout(24, 80);
    check_acc_layout(30, 100);
    check_acc_layout(60, 200);
    acbb_layout l;
    /* 80x24: body rows 1..21; rows 3..21 split: table (19 - 2) / 2 = 8,
     * frontier 2, chart 9 (title, 7 plot rows, x labels). */
    acbb_layout_compute(24, 80, &l);
    ok(l.acc_table.y == 3 && l.acc_table.h == 8 && l.acc_frontier.y == 11 && l.acc_frontier.h == 2 &&
           l.acc_chart.y == 13 && l.acc_chart.h == 9 && l.acc_chart.w == 80,
       "80x24: accuracy table 8 rows at 3, frontier at 11, chart 9 rows at 13");
    /* 200x60 (wide): table 74 wide on the left, chart from column 75. */
    acbb_layout_compute(60, 200, &l);
    ok(l.acc_table.x == 0 && l.acc_table.w == 74 && l.acc_chart.x == 75 && l.acc_chart.w == 125 &&
           l.acc_chart.h == 55 && l.acc_frontier.h == 8 && l.acc_table.h == 47,
       "200x60: table 74 x 47 + frontier 8 on the left, chart 125 x 55 on the right");
}

static acbb_accuracy_row acc_row(acbb_accuracy_knob k, double ms, double e_loss, double e_T)
{
    acbb_accuracy_row r;
    memset(&r, 0, sizeof r);
    r.knob = k;
    r.status = ACBB_OK;
    r.wall_ms = ms;
    r.e_loss = e_loss;
    r.e_T = e_T;
    return r;
}

static void test_acc_chart(void)
{
    acbb_accuracy_row rows[7];
    rows[0] = acc_row(ACBB_KNOB_CONTACT_GRID, 10, 0.02, 0.01);    /* 2 %: x 1, y log10 2 */
    rows[1] = acc_row(ACBB_KNOB_CONTACT_GRID, 100, 5e-4, 1e-3);   /* 0.1 %: x 2, y -1 */
    rows[2] = acc_row(ACBB_KNOB_CONTACT_GRID, 1000, 0, 0);        /* reference: x 3, y = floor */
    rows[3] = acc_row(ACBB_KNOB_HERTZ, 20, 0.1, 0.1);
    rows[3].status = ACBB_DIVERGED;                                /* failed: left out */
    rows[4] = acc_row(ACBB_KNOB_MODEL, 30, 0.1, 0.1);
    rows[4].skipped = 1;                                           /* skipped: left out */
    rows[5] = acc_row(ACBB_KNOB_HERTZ, 40, NAN, 0.1);              /* undefined: left out */
    rows[6] = acc_row(ACBB_KNOB_NETWORK, 50, 16.5, 0.07);          /* 1650 %: y 3.217 */
    is_close(acbb_acc_error_pct(&rows[1]), 0.1, 1e-12, 0, "acc chart: error = max(e_loss, e_T) in %%");
    ok(isnan(acbb_acc_error_pct(&rows[3])) && isnan(acbb_acc_error_pct(&rows[5])),
       "acc chart: no error for a failed row or an undefined one");
    static acbb_acc_chart m;
    size_t n = acbb_acc_chart_build(rows, 7, &m);
    ok(n == 4 && m.p[0].row == 0 && m.p[1].row == 1 && m.p[2].row == 2 && m.p[3].row == 6,
       "acc chart: 4 points (rows 0 1 2 6), failed/skipped/undefined left out (n = %zu)", n);
    /* Decades: 10 .. 1000 ms -> 1 .. 3; errors 0.1 .. 1650 % -> ceil(3.217) = 4
     * at the top, floor(-1) - 1 = -2 at the bottom (the zeros' decade). */
    ok(m.xmin == 1 && m.xmax == 3 && m.ymin == -2 && m.ymax == 4,
       "acc chart: x 1..3, y -2..4 decades (got %g..%g, %g..%g)", m.xmin, m.xmax, m.ymin, m.ymax);
    is_close(m.p[0].y, 0.30102999566398120, 1e-14, 0, "acc chart: 2 %% at log10 2");
    ok(m.p[2].zero && m.p[2].y == -2 && !m.p[0].zero, "acc chart: the reference's 0 sits on the floor");
    is_close(m.p[3].y, log10(1650.0), 1e-14, 0, "acc chart: 1650 %% at log10 1650");

    /* Cells on an 11 x 4 raster (22 x 16 dots): x 1 -> dot 0, cell 0;
     * x 3 -> dot 21, cell 10; x 2 -> dot 10.5 -> cell 5 either way.
     * y log10 2: (1 - 2.30103 / 6) * 15 = 9.247 -> dot 9, row 2;
     * y -2 -> dot 15, row 3; y 4 -> dot 0, row 0. */
    static acbb_chart c;
    int row = -1, col = -1;
    acbb_chart_init(&c, 11, 4, m.xmin, m.xmax, m.ymin, m.ymax);
    ok(acbb_chart_locate(&c, 1, log10(2.0), &row, &col) && row == 2 && col == 0,
       "acc chart: (10 ms, 2 %%) in cell row 2 col 0 (got %d %d)", row, col);
    ok(acbb_chart_locate(&c, 3, -2, &row, &col) && row == 3 && col == 10,
       "acc chart: (1 s, 0) in the bottom-right cell (got %d %d)", row, col);
    ok(acbb_chart_locate(&c, 2, 4, &row, &col) && row == 0 && col == 5,
       "acc chart: (100 ms, 10^4 %%) in row 0 col 5 (got %d %d)", row, col);
    ok(!acbb_chart_locate(&c, 0.5, 0, &row, &col) && !acbb_chart_locate(&c, 2, NAN, &row, &col),
       "acc chart: points outside the ranges or NaN have no cell");
    /* The marker cell is where acbb_chart_plot put the point's dot. */
    const double px[1] = { 1 }, py[1] = { 0.30102999566398120 };
    acbb_chart_plot(&c, px, py, 1, 0);
    ok(c.dots[2][0] != 0 && c.owner[2][0] == 0, "acc chart: the plotted dot is in the located cell");

    n = acbb_acc_chart_build(rows, 0, &m);
    ok(n == 0 && m.xmax > m.xmin && m.ymin == -1 && m.ymax == 1,
       "acc chart: no points -> 1 ms..10 ms, 0.1 %%..10 %% (tolerance 1 %% inside)");

    int distinct = 1;
    for (int i = 0; i < ACBB_KNOB_COUNT; i++)
        for (int j = i + 1; j < ACBB_KNOB_COUNT; j++)
            distinct &= acbb_acc_knob_letter((acbb_accuracy_knob)i) != acbb_acc_knob_letter((acbb_accuracy_knob)j);
    ok(distinct && acbb_acc_knob_letter(ACBB_KNOB_CONTACT_GRID) == 'G', "acc chart: 7 distinct knob letters");

    char b[16];
    acbb_acc_fmt_pct(0.02205804262, b, sizeof b);
    ok(strcmp(b, "2.21") == 0, "fmt pct: 0.0220580 -> 2.21 (got %s)", b);
    acbb_acc_fmt_pct(1.724105806e-05, b, sizeof b);
    ok(strcmp(b, "2e-03") == 0, "fmt pct: 1.72e-5 -> 2e-03 (got %s)", b);
    acbb_acc_fmt_pct(0, b, sizeof b);
    ok(strcmp(b, "0") == 0, "fmt pct: exact 0 -> 0");
    acbb_acc_fmt_pct(NAN, b, sizeof b);
    ok(strcmp(b, "-") == 0, "fmt pct: NaN -> -");
    acbb_acc_fmt_pct(16.4865, b, sizeof b);
    ok(strcmp(b, "2e+03") == 0, "fmt pct: 1648.65 %% -> 2e+03 (got %s)", b);
    acbb_acc_fmt_pct_decade(0, b, sizeof b);
    int dec_ok = strcmp(b, "1%") == 0;
    acbb_acc_fmt_pct_decade(-5, b, sizeof b);
    dec_ok &= strcmp(b, "1e-05%") == 0;
    acbb_acc_fmt_ms_decade(3, b, sizeof b);
    dec_ok &= strcmp(b, "1s") == 0;
    acbb_acc_fmt_ms_decade(7, b, sizeof b);
    ok(dec_ok && strcmp(b, "1e+07ms") == 0, "decade labels: 1%%, 1e-05%%, 1s, 1e+07ms");
    acbb_accuracy_row r = acc_row(ACBB_KNOB_CONTACT_GRID, 1, 0, 0);
    snprintf(r.key, sizeof r.key, "fidelity.contact_grid");
    snprintf(r.value, sizeof r.value, "4");
    acbb_acc_setting_label(&r, b, sizeof b);
    ok(strcmp(b, "contact_grid=4") == 0, "setting label: contact_grid=4");
}

/* ---- the engine's cancel hook (include/acbb/accuracy.h) ---- */

typedef struct {
    _Atomic int *cancel;
    size_t at;         /* set the flag when this many settings are done */
    size_t calls;
} cancel_at;

static void cancel_on_progress(void *ctx, size_t done, size_t total)
{
    cancel_at *c = ctx;
    (void)total;
    c->calls++;
    if (done == c->at) atomic_store(c->cancel, 1);
}

typedef struct {
    _Atomic int *cancel;
    int after_ms;
    double t_set;
} cancel_later;

static void *cancel_thread(void *p)
{
    cancel_later *c = p;
    sleep_ms(c->after_ms);
    c->t_set = now_s();
    atomic_store(c->cancel, 1);
    return NULL;
}

static void test_accuracy_cancel(const acbb_scene *s0)
{
    static acbb_accuracy_row rows[ACBB_BENCH_MAX_ROWS], full[ACBB_BENCH_MAX_ROWS];
    acbb_error err = { { 0 } };
    _Atomic int flag = 1;
    size_t n = 99;
    acbb_accuracy_options o = { .knobs = ACBB_ACCURACY_KNOB_BIT(ACBB_KNOB_CONTACT_GRID), .repeats = 1,
                                .cancel = &flag };
    acbb_status st = acbb_accuracy_run(s0, &o, rows, ACBB_BENCH_MAX_ROWS, &n, NULL, NULL, &err);
    ok(st == ACBB_CANCELLED && n == 0, "cancel: a set flag runs nothing (st %d, n %zu)", st, n);
    has_substr(err.msg, "accuracy: cancelled after 0 of 9 settings", "cancel: the message counts");

    /* Cancelled from the progress callback after 2 settings: exactly 2 rows,
     * their results as in a full run (deterministic), errors NaN. */
    atomic_store(&flag, 0);
    cancel_at at = { &flag, 2, 0 };
    st = acbb_accuracy_run(s0, &o, rows, ACBB_BENCH_MAX_ROWS, &n, cancel_on_progress, &at, &err);
    ok(st == ACBB_CANCELLED && n == 2 && at.calls == 2, "cancel after 2 of 9: 2 rows (n %zu)", n);
    has_substr(err.msg, "cancelled after 2 of 9 settings", "cancel after 2: message");
    acbb_accuracy_options plain = { .knobs = o.knobs, .repeats = 1 };
    size_t nf = 0;
    st = acbb_accuracy_run(s0, &plain, full, ACBB_BENCH_MAX_ROWS, &nf, NULL, NULL, &err);
    ok(st == ACBB_OK && nf == 9, "no hook: the whole plan runs (9 rows)");
    ok(rows[0].loss == full[0].loss && rows[1].dT_outer == full[1].dT_outer &&
           strcmp(rows[1].value, "6") == 0,
       "cancel: the finished rows hold the full run's results (grid 4 and 6)");
    ok(isnan(rows[0].e_loss) && isnan(rows[1].e_T) && full[0].e_loss > 0,
       "cancel: errors left NaN (no reference ran)");

    /* Mid-run: the network knob on a 24-point grid takes a few hundred ms
     * per setting; a cancel 30 ms in must end the call within a small part
     * of that (one coupled step), not after the setting. */
    acbb_scene s = *s0;
    ok(acbb_scene_set(&s, "fidelity.contact_grid", "24", &err) == ACBB_OK, "scene: contact_grid 24");
    acbb_accuracy_options on = { .knobs = ACBB_ACCURACY_KNOB_BIT(ACBB_KNOB_NETWORK), .repeats = 1 };
    st = acbb_accuracy_run(&s, &on, full, ACBB_BENCH_MAX_ROWS, &nf, NULL, NULL, &err);
    double row_ms = full[0].wall_ms;
    ok(st == ACBB_OK && nf == 2 && row_ms > 100, "network=7 at grid 24 takes %.0f ms (> 100)", row_ms);
    atomic_store(&flag, 0);
    on.cancel = &flag;
    cancel_later cl = { &flag, 30, 0 };
    pthread_t th;
    pthread_create(&th, NULL, cancel_thread, &cl);
    st = acbb_accuracy_run(&s, &on, rows, ACBB_BENCH_MAX_ROWS, &n, NULL, NULL, &err);
    double late_ms = 1e3 * (now_s() - cl.t_set);
    pthread_join(th, NULL);
    ok(st == ACBB_CANCELLED && n == 0, "mid-run cancel: the interrupted setting is dropped (n %zu)", n);
    ok(late_ms < 0.25 * row_ms, "mid-run cancel: returned %.1f ms after the flag (setting: %.0f ms)",
       late_ms, row_ms);
}

/* ---- the benchmark thread (bench.c) ---- */

static acbb_bench_state bst; /* test scratch, main thread only */

static void test_bench(const acbb_scene *s0)
{
    acbb_bench *b = NULL;
    acbb_error err = { { 0 } };
    ok(acbb_bench_new(&b, &err) == ACBB_OK, "bench: created");
    acbb_bench_read(b, &bst);
    ok(bst.phase == ACBB_BENCH_IDLE && bst.n == 0 && bst.picks[0] == -1, "bench: idle at first");
    ok(!acbb_bench_cancel(b), "bench: nothing to cancel when idle");

    /* A short plan: the hertz knob (3 settings). The thread's rows must be
     * the engine's own (errors are deterministic). */
    static acbb_accuracy_row direct[ACBB_BENCH_MAX_ROWS];
    acbb_accuracy_options o = { .knobs = ACBB_ACCURACY_KNOB_BIT(ACBB_KNOB_HERTZ), .repeats = 1 };
    size_t nd = 0;
    acbb_accuracy_run(s0, &o, direct, ACBB_BENCH_MAX_ROWS, &nd, NULL, NULL, &err);
    ok(acbb_bench_start(b, s0, &o, &err) == ACBB_OK, "bench: hertz plan started (%s)", err.msg);
    ok(acbb_bench_wait(b, 60000), "bench: the plan ends");
    acbb_bench_read(b, &bst);
    int same = bst.n == nd && nd == 3;
    for (size_t i = 0; same && i < nd; i++)
        same = bst.rows[i].e_loss == direct[i].e_loss && bst.rows[i].e_T == direct[i].e_T &&
               strcmp(bst.rows[i].value, direct[i].value) == 0;
    ok(bst.phase == ACBB_BENCH_DONE && bst.done == 3 && bst.total == 3 && same,
       "bench: done, 3/3 settings, rows equal a direct acbb_accuracy_run");
    long p = bst.picks[ACBB_KNOB_HERTZ];
    ok(p >= 0 && p < 3 && bst.rows[p].e_loss <= ACBB_ACCURACY_FRONTIER_TOL && bst.picks[ACBB_KNOB_MODEL] == -1,
       "bench: frontier pick for hertz within 1 %%, none for absent knobs");
    ok(bst.ended_s >= bst.started_s && bst.run_id == 1 && bst.opt.cancel == NULL &&
           bst.opt.knobs == o.knobs,
       "bench: run 1, timed, options kept without the hook");
    fd_set rf;
    struct timeval tv = { 0, 0 };
    FD_ZERO(&rf);
    FD_SET(acbb_bench_wake_fd(b), &rf);
    ok(select(acbb_bench_wake_fd(b) + 1, &rf, NULL, NULL, &tv) == 1, "bench: wake-up pipe readable");
    acbb_bench_drain_wake(b);
    FD_ZERO(&rf);
    FD_SET(acbb_bench_wake_fd(b), &rf);
    tv.tv_sec = 0;
    ok(select(acbb_bench_wake_fd(b) + 1, &rf, NULL, NULL, &tv) == 0, "bench: drained");

    /* Cancel: contact_grid (9 settings, ~2 s); read concurrently while it
     * runs (TSan watches), cancel after the first rows arrive. */
    o.knobs = ACBB_ACCURACY_KNOB_BIT(ACBB_KNOB_CONTACT_GRID);
    ok(acbb_bench_start(b, s0, &o, &err) == ACBB_OK, "bench: contact_grid plan started");
    double t0 = now_s();
    size_t seen = 0, reads = 0;
    do {
        acbb_bench_read(b, &bst);
        reads++;
        if (bst.done < seen || bst.n != bst.done) break; /* must never go back */
        seen = bst.done;
        sleep_ms(1);
    } while (bst.done < 2 && bst.phase == ACBB_BENCH_RUNNING && now_s() - t0 < 120);
    ok(bst.phase == ACBB_BENCH_RUNNING && bst.done >= 2 && bst.n == bst.done && bst.total == 9,
       "bench: progress published row by row (%zu/%zu after %zu reads)", bst.done, bst.total, reads);
    ok(bst.run_id == 2 && isnan(bst.rows[0].e_loss) && bst.rows[0].loss > 0,
       "bench: live rows have results, errors still unknown");
    /* The plan has ~2 s to go: its thread is alive for these two checks. */
    int sb = worker_threads_block_signals();
    ok(sb == 1, "bench: its thread blocks SIGINT/SIGTERM/SIGHUP/SIGWINCH (%d)", sb);
    ok(acbb_bench_start(b, s0, &o, &err) == ACBB_EINVAL, "bench: a second start while running is refused");
    has_substr(err.msg, "already running", "bench: ... saying so");
    ok(acbb_bench_cancel(b), "bench: cancel accepted while running");
    acbb_bench_read(b, &bst);
    ok(bst.cancel_requested, "bench: the cancel request is published");
    ok(acbb_bench_wait(b, 60000), "bench: cancelled plan ends");
    acbb_bench_read(b, &bst);
    ok(bst.phase == ACBB_BENCH_CANCELLED && bst.n < 9 && bst.n >= 2, "bench: cancelled with %zu rows", bst.n);
    has_substr(bst.message, "cancelled after", "bench: cancel message");
    ok(!acbb_bench_cancel(b), "bench: nothing to cancel after the end");

    /* A scene the engine refuses: FAILED with its message. */
    acbb_scene bad = *s0;
    bad.ball_diameter = -1.0;
    ok(acbb_bench_start(b, &bad, &o, &err) == ACBB_OK && acbb_bench_wait(b, 60000),
       "bench: bad scene: the thread starts and ends");
    acbb_bench_read(b, &bst);
    ok(bst.phase == ACBB_BENCH_FAILED && bst.n == 0 && bst.message[0], "bench: failed: %s", bst.message);
    o.repeats = ACBB_ACCURACY_MAX_REPEATS + 1;
    ok(acbb_bench_start(b, s0, &o, &err) == ACBB_EINVAL, "bench: bad options refused at start");
    o.repeats = 1;

    /* Freeing while running cancels and joins within a step or so. */
    ok(acbb_bench_start(b, s0, &o, &err) == ACBB_OK, "bench: started again");
    sleep_ms(20);
    t0 = now_s();
    acbb_bench_free(b);
    ok(now_s() - t0 < 1.0, "bench: free while running joins quickly (%.3f s)", now_s() - t0);
}

int main(void)
{
    gsl_set_error_handler_off();
    test_layout();
    test_progress();
    test_chart();
    test_editor();
    test_acc_layout();
    test_acc_chart();
    acbb_scene s0;
    acbb_error err = { { 0 } };
    if (acbb_scene_load("presets/7008C.ini", &s0, &err) != ACBB_OK) {
        ok(0, "load presets/7008C.ini: %s", err.msg);
        return done_testing();
    }
    test_accuracy_cancel(&s0);
    test_bench(&s0);
    test_worker_basics(&s0);
    const char *env = getenv("ACBB_WORKER_CYCLES");
    test_worker_cycles(&s0, env ? atoi(env) : 200);
    return done_testing();
}
