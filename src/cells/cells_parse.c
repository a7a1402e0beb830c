/* The cell model of an MCNP deck (cells.h): cell cards, surface cards and the data cards that place
 * them, read through the deck reader's card layer (scene/deck_internal.h: READ files, comments,
 * continuations, TRn cards). MCNP6 manual, Sec. 3.2.1 (cell cards: "j m d geom params", "j LIKE n
 * BUT list"), Sec. 3.2.2 (surface cards), Sec. 3.3.1 (cell parameters U, FILL, TRCL, LAT, IMP),
 * Sec. 3.1 (vertical input format). docs/deck.md lists what is read and the conventions chosen.
 *
 * Order of work: surface cards become cells_sdef parts (TRn applied) and are appended to the model's
 * surfaces; cell cards are split into number, material, density, geometry text and keywords; data
 * cards give cell parameters (horizontal or vertical form) that the cell cards did not give; then
 * every cell is built (LIKE n BUT and #n resolved first, recursively), its geometry turned into RPN
 * terms by recursive descent (precedence: complement, intersection, union); last the windows. */
#include <ctype.h>
#include <limits.h>
#include <stdint.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cells/cells_internal.h"
#include "cells/window_bound.h"

#define CELLS_MAX_NEST 200        /* nesting of parentheses, complements and #n chains */
#define CELLS_MAX_TERMS (1 << 20) /* terms of one region (complements copy whole regions) */
#define CELLS_MAX_TOTAL (1 << 24) /* terms of the whole model (bounds memory on pathological decks) */
#define CELLS_MAX_INDEX 1000000L  /* lattice index bound |i| of a FILL array */


/* ---- growable arrays ------------------------------------------------------------------------ */

static int grow(void **arr, size_t *cap, size_t n, size_t sz)
{
    if (n < *cap) return 0;
    size_t nc = *cap ? 2 * *cap : 16;
    void *p = realloc(*arr, nc * sz);
    if (!p) return -1;
    *arr = p;
    *cap = nc;
    return 0;
}

/* ---- number -> index maps (open addressing; val SIZE_MAX marks an empty slot) ----------------- */

typedef struct lmap {
    long *key;
    size_t *val;
    size_t cap, n;
} lmap;

static size_t lhash(long k)
{
    uint64_t x = (uint64_t)k * 0x9E3779B97F4A7C15ull;
    return (size_t)(x ^ (x >> 31));
}

static size_t lmap_get(const lmap *m, long k)
{
    if (!m->cap) return SIZE_MAX;
    for (size_t i = lhash(k) & (m->cap - 1);; i = (i + 1) & (m->cap - 1)) {
        if (m->val[i] == SIZE_MAX) return SIZE_MAX;
        if (m->key[i] == k) return m->val[i];
    }
}

/* Inserts or replaces k -> v. -1 when memory ran out. */
static int lmap_put(lmap *m, long k, size_t v)
{
    if (2 * (m->n + 1) > m->cap) {
        size_t nc = m->cap ? 2 * m->cap : 64;
        lmap g = {malloc(nc * sizeof *g.key), malloc(nc * sizeof *g.val), nc, 0};
        if (!g.key || !g.val) {
            free(g.key);
            free(g.val);
            return -1;
        }
        for (size_t i = 0; i < nc; ++i) g.val[i] = SIZE_MAX;
        for (size_t i = 0; i < m->cap; ++i)
            if (m->val[i] != SIZE_MAX) lmap_put(&g, m->key[i], m->val[i]);
        free(m->key);
        free(m->val);
        *m = g;
    }
    size_t i = lhash(k) & (m->cap - 1);
    while (m->val[i] != SIZE_MAX && m->key[i] != k) i = (i + 1) & (m->cap - 1);
    if (m->val[i] == SIZE_MAX) m->n++;
    m->key[i] = k, m->val[i] = v;
    return 0;
}

static void lmap_free(lmap *m)
{
    free(m->key);
    free(m->val);
    memset(m, 0, sizeof *m);
}

/* One surface card. */
typedef struct sentry {
    long number;
    int line;
    char card[8];
    int state;    /* 0 modelled, 1 not modelled (unchecked), -1 malformed */
    cells_sdef def;
    size_t first; /* index of part 0 in the model's surfaces */
} sentry;

/* One keyword of a cell card (or of the data block): its name, upper case with the particle
 * designators (IMP:N), whether starred (*TRCL, *FILL), and its value tokens. */
typedef struct kw {
    char name[24];
    int star;
    char **val;
    size_t nval;
    int line;
} kw;

/* One cell card, split. */
typedef struct ccard {
    long number;
    int line;
    long like;      /* LIKE n BUT: n (0: none) */
    long mat;
    double rho;
    int has_mat, has_rho;
    char *geom;     /* geometry text (NULL for LIKE) */
    kw *kws;
    size_t nkws, capk;
    int state;      /* 0 not built, 1 building, 2 built, -1 failed */
    size_t cell;    /* index in the model */
    const prox_deck_card *card;
} ccard;

typedef struct ctx {
    prox_cell_model *m;
    prox_deck_raw raw;
    size_t cap_surfs, cap_terms, cap_cells, cap_windows, cap_errors, cap_unchecked;
    sentry *se;
    size_t nse, cap_se;
    ccard *cc;
    size_t ncc, cap_cc;
    char **strs;   /* token storage to free */
    size_t nstrs, cap_strs;
    lmap surf_of, cell_of, universes; /* surface / cell number -> index; universes with cells */
    int depth;     /* cells being built (complements build the cells they name first) */
    const prox_deck_card *cur; /* card being read: errors from an included file name its line */
    int nomem;
} ctx;

/* ---- notes ---------------------------------------------------------------------------------- */

/* Adds an error on main-deck line `line`; when the card being read comes from a file brought in by
 * READ, the text starts with "'<file>' line <n>: " (as the deck reader's notes do). */
static void add_error(ctx *c, int line, const char *fmt, ...)
{
    prox_cell_model *m = c->m;
    if (grow((void **)&m->errors, &c->cap_errors, m->nerrors, sizeof *m->errors)) {
        c->nomem = 1;
        return;
    }
    prox_deck_note *n = &m->errors[m->nerrors++];
    n->line = line;
    char msg[PROX_DECK_TEXT];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const prox_deck_card *k = c->cur;
    if (k && k->file > 0 && (size_t)k->file < c->raw.nfiles && k->line == line) {
        const char *f = c->raw.files[k->file];
        size_t L = strlen(f);
        int w = snprintf(n->text, sizeof n->text, "'%s%s' line %d: ", L > 40 ? "..." : "", L > 40 ? f + L - 37 : f,
                         k->fline);
        size_t at = w > 0 ? (size_t)w : 0, lm = strlen(msg); /* the message, cut to the note (intended) */
        for (size_t i = 0; i < lm && at + 1 < sizeof n->text; ++i) n->text[at++] = msg[i];
        n->text[at < sizeof n->text ? at : sizeof n->text - 1] = 0;
    } else
        memcpy(n->text, msg, sizeof msg);
}

/* Counts one more occurrence of something the model leaves unchecked (one entry per kind). */
static void add_unchecked(ctx *c, int line, const char *fmt, ...)
{
    char what[PROX_DECK_TEXT];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    prox_cell_model *m = c->m;
    for (size_t i = 0; i < m->nunchecked; ++i)
        if (!strcmp(m->unchecked[i].what, what)) {
            m->unchecked[i].count++;
            if (line && (!m->unchecked[i].first_line || line < m->unchecked[i].first_line))
                m->unchecked[i].first_line = line;
            return;
        }
    if (grow((void **)&m->unchecked, &c->cap_unchecked, m->nunchecked, sizeof *m->unchecked)) {
        c->nomem = 1;
        return;
    }
    prox_unchecked *u = &m->unchecked[m->nunchecked++];
    memcpy(u->what, what, sizeof what);
    u->count = 1;
    u->first_line = line;
}

