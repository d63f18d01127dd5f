/* Tests of the gnuplot export (plot.h) on a synthetic run whose values are
 * known here: temperatures rise as T = 20 + dT (1 - exp(-t/100)) C, the
 * losses are constants, and 16 balls carry Q = 100 + 50 cos(psi) N at
 * alpha = 20 + 10 cos(psi) deg. Needs gnuplot (gnuplot-nox) on PATH. */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <gsl/gsl_errno.h>
#include "tap.h"
#include "acbb/tools/plot.h"

#define PI 3.14159265358979323846
#define TITLE "SynthTitle 42"

static acbb_snapshot snap;
static acbb_history hist;
static char dir[64];

static void make_run(void)
{
    memset(&snap, 0, sizeof snap);
    snap.n_balls = 16;
    for (int i = 0; i < 16; i++) {
        double psi = 2.0 * PI * i / 16.0;
        acbb_ball_view *b = &snap.balls[i];
        b->psi = psi;
        b->Qi = 100.0 + 50.0 * cos(psi);
        b->Qo = 120.0 + 50.0 * cos(psi);
        b->alpha_i = (20.0 + 10.0 * cos(psi)) * PI / 180.0;
        b->alpha_o = (18.0 + 8.0 * cos(psi)) * PI / 180.0;
    }
    acbb_history_init(&hist);
    for (int k = 0; k < 50; k++) {
        double rise = 1.0 - exp(-10.0 * k / 100.0);
        snap.iteration = k;
        snap.time = 10.0 * k;
        snap.T_outer_ring = 20.0 + 30.0 * rise;
        snap.T_inner_ring = 20.0 + 25.0 * rise;
        snap.T_ball = snap.T_inner_ring + 2.0;
        snap.T_housing = 20.0 + 10.0 * rise;
        snap.losses = (acbb_losses){ { 1, 2, 3, 4, 5, 0 }, 15, 6, 4 };
        acbb_history_push(&hist, &snap);
    }
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *buf = malloc(1 << 22);
    size_t n = buf ? fread(buf, 1, (1 << 22) - 1, f) : 0;
    fclose(f);
    if (buf) buf[n] = '\0';
    *len = n;
    return buf;
}

static bool exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* Number of entries in `d` whose name contains ".tmp." (left-over temps). */
static int temp_files(const char *d)
{
    DIR *dp = opendir(d);
    int n = 0;
    if (!dp) return -1;
    for (struct dirent *e; (e = readdir(dp));) n += strstr(e->d_name, ".tmp.") != NULL;
    closedir(dp);
    return n;
}

/* Open descriptors of this process (pipes leaked by a plot call show here). */
static int open_fds(void)
{
    DIR *dp = opendir("/proc/self/fd");
    int n = 0;
    if (!dp) return -1;
    while (readdir(dp)) n++;
    closedir(dp);
    return n;
}

static void test_names(void)
{
    ok(acbb_plot_format_from_name("png") == ACBB_PLOT_PNG, "format 'png'");
    ok(acbb_plot_format_from_name("SVG") == ACBB_PLOT_SVG, "format 'SVG' (case-insensitive)");
    ok(acbb_plot_format_from_name("dumb") == ACBB_PLOT_DUMB, "format 'dumb'");
    ok(acbb_plot_format_from_name("out/run.png") == ACBB_PLOT_PNG, "format from .png extension");
    ok(acbb_plot_format_from_name("a.b/run.Svg") == ACBB_PLOT_SVG, "format from .Svg extension");
    ok(acbb_plot_format_from_name("run.jpg") == -1, "unknown extension -> -1");
    ok(acbb_plot_format_from_name("run.dumb") == -1, "dumb is not a file extension");
    ok(acbb_plot_format_from_name("dir.png/run") == -1, "a dot in the directory is no extension");
    ok(acbb_plot_format_from_name("run.") == -1 && acbb_plot_format_from_name(NULL) == -1,
       "empty extension and NULL -> -1");
    static const char *kinds[] = { "temperature", "losses", "loads", "angles", "history-loads" };
    int round_trip = 1;
    for (int k = 0; k < 5; k++)
        round_trip &= acbb_plot_kind_from_name(kinds[k]) == k &&
                      strcmp(acbb_plot_kind_name((acbb_plot_kind)k), kinds[k]) == 0;
    ok(round_trip, "the five kind names round-trip in enum order");
    ok(acbb_plot_kind_from_name("Temperature") == -1 && acbb_plot_kind_from_name("all") == -1,
       "kind names are exact; 'all' is a CLI notion, not a kind");
    ok(strcmp(acbb_plot_kind_name((acbb_plot_kind)99), "unknown") == 0, "bad kind -> unknown");
    setenv("ACBB_GNUPLOT", "/opt/gp/gnuplot", 1);
    ok(strcmp(acbb_plot_program(), "/opt/gp/gnuplot") == 0, "ACBB_GNUPLOT picks the program");
    unsetenv("ACBB_GNUPLOT");
    ok(strcmp(acbb_plot_program(), "gnuplot") == 0, "default program is gnuplot");
}

