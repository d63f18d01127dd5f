/* acbb fuzzing — merge inputs and the --baseline JSON (fuzz_cli.h). The
 * CLI's own functions are called in-process (cli/merge.c, cli/baseline.c);
 * their stdout goes to a private file that is read back for inf/nan. */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "acbb/sim.h"
#include "args.h"
#include "baseline.h"
#include "exit.h"
#include "fuzz_cli.h"
#include "sweep.h"

static char dir[4096];

static int scratch(void)
{
    if (dir[0]) return 0;
    const char *t = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/acbb-fuzzcli-XXXXXX", t && *t ? t : "/tmp");
    return mkdtemp(dir) ? 0 : -1;
}

static int put(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    int bad = fwrite(data, 1, size, f) != size;
    return fclose(f) != 0 || bad ? -1 : 0;
}

/* The whole file (malloc'd, NUL-terminated; *len its size). */
static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *buf = NULL;
    size_t cap = 0;
    *len = 0;
    for (;;) {
        if (*len + 4097 > cap) {
            char *b = realloc(buf, cap = 2 * cap + 8192);
            if (!b) break;
            buf = b;
        }
        size_t r = fread(buf + *len, 1, 4096, f);
        *len += r;
        if (r == 0) break;
    }
    fclose(f);
    if (buf) buf[*len] = '\0';
    return buf;
}

/* A whole word inf / nan (any case) in text: a non-finite value printed. */
static int has_nonfinite(const char *s)
{
    for (const char *p = s; *p; p++) {
        int start = p == s || !((p[-1] >= 'a' && p[-1] <= 'z') || (p[-1] >= 'A' && p[-1] <= 'Z') ||
                                p[-1] == '_' || p[-1] == '.');
        if (start && (strncasecmp(p, "inf", 3) == 0 || strncasecmp(p, "nan", 3) == 0)) {
            char c = p[3];
            if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_')) return 1;
        }
    }
    return 0;
}

static acbb_fuzz_outcome broken(char *why, size_t n, const char *what, int rc)
{
    snprintf(why, n, "%s (exit %d)", what, rc);
    return ACBB_FUZZ_BROKEN;
}

static int merge(const char *out, const char *in)
{
    acbb_cli_args a;
    memset(&a, 0, sizeof a);
    a.cmd = "merge";
    a.pos[0] = out;
    a.pos[1] = in;
    a.n_pos = 2;
    return acbb_cli_cmd_merge(&a);
}

/* stderr off while the CLI speaks (its messages are expected), on after. */
static int quiet_stderr(void)
{
    fflush(stderr);
    int saved = dup(2), null = open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, 2), close(null);
    return saved;
}

static void restore_stderr(int saved)
{
    fflush(stderr);
    if (saved >= 0) dup2(saved, 2), close(saved);
}

acbb_fuzz_outcome acbb_fuzz_merge(const uint8_t *data, size_t size, char *why, size_t n)
{
    char in[4200], out[4200], again[4200];
    if (scratch() != 0) return broken(why, n, "no scratch directory", 0);
    snprintf(in, sizeof in, "%s/in", dir);
    snprintf(out, sizeof out, "%s/out", dir);
    snprintf(again, sizeof again, "%s/again", dir);
    unlink(out);
    unlink(again);
    if (put(in, data, size) != 0) return broken(why, n, "cannot write the input", 0);
    int saved = quiet_stderr();
    int rc = merge(out, in), rc2 = -1;
    /* 3: points missing, the merged file written all the same */
    int wrote = rc == ACBB_EXIT_OK || rc == ACBB_EXIT_SOLVER;
    if (wrote) rc2 = merge(again, out);
    restore_stderr(saved);
    if (!wrote && rc != ACBB_EXIT_INPUT) return broken(why, n, "merge: exit not 0, 2 or 3", rc);
    if (!wrote) return snprintf(why, n, "merge refused it (exit 2)"), ACBB_FUZZ_REJECTED;
    size_t la = 0, lb = 0;
    char *a = slurp(out, &la), *b = slurp(again, &lb);
    acbb_fuzz_outcome o = ACBB_FUZZ_ACCEPTED;
    /* Its numbers are finite: the second merge re-checks every record. */
    if (!a) o = broken(why, n, "merge output missing", rc);
    else if (rc2 != rc || !b || la != lb || memcmp(a, b, la) != 0)
        o = broken(why, n, "merge output is not canonical (merging it again differs)", rc2);
    free(a);
    free(b);
    return o;
}

/* ---- resume: the sweep-file reader of a resumed sweep (sweep_sink.c) ---- */

/* The one sweep every resume input is read as (tests/fuzz/corpus/resume
 * holds its outputs): `acbb sweep presets/7008C.ini --set
 * fidelity.model=quasi-static --grid operating.axial_load_N=100,200 --grid
 * effects.thermal_expansion=on,off`, steady. */
static acbb_sweep *res_grid;
static acbb_scene res_scene;
static acbb_cli_sweep_id res_id;

static int resume_sweep(void)
{
    if (res_grid) return 0;
    acbb_error err = { { 0 } };
    if (acbb_scene_load("presets/7008C.ini", &res_scene, &err) != ACBB_OK ||
        acbb_scene_set(&res_scene, "fidelity.model", "quasi-static", &err) != ACBB_OK ||
        acbb_sweep_new(&res_grid) != ACBB_OK)
        return -1;
    if (acbb_sweep_add(res_grid, "operating.axial_load_N=100,200", &err) != ACBB_OK ||
        acbb_sweep_add(res_grid, "effects.thermal_expansion=on,off", &err) != ACBB_OK)
        return -1;
    acbb_cli_sweep_id_init(&res_id, res_grid, &res_scene, 0, NULL);
    return 0;
}

