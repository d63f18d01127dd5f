/* acbb TUI — the event loop (the cmus ui_curses.c idea).
 *
 * One select() waits on stdin, the worker's wake-up pipe and the signal
 * self-pipe. Keys are handled at once and redrawn at once; snapshots only
 * mark the screen stale, and a stale screen is redrawn at most every
 * FRAME_S (about 10 Hz). Every frame copies the worker's state out once,
 * erases stdscr, draws, and ends with one doupdate(): never clear(). */
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <time.h>
#include <unistd.h>

#include "acbb/tools/measure.h"
#include "../cli/exit.h"
#include "screens.h"
#include "recover.h"
#include "results.h"

#define FRAME_S 0.1          /* redraw cap for snapshot-driven frames */
#define IDLE_TIMEOUT_S 1.0   /* redraw the clock now and then while nothing happens */
#define RECOVER_S 5.0        /* unsaved edits go to the recovery file this often */
#define HANGUP_SPINS 1000    /* stdin readable but no key, this often: the tty is gone */

/* Simulated seconds per wall second. The default, x200, shows the
 * transients of the presets (2000-5000 simulated s) in 10-25 s of wall
 * time: long enough to watch, short enough for a lesson. */
static const int pace_ladder[] = { 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 0 };
#define PACE_DEFAULT 200
#define PACE_N (int)(sizeof pace_ladder / sizeof pace_ladder[0])

int acbb_app_pace(int idx)
{
    if (idx < 0) idx = 0;
    if (idx >= PACE_N) idx = PACE_N - 1;
    return pace_ladder[idx];
}

static int pace_index(int steps_per_s)
{
    if (steps_per_s <= 0) return PACE_N - 1;
    int best = 0;
    for (int i = 0; i < PACE_N - 1; i++)
        if (pace_ladder[i] <= steps_per_s) best = i;
    return best;
}

void acbb_app_msg(acbb_app *a, acbb_role role, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(a->msg, sizeof a->msg, fmt, ap);
    va_end(ap);
    a->msg_role = role;
    a->msg_cmd = 0;
}

void acbb_app_prompt(acbb_app *a, acbb_prompt_kind kind, const char *label, const char *init)
{
    a->mode = ACBB_MODE_PROMPT;
    a->prompt.kind = kind;
    snprintf(a->prompt.label, sizeof a->prompt.label, "%s", label);
    snprintf(a->prompt.buf, sizeof a->prompt.buf, "%s", init);
    a->prompt.len = strlen(a->prompt.buf);
    a->prompt.commit = NULL;
    a->prompt.names = NULL;
    a->prompt.shown[0] = '\0';
}

void acbb_app_ask(acbb_app *a, const char *label, const char *init, acbb_prompt_fn commit,
                  acbb_name_fn names)
{
    acbb_app_prompt(a, ACBB_PROMPT_CALL, label, init);
    a->prompt.commit = commit;
    a->prompt.names = names;
}

/* Unsaved edits of this preset from an earlier session: offer them back. */
static void offer_recovery(acbb_app *a)
{
    if (!acbb_recover_pending(&a->ed, a->confirm.path, sizeof a->confirm.path)) return;
    a->mode = ACBB_MODE_CONFIRM;
    a->confirm.kind = ACBB_CONFIRM_RECOVER;
}

static void open_now(acbb_app *a, const char *path)
{
    acbb_error err = { { 0 } };
    if (acbb_editor_open(&a->ed, path, &err) != ACBB_OK) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s", err.msg);
        return;
    }
    a->edit_error[0] = '\0';
    /* The last preset's results must not pose as this one's (issue 21 item 2):
     * the worker goes back to ambient with the new scene, idle. */
    acbb_app_post(a, ACBB_CMD_RESET, &a->ed.scene, 0, "reset");
    acbb_results_drop(a); /* and so must every other screen's (issue 29 item 2), the baseline too */
    acbb_app_msg(a, ACBB_ROLE_OK, "opened %s (r: run it, a: apply warm)", path);
    offer_recovery(a);
}

void acbb_app_open(acbb_app *a, const char *path)
{
    if (a->ed.modified) {
        a->mode = ACBB_MODE_CONFIRM;
        a->confirm.kind = ACBB_CONFIRM_OPEN;
        snprintf(a->confirm.path, sizeof a->confirm.path, "%s", path);
        return;
    }
    open_now(a, path);
}

