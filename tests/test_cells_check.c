/* Tests of the certified cell check (include/prox/cellcheck.h, src/cells/classify.c, check*.c):
 * the box-surface classification against brute-force sampling, and hand-built and parsed models
 * with known overlaps and gaps: a slab overlap (volume against the exact 100), slivers just above and
 * just below the resolution, tangent cells (no false alarm), unions and complements, a filled
 * universe in a window placed off the origin, a gap from a removed cell. Every witness is checked
 * against the test's own membership (plane and sphere inequalities written out here). */
#include <stdlib.h>
#include <string.h>

#include "test_util.h"
#include "cells/check_internal.h"
#include "prox/cellcheck.h"

/* ---- a hand-built model ---- */

typedef struct hm {
    prox_cell_model m;
    prox_surf surfs[256];
    prox_term terms[4096];
    prox_cell cells[64];
    prox_window windows[8];
} hm;

static hm *hm_new(void)
{
    hm *h = calloc(1, sizeof *h);
    assert_non_null(h);
    h->m.surfs = h->surfs, h->m.terms = h->terms, h->m.cells = h->cells, h->m.windows = h->windows;
    return h;
}

static size_t add_surf(hm *h, prox_surf s)
{
    s.number = (long)h->m.nsurfs + 1;
    h->surfs[h->m.nsurfs] = s;
    return h->m.nsurfs++;
}

/* Plane x_axis = d written with local origin o (so that the same plane can be written two ways). */
static size_t plane_o(hm *h, int axis, double d, prox_vec3 o)
{
    prox_surf s = {.kind = PROX_SURF_QUADRIC, .o = o};
    const double oo[3] = {o.x, o.y, o.z};
    s.q[6 + axis] = 1.0;
    s.q[9] = oo[axis] - d;
    return add_surf(h, s);
}
static size_t plane(hm *h, int axis, double d) { return plane_o(h, axis, d, prox_v3(0, 0, 0)); }

static size_t sphere(hm *h, prox_vec3 c, double r)
{
    prox_surf s = {.kind = PROX_SURF_QUADRIC, .o = c};
    s.q[0] = s.q[1] = s.q[2] = 1.0;
    s.q[9] = -r * r;
    return add_surf(h, s);
}

static size_t cz(hm *h, double x, double y, double r)
{
    prox_surf s = {.kind = PROX_SURF_QUADRIC, .o = prox_v3(x, y, 0)};
    s.q[0] = s.q[1] = 1.0;
    s.q[9] = -r * r;
    return add_surf(h, s);
}

/* Region in a small postfix language: "-3" / "+3" surface index 3 with sense, "&", "|", "!", "A". */
static void expr(hm *h, const char *text, size_t *e, size_t *n)
{
    *e = h->m.nterms;
    char buf[2048];
    snprintf(buf, sizeof buf, "%s", text);
    for (char *tok = strtok(buf, " "); tok; tok = strtok(NULL, " ")) {
        prox_term t = {0};
        if (!strcmp(tok, "&")) t.op = PROX_OP_AND;
        else if (!strcmp(tok, "|")) t.op = PROX_OP_OR;
        else if (!strcmp(tok, "!")) t.op = PROX_OP_NOT;
        else if (!strcmp(tok, "A")) t.op = PROX_OP_ALL;
        else {
            t.op = PROX_OP_LEAF;
            t.sense = tok[0] == '-' ? -1 : 1;
            t.surf = (size_t)strtoul(tok + 1, NULL, 10);
        }
        h->terms[h->m.nterms++] = t;
    }
    *n = h->m.nterms - *e;
}

static size_t cell(hm *h, long number, long universe, int outside, const char *text)
{
    prox_cell *c = &h->cells[h->m.ncells];
    memset(c, 0, sizeof *c);
    c->number = number, c->universe = universe, c->outside = outside;
    expr(h, text, &c->expr, &c->nexpr);
    return h->m.ncells++;
}