static void test_png_svg(const acbb_plot_data *d)
{
    char path[256];
    acbb_error err = { { 0 } };
    snprintf(path, sizeof path, "%s/t.png", dir);
    acbb_status st = acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_PNG, path, 800, 500, d, &err);
    ok(st == ACBB_OK, "PNG temperature plot written (%s)", err.msg);
    size_t len = 0;
    char *buf = slurp(path, &len);
    ok(buf && len > 1024 && memcmp(buf, "\x89PNG\r\n\x1a\n", 8) == 0,
       "PNG signature and > 1 kB (%zu bytes)", len);
    ok(buf && len > 24 && (((unsigned char)buf[16] << 24 | (unsigned char)buf[17] << 16 |
                            (unsigned char)buf[18] << 8 | (unsigned char)buf[19]) == 800) &&
           (((unsigned char)buf[20] << 24 | (unsigned char)buf[21] << 16 |
             (unsigned char)buf[22] << 8 | (unsigned char)buf[23]) == 500),
       "PNG IHDR says 800 x 500 pixels");
    free(buf);
    struct stat sb;
    ok(stat(path, &sb) == 0 && (sb.st_mode & 0777) == 0644, "PNG is 0644, not mkstemp's 0600");

    snprintf(path, sizeof path, "%s/t.svg", dir);
    /* a gnuplot that keeps the script it is sent: the y range is checked there */
    char wrap[128], sent[128];
    snprintf(wrap, sizeof wrap, "%s/gpwrap", dir);
    snprintf(sent, sizeof sent, "%s/sent.gp", dir);
    FILE *wf = fopen(wrap, "w");
    if (wf) {
        fprintf(wf, "#!/bin/sh\ntee '%s' | gnuplot\n", sent);
        fclose(wf);
    }
    chmod(wrap, 0755);
    setenv("ACBB_GNUPLOT", wrap, 1);
    st = acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_SVG, path, 800, 500, d, &err);
    unsetenv("ACBB_GNUPLOT");
    ok(st == ACBB_OK, "SVG temperature plot written (%s)", err.msg);
    buf = slurp(path, &len);
    has_substr(buf, "<svg", "SVG has an <svg element");
    has_substr(buf, TITLE ": bearing temperatures", "SVG has the title");
    has_substr(buf, "temperature (\u00b0C)", "SVG y label has the unit, degrees C");
    has_substr(buf, "time (s)", "SVG x label has the unit");
    has_substr(buf, "outer ring", "SVG legend names the outer ring");
    /* T_outer tends to 20 + 30 (1 - e^-4.9) = 49.78 C: the y axis covers
     * 20..49.78 C, raised at most by a key's rows above the data. */
    size_t slen;
    char *gp = slurp(sent, &slen);
    const char *yr = gp ? strstr(gp, "set yrange [") : NULL;
    double ylo = yr ? strtod(yr + 12, NULL) : NAN, yhi = yr ? strtod(strchr(yr, ':') + 1, NULL) : NAN;
    ok(ylo <= 20.0 && ylo >= 0.0 && yhi >= 49.78 && yhi <= 100.0,
       "SVG y axis covers 20..49.8 C from 0 up, no more than a key's room above (%g..%g)", ylo, yhi);
    free(gp);
    unlink(sent);
    unlink(wrap);
    free(buf);

    /* Angles: 20 + 10 cos(psi) deg spans exactly 10..30 deg; in radians the
     * axis would read 0.2..0.5, so a 30 tic proves the rad -> deg scale. */
    snprintf(path, sizeof path, "%s/a.svg", dir);
    st = acbb_plot_file(ACBB_PLOT_ANGLES, ACBB_PLOT_SVG, path, 800, 500, d, &err);
    ok(st == ACBB_OK, "SVG angles plot written (%s)", err.msg);
    buf = slurp(path, &len);
    has_substr(buf, "> 30</tspan></text>", "angle axis in degrees: 30 deg tic");
    has_substr(buf, "> 10</tspan></text>", "angle axis in degrees: 10 deg tic");
    has_substr(buf, "angle (\u00b0)", "angle label has the unit, the degree sign");
    has_substr(buf, "ball azimuth (\u00b0)", "azimuth label has the unit");
    has_substr(buf, "\u03b1", "the contact angles are labelled alpha as the Greek letter");
    ok(buf && !strstr(buf, "> 0.5</tspan></text>"), "no radian-scale tic");
    free(buf);
    ok(temp_files(dir) == 0, "no temp files left after successful writes");
}