/* ---- model arrays --------------------------------------------------------------------------- */

static size_t push_surf(ctx *c, const prox_surf *s)
{
    prox_cell_model *m = c->m;
    if (grow((void **)&m->surfs, &c->cap_surfs, m->nsurfs, sizeof *m->surfs)) {
        c->nomem = 1;
        return 0;
    }
    m->surfs[m->nsurfs] = *s;
    return m->nsurfs++;
}

static void push_term(ctx *c, prox_op op, int sense, size_t surf)
{
    prox_cell_model *m = c->m;
    if (grow((void **)&m->terms, &c->cap_terms, m->nterms, sizeof *m->terms)) {
        c->nomem = 1;
        return;
    }
    m->terms[m->nterms++] = (prox_term){op, sense, surf};
}

/* ---- tokens --------------------------------------------------------------------------------- */

/* Splits s (modified in place) on blanks and '=', with '(' and ')' as tokens of their own; the token
 * pointers go to a new array kept in c->strs. Returns the count, *out the array. */
static size_t split(ctx *c, char *s, char ***out)
{
    size_t n = 0, cap = 0;
    char **t = NULL;
    /* pass 1: count, with parentheses given room: copy into a spaced buffer */
    size_t len = strlen(s);
    char *b = malloc(3 * len + 1);
    if (!b) {
        c->nomem = 1;
        *out = NULL;
        return 0;
    }
    size_t k = 0;
    for (size_t i = 0; i < len; ++i) {
        if (s[i] == '(' || s[i] == ')') b[k++] = ' ', b[k++] = s[i], b[k++] = ' ';
        else b[k++] = s[i] == '=' || isspace((unsigned char)s[i]) ? ' ' : s[i];
    }
    b[k] = 0;
    for (char *p = b; *p;) {
        while (*p == ' ') ++p;
        if (!*p) break;
        if (grow((void **)&t, &cap, n, sizeof *t)) {
            c->nomem = 1;
            break;
        }
        t[n++] = p;
        while (*p && *p != ' ') ++p;
        if (*p) *p++ = 0;
    }
    if (grow((void **)&c->strs, &c->cap_strs, c->nstrs + 1, sizeof *c->strs)) {
        c->nomem = 1;
        free(b);
        free(t);
        *out = NULL;
        return 0;
    }
    c->strs[c->nstrs++] = b;
    c->strs[c->nstrs++] = (char *)t;
    *out = t;
    return n;
}

/* 1 when the token starts a keyword: a letter, or '*' and a letter. */
static int is_keyword(const char *t)
{
    if (*t == '*') ++t;
    return isalpha((unsigned char)*t);
}

static void upper_copy(char *dst, size_t sz, const char *src)
{
    size_t i = 0;
    for (; src[i] && i + 1 < sz; ++i) dst[i] = (char)toupper((unsigned char)src[i]);
    dst[i] = 0;
}

/* Groups tokens tok[0..n) into keywords (a keyword token and the values up to the next one). */
static int group_keywords(ctx *c, ccard *cc, char **tok, size_t n, int line)
{
    for (size_t i = 0; i < n;) {
        if (!is_keyword(tok[i])) {
            add_error(c, line, "cell %ld: '%s' where a keyword was expected", cc->number, tok[i]);
            return -1;
        }
        if (grow((void **)&cc->kws, &cc->capk, cc->nkws, sizeof *cc->kws)) {
            c->nomem = 1;
            return -1;
        }
        kw *k = &cc->kws[cc->nkws++];
        k->star = tok[i][0] == '*';
        upper_copy(k->name, sizeof k->name, tok[i] + k->star);
        k->line = line;
        size_t j = i + 1;
        while (j < n && !is_keyword(tok[j])) ++j;
        k->val = tok + i + 1;
        k->nval = j - i - 1;
        i = j;
    }
    return 0;
}

/* The name of a keyword without its particle designators ("IMP:N" -> "IMP"). */
static void base_name(const char *name, char *out, size_t sz)
{
    size_t i = 0;
    for (; name[i] && name[i] != ':' && i + 1 < sz; ++i) out[i] = name[i];
    out[i] = 0;
}

/* ---- surface cards ---------------------------------------------------------------------------- */

static const prox_deck_tr *find_tr(const ctx *c, long n)
{
    for (size_t i = 0; i < c->raw.ntrs; ++i)
        if (c->raw.trs[i].n == n) return &c->raw.trs[i];
    return NULL;
}

static sentry *find_surface(ctx *c, long n)
{
    size_t i = lmap_get(&c->surf_of, n);
    return i == SIZE_MAX ? NULL : &c->se[i];
}

/* "j [n] A list": j optionally prefixed by * (reflecting) or + (white); n > 0 a TRn, n < 0 a
 * periodic partner (the geometry is unchanged: accepted). */
static void surface_card(ctx *c, char *text, int line)
{
    char **tok;
    size_t nt = split(c, text, &tok);
    if (!nt) return;
    const char *js = tok[0];
    if (*js == '*' || *js == '+') ++js;
    long j, n = 0;
    if (prox_deck_long(js, &j) || j < 1 || *js == '+' || *js == '-') {
        add_error(c, line, "surface number '%s' is not a positive integer", tok[0]);
        return;
    }
    size_t k = 1;
    if (k < nt && !prox_deck_long(tok[k], &n)) ++k;
    if (k >= nt) {
        add_error(c, line, "surface %ld has no mnemonic", j);
        return;
    }
    if (find_surface(c, j)) {
        add_error(c, line, "surface %ld is already defined on line %d", j, find_surface(c, j)->line);
        return;
    }
    if (grow((void **)&c->se, &c->cap_se, c->nse, sizeof *c->se)) {
        c->nomem = 1;
        return;
    }
    if (lmap_put(&c->surf_of, j, c->nse)) {
        c->nomem = 1;
        return;
    }
    sentry *e = &c->se[c->nse++];
    memset(e, 0, sizeof *e);
    e->number = j, e->line = line;
    upper_copy(e->card, sizeof e->card, tok[k]);
    if (!isalpha((unsigned char)tok[k][0])) {
        add_error(c, line, "surface %ld: '%s' is not a surface mnemonic", j, tok[k]);
        e->state = -1;
        return;
    }
    const prox_deck_tr *t = NULL;
    if (n > 0 && !(t = find_tr(c, n))) {
        add_error(c, line, "surface %ld: transformation TR%ld is not defined", j, n);
        e->state = -1;
        return;
    }
    double v[64];
    size_t nv;
    char err[PROX_DECK_TEXT - 40];
    if (prox_deck_entries(tok + k + 1, nt - k - 1, v, &nv, 64, err, sizeof err)) {
        add_error(c, line, "surface %ld %s: %s", j, e->card, err);
        e->state = -1;
        return;
    }
    int r = cells_surface_card(e->card, v, nv, t, &e->def, err, sizeof err);
    if (r < 0) {
        add_error(c, line, "surface %ld %s: %s", j, e->card, err);
        e->state = -1;
        return;
    }
    if (r > 0) {
        add_unchecked(c, line, "surface card %s", e->card);
        e->state = 1;
        return;
    }
    e->first = c->m->nsurfs;
    for (int p = 0; p < e->def.nparts; ++p) {
        e->def.part[p].number = j;
        e->def.part[p].line = line;
        if (!e->def.body) e->def.part[p].facet = 0;
        push_surf(c, &e->def.part[p]);
    }
}