static void window(hm *h, long universe, size_t cell_index, const char *text)
{
    prox_window *w = &h->windows[h->m.nwindows++];
    memset(w, 0, sizeof *w);
    w->universe = universe, w->cell = cell_index;
    if (text) expr(h, text, &w->expr, &w->nexpr);
}

/* "x in [x0, x1] and y, z in [0, 10]" as postfix over planes made here. */
static const char *slab(hm *h, double x0, double x1, char *buf, size_t n)
{
    size_t a = plane(h, 0, x0), b = plane(h, 0, x1), c = plane(h, 1, 0), d = plane(h, 1, 10), e = plane(h, 2, 0),
           f = plane(h, 2, 10);
    snprintf(buf, n, "+%zu -%zu & +%zu & -%zu & +%zu & -%zu &", a, b, c, d, e, f);
    return buf;
}

static prox_cells_report run(hm *h, double res, int threads)
{
    prox_cells_check_opts o = {.resolution = res, .threads = threads};
    prox_cells_report r;
    assert_int_equal(prox_cells_check(&h->m, &o, &r), PROX_OK);
    if (getenv("PROX_TEST_VERBOSE"))
        fprintf(stderr, "check: %zu boxes, %zu clean, %zu leaves, %.3f s; %zu overlaps %zu gaps %zu undecided\n",
                r.stats.boxes, r.stats.clean, r.stats.leaves, r.stats.seconds, r.noverlaps, r.ngaps, r.nundecided);
    for (size_t i = 0; getenv("PROX_TEST_VERBOSE") && i < r.noverlaps; ++i)
        fprintf(stderr, "  overlap %ld %ld volume >= %g\n", r.overlaps[i].cells[0], r.overlaps[i].cells[1], r.overlaps[i].volume_min);
    for (size_t i = 0; getenv("PROX_TEST_VERBOSE") && i < r.ngaps; ++i) fprintf(stderr, "  gap volume >= %g\n", r.gaps[i].volume_min);
    return r;
}

static int in_slab(prox_vec3 p, double x0, double x1)
{
    return p.x > x0 && p.x < x1 && p.y > 0 && p.y < 10 && p.z > 0 && p.z < 10;
}

/* ---- classification against sampling ---- */

static double eval_q(const prox_surf *s, double x, double y, double z)
{
    return prox_surf_eval(s, prox_v3(x, y, z));
}

static void classify_vs_sampling(void **state)
{
    (void)state;
    test_rng g = test_rng_seed(7);
    size_t decided = 0;
    for (int it = 0; it < 3000; ++it) {
        prox_surf s = {.kind = PROX_SURF_QUADRIC, .o = prox_v3(test_range(&g, -5, 5), test_range(&g, -5, 5), 0)};
        for (int k = 0; k < 10; ++k) s.q[k] = test_range(&g, -1, 1);
        if (it % 5 == 0) { /* a torus now and then */
            s.kind = PROX_SURF_TORUS;
            double w[3] = {test_range(&g, -1, 1), test_range(&g, -1, 1), test_range(&g, -1, 1)};
            double n = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            s.w = prox_v3(w[0] / n, w[1] / n, w[2] / n);
            s.ta = 3, s.tb = 1, s.tc = 1.5;
        }
        prox_ccbox b;
        for (int i = 0; i < 3; ++i) {
            double c = test_range(&g, -6, 6), hw = pow(10.0, test_range(&g, -3, 0.5));
            b.lo[i] = c - hw, b.hi[i] = c + hw;
        }
        int v = prox_cc_classify(&s, &b);
        if (!v) continue;
        ++decided;
        for (int k = 0; k < 200; ++k) {
            double x = test_range(&g, b.lo[0], b.hi[0]), y = test_range(&g, b.lo[1], b.hi[1]),
                   z = test_range(&g, b.lo[2], b.hi[2]);
            if (k < 8) x = k & 1 ? b.hi[0] : b.lo[0], y = k & 2 ? b.hi[1] : b.lo[1], z = k & 4 ? b.hi[2] : b.lo[2];
            double f = eval_q(&s, x, y, z);
            assert_true(v < 0 ? f < 1e-12 : f > -1e-12); /* up to the rounding allowance */
        }
    }
    assert_true(decided > 1000);
}