/* ---- commands to the worker ---- */

void acbb_app_post(acbb_app *a, acbb_worker_cmd cmd, const acbb_scene *s, int warm, const char *what)
{
    unsigned long seq = acbb_worker_post(a->worker, cmd, s, warm);
    if (seq == 0) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "worker busy; %s not sent, try again", what);
        return;
    }
    if (cmd == ACBB_CMD_START) a->start_cmd = seq;
    acbb_app_msg(a, ACBB_ROLE_NORMAL, "%s", what);
    /* Once the worker took it, the status line (or the TE/WTE screen)
     * shows what it did: the key hints come back rather than staying
     * hidden for the whole run (issue 29 item 6). */
    a->msg_cmd = seq;
}

static void pause_or_resume(acbb_app *a)
{
    if (a->st.phase == ACBB_WORKER_RUNNING) acbb_app_post(a, ACBB_CMD_PAUSE, NULL, 0, "paused");
    else if (a->st.phase == ACBB_WORKER_PAUSED) acbb_app_post(a, ACBB_CMD_RESUME, NULL, 0, "resumed");
    else acbb_app_msg(a, ACBB_ROLE_WARN, "no run in progress (r starts one)");
}

static void change_pace(acbb_app *a, int dir)
{
    a->pace_idx += dir;
    if (a->pace_idx < 0) a->pace_idx = 0;
    if (a->pace_idx >= PACE_N) a->pace_idx = PACE_N - 1;
    int p = acbb_app_pace(a->pace_idx);
    acbb_worker_set_pace(a->worker, p);
    if (p > 0) acbb_app_msg(a, ACBB_ROLE_NORMAL, "pace x%d: %d simulated s per second", p, p);
    else acbb_app_msg(a, ACBB_ROLE_NORMAL, "pace: flat out");
}

static void save(acbb_app *a, const char *path)
{
    acbb_error err = { { 0 } };
    char dir[PATH_MAX];
    const char *target = path ? path : a->ed.path;
    if (a->installed && target[0] && a->installed(target, dir, sizeof dir)) {
        /* An installed preset is every user's (issue 26 item 6, as `acbb
         * edit`): save as a file of one's own instead. */
        acbb_app_prompt(a, ACBB_PROMPT_SAVE_AS, "installed preset, shared by every user: save as: ",
                        "my-preset.ini");
        return;
    }
    if (acbb_editor_save(&a->ed, path, &err) != ACBB_OK && a->ed.conflict) {
        a->mode = ACBB_MODE_CONFIRM; /* changed on disk: reload / overwrite / elsewhere */
        a->confirm.kind = ACBB_CONFIRM_CHANGED;
    } else if (err.msg[0]) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "save failed: %s", err.msg);
    } else {
        acbb_recover_clear(&a->ed);
        acbb_app_msg(a, ACBB_ROLE_OK, "saved %s", a->ed.path);
    }
}

/* The file changed on disk since it was read (issue 20 item 2). */
static void changed_key(acbb_app *a, int ch)
{
    acbb_error err = { { 0 } };
    if (ch == 'r' || ch == 'R') {
        char path[sizeof a->ed.path];
        snprintf(path, sizeof path, "%s", a->ed.path);
        acbb_recover_clear(&a->ed);
        open_now(a, path);
    } else if ((ch == 'o' || ch == 'O') && acbb_editor_overwrite(&a->ed, &err) == ACBB_OK) {
        acbb_recover_clear(&a->ed);
        acbb_app_msg(a, ACBB_ROLE_OK, "saved %s over the changes on disk", a->ed.path);
    } else if (ch == 'o' || ch == 'O') {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "save failed: %s", err.msg);
    } else if (ch == 's' || ch == 'S') {
        acbb_app_prompt(a, ACBB_PROMPT_SAVE_AS, "save as: ", a->ed.path);
    } else {
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "not saved (the file on disk is unchanged)");
    }
}

/* Work is going on (a run, or any screen's background job): q must not
 * throw it away unasked (issue 21 item 6, issue 29 item 3). */