/* ---- cell cards ------------------------------------------------------------------------------- */

static ccard *find_cell(ctx *c, long n)
{
    size_t i = lmap_get(&c->cell_of, n);
    return i == SIZE_MAX ? NULL : &c->cc[i];
}

/* Position where the geometry of a cell card ends: the first keyword (a letter, or '*' and a
 * letter, starting a word). */
static size_t geometry_end(const char *s)
{
    for (size_t i = 0; s[i]; ++i) {
        int start = i == 0 || isspace((unsigned char)s[i - 1]) || s[i - 1] == ')' || s[i - 1] == '(';
        if (!start) continue;
        if (isalpha((unsigned char)s[i])) return i;
        if (s[i] == '*' && isalpha((unsigned char)s[i + 1])) return i;
    }
    return strlen(s);
}

/* Reads the next blank-delimited word of s at *pos into w (size sz). 0 when there is none. */
static int next_word(const char *s, size_t *pos, char *w, size_t sz)
{
    size_t i = *pos, k = 0;
    while (s[i] && isspace((unsigned char)s[i])) ++i;
    if (!s[i]) return 0;
    while (s[i] && !isspace((unsigned char)s[i])) {
        if (k + 1 < sz) w[k++] = s[i];
        ++i;
    }
    w[k] = 0;
    *pos = i;
    return 1;
}

/* "j m d geom params" | "j 0 geom params" | "j LIKE n BUT params". */
static void cell_card(ctx *c, char *text, int line)
{
    size_t pos = 0;
    char w[64];
    long j;
    if (!next_word(text, &pos, w, sizeof w)) return;
    if (prox_deck_long(w, &j) || j < 1 || w[0] == '+' || w[0] == '-') {
        add_error(c, line, "cell number '%s' is not a positive integer", w);
        return;
    }
    ccard *dup = find_cell(c, j);
    if (dup) {
        add_error(c, line, "cell %ld is already defined on line %d", j, dup->line);
        return;
    }
    if (grow((void **)&c->cc, &c->cap_cc, c->ncc, sizeof *c->cc)) {
        c->nomem = 1;
        return;
    }
    ccard *cc = &c->cc[c->ncc];
    memset(cc, 0, sizeof *cc);
    cc->number = j, cc->line = line, cc->card = c->cur;
    if (!next_word(text, &pos, w, sizeof w)) {
        add_error(c, line, "cell %ld has no material", j);
        return;
    }
    char *rest;
    if (prox_deck_ieq(w, "LIKE")) {
        if (!next_word(text, &pos, w, sizeof w) || prox_deck_long(w, &cc->like) || cc->like < 1) {
            add_error(c, line, "cell %ld: LIKE needs a cell number", j);
            return;
        }
        if (!next_word(text, &pos, w, sizeof w) || !prox_deck_ieq(w, "BUT")) {
            add_error(c, line, "cell %ld: LIKE %ld must be followed by BUT", j, cc->like);
            return;
        }
        rest = text + pos;
    } else {
        if (prox_deck_long(w, &cc->mat) || cc->mat < 0) {
            add_error(c, line, "cell %ld: material '%s' is not a number >= 0", j, w);
            return;
        }
        cc->has_mat = 1;
        if (cc->mat) {
            if (!next_word(text, &pos, w, sizeof w) || prox_deck_number(w, &cc->rho)) {
                add_error(c, line, "cell %ld: material %ld needs a density", j, cc->mat);
                return;
            }
            cc->has_rho = 1;
        }
        char *g = text + pos;
        size_t ge = geometry_end(g);
        cc->geom = malloc(ge + 1);
        if (!cc->geom) {
            c->nomem = 1;
            return;
        }
        memcpy(cc->geom, g, ge);
        cc->geom[ge] = 0;
        rest = g + ge;
    }
    char **tok;
    size_t nt = split(c, rest, &tok);
    if (c->nomem) {
        free(cc->geom);
        return;
    }
    if (group_keywords(c, cc, tok, nt, line)) {
        free(cc->geom);
        free(cc->kws);
        return;
    }
    if (lmap_put(&c->cell_of, j, c->ncc)) {
        c->nomem = 1;
        free(cc->geom);
        free(cc->kws);
        return;
    }
    c->ncc++;
}

/* ---- data cards: cell parameters given in the data block ------------------------------------- */

