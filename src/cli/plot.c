/* prox plot DECK (--slice x=V | y=V | z=V | --plane x1,y1,z1,x2,y2,z2,x3,y3,z3) [-o FILE.png]:
 * a picture of the real world's cells on a plane. Every pixel is classified by exact membership
 * (prox_cell_contains): one cell gives that cell's colour, two or more the overlap colour, none the
 * gap colour; boundaries are drawn where the cell changes, cell numbers at the middle of their
 * regions, and the witness points of the cell check (prox_cells_check) that lie near the plane are
 * marked. Filled cells are drawn as one cell (their universe is not descended into). Needs cairo
 * (built when pkg-config finds it); without it the command reports so and exits 2. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "prox/cellcheck.h"
#include "prox/cells.h"

#ifdef PROX_HAVE_CAIRO
#include <cairo.h>
#endif

typedef struct plot_opts {
    const char *path, *out;
    int have_plane;
    prox_vec3 p0, u, v; /* origin and orthonormal in-plane axes */
    int width;
    double resolution;
    double ext[4];      /* --extent umin,umax,vmin,vmax; ext[1] > ext[0] when given */
    int nocheck;
} plot_opts;

static void plot_usage(FILE *f)
{
    fprintf(f, "usage: prox plot DECK (--slice x=V | --slice y=V | --slice z=V | --plane x1,y1,z1,x2,y2,z2,x3,y3,z3)\n"
               "                 [-o FILE.png] [--width PIXELS] [--extent UMIN,UMAX,VMIN,VMAX] [--resolution R] [--no-check]\n"
               "  draws the real world's cells on a plane (cell numbers, boundaries), overlaps in black,\n"
               "  gaps in red, and the cell check's witness points near the plane as crosses\n"
               "  (default output: slice.png, 800 pixels wide, the whole model; --extent: a window of the plane\n"
               "  in its own coordinates, u and v: (y, z) for x=V, (x, z) for y=V, (x, y) for z=V)\n");
}

static int parse_plane(const char *s, plot_opts *o)
{
    double a[9];
    char *end;
    for (int i = 0; i < 9; ++i) {
        a[i] = strtod(s, &end);
        if (end == s || (i < 8 && *end != ',') || (i == 8 && *end)) return -1;
        s = end + 1;
    }
    prox_vec3 p1 = prox_v3(a[0], a[1], a[2]), p2 = prox_v3(a[3], a[4], a[5]), p3 = prox_v3(a[6], a[7], a[8]);
    prox_vec3 e1 = prox_v3_sub(p2, p1), e2 = prox_v3_sub(p3, p1), n = prox_v3_cross(e1, e2);
    double ln = prox_v3_norm(n), l1 = prox_v3_norm(e1);
    if (!(ln > 1e-12 * l1 * prox_v3_norm(e2)) || !isfinite(ln)) return -1;
    o->p0 = p1;
    o->u = prox_v3_scale(e1, 1.0 / l1);
    n = prox_v3_scale(n, 1.0 / ln);
    o->v = prox_v3_cross(n, o->u);
    o->have_plane = 1;
    return 0;
}

static int parse_slice(const char *s, plot_opts *o)
{
    char *end;
    if ((s[0] != 'x' && s[0] != 'y' && s[0] != 'z') || s[1] != '=') return -1;
    double c = strtod(s + 2, &end);
    if (end == s + 2 || *end || !isfinite(c)) return -1;
    o->p0 = prox_v3(s[0] == 'x' ? c : 0, s[0] == 'y' ? c : 0, s[0] == 'z' ? c : 0);
    /* Right-handed views: x=V shows (y, z), y=V shows (x, z), z=V shows (x, y). */
    o->u = s[0] == 'x' ? prox_v3(0, 1, 0) : prox_v3(1, 0, 0);
    o->v = s[0] == 'z' ? prox_v3(0, 1, 0) : prox_v3(0, 0, 1);
    o->have_plane = 1;
    return 0;
}