static void request_quit(acbb_app *a)
{
    if (acbb_results_busy(a, NULL, NULL) &&
        !(a->mode == ACBB_MODE_CONFIRM && a->confirm.kind == ACBB_CONFIRM_QUIT_RUN)) {
        a->mode = ACBB_MODE_CONFIRM;
        a->confirm.kind = ACBB_CONFIRM_QUIT_RUN;
        return;
    }
    if (!a->ed.modified) {
        a->quit = 1;
        return;
    }
    a->mode = ACBB_MODE_CONFIRM;
    a->confirm.kind = ACBB_CONFIRM_QUIT;
}

/* ---- keys ---- */

int acbb_app_polished(const acbb_app *a)
{
    return a->st.phase == ACBB_WORKER_DONE && a->st.snap.state == ACBB_RUN_CONVERGED && a->hist.n > 1;
}

/* `/` and n/N go to the screen's (or the help's) search. */
static void search(acbb_app *a, int dir)
{
    if (!a->search[0]) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "no search yet: / types one");
        return;
    }
    int found = a->search_help ? acbb_screen_help_search(a, a->search, dir)
                               : acbb_screen_current(a)->search(a, a->search, dir);
    if (found) acbb_app_msg(a, ACBB_ROLE_NORMAL, "/%s  (n next, N previous)", a->search);
    else acbb_app_msg(a, ACBB_ROLE_WARN, "not found: %s", a->search);
}

static void search_begin(acbb_app *a, int in_help)
{
    if (!in_help && !acbb_screen_current(a)->search) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "/ searches the Edit and Nodes screens and the help (?)");
        return;
    }
    a->search_help = in_help;
    acbb_app_prompt(a, ACBB_PROMPT_SEARCH, "/", "");
}

int acbb_app_search_key(acbb_app *a, int ch, int in_help)
{
    switch (ch) {
    case '/': search_begin(a, in_help); return 1;
    case 'n': case 'N':
        if (!in_help && !acbb_screen_current(a)->search) {
            search_begin(a, 0); /* says where / works */
            return 1;
        }
        a->search_help = in_help;
        search(a, ch == 'n' ? 1 : -1);
        return 1;
    default: return 0;
    }
}

static void global_key(acbb_app *a, int ch)
{
    for (int i = 0; i < acbb_screen_count; i++)
        if (ch == acbb_screens[i]->key) {
            acbb_screen_show(a, i);
            return;
        }
    switch (ch) {
    case '\t': acbb_screen_show(a, a->screen + 1); break;
    case KEY_BTAB: acbb_screen_show(a, a->screen - 1); break;
    case '?': case KEY_F(1): a->mode = ACBB_MODE_HELP; a->help_top = 0; break;
    case 'q': case KEY_F(10): request_quit(a); break;
    case 12: clearok(curscr, TRUE); break; /* Ctrl-L: redraw from scratch */
    case 'v': acbb_screen_run_view(a); break;
    case 'm': acbb_screen_run_pin(a, 1); break;
    case 'M': acbb_screen_run_pin(a, 0); break;
    case '/': case 'n': case 'N': acbb_app_search_key(a, ch, 0); break;
    case KEY_MOUSE: acbb_app_mouse(a); break;
    case 'r': acbb_app_post(a, ACBB_CMD_START, &a->ed.scene, 0, "run started (cold, edited scene)"); break;
    case ' ': case 'p': pause_or_resume(a); break;
    case 'x': acbb_app_post(a, ACBB_CMD_STOP, NULL, 0, "stopped"); break;
    case 'R': acbb_app_post(a, ACBB_CMD_RESET, NULL, 0, "reset to ambient"); break;
    case 'a': acbb_app_post(a, ACBB_CMD_APPLY, &a->ed.scene, 1, "applied edits, warm restart"); break;
    case 'A': acbb_app_post(a, ACBB_CMD_APPLY, &a->ed.scene, 0, "applied edits, cold restart"); break;
    case '+': case '=': change_pace(a, +1); break;
    case '-': change_pace(a, -1); break;
    case 't': acbb_screen_compare_start(a); break;
    case 'u':
        if (acbb_editor_undo(&a->ed)) acbb_app_msg(a, ACBB_ROLE_NORMAL, "undone");
        else acbb_app_msg(a, ACBB_ROLE_WARN, "nothing to undo");
        a->edit_error[0] = '\0';
        break;
    case 'w': save(a, NULL); break;
    case 'W': acbb_app_prompt(a, ACBB_PROMPT_SAVE_AS, "save as: ", a->ed.path); break;
    case 'o': acbb_screen_browse_begin(a); break;
    case 'g': acbb_screen_plot_export(a); break;
    case '[': case ']': acbb_set_choose(a, a->bearing + (ch == ']' ? 1 : -1)); break;
    case 'b': acbb_screen_accuracy_start(a, 0); break;
    case 'B': acbb_screen_accuracy_start(a, 1); break;
    case 27: a->msg[0] = '\0'; break;
    case KEY_RESIZE: break;
    default:
        acbb_app_msg(a, ACBB_ROLE_WARN, "unknown key (? lists every key)");
        break;
    }
}