/* A box near a sphere but not on it is decided (the mean value form is tight). */
static void classify_near_surface(void **state)
{
    (void)state;
    hm *h = hm_new();
    size_t s = sphere(h, prox_v3(1e6, 0, 0), 1.0);
    for (double gap = 1e-3; gap > 5e-8; gap /= 10) { /* down to 1e-13 of the coordinates */
        prox_ccbox out = {{1e6 + 1 + gap, -gap / 4, -gap / 4}, {1e6 + 1 + 1.5 * gap, gap / 4, gap / 4}};
        prox_ccbox in = {{1e6 + 1 - 1.5 * gap, -gap / 4, -gap / 4}, {1e6 + 1 - gap, gap / 4, gap / 4}};
        assert_int_equal(prox_cc_classify(&h->surfs[s], &out), 1);
        assert_int_equal(prox_cc_classify(&h->surfs[s], &in), -1);
    }
    prox_ccbox on = {{1e6 + 1 - 1e-9, -1e-9, -1e-9}, {1e6 + 1 + 1e-9, 1e-9, 1e-9}};
    assert_int_equal(prox_cc_classify(&h->surfs[s], &on), 0);
    free(h);
}

/* ---- models ---- */

/* Two boxes overlapping in a slab 1 thick, and the outside world. */
static void slab_overlap(void **state)
{
    (void)state;
    hm *h = hm_new();
    char a[256], b[256], out[600];
    size_t ca = cell(h, 1, 0, 0, slab(h, 0, 10, a, sizeof a));
    size_t cb = cell(h, 2, 0, 0, slab(h, 9, 20, b, sizeof b));
    snprintf(out, sizeof out, "%s %s | !", a, b);
    cell(h, 3, 0, 1, out);
    window(h, 0, (size_t)-1, NULL);
    prox_cells_report r = run(h, 0.05, 2);
    assert_int_equal(r.noverlaps, 1);
    assert_int_equal(r.ngaps, 0);
    assert_int_equal(r.overlaps[0].cells[0], 1);
    assert_int_equal(r.overlaps[0].cells[1], 2);
    assert_true(r.overlaps[0].index[0] == ca && r.overlaps[0].index[1] == cb);
    assert_true(in_slab(r.overlaps[0].point, 9, 10)); /* independent membership */
    assert_true(r.overlaps[0].volume_min <= 100.0 * (1 + 1e-12));
    assert_true(r.overlaps[0].volume_min >= 50.0);
    /* Same findings on one thread. */
    prox_cells_report r1 = run(h, 0.05, 1);
    assert_int_equal(r1.noverlaps, 1);
    assert_near(r1.overlaps[0].volume_min, r.overlaps[0].volume_min, 1e-9);
    assert_near(r1.overlaps[0].point.x, r.overlaps[0].point.x, 0);
    prox_cells_report_free(&r);
    prox_cells_report_free(&r1);
    free(h);
}

