/* acbb CLI — the contact heat section of `acbb report` (report_contact.h). */
#include <string.h>
#include "report_contact.h"

static const char k_intro[] =
    "Contact heat paths (docs/contact_heat.md): the runaway case, this bearing jumped from "
    "cold to 16000 rpm under rigid preload set at rest by 1000 N (for the 7008C exactly "
    "presets/runaway-rigid-preload.ini), run under each thermal.contact_model and race-side "
    "thermal.contact_multiplier c_mv. A converged run shows its steady state, any other its "
    "last good state and the time it ended.";

/* "converged at c_mv 0.25, 0.5; runaway at 1, 2" for one model. */
static void model_summary(char *buf, size_t cap, const acbb_contact_study *cs, int model)
{
    const acbb_contact_case *c = &cs->cases[model * ACBB_CONTACT_N_MULT];
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < ACBB_CONTACT_N_MULT; i++) {
        int first = 1;
        for (int k = 0; k < i; k++) first &= strcmp(c[k].end.status, c[i].end.status) != 0;
        if (!first) continue;
        n += (size_t)snprintf(buf + n, n < cap ? cap - n : 0, "%s%s at c_mv", n ? "; " : "",
                              c[i].end.status);
        for (int k = i; k < ACBB_CONTACT_N_MULT; k++)
            if (strcmp(c[k].end.status, c[i].end.status) == 0)
                n += (size_t)snprintf(buf + n, n < cap ? cap - n : 0, "%s %g",
                                      k == i ? "" : ",", c[k].multiplier);
    }
}

static void wrap_text(FILE *f, const char *s)
{
    int col = 0;
    while (*s) {
        size_t w = strcspn(s, " ");
        if (col && col + 1 + (int)w > 79) {
            fputc('\n', f);
            col = 0;
        } else if (col) {
            fputc(' ', f);
            col++;
        }
        fwrite(s, 1, w, f);
        col += (int)w;
        s += w;
        s += strspn(s, " ");
    }
    fputc('\n', f);
}

/* One line per case in `fmt` (text or Markdown): model, c_mv, end, time,
 * T_ball, T_ir, T_or, loss, Fx. */
static void rows(FILE *f, const acbb_contact_study *cs, const char *fmt)
{
    for (int i = 0; i < ACBB_CONTACT_N_CASES; i++) {
        const acbb_contact_case *c = &cs->cases[i];
        fprintf(f, fmt, acbb_contact_model_name(c->model), c->multiplier, c->end.status,
                c->end.time_s, c->end.T_ball_C, c->end.T_inner_ring_C, c->end.T_outer_ring_C,
                c->end.loss_total_W, c->end.reaction_x_N);
    }
}

void acbb_report_contact_text(FILE *f, const acbb_contact_study *cs)
{
    wrap_text(f, k_intro);
    fprintf(f, "%-11s %5s  %-10s %7s %8s %7s %7s %7s %7s\n", "model", "c_mv", "end", "time s",
            "T_ball C", "T_ir C", "T_or C", "loss W", "Fx N");
    rows(f, cs, "%-11s %5g  %-10s %7.0f %8.2f %7.2f %7.2f %7.2f %7.0f\n");
    for (int m = 0; m < 2; m++) {
        char line[256];
        model_summary(line, sizeof line, cs, m);
        fprintf(f, "%-11s %s\n", acbb_contact_model_name(m), line);
    }
}

void acbb_report_contact_md(FILE *f, const acbb_contact_study *cs)
{
    fprintf(f, "\n## Contact heat models on the runaway case\n\n%s\n\n", k_intro);
    fputs("| model | c_mv | end | time s | T_ball C | T_ir C | T_or C | loss W | Fx N |\n"
          "|---|---|---|---|---|---|---|---|---|\n", f);
    rows(f, cs, "| %s | %g | %s | %.0f | %.2f | %.2f | %.2f | %.2f | %.0f |\n");
    fputc('\n', f);
    for (int m = 0; m < 2; m++) {
        char line[256];
        model_summary(line, sizeof line, cs, m);
        fprintf(f, "- **%s**: %s\n", acbb_contact_model_name(m), line);
    }
}

void acbb_report_contact_json(acbb_json *j, const acbb_contact_study *cs)
{
    acbb_json_open(j, "contact_heat", '{', false);
    acbb_json_num(j, "speed_rpm", ACBB_CONTACT_RPM);
    acbb_json_num(j, "preload_N", ACBB_CONTACT_PRELOAD_N);
    acbb_json_num(j, "wall_ms", cs->wall_ms);
    acbb_json_open(j, "runs", '[', false);
    for (int i = 0; i < ACBB_CONTACT_N_CASES; i++) {
        const acbb_contact_case *c = &cs->cases[i];
        acbb_json_open(j, NULL, '{', true);
        acbb_json_str(j, "contact_model", acbb_contact_model_name(c->model));
        acbb_json_num(j, "contact_multiplier", c->multiplier);
        acbb_json_str(j, "status", c->end.status);
        acbb_json_num(j, "time_s", c->end.time_s);
        acbb_json_num(j, "T_ball_C", c->end.T_ball_C);
        acbb_json_num(j, "T_inner_ring_C", c->end.T_inner_ring_C);
        acbb_json_num(j, "T_outer_ring_C", c->end.T_outer_ring_C);
        acbb_json_num(j, "loss_total_W", c->end.loss_total_W);
        acbb_json_num(j, "reaction_x_N", c->end.reaction_x_N);
        acbb_json_close(j, '}');
    }
    acbb_json_close(j, ']');
    acbb_json_close(j, '}');
}