static int screen_key(acbb_app *a, int ch)
{
    const acbb_screen *s = acbb_screen_current(a);
    return s->on_key ? s->on_key(a, ch) : 0;
}

static void prompt_commit(acbb_app *a)
{
    acbb_error err = { { 0 } };
    const char *text = a->prompt.buf;
    a->mode = ACBB_MODE_NORMAL;
    switch (a->prompt.kind) {
    case ACBB_PROMPT_VALUE:
        if (acbb_editor_set(&a->ed, a->ed.cursor, text, &err) != ACBB_OK) {
            snprintf(a->edit_error, sizeof a->edit_error, "%s", err.msg);
            acbb_app_msg(a, ACBB_ROLE_ERROR, "refused: %s", err.msg);
        } else {
            a->edit_error[0] = '\0';
            acbb_screen_editor_edited(a, "edited (a: apply warm, A: apply cold, w: save)");
        }
        break;
    case ACBB_PROMPT_SAVE_AS:
        if (text[0]) save(a, text);
        break;
    case ACBB_PROMPT_OPEN:
        if (text[0]) acbb_app_open(a, text);
        break;
    case ACBB_PROMPT_SEARCH:
        if (a->search_help) a->mode = ACBB_MODE_HELP;
        if (text[0]) {
            snprintf(a->search, sizeof a->search, "%.63s", text);
            search(a, 0);
        }
        break;
    case ACBB_PROMPT_CALL:
        a->prompt.commit(a, text);
        break;
    }
}

/* Tab in a screen's question: complete among its names, listing them. */
static void prompt_complete(acbb_app *a)
{
    if (!a->prompt.names) return;
    int n = acbb_complete(a->prompt.buf, sizeof a->prompt.buf, a->prompt.names, a->prompt.shown,
                          sizeof a->prompt.shown);
    a->prompt.len = strlen(a->prompt.buf);
    if (n == 0) snprintf(a->prompt.shown, sizeof a->prompt.shown, "no name contains %s", a->prompt.buf);
}

static void prompt_key(acbb_app *a, int ch)
{
    switch (ch) {
    case 27:
        a->mode = a->prompt.kind == ACBB_PROMPT_SEARCH && a->search_help ? ACBB_MODE_HELP : ACBB_MODE_NORMAL;
        acbb_app_msg(a, ACBB_ROLE_NORMAL, "cancelled");
        return;
    case '\n': case '\r': case KEY_ENTER: prompt_commit(a); return;
    case '\t': prompt_complete(a); return;
    case KEY_BACKSPACE: case 127: case 8:
        if (a->prompt.len > 0) a->prompt.buf[--a->prompt.len] = '\0';
        return;
    case 21: /* Ctrl-U */
        a->prompt.len = 0;
        a->prompt.buf[0] = '\0';
        return;
    default:
        if (ch >= 32 && ch < 127 && a->prompt.len + 1 < sizeof a->prompt.buf) {
            a->prompt.buf[a->prompt.len++] = (char)ch;
            a->prompt.buf[a->prompt.len] = '\0';
        }
    }
}