/* Adjacent boxes: one shared plane, and the same plane written twice (another local origin). */
static void adjacent_clean(void **state)
{
    (void)state;
    for (int twice = 0; twice < 2; ++twice) {
        hm *h = hm_new();
        char a[256], b[256], out[600];
        slab(h, 0, 10, a, sizeof a);
        if (twice) {
            size_t p = plane_o(h, 0, 10, prox_v3(3.3, 1, 7)), c = plane(h, 1, 0), d = plane(h, 1, 10),
                   e = plane(h, 2, 0), f = plane(h, 2, 10), q = plane(h, 0, 20);
            snprintf(b, sizeof b, "+%zu -%zu & +%zu & -%zu & +%zu & -%zu &", p, q, c, d, e, f);
        } else {
            /* Reuse surface 1 (x = 10) of the first slab. */
            size_t q = plane(h, 0, 20);
            snprintf(b, sizeof b, "+1 -%zu & +2 & -3 & +4 & -5 &", q);
        }
        cell(h, 1, 0, 0, a);
        cell(h, 2, 0, 0, b);
        snprintf(out, sizeof out, "%s %s | !", a, b);
        cell(h, 3, 0, 1, out);
        window(h, 0, (size_t)-1, NULL);
        prox_cells_report r = run(h, 0.01, 2);
        assert_int_equal(r.noverlaps, 0);
        assert_int_equal(r.ngaps, 0);
        assert_int_equal(r.nundecided, 0);
        assert_true(r.stats.leaves == 0);
        prox_cells_report_free(&r);
        free(h);
    }
}

/* Overlap (and gap) slivers of thickness t between slabs, above and below the resolution R. */
static void slivers(void **state)
{
    (void)state;
    const double R = 0.1;
    const double ts[2] = {2.5 * R, 0.3 * R};
    for (int kind = 0; kind < 2; ++kind)
        for (int k = 0; k < 2; ++k) {
            hm *h = hm_new();
            char a[256], b[256], out[600];
            double t = ts[k], x1 = kind == 0 ? 10 - t : 10 + t; /* overlap: B starts inside A; gap: after it */
            cell(h, 1, 0, 0, slab(h, 0, 10, a, sizeof a));
            cell(h, 2, 0, 0, slab(h, x1, 20, b, sizeof b));
            /* The outside: beyond the hull [0, 20] x [0, 10]^2 (so a gap between the slabs is a gap). */
            char hull[256];
            snprintf(out, sizeof out, "%s !", slab(h, 0, 20, hull, sizeof hull));
            cell(h, 3, 0, 1, out);
            window(h, 0, (size_t)-1, NULL);
            prox_cells_report r = run(h, R, 2);
            size_t found = kind == 0 ? r.noverlaps : r.ngaps;
            if (k == 0) { /* above: always found, with a proved volume */
                assert_int_equal(found, 1);
                double v = kind == 0 ? r.overlaps[0].volume_min : r.gaps[0].volume_min;
                assert_true(v > 0 && v <= 100 * t * (1 + 1e-9));
            } else assert_true(found == 1 || r.nundecided >= 1); /* below: found or listed, never clean */
            if (kind == 0 && r.noverlaps) assert_true(in_slab(r.overlaps[0].point, x1, 10));
            if (kind == 1 && r.ngaps) assert_true(in_slab(r.gaps[0].point, 10, x1));
            assert_int_equal(kind == 0 ? r.ngaps : r.noverlaps, 0);
            prox_cells_report_free(&r);
            free(h);
        }
}

