/* MCNP input deck reader: surface block -> prox_shape bodies in the global frame.
 * Follows the MCNP6 user manual (LA-CP-13-00634), Ch. 3: input format (Sec. 3.1: message block,
 * title card, blank-line delimiters, comment cards, `$` comments, continuation by 5 leading blanks
 * or `&`, the shorthands nR nI xM nJ nILOG), surface cards (Sec. 3.2.2: "j n A list", j optionally
 * prefixed by * or +, n > 0 a TRn number, n < 0 a periodic partner), sphere surfaces SO S SX SY SZ
 * (Table 3-4), the macrobodies RPP BOX SPH RCC TRC REC ELL RHP/HEX WED ARB in every card form (Sec.
 * 3.2.2.4; docs/deck.md has the table), and the TRn card (Sec. 3.3.1.7): the point
 * r' written on a surface card lies at r = O + B r' (M = 1) or r = B (r' - O) (M = -1), where the
 * columns of B are the auxiliary axes x', y', z' in main coordinates: (B1 B2 B3) = (xx' yx' zx') etc.
 * With *TRn the B entries are angles in degrees. Patterns read: 0 entries of B (identity), 6 (x' and
 * y' axes; z' = x' cross y'), 9 (all). MCNP's other short patterns are reported as errors. B must be
 * orthonormal within 1e-3 (MCNP's own tolerance); it is then re-orthonormalised (Gram-Schmidt).
 *
 * Columns: MCNP6 reads columns 1-128 of an input line; text beyond is cut and, unless blank or after
 * a `$`, listed as unsupported on its line.
 *
 * Card layer (deck_internal.h): prox_deck_raw_read runs the same reader in "card mode": cards are
 * kept (block, lines, text) for the cell model reader instead of turned into bodies.
 *
 * READ card (Ch. 3, "READ card": READ FILE=name [ECHO|NOECHO] [DECODE=..] [ENCODE=..], anywhere after the
 * title; the file's lines replace the card, its blank lines delimit blocks as usual). Design: the
 * lines are read from a stack of sources (the main deck, then each open file, at most 8 levels
 * deep); every line gets a running "virtual" number, and with prox_deck_read_file a per-line map
 * records its origin (file, line in that file, line of the main deck, i.e. the top-level READ
 * card). Cards carry virtual numbers; add_note and the bodies translate them through the map, so
 * note and body lines are always exact main-deck lines and a note from an included file starts
 * with "'<file>' line <n>: ". A READ card ends the card before it (a new card starts in columns
 * 1-5); it cannot itself be continued. A relative name is resolved against the directory of the
 * file holding the card. A cycle (the resolved path already open, compared as strings; other
 * spellings of the same file end at the depth limit), nesting deeper than 8, a missing file, a file
 * with NUL bytes, a card without FILE= and an unknown keyword are errors on the card's line; the
 * rest of the deck is still read. DECODE (an encoded binary file) is noted as unsupported and the
 * FILE= content is read as text; ECHO, NOECHO and ENCODE (the encoded copy MCNP writes) are accepted. At most 4096 files are read per deck (a bound on
 * READ fan-out). prox_deck_parse has no file context: every READ card there is an unsupported note,
 * and it never touches the filesystem. */
#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "prox/deck.h"
#include "scene/deck_internal.h"

#define DECK_MAX_ENTRIES 64 /* more entries than any card read here can take */
#define DECK_MAX_DEPTH 8    /* READ nesting levels below the main deck */
#define DECK_MAX_READS 4096 /* files read through READ cards in one deck (bounds READ fan-out) */
#define DECK_NAME_SHOWN 64  /* longest file name shown in a note (longer: its tail after "...") */
#define DECK_COLUMNS 128    /* columns of an input line read (MCNP6; MCNP5 read 80) */

/* ---- growable arrays ------------------------------------------------------------------------ */

/* Grows *arr (element size sz) so that it can hold n + 1 elements. 0 on success. */
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

/* A logical card: its text with continuations joined, and the line it starts on. */
typedef struct card {
    int line;
    char *text;
    size_t len, cap;
} card;

/* A surface card parsed up to its entries; placed once every TRn is known. */
typedef struct pending_surface {
    long surface;
    int line;
    char card[8];
    long tr;
    double v[DECK_MAX_ENTRIES];
    size_t nv;
} pending_surface;

/* A TRn card turned into a map r -> o + R r' (deck_internal.h). */
typedef prox_deck_tr transform;

/* Where a line of the expanded input comes from: a file (index into parser.files; 0 = the main
 * deck), its line there, and the line of the main deck that holds it (the top-level READ card). */
typedef struct line_origin {
    int file;
    int line;
    int top;
} line_origin;

/* One text being read: the main deck or a file brought in by READ. */
typedef struct source {
    char *owned;     /* the file's text (NULL for the caller's text) */
    const char *pos; /* next unread character */
    int file;        /* index into parser.files */
    int line;        /* lines read from it so far */
} source;

/* Everything the parser keeps while reading. Card and note line numbers inside the parser are
 * "virtual" lines: the running count of lines read from all sources; origin() maps them back. */
typedef struct parser {
    prox_deck *deck;
    size_t cap_bodies, cap_errors, cap_unsup;
    pending_surface *surf;
    size_t nsurf, cap_surf;
    size_t *surf_slot;      /* hash of surface numbers: index + 1 into surf, 0 empty (open addressing) */
    size_t cap_slot;        /* a power of two, at least twice nsurf */
    transform *tr;
    size_t ntr, cap_tr;
    int nomem;
    int with_files;         /* READ cards are followed (prox_deck_read_file) */
    char **files;           /* resolved paths of the files read; files[0] is the main deck */
    size_t nfiles, cap_files;
    line_origin *map;       /* map[v - 1]: origin of virtual line v (only with_files) */
    size_t nmap, cap_map;
    source stack[DECK_MAX_DEPTH + 1];
    int depth;              /* stack[0..depth] are open; stack[depth] is read */
    prox_deck_raw *raw;     /* card mode: cards are kept here instead of read as bodies */
    size_t cap_cards;
} parser;

/* Slot of surface number j in the hash: its own slot or the empty one where it would go. */
static size_t surf_probe(const parser *p, long j)
{
    size_t mask = p->cap_slot - 1, h = ((size_t)j * (size_t)0x9e3779b97f4a7c15ULL) & mask;
    while (p->surf_slot[h] && p->surf[p->surf_slot[h] - 1].surface != j) h = (h + 1) & mask;
    return h;
}

/* The pending surface numbered j, or NULL: one lookup instead of a scan of every earlier surface. */
static const pending_surface *surf_find(const parser *p, long j)
{
    if (!p->cap_slot) return NULL;
    size_t k = p->surf_slot[surf_probe(p, j)];
    return k ? &p->surf[k - 1] : NULL;
}

/* Enters surf[i] in the hash (doubling it at half load). 0 on success. */
static int surf_enter(parser *p, size_t i)
{
    if (2 * (p->nsurf + 1) > p->cap_slot) {
        size_t nc = p->cap_slot ? 2 * p->cap_slot : 64;
        size_t *old = p->surf_slot, oc = p->cap_slot;
        p->surf_slot = calloc(nc, sizeof *p->surf_slot);
        if (!p->surf_slot) {
            p->surf_slot = old;
            return -1;
        }
        p->cap_slot = nc;
        for (size_t k = 0; k < oc; ++k)
            if (old[k]) p->surf_slot[surf_probe(p, p->surf[old[k] - 1].surface)] = old[k];
        free(old);
    }
    p->surf_slot[surf_probe(p, p->surf[i].surface)] = i + 1;
    return 0;
}

