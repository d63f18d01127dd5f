/* acbb — labels fit to print (issue 21 item 9): the program's plain labels
 * ("omega_x' (rad/s)", "alpha_i", "temperature (C)") become gnuplot
 * enhanced text (gnuplot 5.4 manual, "enhanced text"): Greek names as
 * UTF-8 letters, "_x" and "_{...}" subscripts, "(C)" as "(°C)", "(um)" as
 * "(μm)"; every other enhanced-text control character is escaped. Plain
 * labels stay what the CSV headers and REPORT.md print. */
#include <string.h>
#include "plot_priv.h"

typedef struct { const char *name, *utf8; } greek;

static const greek letters[] = {
    { "alpha", "\u03b1" }, { "delta", "\u03b4" }, { "theta", "\u03b8" }, { "lambda", "\u03bb" },
    { "omega", "\u03c9" }, { "psi", "\u03c8" },   { "mu", "\u03bc" },    { "eta", "\u03b7" },
};

typedef struct { const char *plain, *printed; } unit_sub;

static const unit_sub units[] = {
    { "(C)", "(\u00b0C)" }, { "[C]", "[\u00b0C]" }, { "(um)", "(\u03bcm)" }, { "(deg)", "(\u00b0)" },
};

static int is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
static int is_sub(char c) { return is_alpha(c) || (c >= '0' && c <= '9') || c == '\''; }

typedef struct { char *out; size_t n, len; } obuf;

static void put(obuf *o, const char *s, size_t k)
{
    for (size_t i = 0; i < k && o->len + 1 < o->n; i++) o->out[o->len++] = s[i];
    o->out[o->len] = '\0';
}

/* A Greek name starting a word at p (and ending one): its letter. */
static const greek *greek_at(const char *start, const char *p)
{
    if (p > start && is_alpha(p[-1])) return NULL;
    for (size_t i = 0; i < sizeof letters / sizeof letters[0]; i++) {
        size_t k = strlen(letters[i].name);
        if (strncmp(p, letters[i].name, k) == 0 && !is_alpha(p[k])) return &letters[i];
    }
    return NULL;
}

void plot_markup(const char *plain, char *out, size_t n)
{
    obuf o = { out, n, 0 };
    if (n) out[0] = '\0';
    for (const char *p = plain; p && *p;) {
        const greek *g = greek_at(plain, p);
        size_t u = 0;
        for (; u < sizeof units / sizeof units[0]; u++)
            if (strncmp(p, units[u].plain, strlen(units[u].plain)) == 0) break;
        if (g) {
            put(&o, g->utf8, strlen(g->utf8));
            p += strlen(g->name);
        } else if (u < sizeof units / sizeof units[0]) {
            put(&o, units[u].printed, strlen(units[u].printed));
            p += strlen(units[u].plain);
        } else if (*p == '_' && is_sub(p[1])) { /* subscript: the whole run */
            size_t k = 1;
            while (is_sub(p[k])) k++;
            put(&o, "_{", 2);
            put(&o, p + 1, k - 1);
            put(&o, "}", 1);
            p += k;
            /* gnuplot's SVG puts the text after a subscript in its own
             * tspan, whose leading space a renderer drops ("P_tTE"): a
             * no-break space survives. */
            if (*p == ' ') {
                put(&o, "\u00a0", strlen("\u00a0"));
                p++;
            }
        } else {
            if (strchr("^_{}@&~\\", *p)) put(&o, "\\", 1); /* a literal, not markup */
            put(&o, p, 1);
            p++;
        }
    }
}