/* Open (lock, resume, header) and close the file as a sweep would, running
 * no point. Returns the open's exit status; *found, *close_rc. */
static int resume_once(const char *path, acbb_cli_rec_format fmt, size_t *found, int *close_rc)
{
    unsigned char count[4] = { 0 };
    acbb_cli_sink o;
    int saved = quiet_stderr();
    int rc = acbb_cli_sink_open(&o, path, fmt, &res_id, count, found);
    *close_rc = acbb_cli_sink_close(&o);
    restore_stderr(saved);
    return rc;
}

acbb_fuzz_outcome acbb_fuzz_resume(const uint8_t *data, size_t size, char *why, size_t n)
{
    char path[4200];
    if (scratch() != 0 || resume_sweep() != 0) return broken(why, n, "no scratch or sweep", 0);
    snprintf(path, sizeof path, "%s/resume", dir);
    if (put(path, data, size) != 0) return broken(why, n, "cannot write the input", 0);
    acbb_cli_rec_format fmt = size && data[0] == '#' ? ACBB_CLI_REC_CSV : ACBB_CLI_REC_JSONL;
    /* A CSV input carries its header on its first line (--csv-header): a
     * plain CSV's would be in a sidecar, which a one-file input has not. */
    res_id.csv_header = fmt == ACBB_CLI_REC_CSV;
    size_t found = 0, found2 = 0, la = 0, lb = 0;
    int crc = 0, crc2 = 0;
    int rc = resume_once(path, fmt, &found, &crc);
    char *a = slurp(path, &la), *b = NULL;
    acbb_fuzz_outcome o = ACBB_FUZZ_ACCEPTED;
    if (!a) o = broken(why, n, "the file is gone", rc);
    else if (rc == ACBB_EXIT_INPUT)
        /* Refused: the file as it was (resume never cuts another's file). */
        o = la == size && memcmp(a, data, la) == 0
                ? (snprintf(why, n, "resume refused it (exit 2), the file untouched"), ACBB_FUZZ_REJECTED)
                : broken(why, n, "a refused resume changed the file", rc);
    else if (rc != ACBB_EXIT_OK || crc != 0) o = broken(why, n, "resume: exit not 0 or 2", rc ? rc : crc);
    else if (la == 0 || a[la - 1] != '\n') o = broken(why, n, "resumed file does not end with a whole line", rc);
    else {
        /* Accepted: the file now holds a header and whole records only, so
         * a second resume finds the same and changes nothing. */
        int rc2 = resume_once(path, fmt, &found2, &crc2);
        b = slurp(path, &lb);
        if (rc2 != 0 || crc2 != 0 || found2 != found || !b || la != lb || memcmp(a, b, la) != 0)
            o = broken(why, n, "a second resume differs from the first", rc2);
    }
    free(a);
    free(b);
    return o;
}

/* One quasi-static run of 7008C, made once: the "now" of every baseline. */
static acbb_scene base_scene;
static acbb_snapshot *base_snap;

static int base_run(void)
{
    if (base_snap) return 0;
    acbb_error err = { { 0 } };
    acbb_sim *sim = NULL;
    base_snap = calloc(1, sizeof *base_snap);
    if (!base_snap || acbb_scene_load("presets/7008C.ini", &base_scene, &err) != ACBB_OK) {
        acbb_scene_default(&base_scene);
    }
    base_scene.model = ACBB_MODEL_QUASI_STATIC;
    if (!base_snap || acbb_sim_create(&base_scene, NULL, &sim, &err) != ACBB_OK) return -1;
    acbb_sim_run(sim);
    acbb_sim_snapshot(sim, base_snap);
    acbb_sim_free(sim);
    return 0;
}

acbb_fuzz_outcome acbb_fuzz_baseline(const uint8_t *data, size_t size, char *why, size_t n)
{
    char in[4200], out[4200];
    if (scratch() != 0 || base_run() != 0) return broken(why, n, "no scratch or base run", 0);
    snprintf(in, sizeof in, "%s/base.json", dir);
    snprintf(out, sizeof out, "%s/stdout", dir);
    if (put(in, data, size) != 0) return broken(why, n, "cannot write the input", 0);
    acbb_fuzz_outcome o = ACBB_FUZZ_ACCEPTED;
    for (int json = 0; json < 2 && o == ACBB_FUZZ_ACCEPTED; json++) {
        fflush(stdout);
        int saved_out = dup(1), fd = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (fd >= 0) dup2(fd, 1), close(fd);
        int saved = quiet_stderr();
        int rc = acbb_cli_baseline(in, &base_scene, base_snap, json, false);
        fflush(stdout);
        restore_stderr(saved);
        if (saved_out >= 0) dup2(saved_out, 1), close(saved_out);
        size_t len = 0;
        char *text = slurp(out, &len);
        if (rc != ACBB_EXIT_OK && rc != ACBB_EXIT_INPUT) o = broken(why, n, "--baseline: exit not 0 or 2", rc);
        else if (rc == ACBB_EXIT_INPUT) o = ACBB_FUZZ_REJECTED;
        else if (!text || has_nonfinite(text)) o = broken(why, n, "--baseline output holds inf/nan", rc);
        free(text);
    }
    return o;
}