/* A sphere resting on a plane and two spheres touching: tangent, no overlap and no gap. */
static void tangent_no_false_alarm(void **state)
{
    (void)state;
    hm *h = hm_new();
    size_t s = sphere(h, prox_v3(0, 0, 5), 5), p = plane(h, 2, 0);
    size_t s1 = sphere(h, prox_v3(20, 0, 5), 5), s2 = sphere(h, prox_v3(30, 0, 5), 5);
    size_t bx0 = plane(h, 0, -10), bx1 = plane(h, 0, 40), by0 = plane(h, 1, -10), by1 = plane(h, 1, 10),
           bz0 = plane(h, 2, -5), bz1 = plane(h, 2, 15);
    char box[256], t[1024];
    snprintf(box, sizeof box, "+%zu -%zu & +%zu & -%zu & +%zu & -%zu &", bx0, bx1, by0, by1, bz0, bz1);
    snprintf(t, sizeof t, "-%zu", s);
    cell(h, 1, 0, 0, t);
    snprintf(t, sizeof t, "-%zu", s1);
    cell(h, 2, 0, 0, t);
    snprintf(t, sizeof t, "-%zu", s2);
    cell(h, 3, 0, 0, t);
    snprintf(t, sizeof t, "%s +%zu & +%zu & +%zu & +%zu &", box, p, s, s1, s2);
    cell(h, 4, 0, 0, t);
    snprintf(t, sizeof t, "%s -%zu &", box, p);
    cell(h, 5, 0, 0, t);
    snprintf(t, sizeof t, "%s !", box);
    cell(h, 6, 0, 1, t);
    window(h, 0, (size_t)-1, NULL);
    prox_cells_report r = run(h, 0.05, 2);
    assert_int_equal(r.noverlaps, 0);
    assert_int_equal(r.ngaps, 0);
    double v = 0;
    for (size_t i = 0; i < r.nundecided; ++i) v += r.undecided[i].volume;
    assert_true(v < 1.0); /* only boxes of the resolution at the tangent points */
    prox_cells_report_free(&r);
    free(h);
}

/* A cell made of a union of two spheres and its complement in a box; then a complement that
 * forgets one sphere (overlap of the second sphere minus the first). */
static void unions_and_complements(void **state)
{
    (void)state;
    for (int forget = 0; forget < 2; ++forget) {
        hm *h = hm_new();
        size_t s1 = sphere(h, prox_v3(0, 0, 0), 3), s2 = sphere(h, prox_v3(4, 0, 0), 2);
        size_t bx0 = plane(h, 0, -5), bx1 = plane(h, 0, 8), by0 = plane(h, 1, -5), by1 = plane(h, 1, 5),
               bz0 = plane(h, 2, -5), bz1 = plane(h, 2, 5);
        char box[256], t[1024], u[64];
        snprintf(box, sizeof box, "+%zu -%zu & +%zu & -%zu & +%zu & -%zu &", bx0, bx1, by0, by1, bz0, bz1);
        snprintf(u, sizeof u, "-%zu -%zu |", s1, s2);
        cell(h, 1, 0, 0, u);
        if (forget) snprintf(t, sizeof t, "%s -%zu ! &", box, s1);
        else snprintf(t, sizeof t, "%s %s ! &", box, u);
        cell(h, 2, 0, 0, t);
        snprintf(t, sizeof t, "%s !", box);
        cell(h, 3, 0, 1, t);
        window(h, 0, (size_t)-1, NULL);
        prox_cells_report r = run(h, 0.05, 2);
        assert_int_equal(r.ngaps, 0);
        if (!forget) assert_int_equal(r.noverlaps, 0);
        else {
            assert_int_equal(r.noverlaps, 1);
            prox_vec3 p = r.overlaps[0].point;
            double d1 = sqrt(p.x * p.x + p.y * p.y + p.z * p.z), d2 = sqrt((p.x - 4) * (p.x - 4) + p.y * p.y + p.z * p.z);
            assert_true(d2 < 2 && d1 > 3);
            /* Exact volume of sphere 2 minus the lens it shares with sphere 1 (d = 4, r1 = 3, r2 = 2). */
            double d = 4, r1 = 3, r2 = 2;
            double lens = PROX_PI * pow(r1 + r2 - d, 2) * (d * d + 2 * d * r2 - 3 * r2 * r2 + 2 * d * r1 + 6 * r1 * r2 - 3 * r1 * r1) / (12 * d);
            double exact = 4.0 / 3.0 * PROX_PI * 8 - lens;
            assert_true(r.overlaps[0].volume_min <= exact);
            assert_true(r.overlaps[0].volume_min >= 0.7 * exact);
        }
        prox_cells_report_free(&r);
        free(h);
    }
}