/* The origin of virtual line v (the identity for the caller's text and for line 0). */
static line_origin origin(const parser *p, int v)
{
    if (v > 0 && (size_t)v <= p->nmap) return p->map[v - 1];
    return (line_origin){0, v, v};
}

/* The tail of a path short enough for a note (at most DECK_NAME_SHOWN characters). */
static const char *shown_name(const char *path, int *cut)
{
    size_t n = strlen(path);
    *cut = n > DECK_NAME_SHOWN;
    return *cut ? path + n - (DECK_NAME_SHOWN - 3) : path;
}

/* Writes "line N" (main deck) or "'file' line n" (an included file) for virtual line v. */
static void where(const parser *p, int v, char *buf, size_t sz)
{
    line_origin o = origin(p, v);
    if (o.file == 0) {
        snprintf(buf, sz, "line %d", o.line);
        return;
    }
    int cut;
    const char *name = shown_name(p->files[o.file], &cut);
    snprintf(buf, sz, "'%s%s' line %d", cut ? "..." : "", name, o.line);
}

/* Adds a note (error or unsupported card) with printf-style text, at virtual line v: the note's line
 * is the main-deck line, and a line of an included file is named in front of the text. */
static void add_note(parser *p, int unsupported, int v, const char *fmt, ...)
{
    prox_deck *d = p->deck;
    prox_deck_note **arr = unsupported ? &d->unsupported : &d->errors;
    size_t *n = unsupported ? &d->nunsupported : &d->nerrors;
    size_t *cap = unsupported ? &p->cap_unsup : &p->cap_errors;
    if (grow((void **)arr, cap, *n, sizeof **arr)) {
        p->nomem = 1;
        return;
    }
    prox_deck_note *note = &(*arr)[(*n)++];
    line_origin o = origin(p, v);
    note->line = o.top;
    char msg[PROX_DECK_TEXT];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (o.file == 0) {
        memcpy(note->text, msg, sizeof msg);
        return;
    }
    char at[DECK_NAME_SHOWN + 32];
    where(p, v, at, sizeof at);
    /* "<where>: <msg>", cut to the note's size (copied by hand: the cut is intended) */
    size_t k = 0, la = strlen(at), lm = strlen(msg);
    for (size_t i = 0; i < la && k + 1 < sizeof note->text; ++i) note->text[k++] = at[i];
    for (size_t i = 0; i < 2 && k + 1 < sizeof note->text; ++i) note->text[k++] = ": "[i];
    for (size_t i = 0; i < lm && k + 1 < sizeof note->text; ++i) note->text[k++] = msg[i];
    note->text[k] = 0;
}

/* ---- lexical helpers ------------------------------------------------------------------------ */

/* Case-insensitive equality of two NUL-terminated strings. */
static int ieq(const char *a, const char *b)
{
    for (; *a && *b; ++a, ++b)
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b)) return 0;
    return *a == *b;
}

/* Reads a decimal integer with optional sign; the whole string must be consumed. 0 on success. */
static int parse_long(const char *s, long *out)
{
    const char *q = s;
    if (*q == '+' || *q == '-') ++q;
    if (!isdigit((unsigned char)*q)) return -1;
    for (; *q; ++q)
        if (!isdigit((unsigned char)*q)) return -1;
    errno = 0;
    long v = strtol(s, NULL, 10);
    if (errno == ERANGE) return -1;
    *out = v;
    return 0;
}

/* Length of the MCNP number at the start of s: [+-] digits [. digits] | [+-] . digits, then an
 * optional exponent [eEdD][+-]digits or, with the letter left out, [+-]digits: MCNP reads its entries
 * as Fortran real input, where an exponent may be a signed integer alone (Fortran 2008, 10.7.2.3.2:
 * "1.5-3" is 1.5e-3); the MCNP6 criticality validation decks write densities so (4.7328-2). 0 when s
 * does not start with such a number. Inf, NaN and hex are not numbers here. */
static size_t number_length(const char *s)
{
    size_t i = 0, digits = 0;
    if (s[i] == '+' || s[i] == '-') ++i;
    while (isdigit((unsigned char)s[i])) ++i, ++digits;
    if (s[i] == '.') {
        ++i;
        while (isdigit((unsigned char)s[i])) ++i, ++digits;
    }
    if (!digits) return 0;
    if (s[i] == 'e' || s[i] == 'E' || s[i] == 'd' || s[i] == 'D') {
        size_t j = i + 1;
        if (s[j] == '+' || s[j] == '-') ++j;
        if (!isdigit((unsigned char)s[j])) return i; /* "2d" etc: the letter is not an exponent */
        while (isdigit((unsigned char)s[j])) ++j;
        i = j;
    } else if ((s[i] == '+' || s[i] == '-') && isdigit((unsigned char)s[i + 1])) {
        ++i;
        while (isdigit((unsigned char)s[i])) ++i;
    }
    return i;
}

/* Converts the first len characters of s (a valid number_length prefix) to a double. */
static int convert_number(const char *s, size_t len, double *out)
{
    char buf[64];
    if (len + 1 >= sizeof buf) return -1;
    size_t k = 0;
    for (size_t i = 0; i < len; ++i) {
        /* A sign after the mantissa starts a Fortran exponent without its letter: write the e. */
        if (i && (s[i] == '+' || s[i] == '-') && buf[k - 1] != 'e' && buf[k - 1] != 'E') buf[k++] = 'e';
        buf[k++] = (s[i] == 'd' || s[i] == 'D') ? 'e' : s[i];
    }
    buf[k] = 0;
    double v = strtod(buf, NULL);
    if (!isfinite(v)) return -1;
    *out = v;
    return 0;
}

/* A whole token as a number. 0 on success. */
static int parse_number(const char *s, double *out)
{
    size_t n = number_length(s);
    if (!n || s[n]) return -1;
    return convert_number(s, n, out);
}

/* Splits text in place on blanks; returns the number of tokens (at most max). */
static size_t tokenize(char *text, char **tok, size_t max)
{
    size_t n = 0;
    char *s = text;
    while (*s && n < max) {
        while (*s && isspace((unsigned char)*s)) ++s;
        if (!*s) break;
        tok[n++] = s;
        while (*s && !isspace((unsigned char)*s)) ++s;
        if (*s) *s++ = 0;
    }
    return n;
}

/* ---- entries with the nR nI xM nILOG shorthands --------------------------------------------- */

/* Reads the optional repeat count in front of a shorthand letter sequence `suffix` (e.g. "3R" ->
 * 3, "R" -> 1). Returns 1 when tok is that shorthand, 0 when not, -1 when the count is bad. */
static int shorthand_count(const char *tok, const char *suffix, long *count)
{
    size_t lt = strlen(tok), ls = strlen(suffix);
    if (lt < ls || !ieq(tok + lt - ls, suffix)) return 0;
    if (lt == ls) {
        *count = 1;
        return 1;
    }
    char buf[32];
    if (lt - ls >= sizeof buf) return -1;
    memcpy(buf, tok, lt - ls);
    buf[lt - ls] = 0;
    for (size_t i = 0; buf[i]; ++i)
        if (!isdigit((unsigned char)buf[i])) return 0; /* not a count: maybe xM or a bad token */
    long c;
    if (parse_long(buf, &c) || c < 1) return -1;
    *count = c;
    return 1;
}