static int parse_opts(int argc, char **argv, plot_opts *o)
{
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        int last = i + 1 >= argc;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) return 1;
        if (!strcmp(a, "--slice") || !strcmp(a, "--plane") || !strcmp(a, "-o") || !strcmp(a, "--width") ||
            !strcmp(a, "--resolution") || !strcmp(a, "--extent")) {
            if (last) return fprintf(stderr, "prox plot: %s needs a value\n", a), -1;
            const char *val = argv[++i];
            char *end;
            if (!strcmp(a, "--slice") && parse_slice(val, o)) return fprintf(stderr, "prox plot: bad slice '%s' (x=V, y=V or z=V)\n", val), -1;
            if (!strcmp(a, "--plane") && parse_plane(val, o))
                return fprintf(stderr, "prox plot: bad plane '%s' (three points, not on a line: x1,y1,z1,x2,y2,z2,x3,y3,z3)\n", val), -1;
            if (!strcmp(a, "-o")) o->out = val;
            if (!strcmp(a, "--extent") &&
                (sscanf(val, "%lf,%lf,%lf,%lf", &o->ext[0], &o->ext[1], &o->ext[2], &o->ext[3]) != 4 ||
                 !(o->ext[1] > o->ext[0]) || !(o->ext[3] > o->ext[2]) || !isfinite(o->ext[1] - o->ext[0]) ||
                 !isfinite(o->ext[3] - o->ext[2])))
                return fprintf(stderr, "prox plot: bad extent '%s' (umin,umax,vmin,vmax)\n", val), -1;
            if (!strcmp(a, "--width")) {
                long w = strtol(val, &end, 10);
                if (*end || w < 16 || w > 8192) return fprintf(stderr, "prox plot: --width takes 16 to 8192\n"), -1;
                o->width = (int)w;
            }
            if (!strcmp(a, "--resolution")) {
                o->resolution = strtod(val, &end);
                if (*end || !(o->resolution > 0) || isinf(o->resolution))
                    return fprintf(stderr, "prox plot: bad resolution '%s'\n", val), -1;
            }
        } else if (!strcmp(a, "--no-check")) o->nocheck = 1;
        else if (a[0] == '-' && a[1]) return fprintf(stderr, "prox plot: unknown option '%s'\n", a), -1;
        else if (o->path) return fprintf(stderr, "prox plot: more than one deck given\n"), -1;
        else o->path = a;
    }
    if (!o->path) return fprintf(stderr, "prox plot: no deck given\n"), -1;
    if (!o->have_plane) return fprintf(stderr, "prox plot: give --slice or --plane\n"), -1;
    return 0;
}

#ifdef PROX_HAVE_CAIRO

/* A distinct, light colour for cell i (golden-ratio hues). */
static void cell_colour(size_t i, double rgb[3])
{
    double h = fmod(0.11 + 0.6180339887498949 * (double)i, 1.0) * 6.0, s = 0.45, l = 0.78;
    double c = (1 - fabs(2 * l - 1)) * s, x = c * (1 - fabs(fmod(h, 2.0) - 1)), m = l - c / 2;
    double r = 0, g = 0, b = 0;
    switch ((int)h) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x; break;
    }
    rgb[0] = r + m, rgb[1] = g + m, rgb[2] = b + m;
}

enum { PIX_GAP = -1, PIX_OVERLAP = -2, PIX_OTHER = -3 };

/* The extent of the plane to draw: the model box's corners projected onto (u, v). */
static void extent(const plot_opts *o, prox_vec3 lo, prox_vec3 hi, double ext[4])
{
    ext[0] = ext[2] = INFINITY, ext[1] = ext[3] = -INFINITY;
    for (int k = 0; k < 8; ++k) {
        prox_vec3 c = prox_v3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z), d = prox_v3_sub(c, o->p0);
        double a = prox_v3_dot(d, o->u), b = prox_v3_dot(d, o->v);
        ext[0] = fmin(ext[0], a), ext[1] = fmax(ext[1], a), ext[2] = fmin(ext[2], b), ext[3] = fmax(ext[3], b);
    }
}

/* Classifies every pixel: the index of its one cell, PIX_GAP or PIX_OVERLAP. */
static long *classify_pixels(const prox_cell_model *m, const plot_opts *o, const double ext[4], int w, int h)
{
    long *pix = malloc((size_t)w * (size_t)h * sizeof *pix);
    if (!pix) return NULL;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            double a = ext[0] + (i + 0.5) * (ext[1] - ext[0]) / w, b = ext[3] - (j + 0.5) * (ext[3] - ext[2]) / h;
            prox_vec3 x = prox_v3_add(o->p0, prox_v3_add(prox_v3_scale(o->u, a), prox_v3_scale(o->v, b)));
            long got = PIX_GAP;
            for (size_t c = 0; c < m->ncells; ++c) {
                if (m->cells[c].universe != 0) continue;
                int in = prox_cell_contains(m, c, x);
                if (in == 1) got = got == PIX_GAP ? (long)c : PIX_OVERLAP;
                else if (in < 0 && got == PIX_GAP) got = PIX_OTHER; /* on a surface: not a gap */
                if (got == PIX_OVERLAP) break;
            }
            pix[(size_t)j * w + i] = got;
        }
    return pix;
}