/* Universe 1 (a pin and its moderator) fills a cell of the real world at x in [10, 14]; its window in
 * universe 1's frame is [-2, 2]^2 x [0, 4], written with planes whose local origins sit at the filling
 * cell (as the reader maps them). Clean; then a pin 0.2 too wide (an annulus overlap in universe 1);
 * then a moderator cut short (a gap in the window). */
static void filled_universe(void **state)
{
    (void)state;
    for (int variant = 0; variant < 3; ++variant) {
        hm *h = hm_new();
        char t[1024], fillbox[256];
        /* Real world: the filled cell and the water around it in [0, 20] x [-5, 5] x [-5, 10]. */
        size_t f0 = plane(h, 0, 10), f1 = plane(h, 0, 14), f2 = plane(h, 1, -2), f3 = plane(h, 1, 2), f4 = plane(h, 2, 0),
               f5 = plane(h, 2, 4);
        snprintf(fillbox, sizeof fillbox, "+%zu -%zu & +%zu & -%zu & +%zu & -%zu &", f0, f1, f2, f3, f4, f5);
        size_t w0 = plane(h, 0, 0), w1 = plane(h, 0, 20), w2 = plane(h, 1, -5), w3 = plane(h, 1, 5), w4 = plane(h, 2, -5),
               w5 = plane(h, 2, 10);
        char world[256];
        snprintf(world, sizeof world, "+%zu -%zu & +%zu & -%zu & +%zu & -%zu &", w0, w1, w2, w3, w4, w5);
        size_t fc = cell(h, 10, 0, 0, fillbox);
        h->cells[fc].fill = 1;
        snprintf(t, sizeof t, "%s %s ! &", world, fillbox);
        cell(h, 11, 0, 0, t);
        snprintf(t, sizeof t, "%s !", world);
        cell(h, 12, 0, 1, t);
        window(h, 0, (size_t)-1, NULL);
        /* Universe 1. */
        size_t pin = cz(h, 0, 0, 1.0), wide = cz(h, 0, 0, 0.8), cut = plane(h, 0, 1.5);
        snprintf(t, sizeof t, "-%zu", pin);
        cell(h, 1, 1, 0, t);
        if (variant == 0) snprintf(t, sizeof t, "+%zu", pin);
        else if (variant == 1) snprintf(t, sizeof t, "+%zu", wide);
        else snprintf(t, sizeof t, "+%zu -%zu &", pin, cut);
        cell(h, 2, 1, 0, t);
        /* The window: the filled cell's region mapped into universe 1 (x - 12, z - 0). */
        prox_vec3 o = prox_v3(-12, 0, 0);
        size_t g0 = plane_o(h, 0, -2, o), g1 = plane_o(h, 0, 2, o), g2 = plane_o(h, 1, -2, o), g3 = plane_o(h, 1, 2, o),
               g4 = plane_o(h, 2, 0, o), g5 = plane_o(h, 2, 4, o);
        snprintf(t, sizeof t, "+%zu -%zu & +%zu & -%zu & +%zu & -%zu &", g0, g1, g2, g3, g4, g5);
        window(h, 1, fc, t);
        prox_cells_report r = run(h, 0.02, 2);
        if (variant == 0) assert_true(r.noverlaps == 0 && r.ngaps == 0);
        if (variant == 1) {
            assert_int_equal(r.noverlaps, 1);
            assert_int_equal(r.ngaps, 0);
            assert_int_equal(r.overlaps[0].universe, 1);
            prox_vec3 p = r.overlaps[0].point;
            double rad = hypot(p.x, p.y);
            assert_true(rad > 0.8 && rad < 1 && p.z > 0 && p.z < 4);
            double exact = PROX_PI * (1 - 0.64) * 4;
            assert_true(r.overlaps[0].volume_min <= exact && r.overlaps[0].volume_min > 0.5 * exact);
        }
        if (variant == 2) {
            assert_int_equal(r.noverlaps, 0);
            assert_int_equal(r.ngaps, 1);
            assert_int_equal(r.gaps[0].universe, 1);
            assert_int_equal(r.gaps[0].window_cell, 10);
            prox_vec3 p = r.gaps[0].point;
            assert_true(p.x > 1.5 && p.x < 2 && fabs(p.y) < 2 && p.z > 0 && p.z < 4);
            assert_true(r.gaps[0].volume_min <= 0.5 * 4 * 4 && r.gaps[0].volume_min > 0.5 * 0.5 * 4 * 4);
        }
        prox_cells_report_free(&r);
        free(h);
    }
}