/* Expands the entries tok[0..n) into v; on failure writes the reason to err and returns -1. */
static int expand_entries(char **tok, size_t n, double *v, size_t *nv, size_t max, char *err, size_t errsz)
{
    size_t k = 0;
    long interp = 0;  /* pending nI / nILOG count */
    int interp_log = 0;
    for (size_t i = 0; i < n; ++i) {
        const char *t = tok[i];
        double x;
        long c;
        int r;
        if (!parse_number(t, &x)) {
            if (interp) {
                double a = v[k - 1];
                if (interp_log && !(a > 0 && x > 0)) {
                    snprintf(err, errsz, "'%ldILOG' needs positive neighbours", interp);
                    return -1;
                }
                if (k + (size_t)interp > max) goto too_many;
                for (long j = 1; j <= interp; ++j) {
                    double f = (double)j / (double)(interp + 1);
                    v[k++] = interp_log ? exp(log(a) + f * (log(x) - log(a))) : a + f * (x - a);
                }
                interp = 0;
            }
            if (k >= max) goto too_many;
            v[k++] = x;
            continue;
        }
        if (interp) {
            snprintf(err, errsz, "interpolation must be followed by a number, not '%s'", t);
            return -1;
        }
        if ((r = shorthand_count(t, "ILOG", &c)) != 0) {
            if (r < 0 || !k) goto bad_shorthand;
            interp = c, interp_log = 1;
        } else if ((r = shorthand_count(t, "R", &c)) != 0) {
            if (r < 0 || !k) goto bad_shorthand;
            if (k + (size_t)c > max) goto too_many;
            for (long j = 0; j < c; ++j, ++k) v[k] = v[k - 1];
        } else if ((r = shorthand_count(t, "I", &c)) != 0) {
            if (r < 0 || !k) goto bad_shorthand;
            interp = c, interp_log = 0;
        } else if ((r = shorthand_count(t, "J", &c)) != 0) {
            snprintf(err, errsz, "'%s' (jump to default values) is not supported: these entries have no defaults", t);
            return -1;
        } else {
            size_t len = number_length(t);
            if (len && (t[len] == 'm' || t[len] == 'M') && !t[len + 1] && k) {
                if (convert_number(t, len, &x)) goto bad_number;
                if (k >= max) goto too_many;
                v[k] = x * v[k - 1];
                ++k;
                continue;
            }
            goto bad_number;
        }
        continue;
    bad_shorthand:
        snprintf(err, errsz, "shorthand '%s' %s", t, r < 0 ? "has a bad count" : "has no preceding entry");
        return -1;
    bad_number:
        snprintf(err, errsz, "'%s' is not a number", t);
        return -1;
    }
    if (interp) {
        snprintf(err, errsz, "interpolation at the end of the card has no following entry");
        return -1;
    }
    *nv = k;
    return 0;
too_many:
    snprintf(err, errsz, "more than %zu entries", max);
    return -1;
}

/* ---- surface cards ---------------------------------------------------------------------------- */

/* Entry counts of the body cards: the first form, and a second accepted form (0: none). MCNP6
 * manual, Sec. 3.2.2.4 (macrobodies) and Table 3-4 (sphere surfaces). */
static const struct body_card {
    const char *name;
    size_t n, n2;
} body_cards[] = {{"RCC", 7, 0},  {"BOX", 12, 0}, {"RPP", 6, 0},  {"SPH", 4, 0},  {"TRC", 8, 0},
                  {"REC", 12, 10}, {"ELL", 7, 0}, {"RHP", 15, 9}, {"HEX", 15, 9}, {"WED", 12, 0},
                  {"ARB", 30, 0}, {"SO", 1, 0},   {"S", 4, 0},    {"SX", 2, 0},   {"SY", 2, 0},
                  {"SZ", 2, 0}};

/* The body card named mn (upper case), NULL for a mnemonic that is not a body. */
static const struct body_card *body_card_of(const char *mn)
{
    for (size_t i = 0; i < sizeof body_cards / sizeof body_cards[0]; ++i)
        if (!strcmp(mn, body_cards[i].name)) return &body_cards[i];
    return NULL;
}

/* Parses "j [n] A list" and queues it (or records the error / unsupported card). */
static void surface_card(parser *p, char *text, int line)
{
    char *tok[DECK_MAX_ENTRIES + 4];
    size_t nt = tokenize(text, tok, sizeof tok / sizeof tok[0]);
    if (nt == 0) return; /* only blanks (e.g. lines ended by '&' with nothing after): no card */
    if (nt == sizeof tok / sizeof tok[0]) {
        add_note(p, 0, line, "surface card has too many entries");
        return;
    }
    const char *js = tok[0];
    if (*js == '*' || *js == '+') ++js;
    long j, n = 0;
    if (parse_long(js, &j) || j < 1 || *js == '+' || *js == '-') {
        add_note(p, 0, line, "surface number '%s' is not a positive integer", tok[0]);
        return;
    }
    size_t k = 1;
    if (k < nt && !parse_long(tok[k], &n)) ++k;
    if (k >= nt) {
        add_note(p, 0, line, "surface %ld has no mnemonic", j);
        return;
    }
    char mn[8];
    size_t ml = strlen(tok[k]);
    for (size_t i = 0; i < sizeof mn - 1 && i < ml; ++i) mn[i] = (char)toupper((unsigned char)tok[k][i]);
    mn[ml < sizeof mn - 1 ? ml : sizeof mn - 1] = 0;
    const struct body_card *bc = body_card_of(mn);
    if (!bc) {
        if (!isalpha((unsigned char)tok[k][0]))
            add_note(p, 0, line, "surface %ld: '%s' is not a surface mnemonic", j, tok[k]);
        else
            add_note(p, 1, line, "%ld %s", j, mn);
        return;
    }
    if (n < 0) {
        add_note(p, 0, line, "surface %ld: periodic partner %ld is meaningless for %s", j, -n, mn);
        return;
    }
    const pending_surface *dup = surf_find(p, j);
    if (dup) {
        char at[DECK_NAME_SHOWN + 32];
        where(p, dup->line, at, sizeof at);
        add_note(p, 0, line, "surface %ld is already defined on %s", j, at);
        return;
    }
    if (grow((void **)&p->surf, &p->cap_surf, p->nsurf, sizeof *p->surf)) {
        p->nomem = 1;
        return;
    }
    pending_surface *s = &p->surf[p->nsurf];
    char err[PROX_DECK_TEXT - 40];
    if (expand_entries(tok + k + 1, nt - k - 1, s->v, &s->nv, DECK_MAX_ENTRIES, err, sizeof err)) {
        add_note(p, 0, line, "surface %ld %s: %s", j, mn, err);
        return;
    }
    if (s->nv != bc->n && !(bc->n2 && s->nv == bc->n2)) {
        if (bc->n2)
            add_note(p, 0, line, "surface %ld %s: needs %zu or %zu entries, has %zu", j, mn, bc->n2, bc->n, s->nv);
        else
            add_note(p, 0, line, "surface %ld %s: needs %zu entries, has %zu", j, mn, bc->n, s->nv);
        return;
    }
    s->surface = j, s->line = line, s->tr = n;
    memcpy(s->card, mn, sizeof s->card);
    if (surf_enter(p, p->nsurf)) {
        p->nomem = 1;
        return;
    }
    p->nsurf++;
}

/* ---- TRn cards -------------------------------------------------------------------------------- */

/* cos of an angle in degrees, exact at multiples of 90. */
static double cos_deg(double a)
{
    double r = fmod(a, 360.0);
    if (r < 0) r += 360.0;
    if (r == 0.0) return 1.0;
    if (r == 90.0 || r == 270.0) return 0.0;
    if (r == 180.0) return -1.0;
    return cos(r * (PROX_PI / 180.0));
}

/* Checks that the columns of R are orthonormal within 1e-3 and re-orthonormalises them in place
 * (x' normalised, y' made orthogonal to x', z' = +-(x' cross y') with the sign of the given z'). */
