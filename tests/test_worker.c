/* Tests of the TUI's curses-free parts: the worker thread hand-off (also
 * run under ThreadSanitizer), the layout function for several terminal
 * sizes, the progress estimate, the chart raster and the editor model. */
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

int main(void)
{
    gsl_set_error_handler_off();
    test_layout();
    test_progress();
    test_chart();
    test_editor();
    acbb_scene s0;
    acbb_error err = { { 0 } };
    if (acbb_scene_load("presets/7008C.ini", &s0, &err) != ACBB_OK) {
        ok(0, "load presets/7008C.ini: %s", err.msg);
        return done_testing();
    }
    test_worker_basics(&s0);
    const char *env = getenv("ACBB_WORKER_CYCLES");
    test_worker_cycles(&s0, env ? atoi(env) : 200);
    return done_testing();
}