static void test_dumb(const acbb_plot_data *d)
{
    static char text[16384];
    acbb_error err = { { 0 } };
    acbb_status st = acbb_plot_dumb(ACBB_PLOT_LOADS, 80, 25, d, text, sizeof text, &err);
    ok(st == ACBB_OK, "dumb loads chart rendered (%s)", err.msg);
    has_substr(text, TITLE ": contact loads per ball, load (N)", "dumb title with y unit");
    has_substr(text, "ball azimuth (deg)", "dumb x label");
    /* Qo = 120 + 50 cos(psi) peaks at 170 N, Qi = 100 - 50 = 50 N at the bottom. */
    has_substr(text, "180 +", "dumb y axis top tic 180 (max Qo 170 N)");
    has_substr(text, "40 +", "dumb y axis bottom tic 40 (min Qi 50 N)");
    int lines = 0;
    for (const char *p = text; *p; p++) lines += *p == '\n';
    ok(lines >= 24 && lines <= 26, "dumb chart is 25 rows (%d newlines)", lines);
    ok(strchr(text, '\f') == NULL, "no form feed (nofeed)");

    char small[100];
    st = acbb_plot_dumb(ACBB_PLOT_LOADS, 80, 25, d, small, sizeof small, &err);
    /* 99 bytes fit; the leading form feed gnuplot writes is then dropped. */
    ok(st == ACBB_OK && strlen(small) == sizeof small - 2 &&
           strncmp(small, text, strlen(small)) == 0,
       "dumb output truncated to the buffer, a prefix of the full chart");

    /* A NaN in a row drops the whole row: the huge inner-ring value next to
     * it must not reach the autoscale (max would be 1e9, not 50). */
    static acbb_history h2;
    h2 = hist;
    h2.p[10].T_outer_ring = NAN;
    h2.p[10].T_inner_ring = 1e9;
    h2.p[20].time = INFINITY;
    acbb_plot_data d2 = { &h2, NULL, "nan" };
    st = acbb_plot_dumb(ACBB_PLOT_TEMPERATURE, 80, 25, &d2, text, sizeof text, &err);
    ok(st == ACBB_OK, "history with NaN/Inf rows still plots (%s)", err.msg);
    ok(strstr(text, "e+0") == NULL && strstr(text, "1x10") == NULL && strstr(text, "50 +"),
       "non-finite rows skipped: y axis still ends at 50 C");
}