static int orthonormalize(double R[3][3])
{
    prox_vec3 c[3];
    for (int j = 0; j < 3; ++j) c[j] = prox_v3(R[0][j], R[1][j], R[2][j]);
    for (int j = 0; j < 3; ++j) {
        if (fabs(prox_v3_norm(c[j]) - 1.0) > 1e-3) return -1;
        if (fabs(prox_v3_dot(c[j], c[(j + 1) % 3])) > 1e-3) return -1;
    }
    prox_vec3 x = prox_v3_normalize(c[0]);
    prox_vec3 y = prox_v3_normalize(prox_v3_reject(c[1], x));
    prox_vec3 z = prox_v3_cross(x, y);
    if (prox_v3_dot(z, c[2]) < 0) z = prox_v3_neg(z);
    c[0] = x, c[1] = y, c[2] = z;
    for (int j = 0; j < 3; ++j) R[0][j] = c[j].x, R[1][j] = c[j].y, R[2][j] = c[j].z;
    return 0;
}

/* Builds r = o + R r' from the entries of a TRn card or an inline transform (TRCL, FILL): 3
 * (displacement), 9 (and the x', y' axes; z' = x' cross y'), 12 (full matrix) or 13 (and M). */
int prox_deck_make_tr(const double *v, size_t nv, int degrees, prox_deck_tr *out, char *err, size_t errsz)
{
    if (nv != 3 && nv != 9 && nv != 12 && nv != 13) {
        snprintf(err, errsz, "%zu entries; prox reads 3 (displacement), 9 (and x', y' axes), 12 (full matrix) "
                 "or 13 (and M)", nv);
        return -1;
    }
    transform t = {.o = {v[0], v[1], v[2]}, .identity = nv == 3};
    double R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (size_t e = 3; e < nv && e < 12; ++e) {
        size_t col = (e - 3) / 3, row = (e - 3) % 3;
        R[row][col] = degrees ? cos_deg(v[e]) : v[e];
    }
    if (nv == 9) { /* z' = x' cross y' */
        prox_vec3 z = prox_v3_cross(prox_v3(R[0][0], R[1][0], R[2][0]), prox_v3(R[0][1], R[1][1], R[2][1]));
        R[0][2] = z.x, R[1][2] = z.y, R[2][2] = z.z;
    }
    if (nv > 3 && orthonormalize(R)) {
        snprintf(err, errsz, "rotation matrix is not orthonormal within 1e-3");
        return -1;
    }
    double m = nv == 13 ? v[12] : 1.0;
    if (m != 1.0 && m != -1.0) {
        snprintf(err, errsz, "M must be 1 or -1, not %g", m);
        return -1;
    }
    memcpy(t.R, R, sizeof R);
    if (m < 0) { /* O is the main origin in auxiliary coordinates: r = R (r' - O) = R r' - R O */
        double o2[3];
        for (int i = 0; i < 3; ++i) o2[i] = -(R[i][0] * t.o[0] + R[i][1] * t.o[1] + R[i][2] * t.o[2]);
        memcpy(t.o, o2, sizeof o2);
    }
    if (!t.identity) {
        t.identity = 1;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) t.identity &= R[i][j] == (i == j ? 1.0 : 0.0);
    }
    *out = t;
    return 0;
}

/* Parses a TRn / *TRn card (tok[0] is its name). */
static void tr_card(parser *p, char **tok, size_t nt, int line)
{
    const char *name = tok[0];
    int degrees = *name == '*';
    long n;
    size_t len = strlen(name);
    /* TRn* is read as *TRn (rotation in degrees): a spelling real decks use that MCNP accepts. */
    char num[32];
    size_t off = (size_t)degrees + 2, nlen = len > off ? len - off : 0;
    if (!degrees && nlen > 1 && name[len - 1] == '*') degrees = 1, --nlen;
    if (nlen == 0 || nlen >= sizeof num) {
        add_note(p, 0, line, "'%s': transformation number must be a positive integer", name);
        return;
    }
    memcpy(num, name + off, nlen);
    num[nlen] = '\0';
    if (parse_long(num, &n) || n < 1 || !isdigit((unsigned char)num[0])) {
        add_note(p, 0, line, "'%s': transformation number must be a positive integer", name);
        return;
    }
    for (size_t i = 0; i < p->ntr; ++i)
        if (p->tr[i].n == n) {
            char at[DECK_NAME_SHOWN + 32];
            where(p, p->tr[i].line, at, sizeof at);
            add_note(p, 0, line, "TR%ld is already defined on %s", n, at);
            return;
        }
    double v[DECK_MAX_ENTRIES];
    size_t nv;
    char err[PROX_DECK_TEXT - 40];
    if (expand_entries(tok + 1, nt - 1, v, &nv, DECK_MAX_ENTRIES, err, sizeof err)) {
        add_note(p, 0, line, "TR%ld: %s", n, err);
        return;
    }
    transform t;
    if (prox_deck_make_tr(v, nv, degrees, &t, err, sizeof err)) {
        add_note(p, 0, line, "TR%ld: %s", n, err);
        return;
    }
    t.n = n, t.line = line;
    if (grow((void **)&p->tr, &p->cap_tr, p->ntr, sizeof *p->tr)) {
        p->nomem = 1;
        return;
    }
    p->tr[p->ntr++] = t;
}

/* ---- placing bodies --------------------------------------------------------------------------- */

static prox_vec3 tr_vec(const transform *t, prox_vec3 v)
{
    if (!t || t->identity) return v;
    return prox_v3(t->R[0][0] * v.x + t->R[0][1] * v.y + t->R[0][2] * v.z,
                   t->R[1][0] * v.x + t->R[1][1] * v.y + t->R[1][2] * v.z,
                   t->R[2][0] * v.x + t->R[2][1] * v.y + t->R[2][2] * v.z);
}
static prox_vec3 tr_point(const transform *t, prox_vec3 v)
{
    if (!t) return v;
    return prox_v3_add(prox_v3(t->o[0], t->o[1], t->o[2]), tr_vec(t, v));
}

/* 1 when every column of R is a signed unit axis: an RPP stays an RPP. */
static int axis_permutation(const transform *t)
{
    if (!t || t->identity) return 1;
    for (int j = 0; j < 3; ++j) {
        int ones = 0, zeros = 0;
        for (int i = 0; i < 3; ++i) ones += fabs(t->R[i][j]) == 1.0, zeros += t->R[i][j] == 0.0;
        if (ones != 1 || zeros != 2) return 0;
    }
    return 1;
}

static prox_vec3 v3at(const double *v, size_t i) { return prox_v3(v[i], v[i + 1], v[i + 2]); }

/* The solid of a body card in its own frame (MCNP6 manual, Sec. 3.2.2.4): the card's entries
 * become the stored form; the second card forms go through the constructors of shapes.h. Returns
 * PROX_OK or the status naming the fault. */