static void confirm_key(acbb_app *a, int ch)
{
    a->mode = ACBB_MODE_NORMAL;
    if (a->confirm.kind == ACBB_CONFIRM_RECOVER) {
        char why[512];
        if (ch != 'y' && ch != 'Y') {
            acbb_recover_clear(&a->ed);
            acbb_app_msg(a, ACBB_ROLE_NORMAL, "recovered edits discarded");
        } else if (acbb_recover_restore(&a->ed, a->confirm.path, why, sizeof why) != 0) {
            acbb_app_msg(a, ACBB_ROLE_ERROR, "cannot restore: %s", why);
        } else {
            acbb_app_msg(a, ACBB_ROLE_OK, "edits restored from the recovery file (u undoes, w writes them)");
        }
    } else if (a->confirm.kind == ACBB_CONFIRM_CHANGED) {
        changed_key(a, ch);
    } else if (a->confirm.kind == ACBB_CONFIRM_QUIT_RUN) {
        if (ch == 'y' || ch == 'Y') {
            a->mode = ACBB_MODE_CONFIRM; /* keeps the question while asking on */
            request_quit(a);             /* unsaved edits are asked about next */
        } else {
            const char *noun;
            acbb_results_busy(a, NULL, &noun);
            acbb_app_msg(a, ACBB_ROLE_NORMAL, "not quitting: the %s goes on", noun[0] ? noun : "work");
        }
    } else if (a->confirm.kind == ACBB_CONFIRM_QUIT) {
        if (ch == 'y' || ch == 'Y') {
            acbb_recover_clear(&a->ed); /* the user chose to discard them */
            a->quit = 1;
        } else if (ch == 's' || ch == 'S') {
            save(a, NULL);
            if (!a->ed.modified) a->quit = 1;
        } else acbb_app_msg(a, ACBB_ROLE_NORMAL, "not quitting");
    } else {
        if (ch == 'y' || ch == 'Y') open_now(a, a->confirm.path);
        else acbb_app_msg(a, ACBB_ROLE_NORMAL, "kept the current edits");
    }
}

void acbb_app_key(acbb_app *a, int ch)
{
    /* While the terminal is too small nothing is drawn, so no key may act
     * unseen: only quitting, redrawing and resizing. */
    if (a->lay.too_small) {
        if (a->mode == ACBB_MODE_CONFIRM &&
            (a->confirm.kind == ACBB_CONFIRM_QUIT || a->confirm.kind == ACBB_CONFIRM_QUIT_RUN))
            confirm_key(a, ch);
        else if (ch == 'q' || ch == KEY_F(10)) request_quit(a);
        else if (ch == 12) clearok(curscr, TRUE);
        return;
    }
    switch (a->mode) {
    case ACBB_MODE_PROMPT: prompt_key(a, ch); return;
    case ACBB_MODE_CONFIRM: confirm_key(a, ch); return;
    case ACBB_MODE_HELP: acbb_screen_help_key(a, ch); return;
    case ACBB_MODE_BROWSE: acbb_screen_browse_key(a, ch); return;
    case ACBB_MODE_NORMAL: break;
    }
    /* A message lasts until the next key, then the key hints are back
     * (htop keeps its F-key bar): Esc is not needed to see them. */
    if (ch != KEY_MOUSE && ch != KEY_RESIZE) a->msg[0] = '\0';
    if (!screen_key(a, ch)) global_key(a, ch);
}

/* ---- frame ---- */

const char *acbb_app_hint(const acbb_app *a)
{
    const char *h = acbb_screen_current(a)->hint;
    return h ? h : ACBB_RUN_HINT;
}

/* The question being asked, into buf. */
static void confirm_text(acbb_app *a, char *buf, size_t n)
{
    const char *name = acbb_editor_name(&a->ed), *what;
    switch (a->confirm.kind) {
    case ACBB_CONFIRM_QUIT_RUN:
        acbb_results_busy(a, &what, NULL);
        snprintf(buf, n, "%s is in progress. Quit and lose it? y = quit, n = stay", what[0] ? what : "Work");
        break;
    case ACBB_CONFIRM_QUIT:
        snprintf(buf, n, "Unsaved edits to %s. Quit anyway? y = quit, s = save and quit, n = stay", name);
        break;
    case ACBB_CONFIRM_CHANGED:
        snprintf(buf, n, "%s changed on disk since it was read. r = reload it (drop my edits), "
                 "o = overwrite, s = save elsewhere, n = cancel", name);
        break;
    case ACBB_CONFIRM_RECOVER:
        snprintf(buf, n, "Unsaved edits of %s from an earlier session. Restore them? y/n", name);
        break;
    default:
        snprintf(buf, n, "Unsaved edits. Discard them and open %s? y/n", a->confirm.path);
    }
}

/* A question wider than the row takes the status line too (issue 29 item
 * 7: at 80 columns its answers were cut off). */