static void test_missing_and_failing(const acbb_plot_data *d)
{
    char path[256];
    acbb_error err = { { 0 } };
    snprintf(path, sizeof path, "%s/missing.png", dir);
    setenv("ACBB_GNUPLOT", "/nonexistent/gnuplot", 1);
    acbb_status st = acbb_plot_file(ACBB_PLOT_LOSSES, ACBB_PLOT_PNG, path, 640, 480, d, &err);
    ok(st == ACBB_EIO, "missing ACBB_GNUPLOT program -> ACBB_EIO");
    has_substr(err.msg, "not found", "message says not found");
    ok(!exists(path) && temp_files(dir) == 0, "no file and no temp file left");
    char text[256] = "x";
    st = acbb_plot_dumb(ACBB_PLOT_LOSSES, 80, 25, d, text, sizeof text, &err);
    ok(st == ACBB_EIO && text[0] == '\0', "dumb with a missing program -> ACBB_EIO, empty text");
    unsetenv("ACBB_GNUPLOT");

    const char *old = getenv("PATH");
    char *saved = old ? strdup(old) : NULL;
    setenv("PATH", "/nonexistent", 1);
    st = acbb_plot_file(ACBB_PLOT_LOSSES, ACBB_PLOT_PNG, path, 640, 480, d, &err);
    ok(st == ACBB_EIO && strcmp(err.msg, "gnuplot not found on PATH (install gnuplot-nox)") == 0,
       "gnuplot not on PATH -> exact install hint (%s)", err.msg);
    if (saved) setenv("PATH", saved, 1);
    free(saved);

    /* /bin/false reads nothing: writing the script hits EPIPE. The process
     * must survive, and SIGPIPE must be neither blocked nor pending after. */
    setenv("ACBB_GNUPLOT", "/bin/false", 1);
    static acbb_history big;
    acbb_history_init(&big);
    for (int k = 0; k < ACBB_HISTORY_CAP; k++) {
        snap.time = k;
        acbb_history_push(&big, &snap);
    }
    acbb_plot_data db = { &big, &snap, TITLE };
    st = acbb_plot_file(ACBB_PLOT_LOSSES, ACBB_PLOT_PNG, path, 640, 480, &db, &err);
    ok(st == ACBB_EIO, "gnuplot exiting 1 -> ACBB_EIO");
    has_substr(err.msg, "gnuplot failed", "message says gnuplot failed");
    ok(!exists(path) && temp_files(dir) == 0, "failed run leaves no file, no temp file");
    sigset_t mask, pending;
    sigprocmask(SIG_SETMASK, NULL, &mask);
    sigpending(&pending);
    struct sigaction sa;
    sigaction(SIGPIPE, NULL, &sa);
    ok(!sigismember(&mask, SIGPIPE) && !sigismember(&pending, SIGPIPE) &&
           sa.sa_handler == SIG_DFL,
       "SIGPIPE left as found: default action, unblocked, not pending");

    /* A fake gnuplot that fails like the real one: the first "line N:" line
     * of stderr is reported, not the echoed command or the caret line. */
    char fake[256];
    snprintf(fake, sizeof fake, "%s/fakegp", dir);
    FILE *f = fopen(fake, "w");
    if (f) {
        fputs("#!/bin/sh\ncat >/dev/null\necho 'gnuplot> plot $X' >&2\n"
              "echo '         line 3: warning: empty y range' >&2\n"
              "echo '              ^' >&2\necho '         line 7: no datablock named $X' >&2\n"
              "exit 1\n", f);
        fclose(f);
    }
    chmod(fake, 0755);
    setenv("ACBB_GNUPLOT", fake, 1);
    st = acbb_plot_file(ACBB_PLOT_LOSSES, ACBB_PLOT_PNG, path, 640, 480, d, &err);
    ok(st == ACBB_EIO && strcmp(err.msg, "gnuplot failed: line 7: no datablock named $X") == 0,
       "first error line of stderr reported, not the echo, caret or warning (%s)", err.msg);
    unlink(fake);
    unsetenv("ACBB_GNUPLOT");
}

static void test_paths(const acbb_plot_data *d)
{
    char path[256];
    acbb_error err = { { 0 } };
    snprintf(path, sizeof path, "%s/it's a 'plot' x.svg", dir);
    acbb_plot_data dq = { d->history, d->snapshot, "Bob's \"run\" 50% $x" };
    acbb_status st = acbb_plot_file(ACBB_PLOT_HISTORY_LOADS, ACBB_PLOT_SVG, path, 640, 480, &dq,
                                    &err);
    ok(st == ACBB_OK && exists(path), "path with quotes and spaces written (%s)", err.msg);
    size_t len = 0;
    char *buf = slurp(path, &len);
    has_substr(buf, "<text>Bob's \"run\" 50% $x: contact loads of ball 0</text>",
               "title with quote, %, $ reaches the SVG verbatim");
    free(buf);

    snprintf(path, sizeof path, "%s/no/such/dir/x.png", dir);
    st = acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_PNG, path, 640, 480, d, &err);
    ok(st == ACBB_EIO, "nonexistent directory -> ACBB_EIO");
    has_substr(err.msg, "cannot write", "message says cannot write");
    has_substr(err.msg, "No such file or directory", "message gives the reason");

    /* A regular file as the directory fails even for root. */
    char file_dir[256];
    snprintf(file_dir, sizeof file_dir, "%s/t.png/x.png", dir);
    st = acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_PNG, file_dir, 640, 480, d, &err);
    ok(st == ACBB_EIO && strstr(err.msg, "Not a directory"), "file as directory -> ACBB_EIO (%s)",
       err.msg);

    if (geteuid() != 0) {
        char ro[128];
        snprintf(ro, sizeof ro, "%s/ro", dir);
        mkdir(ro, 0555);
        snprintf(path, sizeof path, "%s/x.png", ro);
        st = acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_PNG, path, 640, 480, d, &err);
        ok(st == ACBB_EIO && strstr(err.msg, "Permission denied"),
           "read-only directory -> ACBB_EIO (%s)", err.msg);
        rmdir(ro);
    } else {
        skip("running as root (root writes anyway)", "read-only directory -> ACBB_EIO");
    }

    snprintf(path, sizeof path, "%s/bad\nname.png", dir);
    st = acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_PNG, path, 640, 480, d, &err);
    ok(st == ACBB_EINVAL, "newline in the path rejected (it would end the gnuplot command)");
}