static prox_status local_shape(const char *c, const double *v, size_t nv, prox_shape *out)
{
    prox_status st = PROX_OK;
    if (!strcmp(c, "RCC")) *out = prox_shape_from_rcc((prox_rcc){v3at(v, 0), v3at(v, 3), v[6]});
    else if (!strcmp(c, "BOX")) *out = prox_shape_from_box((prox_box){v3at(v, 0), {v3at(v, 3), v3at(v, 6), v3at(v, 9)}});
    else if (!strcmp(c, "RPP")) *out = prox_shape_from_rpp((prox_rpp){v[0], v[1], v[2], v[3], v[4], v[5]});
    else if (!strcmp(c, "SPH") || !strcmp(c, "S")) *out = prox_shape_from_sph((prox_sph){v3at(v, 0), v[3]});
    else if (!strcmp(c, "SO")) *out = prox_shape_from_sph((prox_sph){prox_v3(0, 0, 0), v[0]});
    else if (!strcmp(c, "SX")) *out = prox_shape_from_sph((prox_sph){prox_v3(v[0], 0, 0), v[1]});
    else if (!strcmp(c, "SY")) *out = prox_shape_from_sph((prox_sph){prox_v3(0, v[0], 0), v[1]});
    else if (!strcmp(c, "SZ")) *out = prox_shape_from_sph((prox_sph){prox_v3(0, 0, v[0]), v[1]});
    else if (!strcmp(c, "TRC")) *out = prox_shape_from_trc((prox_trc){v3at(v, 0), v3at(v, 3), v[6], v[7]});
    else if (!strcmp(c, "REC")) {
        prox_rec r = {v3at(v, 0), v3at(v, 3), v3at(v, 6), prox_v3(0, 0, 0)};
        if (nv == 12) r.a2 = v3at(v, 9);
        else st = prox_rec_from_radius(r.base, r.axis, r.a1, v[9], &r); /* minor radius form */
        *out = prox_shape_from_rec(r);
    } else if (!strcmp(c, "ELL")) {
        /* R > 0: foci v1, v2 and major radius R; R < 0: centre v1, major semi-axis v2, minor |R| */
        prox_ell e = {0};
        if (v[6] > 0) st = prox_ell_from_foci(v3at(v, 0), v3at(v, 3), v[6], &e);
        else if (v[6] < 0) st = prox_ell_from_axis(v3at(v, 0), v3at(v, 3), -v[6], &e);
        else st = PROX_EINVAL_RADIUS;
        *out = prox_shape_from_ell(e);
    } else if (!strcmp(c, "RHP") || !strcmp(c, "HEX")) {
        prox_rhp h = {v3at(v, 0), v3at(v, 3), {v3at(v, 6), prox_v3(0, 0, 0), prox_v3(0, 0, 0)}};
        if (nv == 15) h.r[1] = v3at(v, 9), h.r[2] = v3at(v, 12);
        else st = prox_rhp_regular(h.base, h.axis, h.r[0], &h);
        *out = prox_shape_from_rhp(h);
    } else if (!strcmp(c, "WED")) *out = prox_shape_from_wed((prox_wed){v3at(v, 0), v3at(v, 3), v3at(v, 6), v3at(v, 9)});
    else if (!strcmp(c, "ARB")) {
        prox_arb a;
        for (int i = 0; i < 8; ++i) a.corner[i] = v3at(v, 3 * (size_t)i);
        for (int i = 0; i < 6; ++i) {
            double f = v[24 + i];
            if (!(f >= 0 && f <= 8888 && f == floor(f))) return PROX_EINVAL_ARB_FACE;
            a.face[i] = (int)f;
        }
        *out = prox_shape_from_arb(a);
    } else return PROX_EINVAL_ARG;
    return st != PROX_OK ? st : prox_shape_validate(out);
}

/* The shape moved by t: points through o + R p, vectors through R v. An RPP stays an RPP under an
 * axis permutation and becomes a BOX under any other rotation. */
static prox_shape move_shape(prox_shape s, const transform *t)
{
    if (!t) return s;
    prox_vec3 *pts[8] = {0}, *vecs[4] = {0};
    switch (s.kind) {
    case PROX_SHAPE_RCC: pts[0] = &s.u.rcc.base, vecs[0] = &s.u.rcc.axis; break;
    case PROX_SHAPE_BOX: pts[0] = &s.u.box.corner; for (int i = 0; i < 3; ++i) vecs[i] = &s.u.box.edge[i]; break;
    case PROX_SHAPE_SPH: pts[0] = &s.u.sph.center; break;
    case PROX_SHAPE_TRC: pts[0] = &s.u.trc.base, vecs[0] = &s.u.trc.axis; break;
    case PROX_SHAPE_REC: pts[0] = &s.u.rec.base, vecs[0] = &s.u.rec.axis, vecs[1] = &s.u.rec.a1, vecs[2] = &s.u.rec.a2; break;
    case PROX_SHAPE_ELL: pts[0] = &s.u.ell.center, vecs[0] = &s.u.ell.axis; break;
    case PROX_SHAPE_RHP: pts[0] = &s.u.rhp.base, vecs[0] = &s.u.rhp.axis; for (int i = 0; i < 3; ++i) vecs[1 + i] = &s.u.rhp.r[i]; break;
    case PROX_SHAPE_WED: pts[0] = &s.u.wed.vertex, vecs[0] = &s.u.wed.v1, vecs[1] = &s.u.wed.v2, vecs[2] = &s.u.wed.v3; break;
    case PROX_SHAPE_ARB: for (int i = 0; i < 8; ++i) pts[i] = &s.u.arb.corner[i]; break;
    case PROX_SHAPE_RPP: {
        prox_rpp r = s.u.rpp;
        if (!axis_permutation(t)) {
            prox_box b = prox_rpp_to_box(&r);
            return move_shape(prox_shape_from_box(b), t);
        }
        prox_vec3 a = tr_point(t, prox_v3(r.xmin, r.ymin, r.zmin)), b = tr_point(t, prox_v3(r.xmax, r.ymax, r.zmax));
        prox_rpp q = {fmin(a.x, b.x), fmax(a.x, b.x), fmin(a.y, b.y), fmax(a.y, b.y), fmin(a.z, b.z), fmax(a.z, b.z)};
        return prox_shape_from_rpp(q);
    }
    default: break;
    }
    for (int i = 0; i < 8; ++i)
        if (pts[i]) *pts[i] = tr_point(t, *pts[i]);
    for (int i = 0; i < 4; ++i)
        if (vecs[i]) *vecs[i] = tr_vec(t, *vecs[i]);
    return s;
}

int prox_deck_body_shape(const char *mn, const double *v, size_t nv, const prox_deck_tr *t, prox_shape *out,
                         char *err, size_t errsz)
{
    const struct body_card *bc = body_card_of(mn);
    if (!bc) return 1;
    if (nv != bc->n && !(bc->n2 && nv == bc->n2)) {
        if (bc->n2) snprintf(err, errsz, "needs %zu or %zu entries, has %zu", bc->n2, bc->n, nv);
        else snprintf(err, errsz, "needs %zu entries, has %zu", bc->n, nv);
        return -1;
    }
    prox_shape local;
    prox_status st = local_shape(mn, v, nv, &local);
    if (st == PROX_OK) {
        local = move_shape(local, t);
        st = prox_shape_validate(&local);
    }
    if (st != PROX_OK) {
        snprintf(err, errsz, "%s", prox_status_str(st));
        return -1;
    }
    *out = local;
    return 0;
}

/* Validates the shape of a pending surface in its own frame, then places it. */
static void resolve_surface(parser *p, const pending_surface *s)
{
    const transform *t = NULL;
    if (s->tr) {
        for (size_t i = 0; i < p->ntr; ++i)
            if (p->tr[i].n == s->tr) t = &p->tr[i];
        if (!t) {
            add_note(p, 0, s->line, "surface %ld: transformation TR%ld is not defined", s->surface, s->tr);
            return;
        }
    }
    prox_shape local;
    char err[PROX_DECK_TEXT - 40];
    if (prox_deck_body_shape(s->card, s->v, s->nv, t, &local, err, sizeof err)) {
        add_note(p, 0, s->line, "surface %ld %s: %s", s->surface, s->card, err);
        return;
    }
    prox_deck *d = p->deck;
    if (grow((void **)&d->bodies, &p->cap_bodies, d->nbodies, sizeof *d->bodies)) {
        p->nomem = 1;
        return;
    }
    prox_deck_body *b = &d->bodies[d->nbodies++];
    b->surface = s->surface;
    b->line = origin(p, s->line).top;
    memcpy(b->card, s->card, sizeof b->card);
    b->tr = s->tr;
    b->shape = local;
}