/* Cell parameters a data card may give for every cell (MCNP6 manual, Sec. 3.3.1). */
static int is_cell_param(const char *base)
{
    static const char *names[] = {"IMP", "U", "FILL", "TRCL", "LAT", "VOL", "PWT", "EXT", "FCL", "WWN", "DXC",
                                  "NONU", "TMP", "ELPT", "COSY", "BFLCL", "UNC", "PD", "MAT", "RHO"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
        if (!strcmp(base, names[i])) return 1;
    return 0;
}

/* Adds keyword `name` with the value token(s) to cell cc unless its card gives it. */
static void give_param(ctx *c, ccard *cc, const char *name, int star, char **val, size_t nval, int line)
{
    for (size_t i = 0; i < cc->nkws; ++i)
        if (!strcmp(cc->kws[i].name, name)) {
            add_error(c, line, "cell %ld: %s is given both on the cell card and in the data block", cc->number, name);
            return;
        }
    if (grow((void **)&cc->kws, &cc->capk, cc->nkws, sizeof *cc->kws)) {
        c->nomem = 1;
        return;
    }
    kw *k = &cc->kws[cc->nkws++];
    memset(k, 0, sizeof *k);
    snprintf(k->name, sizeof k->name, "%s", name);
    k->star = star, k->val = val, k->nval = nval, k->line = line;
}

/* A horizontal cell-parameter data card: one entry per cell, in the order of the cell cards; nR
 * repeats, nJ skips (the default). */
static void param_card(ctx *c, const char *name, int star, char **tok, size_t nt, int line)
{
    if (nt == 0 && !strcmp(name, "NONU")) return; /* a bare NONU: fission as capture in every cell */
    size_t ci = 0;
    for (size_t i = 0; i < nt && ci <= c->ncc; ++i) {
        long cnt;
        const char *t = tok[i];
        size_t L = strlen(t);
        char last = (char)toupper((unsigned char)t[L ? L - 1 : 0]);
        if (L && (last == 'J' || last == 'R') && (L == 1 || isdigit((unsigned char)t[0]))) {
            cnt = 1;
            if (L > 1) {
                char buf[24];
                snprintf(buf, sizeof buf, "%.*s", (int)(L - 1), t);
                if (prox_deck_long(buf, &cnt) || cnt < 1) goto bad;
            }
            if (last == 'J') {
                ci += (size_t)cnt;
                continue;
            }
            if (i == 0) goto bad;
            for (long r = 0; r < cnt && ci < c->ncc; ++r, ++ci) give_param(c, &c->cc[ci], name, star, &tok[i - 1], 1, line);
            continue;
        }
        if (ci >= c->ncc) break;
        give_param(c, &c->cc[ci++], name, star, &tok[i], 1, line);
    }
    if (ci != c->ncc) add_error(c, line, "%s: %zu entries for %zu cells", name, ci, c->ncc);
    return;
bad:
    add_error(c, line, "%s: bad entry", name);
}

/* Vertical input format (MCNP6 manual, Sec. 3.1.2): "# S1 S2 ..." in columns 1-5, then one row per
 * cell "j d1 d2 ..." with the cell number first, or "d1 d2 ..." without it (rows then follow the
 * order of the cell cards); a J skips one entry. Rows end at the next card that does not start
 * with a number. `first` is the card of names (its '#' already blanked). Returns the cards used. */
static size_t vertical_cards(ctx *c, size_t first)
{
    prox_deck_card *hdr = &c->raw.cards[first];
    char **names;
    size_t nn = split(c, hdr->text, &names);
    if (!nn) return 1;
    size_t used = 1, order = 0, nparams = 0;
    for (size_t i = 0; i < nn; ++i) {
        char name[24], base[24];
        upper_copy(name, sizeof name, names[i] + (names[i][0] == '*'));
        base_name(name, base, sizeof base);
        nparams += is_cell_param(base);
    }
    for (size_t k = first + 1; k < c->raw.ncards; ++k) {
        prox_deck_card *row = &c->raw.cards[k];
        c->cur = row;
        size_t p = 0;
        while (row->text[p] == ' ') ++p;
        if (row->block != PROX_CARD_DATA ||
            !(isdigit((unsigned char)row->text[p]) || row->text[p] == '-' || row->text[p] == '.'))
            break;
        ++used;
        if (!nparams) continue; /* a source table (SIn, SPn ...): not geometry */
        char **v;
        size_t nv = split(c, row->text, &v);
        ccard *cc = NULL;
        if (nv == nn + 1) {
            long j;
            if (prox_deck_long(v[0], &j) || !(cc = find_cell(c, j))) {
                add_error(c, row->line, "vertical format: cell '%s' is not defined", v[0]);
                continue;
            }
            ++v;
        } else if (nv == nn) {
            if (order >= c->ncc) {
                add_error(c, row->line, "vertical format: more rows than cells");
                continue;
            }
            cc = &c->cc[order++];
        } else {
            add_error(c, row->line, "vertical format: %zu entries for %zu names", nv, nn);
            continue;
        }
        for (size_t i = 0; i < nn; ++i) {
            if (prox_deck_ieq(v[i], "J")) continue;
            char name[24], base[24];
            int star = names[i][0] == '*';
            upper_copy(name, sizeof name, names[i] + star);
            base_name(name, base, sizeof base);
            if (is_cell_param(base)) give_param(c, cc, name, star, &v[i], 1, row->line);
        }
    }
    return used;
}

static void data_cards(ctx *c)
{
    for (size_t k = 0; k < c->raw.ncards; ++k) {
        prox_deck_card *d = &c->raw.cards[k];
        if (d->block != PROX_CARD_DATA) continue;
        c->cur = d;
        size_t p = 0;
        while (d->text[p] == ' ') ++p;
        if (d->text[p] == '#') {
            d->text[p] = ' ';
            k += vertical_cards(c, k) - 1;
            continue;
        }
        char *copy = malloc(strlen(d->text) + 1);
        if (!copy) {
            c->nomem = 1;
            return;
        }
        strcpy(copy, d->text);
        char **tok;
        size_t nt = split(c, copy, &tok);
        free(copy);
        if (!nt) continue;
        int star = tok[0][0] == '*';
        char name[24], base[24];
        upper_copy(name, sizeof name, tok[0] + star);
        base_name(name, base, sizeof base);
        if (is_cell_param(base) && strcmp(base, "MAT") && strcmp(base, "RHO")) param_card(c, name, star, tok + 1, nt - 1, d->line);
    }
}

/* ---- building cells ------------------------------------------------------------------------- */

/* What a cell's keywords say (after LIKE BUT). */
typedef struct cellparams {
    long mat;
    double rho;
    long universe;
    int lat;
    int has_imp, imp_nonzero;
    const kw *fill, *trcl;
} cellparams;

/* Reads an inline transform "( e1 e2 ... )" or a TR number in tokens val[*i...]; advances *i. */
static int read_transform(ctx *c, char **val, size_t nval, size_t *i, int star, prox_deck_tr *t, int *has, int line,
                          long cell, const char *what)
{
    *has = 0;
    if (*i >= nval) return 0;
    if (strcmp(val[*i], "(")) {
        if (strcmp(what, "TRCL")) return 0; /* FILL: no transform */
        long n;
        if (prox_deck_long(val[*i], &n) || n < 0) goto bad;
        ++*i;
        if (n == 0) return 0;
        const prox_deck_tr *f = find_tr(c, n);
        if (!f) {
            add_error(c, line, "cell %ld: %s transformation TR%ld is not defined", cell, what, n);
            return -1;
        }
        *t = *f, *has = 1;
        return 0;
    }
    size_t j = *i + 1;
    while (j < nval && strcmp(val[j], ")")) ++j;
    if (j >= nval) goto bad;
    double v[64];
    size_t nv;
    char err[PROX_DECK_TEXT - 60];
    if (prox_deck_entries(val + *i + 1, j - *i - 1, v, &nv, 64, err, sizeof err)) {
        add_error(c, line, "cell %ld %s: %s", cell, what, err);
        return -1;
    }
    *i = j + 1;
    if (nv == 1) { /* a TR number in parentheses */
        if (!(v[0] >= 0 && v[0] <= 1e9)) goto bad;
        long n = (long)v[0];
        if ((double)n != v[0]) goto bad;
        if (n == 0) return 0;
        const prox_deck_tr *f = find_tr(c, n);
        if (!f) {
            add_error(c, line, "cell %ld: %s transformation TR%ld is not defined", cell, what, n);
            return -1;
        }
        *t = *f, *has = 1;
        return 0;
    }
    if (prox_deck_make_tr(v, nv, star, t, err, sizeof err)) {
        add_error(c, line, "cell %ld %s: %s", cell, what, err);
        return -1;
    }
    *has = 1;
    return 0;
bad:
    add_error(c, line, "cell %ld: malformed %s", cell, what);
    return -1;
}

/* 1 for the MCNP6 cell keywords that do not shape the geometry (MCNP6 manual, Sec. 3.3: volumes,
 * weights, temperatures, variance reduction, tally and physics options): read and left aside. A
 * trailing index (TMP2, WWN3, PD10, DXC1) is part of the name. Any other keyword is unchecked. */
static int is_physics_keyword(const char *base)
{
    static const char *names[] = {"VOL", "PWT", "EXT", "FCL", "WWN", "DXC", "NONU", "PD", "TMP", "ELPT", "COSY",
                                  "BFLCL", "UNC"};
    size_t L = strlen(base);
    while (L && isdigit((unsigned char)base[L - 1])) --L;
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
        if (strlen(names[i]) == L && !strncmp(base, names[i], L)) return 1;
    return 0;
}

/* Interprets the keywords of a cell; 0 on success. */
static int read_params(ctx *c, const ccard *cc, const kw *kws, size_t nk, cellparams *p)
{
    for (size_t i = 0; i < nk; ++i) {
        const kw *k = &kws[i];
        char base[24];
        base_name(k->name, base, sizeof base);
        double x;
        if (!strcmp(base, "IMP")) {
            p->has_imp = 1;
            for (size_t v = 0; v < k->nval; ++v) {
                if (prox_deck_number(k->val[v], &x)) {
                    add_error(c, k->line, "cell %ld: %s value '%s' is not a number", cc->number, k->name, k->val[v]);
                    return -1;
                }
                if (x != 0) p->imp_nonzero = 1;
            }
        } else if (!strcmp(base, "U") || !strcmp(base, "LAT") || !strcmp(base, "MAT")) {
            long n;
            if (k->nval != 1 || prox_deck_long(k->val[0], &n) || n < -LONG_MAX) {
                add_error(c, k->line, "cell %ld: %s needs one integer", cc->number, base);
                return -1;
            }
            if (!strcmp(base, "U")) p->universe = n < 0 ? -n : n; /* U=-n: a hint that the cell is enclosed */
            else if (!strcmp(base, "MAT")) p->mat = n;
            else {
                if (n != 1 && n != 2) {
                    add_error(c, k->line, "cell %ld: LAT must be 1 or 2", cc->number);
                    return -1;
                }
                p->lat = (int)n;
            }
        } else if (!strcmp(base, "RHO")) {
            if (k->nval != 1 || prox_deck_number(k->val[0], &p->rho)) {
                add_error(c, k->line, "cell %ld: RHO needs one number", cc->number);
                return -1;
            }
        } else if (!strcmp(base, "FILL")) p->fill = k;
        else if (!strcmp(base, "TRCL")) p->trcl = k;
        else if (!is_physics_keyword(base)) add_unchecked(c, k->line, "cell keyword %s", base);
    }
    return 0;
}

/* The keywords of a cell after LIKE n BUT: n's (resolved) with this card's replacing them. Returns a
 * new array (caller frees) of *nk entries. */
static kw *resolve_keywords(ctx *c, ccard *cc, size_t *nk, int depth)
{
    kw *base = NULL;
    size_t nb = 0;
    if (cc->like) {
        ccard *o = find_cell(c, cc->like);
        if (!o || depth > 64) {
            if (!o) add_error(c, cc->line, "cell %ld: LIKE %ld names a cell that is not defined", cc->number, cc->like);
            else add_error(c, cc->line, "cell %ld: LIKE chain too deep or cyclic", cc->number);
            return NULL;
        }
        base = resolve_keywords(c, o, &nb, depth + 1);
        if (!base) return NULL;
    }
    kw *out = malloc((nb + cc->nkws + 1) * sizeof *out);
    if (!out) {
        c->nomem = 1;
        free(base);
        return NULL;
    }
    size_t n = 0;
    for (size_t i = 0; i < nb; ++i) {
        int replaced = 0;
        for (size_t j = 0; j < cc->nkws; ++j) replaced |= !strcmp(base[i].name, cc->kws[j].name);
        if (!replaced) out[n++] = base[i];
    }
    for (size_t j = 0; j < cc->nkws; ++j) out[n++] = cc->kws[j];
    free(base);
    *nk = n;
    return out;
}

/* The card whose geometry, material and density a cell uses (itself, or the end of its LIKE chain). */
static ccard *geometry_card(ctx *c, ccard *cc)
{
    for (int d = 0; cc && cc->like && d < 64; ++d) cc = find_cell(c, cc->like);
    return cc && !cc->like ? cc : NULL;
}

static int build_cell(ctx *c, ccard *cc);
static int build_cell_now(ctx *c, ccard *cc);

/* ---- geometry: recursive descent emitting RPN ------------------------------------------------ */

typedef struct gp {
    ctx *c;
    const char *s;
    size_t i;
    ccard *cc;
    const prox_deck_tr *trcl;
    size_t start;   /* first term of the region */
    int fail;       /* -1 error (reported), 1 unmodelled surface */
    int nest;       /* parentheses open */
    size_t cache_key[64], cache_val[64];
    int ncache;
} gp;

static void ws(gp *g)
{
    while (g->s[g->i] && isspace((unsigned char)g->s[g->i])) ++g->i;
}

/* Index of the model surface for part p of surface entry e in this cell's frame. */
static size_t leaf_surf(gp *g, const sentry *e, int p)
{
    size_t base = e->first + (size_t)p;
    if (!g->trcl) return base;
    for (int k = 0; k < g->ncache; ++k)
        if (g->cache_key[k] == base) return g->cache_val[k];
    prox_surf s = cells_surf_transform(&g->c->m->surfs[base], g->trcl);
    size_t idx = push_surf(g->c, &s);
    if (g->ncache < 64) g->cache_key[g->ncache] = base, g->cache_val[g->ncache++] = idx;
    return idx;
}

static void gerr(gp *g, const char *fmt, ...)
{
    if (g->fail) return;
    char msg[PROX_DECK_TEXT - 30];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    add_error(g->c, g->cc->line, "cell %ld: %s", g->cc->number, msg);
    g->fail = -1;
}

static void g_union(gp *g);
static void g_group(gp *g, char ch);

/* A signed surface reference [+-]n[.k]. */
static void g_surface(gp *g)
{
    const char *s = g->s + g->i;
    int sense = 1;
    size_t k = 0;
    if (s[k] == '+' || s[k] == '-') sense = s[k++] == '-' ? -1 : 1;
    if (!isdigit((unsigned char)s[k])) {
        gerr(g, "unexpected '%c' in the geometry", s[k] ? s[k] : ' ');
        return;
    }
    long n = 0, facet = 0;
    for (; isdigit((unsigned char)s[k]); ++k) {
        n = n * 10 + (s[k] - '0');
        if (n > 1000000000L) break;
    }
    if (s[k] == '.') {
        ++k;
        if (!isdigit((unsigned char)s[k])) {
            gerr(g, "malformed facet reference");
            return;
        }
        for (; isdigit((unsigned char)s[k]); ++k)
            if (facet < 1000) facet = facet * 10 + (s[k] - '0');
    }
    g->i += k;
    const sentry *e = find_surface(g->c, n);
    if (!e) {
        gerr(g, "surface %ld is not defined", n);
        return;
    }
    if (e->state) { /* not modelled: the cell is unchecked; malformed: the card's error stands */
        if (!g->fail || e->state < 0) g->fail = e->state < 0 ? -1 : 1;
        return;
    }
    if (facet) {
        if (!e->def.body || facet > e->def.nparts) {
            gerr(g, "surface %ld has no facet %ld", n, facet);
            return;
        }
        push_term(g->c, PROX_OP_LEAF, sense, leaf_surf(g, e, (int)facet - 1));
        return;
    }
    /* negative side: AND of (part k on side in[k]); positive side by De Morgan: OR of the others */
    for (int p = 0; p < e->def.nparts; ++p) {
        push_term(g->c, PROX_OP_LEAF, sense < 0 ? e->def.in[p] : -e->def.in[p], leaf_surf(g, e, p));
        if (p) push_term(g->c, sense < 0 ? PROX_OP_AND : PROX_OP_OR, 0, 0);
    }
}

static void g_factor(gp *g)
{
    ws(g);
    char ch = g->s[g->i];
    if (g->c->m->nterms - g->start > CELLS_MAX_TERMS) {
        gerr(g, "the region has more than %d terms", CELLS_MAX_TERMS);
        return;
    }
    if (g->c->m->nterms > CELLS_MAX_TOTAL) {
        gerr(g, "the model has more than %d terms", CELLS_MAX_TOTAL);
        return;
    }
    if (ch == '(' || ch == '#') {
        if (++g->nest > CELLS_MAX_NEST) {
            gerr(g, "parentheses and complements nested deeper than %d", CELLS_MAX_NEST);
            return;
        }
        g_group(g, ch);
        --g->nest;
        return;
    }
    g_surface(g);
}

/* '(' union ')' or a complement '#n' / '#(...)'. */
static void g_group(gp *g, char ch)
{
    if (ch == '(') {
        ++g->i;
        g_union(g);
        ws(g);
        if (g->s[g->i] != ')') {
            gerr(g, "missing ')'");
            return;
        }
        ++g->i;
        return;
    }
    if (ch == '#') {
        ++g->i;
        ws(g);
        if (g->s[g->i] == '(') {
            g_factor(g);
            push_term(g->c, PROX_OP_NOT, 0, 0);
            return;
        }
        long n = 0;
        if (!isdigit((unsigned char)g->s[g->i])) {
            gerr(g, "'#' needs a cell number or '('");
            return;
        }
        while (isdigit((unsigned char)g->s[g->i]) && n < 1000000000L) n = n * 10 + (g->s[g->i++] - '0');
        ccard *o = find_cell(g->c, n);
        if (!o) {
            gerr(g, "#%ld names a cell that is not defined", n);
            return;
        }
        if (o->state != 2) {
            if (o->state != -1) gerr(g, "#%ld: complements refer to each other in a cycle", n);
            else g->fail = -1; /* cell n's own error is reported on its card */
            return;
        }
        const prox_cell *oc = &g->c->m->cells[o->cell];
        if (oc->unchecked) {
            if (!g->fail) g->fail = 1;
            return;
        }
        for (size_t t = 0; t < oc->elem_nexpr && !g->c->nomem; ++t) { /* as written (a lattice: its element) */
            prox_term term = g->c->m->terms[oc->elem_expr + t];
            push_term(g->c, term.op, term.sense, term.surf);
        }
        push_term(g->c, PROX_OP_NOT, 0, 0);
        return;
    }
}

static int starts_factor(char ch) { return ch == '(' || ch == '#' || ch == '+' || ch == '-' || isdigit((unsigned char)ch); }

static void g_inter(gp *g)
{
    g_factor(g);
    for (;;) {
        if (g->fail) return;
        ws(g);
        if (!starts_factor(g->s[g->i])) return;
        g_factor(g);
        push_term(g->c, PROX_OP_AND, 0, 0);
    }
}

static void g_union(gp *g)
{
    g_inter(g);
    for (;;) {
        if (g->fail) return;
        ws(g);
        if (g->s[g->i] != ':') return;
        ++g->i;
        g_inter(g);
        push_term(g->c, PROX_OP_OR, 0, 0);
    }
}

/* Builds the cells that `geom` complements (#n) before it. */
static int build_complemented(ctx *c, const char *geom)
{
    for (size_t i = 0; geom[i]; ++i) {
        if (geom[i] != '#') continue;
        size_t k = i + 1;
        while (geom[k] && isspace((unsigned char)geom[k])) ++k;
        if (!isdigit((unsigned char)geom[k])) continue;
        long n = 0;
        while (isdigit((unsigned char)geom[k]) && n < 1000000000L) n = n * 10 + (geom[k++] - '0');
        ccard *o = find_cell(c, n);
        if (o && o->state == 0) build_cell(c, o);
    }
    return 0;
}

/* Builds the geometry of cell cc into terms; sets the model cell's expr/nexpr or unchecked. */
static void build_geometry(ctx *c, ccard *cc, const ccard *g, prox_cell *cell, const prox_deck_tr *trcl)
{
    build_complemented(c, g->geom);
    size_t start = c->m->nterms;
    gp st = {.c = c, .s = g->geom, .cc = cc, .trcl = trcl, .start = start};
    ws(&st);
    if (!st.s[st.i]) push_term(c, PROX_OP_ALL, 0, 0);
    else {
        g_union(&st);
        ws(&st);
        if (!st.fail && st.s[st.i]) gerr(&st, "unexpected '%c' in the geometry", st.s[st.i]);
        if (!st.fail && c->m->nterms - start > CELLS_MAX_TERMS) gerr(&st, "the region has more than %d terms", CELLS_MAX_TERMS);
    }
    if (st.fail || c->nomem) { /* a surface not modelled, or an error reported above: empty region */
        c->m->nterms = start;
        cell->unchecked = 1;
        push_term(c, PROX_OP_ALL, 0, 0);
        push_term(c, PROX_OP_NOT, 0, 0);
        cell->expr = cell->elem_expr = start;
        cell->nexpr = cell->elem_nexpr = 2;
        if (st.fail > 0) add_unchecked(c, cc->line, "cell using a surface not modelled");
        return;
    }
    cell->expr = cell->elem_expr = start;
    cell->nexpr = cell->elem_nexpr = c->m->nterms - start;
    if (cell->lat) { /* the lattice fills its universe: all space; the element keeps the written region */
        cell->expr = c->m->nterms;
        cell->nexpr = 1;
        push_term(c, PROX_OP_ALL, 0, 0);
    }
}

/* Builds one cell (after the cells it is LIKE and those it complements). 0 on success. */
static int build_cell(ctx *c, ccard *cc)
{
    if (cc->state == 2) return 0;
    if (cc->state == 1 || cc->state == -1) return -1;
    if (c->depth >= CELLS_MAX_NEST) {
        add_error(c, cc->line, "cell %ld: complements of cells nested deeper than %d", cc->number, CELLS_MAX_NEST);
        cc->state = -1;
        return -1;
    }
    c->depth++;
    const prox_deck_card *saved = c->cur;
    c->cur = cc->card;
    int r = build_cell_now(c, cc);
    c->cur = saved;
    c->depth--;
    return r;
}

/* build_cell after the guards. */
static int build_cell_now(ctx *c, ccard *cc)
{
    cc->state = 1;
    const ccard *g = geometry_card(c, cc);
    if (!g) {
        if (!find_cell(c, cc->like)) add_error(c, cc->line, "cell %ld: LIKE %ld names a cell that is not defined", cc->number, cc->like);
        else add_error(c, cc->line, "cell %ld: LIKE chain is cyclic", cc->number);
        cc->state = -1;
        return -1;
    }
    size_t nk = 0;
    kw *kws = resolve_keywords(c, cc, &nk, 0);
    if (!kws) {
        cc->state = -1;
        return -1;
    }
    cellparams p = {.mat = g->mat, .rho = g->rho};
    if (read_params(c, cc, kws, nk, &p)) {
        free(kws);
        cc->state = -1;
        return -1;
    }
    prox_deck_tr trcl;
    int has_trcl = 0;
    if (p.trcl) {
        size_t i = 0;
        if (read_transform(c, p.trcl->val, p.trcl->nval, &i, p.trcl->star, &trcl, &has_trcl, p.trcl->line, cc->number,
                           "TRCL") ||
            i != p.trcl->nval) {
            if (i != p.trcl->nval) add_error(c, p.trcl->line, "cell %ld: malformed TRCL", cc->number);
            free(kws);
            cc->state = -1;
            return -1;
        }
    }
    prox_cell cell = {.number = cc->number, .line = cc->line, .material = p.mat, .density = p.mat ? p.rho : 0,
                      .universe = p.universe, .outside = p.has_imp && !p.imp_nonzero, .lat = (prox_lat_kind)p.lat};
    build_geometry(c, cc, g, &cell, has_trcl ? &trcl : NULL);
    prox_cell_model *m = c->m;
    if (grow((void **)&m->cells, &c->cap_cells, m->ncells, sizeof *m->cells)) {
        c->nomem = 1;
        free(kws);
        return -1;
    }
    cc->cell = m->ncells;
    m->cells[m->ncells++] = cell;
    /* keep the fill keyword for the windows: stored by index */
    cc->state = 2;
    free(kws);
    return 0;
}

/* ---- windows ------------------------------------------------------------------------------- */

/* Appends a window: the region of cell `ci` mapped by the inverse of `place` (NULL: as is).
 * Returns its index, or SIZE_MAX when out of memory. */
static size_t add_window(ctx *c, long u, size_t ci, const prox_deck_tr *place)
{
    prox_cell_model *m = c->m;
    const prox_cell *cell = &m->cells[ci];
    size_t start = m->nterms;
    prox_deck_tr inv;
    if (place) inv = cells_tr_inverse(place);
    for (size_t t = 0; t < cell->elem_nexpr && !c->nomem; ++t) { /* a lattice: its element (0,0,0) */
        prox_term term = m->terms[cell->elem_expr + t];
        if (place && term.op == PROX_OP_LEAF) {
            prox_surf s = cells_surf_transform(&m->surfs[term.surf], &inv);
            term.surf = push_surf(c, &s);
        }
        push_term(c, term.op, term.sense, term.surf);
    }
    if (c->nomem) return SIZE_MAX;
    if (grow((void **)&m->windows, &c->cap_windows, m->nwindows, sizeof *m->windows)) {
        c->nomem = 1;
        return SIZE_MAX;
    }
    prox_window w = {.universe = u, .cell = ci, .expr = start, .nexpr = m->nterms - start};
    for (int i = 0; i < 3; ++i) {
        w.place_o[i] = place ? place->o[i] : 0.0;
        for (int j = 0; j < 3; ++j) w.place_R[i][j] = place ? place->R[i][j] : (double)(i == j);
    }
    m->windows[m->nwindows] = w;
    return m->nwindows++;
}

static int universe_exists(const ctx *c, long u) { return lmap_get(&c->universes, u) != SIZE_MAX; }

/* One fill target: universe u placed by `place` (may be NULL) into cell ci. Adds the window once
 * per distinct (universe, placement) of a cell. */
typedef struct fill_seen {
    long u;
    int has;
    prox_deck_tr t;
    size_t win; /* its window (SIZE_MAX: none) */
} fill_seen;

typedef struct seen_list {
    fill_seen *v;
    size_t n, cap;
} seen_list;

static size_t window_for(ctx *c, ccard *cc, long u, const prox_deck_tr *trcl, const prox_deck_tr *ft, seen_list *sl,
                         int line)
{
    prox_deck_tr place;
    const prox_deck_tr *pl = NULL;
    if (trcl && ft) place = cells_tr_compose(trcl, ft), pl = &place;
    else if (trcl) place = *trcl, pl = &place;
    else if (ft) place = *ft, pl = &place;
    for (size_t i = 0; i < sl->n; ++i) { /* one window per distinct (universe, placement) */
        const fill_seen *f = &sl->v[i];
        if (f->u == u && f->has == (pl != NULL) &&
            (!pl || (!memcmp(f->t.o, pl->o, sizeof pl->o) && !memcmp(f->t.R, pl->R, sizeof pl->R))))
            return f->win;
    }
    if (grow((void **)&sl->v, &sl->cap, sl->n, sizeof *sl->v)) {
        c->nomem = 1;
        return SIZE_MAX;
    }
    fill_seen *f = &sl->v[sl->n++];
    *f = (fill_seen){u, pl != NULL, pl ? *pl : (prox_deck_tr){0}, SIZE_MAX};
    if (!universe_exists(c, u)) {
        add_error(c, line, "cell %ld: FILL names universe %ld, which has no cells", cc->number, u);
        return SIZE_MAX;
    }
    if (u == c->m->cells[cc->cell].universe) {
        add_error(c, line, "cell %ld: fills its own universe %ld", cc->number, u);
        return SIZE_MAX;
    }
    return f->win = add_window(c, u, cc->cell, pl);
}

/* Records that lattice element (i, j, k) holds window w (elements of a FILL array). */
static void add_element(ctx *c, size_t w, const long ijk[3])
{
    if (w == SIZE_MAX) return;
    prox_window *x = &c->m->windows[w];
    size_t n = x->nelem;
    if ((n & (n - 1)) == 0) { /* 0 or a power of two: double the room */
        void *p = realloc(x->elem, (n ? 2 * n : 1) * sizeof *x->elem);
        if (!p) {
            c->nomem = 1;
            return;
        }
        x->elem = p;
    }
    memcpy(x->elem[x->nelem++], ijk, sizeof x->elem[0]);
}

/* What the windows of one filled cell are built from. */
typedef struct fill_job {
    ctx *c;
    ccard *cc;
    prox_cell *cell;
    const kw *fill;
    const prox_deck_tr *trcl; /* the cell's TRCL (NULL: none) */
    seen_list seen;
} fill_job;

/* FILL=u [(transform)]. */
static void fill_single(fill_job *j)
{
    char **v = j->fill->val;
    size_t nv = j->fill->nval, i = 1;
    long u;
    if (prox_deck_long(v[0], &u) || u < 0) {
        add_error(j->c, j->fill->line, "cell %ld: FILL universe '%s' is not a number", j->cc->number, v[0]);
        return;
    }
    prox_deck_tr ft;
    int has_ft = 0;
    if (read_transform(j->c, v, nv, &i, j->fill->star, &ft, &has_ft, j->fill->line, j->cc->number, "FILL")) return;
    if (i != nv) {
        add_error(j->c, j->fill->line, "cell %ld: malformed FILL", j->cc->number);
        return;
    }
    j->cell->fill = u;
    if (u) window_for(j->c, j->cc, u, j->trcl, has_ft ? &ft : NULL, &j->seen, j->fill->line);
    /* On a lattice every element holds u: the window lists no element (nelem 0). */
}

/* Reads the index range "lo:hi" of token t. 0 on success. */
static int index_range(const char *t, long *lo, long *hi)
{
    const char *colon = strchr(t, ':');
    char a[32], b[32];
    if (!colon || (size_t)(colon - t) >= sizeof a || strlen(colon + 1) >= sizeof b) return -1;
    snprintf(a, sizeof a, "%.*s", (int)(colon - t), t);
    snprintf(b, sizeof b, "%s", colon + 1);
    if (prox_deck_long(a, lo) || prox_deck_long(b, hi) || *hi < *lo) return -1;
    return labs(*lo) > CELLS_MAX_INDEX || labs(*hi) > CELLS_MAX_INDEX ? -1 : 0;
}

/* Element number `at` of a fill array (i fastest, then j, then k) holds window w. */
static void element_at(ctx *c, size_t w, size_t at, const long lo[3], const long n[3])
{
    size_t ni = (size_t)n[0], nj = (size_t)n[1];
    long ijk[3] = {lo[0] + (long)(at % ni), lo[1] + (long)(at / ni % nj), lo[2] + (long)(at / (ni * nj))};
    add_element(c, w, ijk);
}

/* Lattice fill array: i1:i2 j1:j2 k1:k2, then one entry per element, each optionally followed by a
 * transform in parentheses; nR repeats the previous entry. An entry 0 or equal to the lattice's own
 * universe fills no universe (the element holds the lattice cell's material). */
static void fill_array(fill_job *j)
{
    char **v = j->fill->val;
    size_t nv = j->fill->nval, want = 1, got = 0, i, prev = SIZE_MAX;
    long lo[3], n[3];
    for (int d = 0; d < 3; ++d) {
        long hi;
        if (d >= (int)nv || index_range(v[d], &lo[d], &hi)) goto bad;
        n[d] = hi - lo[d] + 1;
        want *= (size_t)n[d];
    }
    if (!j->cell->lat) {
        add_error(j->c, j->fill->line, "cell %ld: a FILL array needs LAT", j->cc->number);
        return;
    }
    int have_prev = 0;
    for (i = 3; i < nv;) {
        long u, cnt;
        size_t L = strlen(v[i]);
        if (L > 1 && toupper((unsigned char)v[i][L - 1]) == 'R' && have_prev) { /* the same window again */
            char buf[24];
            snprintf(buf, sizeof buf, "%.*s", (int)(L - 1), v[i]);
            if (prox_deck_long(buf, &cnt) || cnt < 1) goto bad;
            if ((size_t)cnt > want - (got < want ? got : want)) /* too many: reported below */
                got += (size_t)cnt;
            else
                for (long r = 0; r < cnt; ++r) element_at(j->c, prev, got++, lo, n);
            ++i;
            continue;
        }
        if (prox_deck_long(v[i++], &u)) goto bad;
        prox_deck_tr ft;
        int has_ft = 0;
        if (read_transform(j->c, v, nv, &i, j->fill->star, &ft, &has_ft, j->fill->line, j->cc->number, "FILL")) return;
        have_prev = 1, prev = SIZE_MAX;
        if (u != 0 && u != j->cell->universe)
            prev = window_for(j->c, j->cc, u, j->trcl, has_ft ? &ft : NULL, &j->seen, j->fill->line);
        if (got < want) element_at(j->c, prev, got, lo, n);
        ++got;
    }
    if (got != want)
        add_error(j->c, j->fill->line, "cell %ld: FILL array has %zu entries for %zu elements", j->cc->number, got, want);
    return;
bad:
    add_error(j->c, j->fill->line, "cell %ld: malformed FILL array", j->cc->number);
}

/* The windows of one filled or lattice cell. */
static void cell_windows(ctx *c, ccard *cc)
{
    size_t nk = 0;
    kw *kws = resolve_keywords(c, cc, &nk, 0);
    if (!kws) return;
    const kw *fill = NULL, *trk = NULL;
    for (size_t i = 0; i < nk; ++i) {
        char base[24];
        base_name(kws[i].name, base, sizeof base);
        if (!strcmp(base, "FILL")) fill = &kws[i];
        if (!strcmp(base, "TRCL")) trk = &kws[i];
    }
    fill_job j = {.c = c, .cc = cc, .cell = &c->m->cells[cc->cell], .fill = fill};
    if (fill && !fill->nval) add_error(c, fill->line, "cell %ld: FILL needs a universe", cc->number);
    if (fill && fill->nval && !j.cell->unchecked) {
        prox_deck_tr trcl;
        int has_trcl = 0;
        size_t i = 0;
        if (trk) read_transform(c, trk->val, trk->nval, &i, trk->star, &trcl, &has_trcl, trk->line, cc->number, "TRCL");
        j.trcl = has_trcl ? &trcl : NULL;
        if (strchr(fill->val[0], ':')) fill_array(&j);
        else fill_single(&j);
    }
    free(j.seen.v);
    free(kws);
}

/* ---- driver --------------------------------------------------------------------------------- */

/* The card layer's notes: its errors stay errors; what it listed as unsupported (READ cards without
 * file access, DECODE, text beyond the column limit) is unchecked, by kind. */
static void card_layer_notes(ctx *c)
{
    snprintf(c->m->title, sizeof c->m->title, "%s", c->raw.deck.title);
    for (size_t i = 0; i < c->raw.deck.nerrors; ++i)
        add_error(c, c->raw.deck.errors[i].line, "%s", c->raw.deck.errors[i].text);
    for (size_t i = 0; i < c->raw.deck.nunsupported; ++i) {
        const char *t = c->raw.deck.unsupported[i].text;
        const char *colon = strchr(t, ':');
        int n = colon ? (int)(colon - t) : (int)strlen(t);
        if (!strncmp(t, "text beyond column", 18)) n = (int)(strstr(t, "ignored") + 7 - t);
        add_unchecked(c, c->raw.deck.unsupported[i].line, "%.*s", n < 80 ? n : 80, t);
    }
}

/* Reads every card of one block. */
static void read_block(ctx *c, int block)
{
    for (size_t k = 0; k < c->raw.ncards && !c->nomem; ++k) {
        prox_deck_card *d = &c->raw.cards[k];
        c->cur = d;
        if (d->block != block) continue;
        if (block == PROX_CARD_SURFACE) surface_card(c, d->text, d->line);
        else cell_card(c, d->text, d->line);
    }
    c->cur = NULL;
}

/* Puts the model's cells in card order (LIKE and #n build cells out of order). */
static void order_cells(ctx *c)
{
    prox_cell_model *m = c->m;
    if (c->nomem || !m->ncells) return;
    prox_cell *sorted = malloc(m->ncells * sizeof *sorted);
    if (!sorted) {
        c->nomem = 1;
        return;
    }
    size_t n = 0;
    for (size_t i = 0; i < c->ncc; ++i)
        if (c->cc[i].state == 2) {
            sorted[n] = m->cells[c->cc[i].cell];
            c->cc[i].cell = n++;
        }
    memcpy(m->cells, sorted, n * sizeof *sorted);
    m->ncells = n;
    free(sorted);
}

/* The real world's window (all space), then those of every filled and lattice cell. */
static void make_windows(ctx *c)
{
    prox_cell_model *m = c->m;
    for (size_t i = 0; i < m->ncells && !c->nomem; ++i)
        if (lmap_put(&c->universes, m->cells[i].universe, 1)) c->nomem = 1;
    if (c->nomem) return;
    if (grow((void **)&m->windows, &c->cap_windows, m->nwindows, sizeof *m->windows)) {
        c->nomem = 1;
        return;
    }
    m->windows[m->nwindows++] =
        (prox_window){.universe = 0, .cell = (size_t)-1, .place_R = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (size_t i = 0; i < c->ncc && !c->nomem; ++i)
        if (c->cc[i].state == 2) {
            c->cur = c->cc[i].card;
            cell_windows(c, &c->cc[i]);
        }
    c->cur = NULL;
}

static void ctx_free(ctx *c)
{
    for (size_t i = 0; i < c->ncc; ++i) {
        free(c->cc[i].geom);
        free(c->cc[i].kws);
    }
    free(c->cc);
    free(c->se);
    lmap_free(&c->surf_of);
    lmap_free(&c->cell_of);
    lmap_free(&c->universes);
    for (size_t i = 0; i < c->nstrs; ++i) free(c->strs[i]);
    free(c->strs);
    prox_deck_raw_free(&c->raw);
}

/* Surfaces first (cells name them), then cells, the data block's cell parameters, the cells'
 * regions, and the windows. */
static prox_status finish(ctx *c)
{
    card_layer_notes(c);
    read_block(c, PROX_CARD_SURFACE);
    read_block(c, PROX_CARD_CELL);
    if (!c->nomem) data_cards(c);
    for (size_t i = 0; i < c->ncc && !c->nomem; ++i) build_cell(c, &c->cc[i]);
    order_cells(c);
    if (!c->nomem) make_windows(c);
    if (!c->nomem && cells_bound_windows(c->m) != PROX_OK) c->nomem = 1; /* window_bound.c */
    ctx_free(c);
    if (c->nomem) {
        prox_cells_free(c->m);
        return PROX_ENOMEM;
    }
    return PROX_OK;
}

static prox_status run(const char *text, const char *path, prox_cell_model *m)
{
    if (!m || (!text && !path)) return PROX_EINVAL_ARG;
    ctx c = {.m = m};
    prox_status st = prox_deck_raw_read(text, path, &c.raw);
    if (st != PROX_OK) {
        prox_deck_raw_free(&c.raw);
        return st;
    }
    return finish(&c);
}

PROX_API prox_status prox_cells_read_file(const char *path, prox_cell_model *m)
{
    if (!path) return PROX_EINVAL_ARG;
    return run(NULL, path, m);
}

PROX_API prox_status prox_cells_parse(const char *text, prox_cell_model *m)
{
    if (!text) return PROX_EINVAL_ARG;
    return run(text, NULL, m);
}

PROX_API void prox_cells_free(prox_cell_model *m)
{
    if (!m) return;
    free(m->surfs);
    free(m->terms);
    free(m->cells);
    for (size_t i = 0; i < m->nwindows; ++i) free(m->windows[i].elem);
    free(m->windows);
    free(m->errors);
    free(m->unchecked);
    memset(m, 0, sizeof *m);
}