static void test_bad_input(const acbb_plot_data *d)
{
    char path[256];
    acbb_error err = { { 0 } };
    snprintf(path, sizeof path, "%s/bad.png", dir);
    acbb_plot_data no_snap = { d->history, NULL, NULL };
    ok(acbb_plot_file(ACBB_PLOT_LOADS, ACBB_PLOT_PNG, path, 640, 480, &no_snap, &err) ==
           ACBB_EINVAL, "per-ball kind without a snapshot -> EINVAL");
    static acbb_history empty;
    acbb_history_init(&empty);
    acbb_plot_data no_hist = { &empty, d->snapshot, NULL };
    ok(acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_PNG, path, 640, 480, &no_hist, &err) ==
           ACBB_EINVAL, "history kind with an empty history -> EINVAL");
    has_substr(err.msg, "history", "message names the history");
    ok(acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_PNG, path, 10, 480, d, &err) ==
           ACBB_EINVAL, "10 px wide -> EINVAL");
    ok(acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_DUMB, path, 640, 480, d, &err) ==
           ACBB_EINVAL, "dumb is not a file format");
    ok(acbb_plot_file((acbb_plot_kind)7, ACBB_PLOT_PNG, path, 640, 480, d, &err) == ACBB_EINVAL,
       "unknown kind -> EINVAL");
    static acbb_history nan_hist;
    nan_hist = hist;
    for (size_t i = 0; i < nan_hist.n; i++) nan_hist.p[i].T_ball = NAN;
    acbb_plot_data dn = { &nan_hist, NULL, NULL };
    ok(acbb_plot_file(ACBB_PLOT_TEMPERATURE, ACBB_PLOT_PNG, path, 640, 480, &dn, &err) ==
           ACBB_EINVAL, "no finite row -> EINVAL");
    has_substr(err.msg, "no finite data", "message says no finite data");
    ok(acbb_plot_check_size(ACBB_PLOT_PNG, 64, 20000, &err) == ACBB_OK &&
           acbb_plot_check_size(ACBB_PLOT_SVG, 63, 600, &err) == ACBB_EINVAL &&
           acbb_plot_check_size(ACBB_PLOT_PNG, 800, 20001, &err) == ACBB_EINVAL,
       "pixel sizes: 64..20000 per side");
    ok(acbb_plot_check_size(ACBB_PLOT_DUMB, 20, 8, &err) == ACBB_OK &&
           acbb_plot_check_size(ACBB_PLOT_DUMB, 19, 25, &err) == ACBB_EINVAL &&
           acbb_plot_check_size(ACBB_PLOT_DUMB, 80, 7, &err) == ACBB_EINVAL,
       "dumb sizes: at least 20 columns and 8 rows");
    has_substr(err.msg, "plot size 80x7", "size message names the size");
    char text[64];
    ok(acbb_plot_dumb(ACBB_PLOT_LOSSES, 5, 25, d, text, sizeof text, &err) == ACBB_EINVAL,
       "5-column dumb chart -> EINVAL");
    ok(!exists(path) && temp_files(dir) == 0, "rejected input creates no file");
}

int main(void)
{
    gsl_set_error_handler_off();
    snprintf(dir, sizeof dir, "/tmp/acbb-plot-XXXXXX");
    if (!mkdtemp(dir)) {
        ok(0, "mkdtemp: %s", strerror(errno));
        return done_testing();
    }
    make_run();
    acbb_plot_data d = { &hist, &snap, TITLE };
    int fds_before = open_fds();
    test_names();
    test_png_svg(&d);
    test_dumb(&d);
    test_missing_and_failing(&d);
    test_paths(&d);
    test_bad_input(&d);
    int fds_after = open_fds();
    ok(fds_before > 0 && fds_after == fds_before, "no descriptor leaked (%d before, %d after)",
       fds_before, fds_after);
    errno = 0;
    ok(waitpid(-1, NULL, WNOHANG) == -1 && errno == ECHILD, "every gnuplot child was reaped");

    /* Clean up the scratch directory. */
    DIR *dp = opendir(dir);
    if (dp) {
        for (struct dirent *e; (e = readdir(dp));) {
            if (e->d_name[0] == '.' && (!e->d_name[1] || !strcmp(e->d_name, ".."))) continue;
            char p[512];
            snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
            unlink(p);
        }
        closedir(dp);
    }
    ok(rmdir(dir) == 0, "scratch directory empty at the end");
    return done_testing();
}