/* ---- cell and data cards ---------------------------------------------------------------------- */

/* Cell placements (FILL, TRCL, LAT) move or replicate surfaces: reported, since bodies here are in
 * the frame of their surface card. The cell's Boolean geometry itself is not needed. */
static void cell_card(parser *p, char *text, int line)
{
    for (char *s = text; *s; ++s)
        if (*s == '=' || *s == '(' || *s == ')' || *s == ':') *s = ' ';
    char *tok[512];
    size_t nt = tokenize(text, tok, 512);
    for (size_t i = 1; i < nt; ++i) {
        const char *t = tok[i][0] == '*' ? tok[i] + 1 : tok[i];
        if (ieq(t, "fill") || ieq(t, "trcl") || ieq(t, "lat")) {
            add_note(p, 1, line, "cell %s %s (bodies are reported in their surface card's frame)", tok[0], tok[i]);
            return;
        }
    }
}

/* A data card: only TRn / *TRn matter. */
static void data_card(parser *p, char *text, int line)
{
    char *tok[DECK_MAX_ENTRIES + 4];
    size_t nt = tokenize(text, tok, sizeof tok / sizeof tok[0]);
    if (!nt) return;
    const char *name = tok[0] + (tok[0][0] == '*');
    if (strlen(name) > 2 && tolower((unsigned char)name[0]) == 't' && tolower((unsigned char)name[1]) == 'r' &&
        (isdigit((unsigned char)name[2]) || name[2] == '-' || name[2] == '+')) {
        if (nt == sizeof tok / sizeof tok[0]) {
            add_note(p, 0, line, "'%s': too many entries", tok[0]);
            return;
        }
        tr_card(p, tok, nt, line);
    }
}

/* ---- lines, cards and blocks ------------------------------------------------------------------ */

enum block { B_MESSAGE, B_TITLE, B_CELLS, B_SURFACES, B_DATA, B_DONE };

/* Appends n characters (and a separating blank) to a card. */
static int card_append(card *c, const char *s, size_t n)
{
    if (c->len + n + 2 > c->cap) {
        size_t nc = (c->len + n + 2) * 2;
        char *q = realloc(c->text, nc);
        if (!q) return -1;
        c->text = q, c->cap = nc;
    }
    c->text[c->len++] = ' ';
    memcpy(c->text + c->len, s, n);
    c->len += n;
    c->text[c->len] = 0;
    return 0;
}

/* Card mode: keeps a copy of the card (block, lines, text) for the cell model reader. */
static void keep_card(parser *p, const card *c, int block)
{
    prox_deck_raw *r = p->raw;
    if (grow((void **)&r->cards, &p->cap_cards, r->ncards, sizeof *r->cards)) {
        p->nomem = 1;
        return;
    }
    char *t = malloc(c->len + 1);
    if (!t) {
        p->nomem = 1;
        return;
    }
    memcpy(t, c->text, c->len + 1);
    line_origin o = origin(p, c->line);
    r->cards[r->ncards++] = (prox_deck_card){
        .block = block == B_CELLS ? PROX_CARD_CELL : block == B_SURFACES ? PROX_CARD_SURFACE : PROX_CARD_DATA,
        .line = o.top, .fline = o.line, .file = o.file, .text = t};
}

/* Hands a finished card to the block's reader. */
static void flush_card(parser *p, card *c, int block)
{
    if (c->line && c->len && p->raw && block >= B_CELLS && block <= B_DATA) {
        keep_card(p, c, block);
        if (block == B_DATA) data_card(p, c->text, c->line);
    } else if (c->line && c->len) {
        if (block == B_CELLS) cell_card(p, c->text, c->line);
        else if (block == B_SURFACES) surface_card(p, c->text, c->line);
        else if (block == B_DATA) data_card(p, c->text, c->line);
    }
    c->line = 0, c->len = 0;
    if (c->text) c->text[0] = 0;
}

/* 1 when the line is a comment card: 'c' in columns 1-5 after blanks only, then a blank or the end. */
static int is_comment(const char *s, size_t n)
{
    size_t i = 0;
    while (i < n && i < 5 && s[i] == ' ') ++i;
    if (i >= n || i >= 5 || (s[i] != 'c' && s[i] != 'C')) return 0;
    return i + 1 == n || isspace((unsigned char)s[i + 1]);
}

/* Copies one physical line with tabs expanded (stops of 8) and the CR of CRLF dropped. */
static size_t expand_line(const char *s, size_t n, char *out, size_t cap)
{
    size_t k = 0;
    for (size_t i = 0; i < n && k + 9 < cap; ++i) {
        if (s[i] == '\r' && i + 1 == n) break;
        if (s[i] == '\t') {
            do out[k++] = ' ';
            while (k % 8);
        } else out[k++] = s[i] == '\r' ? ' ' : s[i];
    }
    out[k] = 0;
    return k;
}

/* Feeds one non-blank, non-comment line of a card block. */
static int feed_line(parser *p, card *c, int *amp, char *s, size_t n, int line, int block)
{
    char *dollar = memchr(s, '$', n);
    if (dollar) n = (size_t)(dollar - s);
    while (n && isspace((unsigned char)s[n - 1])) --n;
    int cont_amp = n && s[n - 1] == '&';
    if (cont_amp) --n;
    int leading = 0;
    while (leading < 5 && (size_t)leading < n && s[leading] == ' ') ++leading;
    int continuation = *amp || (leading == 5 || (size_t)leading == n);
    if (continuation && !c->line) {
        if (!*amp && n == 0 && dollar) return 0; /* a line holding only a `$` comment */
        add_note(p, 0, line, "continuation line with no card to continue");
        *amp = cont_amp;
        return 0;
    }
    if (!continuation) {
        flush_card(p, c, block);
        c->line = line;
    }
    *amp = cont_amp;
    return card_append(c, s, n);
}

/* Cuts a card line at column DECK_COLUMNS (MCNP6 reads columns 1-128 of an input line; text beyond
 * is not part of the card). Text cut off, unless it follows a `$`, is listed as unsupported on its
 * line: never dropped silently. Returns the new length. */
static size_t column_limit(parser *p, char *buf, size_t m, int line)
{
    if (m <= DECK_COLUMNS) return m;
    int text = 0;
    for (size_t i = DECK_COLUMNS; i < m; ++i) text |= !isspace((unsigned char)buf[i]);
    if (text && !memchr(buf, '$', DECK_COLUMNS))
        add_note(p, 1, line, "text beyond column %d ignored: '%.20s'", DECK_COLUMNS, buf + DECK_COLUMNS);
    buf[DECK_COLUMNS] = 0;
    return DECK_COLUMNS;
}

/* ---- READ cards: files inserted in place of the card ------------------------------------------ */

/* A copy of the n first characters of s (NULL when memory ran out). */
static char *copy_string(const char *s, size_t n)
{
    char *q = malloc(n + 1);
    if (!q) return NULL;
    memcpy(q, s, n);
    q[n] = 0;
    return q;
}

/* 1 when c separates directories in a path. */
static int is_separator(char c)
{
#ifdef _WIN32
    if (c == '\\') return 1;
#endif
    return c == '/';
}