/* Two adjacent boxes and the outside; the second box's cell removed: its region is a gap. */
static void removed_cell_gap(void **state)
{
    (void)state;
    hm *h = hm_new();
    char a[256], b[256], out[600];
    slab(h, 0, 10, a, sizeof a);
    size_t q = plane(h, 0, 20);
    snprintf(b, sizeof b, "+1 -%zu & +2 & -3 & +4 & -5 &", q);
    cell(h, 1, 0, 0, a);
    snprintf(out, sizeof out, "%s %s | !", a, b);
    cell(h, 3, 0, 1, out);
    window(h, 0, (size_t)-1, NULL);
    prox_cells_report r = run(h, 0.05, 2);
    assert_int_equal(r.noverlaps, 0);
    assert_int_equal(r.ngaps, 1);
    assert_true(in_slab(r.gaps[0].point, 10, 20));
    assert_true(r.gaps[0].volume_min <= 1000 * (1 + 1e-12) && r.gaps[0].volume_min > 900);
    assert_int_equal(r.gaps[0].window_cell, 0);
    prox_cells_report_free(&r);
    free(h);
}

/* Parsed decks (prox_cells_parse): universe 1 (a pin and its moderator) fills an RPP moved by
 * TRCL=(10 0 0); clean as written, a gap when the moderator stops at x = 1.5 of the universe's
 * frame, an overlap when it starts at radius 0.8. */
static void parsed_fill_trcl(void **state)
{
    (void)state;
    const char *moderator[3] = {"11", "11 -13", "12"};
    for (int v = 0; v < 3; ++v) {
        char text[1024];
        snprintf(text, sizeof text,
                 "fill with trcl\n"
                 "1 0 -1 fill=1 trcl=(10 0 0) imp:n=1\n"
                 "2 0 #1 -2 imp:n=1\n"
                 "3 0 2 imp:n=0\n"
                 "11 0 -11 u=1 imp:n=1\n"
                 "12 0 %s u=1 imp:n=1\n"
                 "\n"
                 "1 RPP -2 2 -2 2 0 4\n"
                 "2 SO 50\n"
                 "11 CZ 1\n"
                 "12 CZ 0.8\n"
                 "13 PX 1.5\n"
                 "\n",
                 moderator[v]);
        prox_cell_model m = {0};
        assert_int_equal(prox_cells_parse(text, &m), PROX_OK);
        assert_int_equal(m.nerrors, 0);
        prox_cells_check_opts o = {.resolution = 0.05};
        prox_cells_report r;
        assert_int_equal(prox_cells_check(&m, &o, &r), PROX_OK);
        if (v == 0) assert_true(r.noverlaps == 0 && r.ngaps == 0);
        if (v == 1) {
            assert_int_equal(r.noverlaps, 0);
            assert_int_equal(r.ngaps, 1);
            assert_int_equal(r.gaps[0].universe, 1);
            assert_int_equal(r.gaps[0].window_cell, 1);
            prox_vec3 p = r.gaps[0].point; /* in universe 1's frame */
            assert_true(p.x > 1.5 && p.x < 2 && fabs(p.y) < 2 && p.z > 0 && p.z < 4 && hypot(p.x, p.y) > 1);
        }
        if (v == 2) {
            assert_int_equal(r.ngaps, 0);
            assert_int_equal(r.noverlaps, 1);
            assert_int_equal(r.overlaps[0].universe, 1);
            assert_true(r.overlaps[0].cells[0] == 11 && r.overlaps[0].cells[1] == 12);
            prox_vec3 p = r.overlaps[0].point;
            assert_true(hypot(p.x, p.y) > 0.8 && hypot(p.x, p.y) < 1 && p.z > 0 && p.z < 4);
        }
        prox_cells_report_free(&r);
        prox_cells_free(&m);
    }
}