static void draw_confirm(acbb_app *a, acbb_rect r)
{
    char text[PATH_MAX + 256];
    confirm_text(a, text, sizeof text);
    if ((int)strlen(text) <= r.w) {
        acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_WARN, "%s", text);
        return;
    }
    int y = a->lay.status.y;
    move(y, 0);
    clrtoeol();
    acbb_put_wrap(a, y, r.x, r.w, r.y - y + 1, ACBB_ROLE_WARN, text);
}

static void draw_message(acbb_app *a)
{
    acbb_rect r = a->lay.message;
    if (a->mode == ACBB_MODE_PROMPT) {
        acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_HEADER, "%s", a->prompt.label);
        int x = r.x + (int)strlen(a->prompt.label);
        int room = r.x + r.w - x - 1;
        size_t off = a->prompt.len > (size_t)room && room > 0 ? a->prompt.len - (size_t)room : 0;
        acbb_put(a, r.y, x, room + 1, ACBB_ROLE_NORMAL, "%s_", a->prompt.buf + off);
        if (a->prompt.shown[0]) { /* the matches, over the status line */
            move(a->lay.status.y, 0);
            clrtoeol();
            acbb_put(a, a->lay.status.y, 0, a->lay.status.w, ACBB_ROLE_DIM, "%s", a->prompt.shown);
        }
    } else if (a->mode == ACBB_MODE_CONFIRM) {
        draw_confirm(a, r);
    } else if (a->msg[0] && !(a->msg_cmd && a->st.cmd_done >= a->msg_cmd)) {
        acbb_put(a, r.y, r.x, r.w, a->msg_role, "%s", a->msg);
    } else {
        acbb_put(a, r.y, r.x, r.w, ACBB_ROLE_DIM, "%s", acbb_app_hint(a));
    }
}

static void draw_body(acbb_app *a)
{
    if (a->mode == ACBB_MODE_HELP) {
        acbb_screen_help_draw(a);
        return;
    }
    acbb_screen_current(a)->draw(a);
    if (a->mode == ACBB_MODE_BROWSE) acbb_screen_browse_draw(a);
}

/* Take the worker's latest state and derive what the status line needs. */
static void take_state(acbb_app *a)
{
    acbb_worker_read(a->worker, &a->st, &a->hist);
    acbb_results_take(a);
    if (a->st.run_id != a->prog_run) {
        acbb_progress_reset(&a->prog);
        a->prog_run = a->st.run_id;
    }
    if (a->st.phase == ACBB_WORKER_RUNNING && a->st.snap.iteration > 0)
        acbb_progress_update(&a->prog, a->st.snap.residual, a->st.run_wall_s,
                             a->st.scene.steady_tol);
    if (a->st.err_cmd > a->shown_err) {
        a->shown_err = a->st.err_cmd;
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s", a->st.message);
    }
    if (a->exit_after_steady && a->start_cmd && a->st.cmd_done >= a->start_cmd &&
        a->st.phase == ACBB_WORKER_DONE) {
        a->quit = 1;
        a->exit_code = a->st.snap.state == ACBB_RUN_CONVERGED ? ACBB_EXIT_OK : ACBB_EXIT_SOLVER;
    }
}

static void frame(acbb_app *a)
{
    int rows, cols;
    take_state(a);
    getmaxyx(stdscr, rows, cols);
    acbb_layout_compute(rows, cols, &a->lay);
    erase();
    if (a->lay.too_small) {
        acbb_put(a, 0, 0, cols, ACBB_ROLE_ERROR, "terminal too small: %dx%d, need %dx%d", cols, rows,
                 ACBB_LAYOUT_MIN_COLS, ACBB_LAYOUT_MIN_ROWS);
        if (rows > 1)
            acbb_put(a, 1, 0, cols, ACBB_ROLE_NORMAL, "%s",
                     a->mode == ACBB_MODE_CONFIRM ? "unsaved edits: quit anyway? y/n"
                                                  : "keys wait until it is larger; q quits");
    } else {
        acbb_draw_title(a);
        draw_body(a);
        acbb_draw_status(a);
        draw_message(a);
    }
    wnoutrefresh(stdscr);
    doupdate();
}

/* ---- the loop ---- */

/* The wake-up pipes: 0 the Sim worker, 1 + i screen i's job (screens.h
 * wake_fd; -1 when it has none). */
#define N_WAKES (1 + ACBB_MAX_TABS)