/* The path of `name` (as written on a READ card) resolved against the directory of `parent`: an
 * absolute name stays, a relative one gets parent's directory in front. NULL when memory ran out. */
static char *resolve_path(const char *parent, const char *name)
{
    int absolute = is_separator(name[0]);
#ifdef _WIN32
    absolute |= isalpha((unsigned char)name[0]) && name[1] == ':';
#endif
    size_t dir = 0;
    if (!absolute)
        for (size_t i = 0; parent[i]; ++i)
            if (is_separator(parent[i])) dir = i + 1;
    size_t n = strlen(name);
    char *q = malloc(dir + n + 1);
    if (!q) return NULL;
    memcpy(q, parent, dir);
    memcpy(q + dir, name, n + 1);
    return q;
}

/* The file name after the last directory separator. */
static const char *base_name(const char *path)
{
    const char *b = path;
    for (const char *s = path; *s; ++s)
        if (is_separator(*s)) b = s + 1;
    return b;
}

/* Reads a whole file into a NUL-terminated buffer. 0 on success, 1 when it cannot be read, 2 when
 * it holds NUL bytes (not a text deck), -1 when memory ran out. */
static int load_file(const char *path, char **out)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 1;
    char *text = NULL;
    size_t n = 0, cap = 0;
    for (;;) {
        if (cap - n < 65536) {
            size_t nc = cap ? 2 * cap : 131072;
            char *q = realloc(text, nc);
            if (!q) {
                fclose(f);
                free(text);
                return -1;
            }
            text = q, cap = nc;
        }
        size_t got = fread(text + n, 1, cap - n - 1, f);
        n += got;
        if (got == 0) break;
    }
    int bad = ferror(f);
    fclose(f);
    if (bad) {
        free(text);
        return 1;
    }
    text[n] = 0;
    if (memchr(text, 0, n)) {
        free(text);
        return 2;
    }
    *out = text;
    return 0;
}

/* Adds a resolved path (taken over) to the list of files. Its index, or -1 when memory ran out. */
static int add_file(parser *p, char *path)
{
    if (grow((void **)&p->files, &p->cap_files, p->nfiles, sizeof *p->files)) {
        free(path);
        p->nomem = 1;
        return -1;
    }
    p->files[p->nfiles] = path;
    return (int)p->nfiles++;
}

/* 1 when the line (tabs expanded) is a READ card: the keyword READ starts in columns 1-5 and is
 * followed by a blank, '=' or the end of the line (a line with 5 leading blanks continues a card). */
static int is_read_card(const char *s, size_t n)
{
    size_t i = 0;
    while (i < n && i < 5 && s[i] == ' ') ++i;
    if (i >= 5 || n - i < 4) return 0;
    for (size_t k = 0; k < 4; ++k)
        if (tolower((unsigned char)s[i + k]) != "read"[k]) return 0;
    return i + 4 == n || isspace((unsigned char)s[i + 4]) || s[i + 4] == '=' || s[i + 4] == '$';
}

/* Writes the names of the open files and `next` as "a.i -> b.i -> next" (base names). */
static void chain_names(const parser *p, const char *next, char *buf, size_t sz)
{
    size_t k = 0;
    buf[0] = 0;
    for (int i = 0; i <= p->depth && k < sz; ++i) {
        int w = snprintf(buf + k, sz - k, "%s -> ", base_name(p->files[p->stack[i].file]));
        if (w < 0) return;
        k += (size_t)w;
    }
    if (k < sz) snprintf(buf + k, sz - k, "%s", base_name(next));
}

/* Reads a READ card (line s of n characters, virtual line v) and, when READ cards are followed,
 * opens its file as the next source. Keywords: FILE=name, NOECHO, DECODE=..., ENCODE=...; `block`:
 * the block the card is in. */
static void read_card(parser *p, char *s, size_t n, int v, int block)
{
    char *dollar = memchr(s, '$', n);
    if (dollar) n = (size_t)(dollar - s);
    while (n && isspace((unsigned char)s[n - 1])) --n;
    s[n] = 0;
    while (*s == ' ') ++s;
    if (!p->with_files) {
        add_note(p, 1, v, "%.100s: included files are read by prox_deck_read_file", s);
        return;
    }
    char *q = s + 4, *file = NULL;
    for (;;) {
        while (isspace((unsigned char)*q)) ++q;
        if (!*q) break;
        char *key = q;
        while (isalnum((unsigned char)*q)) ++q;
        size_t kl = (size_t)(q - key);
        if (kl == 0) {
            add_note(p, 0, v, "READ: unexpected '%c'", *q);
            return;
        }
        while (isspace((unsigned char)*q)) ++q;
        char *val = NULL;
        if (*q == '=') {
            ++q;
            while (isspace((unsigned char)*q)) ++q;
            val = q;
            while (*q && !isspace((unsigned char)*q)) ++q;
            if (*q) *q++ = 0;
            if (!*val) val = NULL;
        }
        char kw[8] = {0};
        for (size_t i = 0; i < kl && i < sizeof kw - 1; ++i) kw[i] = (char)toupper((unsigned char)key[i]);
        if (kl < sizeof kw && !strcmp(kw, "FILE")) {
            if (!val) {
                add_note(p, 0, v, "READ: FILE needs '=name'");
                return;
            }
            file = val;
        } else if (kl < sizeof kw && (!strcmp(kw, "NOECHO") || !strcmp(kw, "ECHO"))) {
            /* echo control of the output file: nothing to do here */
        } else if (kl < sizeof kw && !strcmp(kw, "ENCODE")) {
            /* names the encoded copy MCNP writes of FILE=; the input is FILE= itself, as text */
        } else if (kl < sizeof kw && !strcmp(kw, "DECODE")) {
            add_note(p, 1, v, "READ %s=%.60s: binary files are not read (FILE= is read as text)", kw,
                     val ? val : "");
        } else {
            add_note(p, 0, v, "READ: unknown keyword '%.*s'", (int)(kl < 40 ? kl : 40), key);
            return;
        }
    }
    if (!file) {
        add_note(p, 0, v, "READ card without FILE=name");
        return;
    }
    char *path = resolve_path(p->files[p->stack[p->depth].file], file);
    if (!path) {
        p->nomem = 1;
        return;
    }
    char chain[PROX_DECK_TEXT];
    for (int i = 0; i <= p->depth; ++i)
        if (!strcmp(p->files[p->stack[i].file], path)) {
            chain_names(p, path, chain, sizeof chain);
            add_note(p, 0, v, "READ FILE=%.40s: cycle %s", file, chain);
            free(path);
            return;
        }
    if (p->depth == DECK_MAX_DEPTH) {
        chain_names(p, path, chain, sizeof chain);
        add_note(p, 0, v, "READ FILE=%.40s: nested deeper than %d levels: %s", file, DECK_MAX_DEPTH, chain);
        free(path);
        return;
    }
    if (p->nfiles > DECK_MAX_READS) {
        add_note(p, 0, v, "READ FILE=%.40s: more than %d files read through READ", file, DECK_MAX_READS);
        free(path);
        return;
    }
    char *text = NULL;
    int r = load_file(path, &text);
    if (r) {
        if (r < 0) p->nomem = 1;
        else {
            int cut;
            const char *name = shown_name(path, &cut);
            /* In the data block a missing file (most often the material cards, kept apart) leaves
             * the geometry whole: its cards are listed as not read, not an error; a TRn it held
             * is then reported where a surface or cell names it. */
            int data = block == B_DATA && r == 1;
            add_note(p, data, v, "READ FILE=%.40s: %s '%s%s'%s", file,
                     r == 1 ? "cannot read" : "holds NUL bytes, not a text file:", cut ? "..." : "", name,
                     data ? ": its data cards are not read" : "");
        }
        free(path);
        return;
    }
    int idx = add_file(p, path);
    if (idx < 0) {
        free(text);
        return;
    }
    p->stack[++p->depth] = (source){.owned = text, .pos = text, .file = idx};
}