/* Bad input: a malformed region and a model with errors give a status. */
/* A model bounded only by polytope macrobodies with tilted sides (an RHP's, a WED's): expanded into
 * facet planes, each cell's side boxes leave an axis open, and the real world could not be boxed
 * (no check at all). The planes' vertices bound the cells; the overlap of cells 1 and 2 (4 < z < 5)
 * is found. Likewise inside an ARB whose faces name their corners out of order round the face. */
static void polytope_world(void **state)
{
    (void)state;
    const char *bodies[3] = {"20 RHP 0 0 0 0 0 10 1 0 0", "20 WED 0 0 0 1 0 0 0 1 0 0 0 10",
                             /* an ARB whose side faces name their corners across the face */
                             "20 ARB 0 0 0 1 0 0 1 1 0 0 1 0 0 0 10 1 0 10 1 1 10 0 1 10 1256 2367 3478 4185 1234 5678"};
    for (int v = 0; v < 3; ++v) {
        char text[512];
        snprintf(text, sizeof text,
                 "two cells overlapping inside a polytope\n"
                 "1 0 -20 -30 imp:n=1\n"
                 "2 0 -20 29 imp:n=1\n"
                 "99 0 20 imp:n=0\n"
                 "\n"
                 "%s\n"
                 "29 PZ 4\n"
                 "30 PZ 5\n"
                 "\n",
                 bodies[v]);
        prox_cell_model m = {0};
        assert_int_equal(prox_cells_parse(text, &m), PROX_OK);
        assert_int_equal(m.nerrors, 0);
        prox_cells_check_opts o = {.resolution = 0.05};
        prox_cells_report r;
        assert_int_equal(prox_cells_check(&m, &o, &r), PROX_OK);
        assert_int_equal(r.nundecided, 0);
        assert_int_equal(r.noverlaps, 1);
        assert_true(r.overlaps[0].cells[0] == 1 && r.overlaps[0].cells[1] == 2);
        assert_true(r.overlaps[0].point.z > 4 && r.overlaps[0].point.z < 5);
        assert_int_equal(r.ngaps, 0);
        prox_cells_report_free(&r);
        prox_cells_free(&m);
    }
}

static void bad_input(void **state)
{
    (void)state;
    hm *h = hm_new();
    plane(h, 0, 0);
    cell(h, 1, 0, 0, "-0 &");
    prox_cells_report r;
    assert_int_equal(prox_cells_check(&h->m, NULL, &r), PROX_EINVAL_ARG);
    assert_int_equal(r.status, PROX_EINVAL_ARG);
    assert_int_equal(prox_cells_check(NULL, NULL, &r), PROX_EINVAL_ARG);
    assert_int_equal(prox_cells_check(&h->m, NULL, NULL), PROX_EINVAL_ARG);
    free(h);
}

int main(void)
{
    gsl_set_error_handler_off();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(classify_vs_sampling), cmocka_unit_test(classify_near_surface),
        cmocka_unit_test(slab_overlap),         cmocka_unit_test(adjacent_clean),
        cmocka_unit_test(slivers),              cmocka_unit_test(tangent_no_false_alarm),
        cmocka_unit_test(unions_and_complements), cmocka_unit_test(filled_universe),
        cmocka_unit_test(removed_cell_gap),     cmocka_unit_test(parsed_fill_trcl),
        cmocka_unit_test(polytope_world),       cmocka_unit_test(bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