typedef struct {
    int input, signal;
    int wake[N_WAKES];
} ready_fds;

static int wake_fd(acbb_app *a, int k)
{
    if (k == 0) return acbb_worker_wake_fd(a->worker);
    const acbb_screen *s = k - 1 < acbb_screen_count ? acbb_screens[k - 1] : NULL;
    return s && s->wake_fd ? s->wake_fd(a) : -1;
}

static void drain_wake(acbb_app *a, int k)
{
    if (k == 0) acbb_worker_drain_wake(a->worker);
    else acbb_screens[k - 1]->wake(a);
}

static void wait_events(acbb_app *a, double timeout_s, ready_fds *r)
{
    fd_set rf;
    int sfd = a->term.sig_rd, maxfd = sfd;
    FD_ZERO(&rf);
    FD_SET(STDIN_FILENO, &rf);
    FD_SET(sfd, &rf);
    for (int k = 0; k < N_WAKES; k++) {
        int fd = wake_fd(a, k);
        if (fd < 0) continue;
        FD_SET(fd, &rf);
        if (fd > maxfd) maxfd = fd;
    }
    struct timeval tv = { (time_t)timeout_s, (suseconds_t)((timeout_s - (long)timeout_s) * 1e6) };
    memset(r, 0, sizeof *r);
    int n = select(maxfd + 1, &rf, NULL, NULL, &tv);
    if (n < 0) {
        r->signal = errno == EINTR; /* the handler's byte is waiting in the pipe */
        return;
    }
    r->input = FD_ISSET(STDIN_FILENO, &rf);
    r->signal = FD_ISSET(sfd, &rf);
    for (int k = 0; k < N_WAKES; k++) {
        int fd = wake_fd(a, k);
        r->wake[k] = fd >= 0 && FD_ISSET(fd, &rf);
    }
}

/* Leaving on a signal or a second Ctrl-C: the edits go to the recovery
 * file; when they cannot, that is said loudly on the restored terminal. */
static void keep_edits(acbb_app *a)
{
    char why[sizeof a->leave_msg - 128];
    if (acbb_recover_write(&a->ed, why, sizeof why) != 0)
        snprintf(a->leave_msg, sizeof a->leave_msg, "acbb tui: UNSAVED EDITS OF %s ARE LOST: "
                 "%s\n", a->ed.path[0] ? a->ed.path : "the default scene", why);
}

static void handle_signals(acbb_app *a, int *redraw)
{
    acbb_term_events ev;
    acbb_term_signals(&a->term, &ev);
    if (ev.winch) {
        acbb_term_resize(&a->term);
        *redraw = 1;
    }
    if (ev.fatal) {
        /* SIGTERM / SIGHUP / SIGQUIT: keep the edits, leave now; the
         * caller restores the terminal. */
        keep_edits(a);
        a->quit = 1;
        a->exit_code = ACBB_EXIT_SIGNAL(ev.fatal);
    } else if (ev.interrupt) {
        /* Ctrl-C is "quit"; a second one while asking means yes, and the
         * edits go to the recovery file rather than being lost. */
        if (a->mode == ACBB_MODE_CONFIRM &&
            (a->confirm.kind == ACBB_CONFIRM_QUIT || a->confirm.kind == ACBB_CONFIRM_QUIT_RUN)) {
            keep_edits(a);
            a->quit = 1;
        }
        else {
            a->mode = ACBB_MODE_NORMAL;
            request_quit(a);
        }
        *redraw = 1;
    }
}

/* Read every key waiting, then act on them; a mouse report that curses
 * left as raw bytes is taken out of them first (mouse.c). */
static void read_keys(acbb_app *a, int *redraw, int *spins)
{
    int k[256], n = 0, ch;
    while (n < (int)(sizeof k / sizeof k[0]) && (ch = getch()) != ERR) k[n++] = ch;
    for (int i = 0; i < n && !a->quit;) {
        int b, x, y, press, used = acbb_mouse_decode(k + i, n - i, &b, &x, &y, &press);
        if (used) {
            acbb_app_mouse_raw(a, b, x, y, press);
            i += used;
        } else acbb_app_key(a, k[i++]);
    }
    *spins = n ? 0 : *spins + 1;
    if (*spins > HANGUP_SPINS) { /* the terminal went away without SIGHUP */
        a->quit = 1;
        a->exit_code = ACBB_EXIT_HANGUP;
    }
    *redraw |= n > 0;
}