/* The next physical line of the input: from the innermost open file, going back to the file that
 * read it when one ends. Sets *s and *n and records the line's origin; 0 at the end of the deck. */
static int next_line(parser *p, const char **s, size_t *n)
{
    source *src = &p->stack[p->depth];
    while (!*src->pos) {
        if (p->depth == 0) return 0;
        free(src->owned);
        src->owned = NULL;
        src = &p->stack[--p->depth];
    }
    const char *e = strchr(src->pos, '\n');
    *s = src->pos;
    *n = e ? (size_t)(e - src->pos) : strlen(src->pos);
    src->pos = e ? e + 1 : src->pos + *n;
    src->line++;
    if (p->with_files) {
        if (grow((void **)&p->map, &p->cap_map, p->nmap, sizeof *p->map)) {
            p->nomem = 1;
            return 0;
        }
        p->map[p->nmap++] = (line_origin){src->file, src->line, p->stack[0].line};
    }
    return 1;
}

/* Splits the input into lines and blocks and reads every card. `line` counts virtual lines (every
 * line read from any source); notes and bodies map them back to the main deck through origin(). */
static void read_blocks(parser *p, const char *text)
{
    int block = B_MESSAGE, line = 0, amp = 0, in_message = 0;
    card c = {0};
    size_t cap = 256;
    char *buf = malloc(cap);
    if (!buf) {
        p->nomem = 1;
        return;
    }
    p->stack[0] = (source){.pos = text};
    p->depth = 0;
    const char *s;
    size_t n;
    while (block != B_DONE && !p->nomem && next_line(p, &s, &n)) {
        ++line;
        if (8 * n + 16 > cap) {
            cap = 8 * n + 16;
            char *q = realloc(buf, cap);
            if (!q) {
                p->nomem = 1;
                break;
            }
            buf = q;
        }
        size_t m = expand_line(s, n, buf, cap);
        size_t first = 0;
        while (first < m && isspace((unsigned char)buf[first])) ++first;
        int blank = first == m;
        if (block == B_MESSAGE) { /* an optional message block ends at the first blank line */
            char low[9] = {0};
            for (size_t i = 0; i < 8 && first + i < m; ++i) low[i] = (char)tolower((unsigned char)buf[first + i]);
            if (strcmp(low, "message:")) block = B_TITLE;
            else {
                in_message = 1;
                block = B_TITLE;
                continue;
            }
        }
        if (in_message) {
            in_message = !blank;
            continue;
        }
        if (block == B_TITLE) {
            snprintf(p->deck->title, sizeof p->deck->title, "%.*s", (int)(m - first), buf + first);
            block = B_CELLS;
            continue;
        }
        if (blank) {
            if (amp) add_note(p, 0, line, "'&' continues a card into a blank line");
            flush_card(p, &c, block);
            amp = 0;
            ++block;
            continue;
        }
        if (is_comment(buf, m)) continue;
        m = column_limit(p, buf, m, line);
        if (!amp && is_read_card(buf, m)) { /* ends the card before it; its file comes next */
            flush_card(p, &c, block);
            read_card(p, buf, m, line, block);
            continue;
        }
        if (feed_line(p, &c, &amp, buf, m, line, block)) p->nomem = 1;
    }
    if (block != B_DONE) flush_card(p, &c, block);
    if (block < B_SURFACES && !p->nomem)
        add_note(p, 0, 0, "the deck ends before its surface block (a blank line must follow the cell cards)");
    for (; p->depth > 0; --p->depth) free(p->stack[p->depth].owned);
    free(c.text);
    free(buf);
}

/* ---- public API -------------------------------------------------------------------------------- */

/* Reads the deck text with the parser set up by the caller, places the bodies, frees the parser. */
static prox_status run(parser *p, const char *text)
{
    read_blocks(p, text);
    for (size_t i = 0; i < p->nsurf && !p->nomem; ++i) resolve_surface(p, &p->surf[i]);
    free(p->surf);
    free(p->surf_slot);
    free(p->map);
    if (p->raw) { /* card mode: the transforms and file names go to the caller */
        p->raw->trs = p->tr, p->raw->ntrs = p->ntr;
        p->raw->files = p->files, p->raw->nfiles = p->nfiles;
        return p->nomem ? PROX_ENOMEM : PROX_OK;
    }
    free(p->tr);
    for (size_t i = 0; i < p->nfiles; ++i) free(p->files[i]);
    free(p->files);
    return p->nomem ? PROX_ENOMEM : PROX_OK;
}

/* Reads `text` (or the file at `path` when text is NULL) in the given parser. */
static prox_status read_deck(parser *p, const char *text, const char *path)
{
    if (text) return run(p, text);
    p->with_files = 1;
    char *owned = NULL;
    int r = load_file(path, &owned);
    if (r) {
        if (r < 0) return PROX_ENOMEM;
        add_note(p, 0, 0, r == 1 ? "cannot read '%s'" : "'%s' holds NUL bytes: not a text deck", path);
        return p->nomem ? PROX_ENOMEM : PROX_OK;
    }
    char *name = copy_string(path, strlen(path));
    if (!name || add_file(p, name) < 0) {
        free(owned);
        free(p->files);
        return PROX_ENOMEM;
    }
    prox_status st = run(p, owned);
    free(owned);
    return st;
}

prox_status prox_deck_raw_read(const char *text, const char *path, prox_deck_raw *raw)
{
    if (!raw || (!text && !path)) return PROX_EINVAL_ARG;
    parser p = {.deck = &raw->deck, .raw = raw};
    return read_deck(&p, text, path);
}

void prox_deck_raw_free(prox_deck_raw *raw)
{
    if (!raw) return;
    prox_deck_free(&raw->deck);
    for (size_t i = 0; i < raw->ncards; ++i) free(raw->cards[i].text);
    free(raw->cards);
    free(raw->trs);
    for (size_t i = 0; i < raw->nfiles; ++i) free(raw->files[i]);
    free(raw->files);
    memset(raw, 0, sizeof *raw);
}

int prox_deck_entries(char **tok, size_t n, double *v, size_t *nv, size_t max, char *err, size_t errsz)
{
    return expand_entries(tok, n, v, nv, max, err, errsz);
}
int prox_deck_long(const char *s, long *out) { return parse_long(s, out); }
int prox_deck_number(const char *s, double *out) { return parse_number(s, out); }
int prox_deck_ieq(const char *a, const char *b) { return ieq(a, b); }
prox_vec3 prox_deck_tr_point(const prox_deck_tr *t, prox_vec3 v) { return tr_point(t, v); }
prox_vec3 prox_deck_tr_vec(const prox_deck_tr *t, prox_vec3 v) { return tr_vec(t, v); }

PROX_API prox_status prox_deck_parse(const char *text, prox_deck *deck)
{
    if (!text || !deck) return PROX_EINVAL_ARG;
    parser p = {.deck = deck};
    return run(&p, text);
}

PROX_API prox_status prox_deck_read_file(const char *path, prox_deck *deck)
{
    if (!path || !deck) return PROX_EINVAL_ARG;
    parser p = {.deck = deck};
    return read_deck(&p, NULL, path);
}

PROX_API void prox_deck_free(prox_deck *deck)
{
    if (!deck) return;
    free(deck->bodies);
    free(deck->errors);
    free(deck->unsupported);
    memset(deck, 0, sizeof *deck);
}