static void draw_pixels(cairo_t *cr, const prox_cell_model *m, const long *pix, int w, int h)
{
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            long p = pix[(size_t)j * w + i];
            double rgb[3] = {1, 1, 1};
            if (p == PIX_GAP) rgb[0] = 0.9, rgb[1] = 0.05, rgb[2] = 0.05;
            else if (p == PIX_OVERLAP) rgb[0] = rgb[1] = rgb[2] = 0.05;
            else if (p >= 0 && m->cells[p].outside) rgb[0] = rgb[1] = rgb[2] = 0.93;
            else if (p >= 0) cell_colour((size_t)p, rgb);
            /* Boundaries: a pixel whose right or lower neighbour differs is darkened. */
            int edge = (i + 1 < w && pix[(size_t)j * w + i + 1] != p) || (j + 1 < h && pix[(size_t)(j + 1) * w + i] != p);
            if (edge && p >= 0) rgb[0] *= 0.35, rgb[1] *= 0.35, rgb[2] *= 0.35;
            cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
            cairo_rectangle(cr, i, j, 1, 1);
            cairo_fill(cr);
        }
}

/* Each cell's number at the mean position of its pixels (cells of at least 40 pixels). */
static int draw_labels(cairo_t *cr, const prox_cell_model *m, const long *pix, int w, int h)
{
    double *sx = calloc(m->ncells + 1, sizeof *sx), *sy = calloc(m->ncells + 1, sizeof *sy);
    size_t *n = calloc(m->ncells + 1, sizeof *n);
    if (!sx || !sy || !n) {
        free(sx), free(sy), free(n);
        return -1;
    }
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            long p = pix[(size_t)j * w + i];
            if (p >= 0) sx[p] += i, sy[p] += j, n[p]++;
        }
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 12);
    for (size_t c = 0; c < m->ncells; ++c) {
        if (n[c] < 40) continue;
        double x = sx[c] / n[c], y = sy[c] / n[c];
        /* The mean may fall outside a ring-shaped cell: move to the nearest pixel of the cell. */
        long xi = lround(x), yi = lround(y);
        if (xi < 0 || yi < 0 || xi >= w || yi >= h || pix[(size_t)yi * w + xi] != (long)c) {
            double best = INFINITY;
            for (int j = 0; j < h; j += 2)
                for (int i = 0; i < w; i += 2)
                    if (pix[(size_t)j * w + i] == (long)c && (i - x) * (i - x) + (j - y) * (j - y) < best)
                        best = (i - x) * (i - x) + (j - y) * (j - y), xi = i, yi = j;
        }
        char t[32];
        snprintf(t, sizeof t, "%ld", m->cells[c].number);
        cairo_text_extents_t te;
        cairo_text_extents(cr, t, &te);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        cairo_move_to(cr, xi - te.width / 2, yi + te.height / 2);
        cairo_show_text(cr, t);
    }
    free(sx), free(sy), free(n);
    return 0;
}

/* Crosses at the check's witness points within `near` of the plane, labelled. */
static void draw_witnesses(cairo_t *cr, const plot_opts *o, const prox_cells_report *r, const double ext[4], int w, int h,
                           double near)
{
    prox_vec3 n = prox_v3_cross(o->u, o->v);
    cairo_set_line_width(cr, 2.0);
    cairo_set_font_size(cr, 11);
    for (size_t k = 0; k < r->noverlaps + r->ngaps; ++k) {
        int ov = k < r->noverlaps;
        prox_vec3 p = ov ? r->overlaps[k].point : r->gaps[k - r->noverlaps].point;
        if ((ov ? r->overlaps[k].universe : r->gaps[k - r->noverlaps].universe) != 0) continue;
        prox_vec3 d = prox_v3_sub(p, o->p0);
        if (fabs(prox_v3_dot(d, n)) > near) continue;
        double x = (prox_v3_dot(d, o->u) - ext[0]) / (ext[1] - ext[0]) * w, y = (ext[3] - prox_v3_dot(d, o->v)) / (ext[3] - ext[2]) * h;
        cairo_set_source_rgb(cr, ov ? 1.0 : 1.0, ov ? 0.85 : 1.0, 0.0);
        cairo_move_to(cr, x - 6, y - 6), cairo_line_to(cr, x + 6, y + 6);
        cairo_move_to(cr, x - 6, y + 6), cairo_line_to(cr, x + 6, y - 6);
        cairo_stroke(cr);
        char t[64];
        if (ov) snprintf(t, sizeof t, "overlap %ld/%ld", r->overlaps[k].cells[0], r->overlaps[k].cells[1]);
        else snprintf(t, sizeof t, "gap");
        cairo_move_to(cr, x + 8, y - 8);
        cairo_show_text(cr, t);
    }
}