static void loop(acbb_app *a)
{
    double last_frame = 0.0, last_recover = 1e-3 * acbb_now_ms();
    int stale = 1, redraw = 1, spins = 0;
    while (!a->quit) {
        double t = 1e-3 * acbb_now_ms();
        if (t - last_recover >= RECOVER_S) {
            char why[sizeof a->leave_msg];
            if (acbb_recover_write(&a->ed, why, sizeof why) != 0)
                acbb_app_msg(a, ACBB_ROLE_WARN, "unsaved edits cannot be kept: %s", why);
            last_recover = t;
        }
        if (redraw || (stale && t - last_frame >= FRAME_S)) {
            frame(a);
            last_frame = t;
            redraw = stale = 0;
            if (a->quit) break;
        }
        double timeout = stale ? FRAME_S - (t - last_frame) : IDLE_TIMEOUT_S;
        if (timeout < 0) timeout = 0;
        ready_fds r;
        wait_events(a, timeout, &r);
        if (r.signal) handle_signals(a, &redraw);
        int woken = 0;
        for (int k = 0; k < N_WAKES; k++)
            if (r.wake[k]) {
                drain_wake(a, k);
                woken = stale = 1;
            }
        if (r.input) read_keys(a, &redraw, &spins);
        if (!r.input && !woken && !r.signal) stale = 1; /* timeout: refresh the clock */
    }
}

/* ---- set-up and tear-down ---- */

static void load_initial(acbb_app *a, const char *preset)
{
    acbb_error err = { { 0 } };
    const char *path = preset ? preset : "presets/7008C.ini";
    acbb_editor_init(&a->ed);
    if (!preset && access(path, F_OK) != 0) {
        acbb_app_msg(a, ACBB_ROLE_WARN, "%s not found: starting from the built-in default scene", path);
        return;
    }
    if (acbb_editor_open(&a->ed, path, &err) != ACBB_OK) {
        acbb_app_msg(a, ACBB_ROLE_ERROR, "%s (using the built-in default scene)", err.msg);
        return;
    }
    acbb_app_msg(a, ACBB_ROLE_NORMAL, "opened %s: r runs it, ? lists every key", path);
    offer_recovery(a);
}

int acbb_app_run(const acbb_app_options *opt)
{
    acbb_error err = { { 0 } };
    acbb_app *a = calloc(1, sizeof *a);
    if (!a) {
        fprintf(stderr, "acbb tui: out of memory\n");
        return ACBB_EXIT_INTERNAL;
    }
    a->exit_after_steady = opt->exit_after_steady;
    a->pace_idx = pace_index(opt->pace < 0 ? PACE_DEFAULT : opt->pace);
    a->acc_knobs = opt->acc_knobs;
    snprintf(a->plot_dir, sizeof a->plot_dir, "%s", opt->plot_dir ? opt->plot_dir : "./acbb-plots");
    a->installed = opt->installed;
    load_initial(a, opt->preset);

    if (acbb_term_open(&a->term, &err) != ACBB_OK) {
        fprintf(stderr, "acbb tui: %s\n", err.msg);
        free(a);
        return ACBB_EXIT_INPUT;
    }
    int rc = 0;
    if (!opt->no_mouse) a->mouse = acbb_term_mouse(&a->term);
    if (acbb_screens_init(a, &err) != ACBB_OK ||
        acbb_worker_new(&a->ed.scene, acbb_app_pace(a->pace_idx), &a->worker, &err) != ACBB_OK) {
        acbb_term_close(&a->term);
        acbb_screens_free(a);
        fprintf(stderr, "acbb tui: %s\n", err.msg);
        rc = ACBB_EXIT_INTERNAL;
    } else {
        if (a->exit_after_steady) acbb_app_post(a, ACBB_CMD_START, &a->ed.scene, 0, "run started");
        loop(a);
        /* Restore the terminal first so a slow join never leaves it raw.
         * A running benchmark, sweep or sensitivity run is cancelled: it
         * stops within one step. */
        acbb_term_close(&a->term);
        fputs(a->leave_msg, stderr);
        acbb_screens_free(a);
        acbb_worker_free(a->worker);
        rc = a->exit_code;
    }
    free(a);
    return rc;
}