static int render(const prox_cell_model *m, const plot_opts *o, const prox_cells_report *r)
{
    double ext[4];
    if (o->ext[1] > o->ext[0]) memcpy(ext, o->ext, sizeof ext);
    else extent(o, r->lo, r->hi, ext);
    if (!(ext[1] > ext[0]) || !(ext[3] > ext[2])) {
        fprintf(stderr, "prox plot: the plane misses the model box\n");
        return 2;
    }
    int w = o->width, h = (int)lround(w * (ext[3] - ext[2]) / (ext[1] - ext[0]));
    if (h < 16) h = 16;
    if (h > 8192) h = 8192;
    long *pix = classify_pixels(m, o, ext, w, h);
    if (!pix) return fprintf(stderr, "prox plot: %s\n", prox_status_str(PROX_ENOMEM)), 2;
    cairo_surface_t *sf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    cairo_t *cr = cairo_create(sf);
    draw_pixels(cr, m, pix, w, h);
    int code = draw_labels(cr, m, pix, w, h) ? 2 : 0;
    double px = (ext[1] - ext[0]) / w;
    draw_witnesses(cr, o, r, ext, w, h, fmax(fmax(4.0 * px, 2.0 * r->resolution), 0.01 * hypot(ext[1] - ext[0], ext[3] - ext[2])));
    cairo_destroy(cr);
    if (!code && cairo_surface_write_to_png(sf, o->out) != CAIRO_STATUS_SUCCESS) {
        fprintf(stderr, "prox plot: cannot write '%s'\n", o->out);
        code = 2;
    }
    cairo_surface_destroy(sf);
    cairo_debug_reset_static_data(); /* cairo's caches, so that leak checkers see only real leaks */
    free(pix);
    return code;
}

static int plot(const plot_opts *o)
{
    prox_cell_model m = {0};
    prox_status st = prox_cells_read_file(o->path, &m);
    if (st != PROX_OK || m.nerrors || !m.ncells) {
        if (st != PROX_OK) fprintf(stderr, "prox plot: %s\n", prox_status_str(st));
        for (size_t i = 0; i < m.nerrors; ++i) fprintf(stderr, "error: line %d: %s\n", m.errors[i].line, m.errors[i].text);
        if (st == PROX_OK && !m.nerrors) fprintf(stderr, "prox plot: the deck has no cells\n");
        prox_cells_free(&m);
        return 2;
    }
    prox_cells_report r = {0};
    prox_cells_check_opts co = {.resolution = o->resolution, .progress = 1};
    st = prox_cells_check(&m, &co, &r);
    if (st != PROX_OK) {
        fprintf(stderr, "prox plot: %s\n", prox_status_str(st));
        prox_cells_free(&m);
        return 2;
    }
    if (o->nocheck) r.noverlaps = r.ngaps = 0; /* the box still comes from the check */
    int code = render(&m, o, &r);
    if (!code)
        printf("%s: %zu overlapping cell pair%s, %zu gap%s in the deck (witnesses near the plane marked)\n", o->out,
               r.noverlaps, r.noverlaps == 1 ? "" : "s", r.ngaps, r.ngaps == 1 ? "" : "s");
    prox_cells_report_free(&r);
    prox_cells_free(&m);
    return code;
}

#else

static int plot(const plot_opts *o)
{
    (void)o;
    fprintf(stderr, "prox plot: this prox was built without cairo (install libcairo2-dev, run cmake again)\n");
    return 2;
}

#endif

int prox_cli_plot(int argc, char **argv)
{
    plot_opts o = {.out = "slice.png", .width = 800};
    int pr = parse_opts(argc, argv, &o);
    if (pr) {
        plot_usage(pr > 0 ? stdout : stderr);
        return pr > 0 ? 0 : 2;
    }
    return plot(&o);
}
