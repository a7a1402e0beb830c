/* Exact membership in a cell's region: the RPN expression evaluated in three-valued (Kleene) logic.
 * A leaf is 1 or 0 by the sign of f(x), and "undecided" (-1) when f(x) == 0 exactly; AND is 0 when
 * any operand is 0, OR is 1 when any operand is 1, NOT keeps an undecided value. The result is
 * therefore -1 only when x lies on a surface whose side decides the answer. */
#include <math.h>
#include <stdlib.h>

#include "cells/cells_internal.h"

/* Below this |y| every quadratic term is finite, so a zero coefficient gives an exact zero term. */
#define PLANE_Y_MAX 1e150

PROX_API double prox_surf_eval(const prox_surf *s, prox_vec3 x)
{
    if (!s) return NAN;
    prox_vec3 y = prox_v3_sub(x, s->o);
    if (s->kind == PROX_SURF_TORUS) { /* ((y.w)/B)^2 + ((|y - (y.w) w| - A)/C)^2 - 1 */
        double a = prox_v3_dot(y, s->w);
        double r = prox_v3_norm(prox_v3_mad(y, -a, s->w));
        double u = a / s->tb, v = (r - s->ta) / s->tc;
        return u * u + v * v - 1.0;
    }
    const double *q = s->q;
    /* A plane: the same sum with its exact-zero quadratic terms left out (the value is the same bit
     * for bit while they are finite zeros, |y| < PLANE_Y_MAX). */
    if ((q[0] == 0.0) & (q[1] == 0.0) & (q[2] == 0.0) & (q[3] == 0.0) & (q[4] == 0.0) & (q[5] == 0.0) &&
        fabs(y.x) < PLANE_Y_MAX && fabs(y.y) < PLANE_Y_MAX && fabs(y.z) < PLANE_Y_MAX)
        return y.x * q[6] + y.y * q[7] + y.z * q[8] + q[9];
    return y.x * (q[0] * y.x + q[3] * y.y + q[5] * y.z + q[6]) + y.y * (q[1] * y.y + q[4] * y.z + q[7]) +
           y.z * (q[2] * y.z + q[8]) + q[9];
}

#define STACK_LOCAL 128

PROX_API int prox_region_contains(const prox_cell_model *m, size_t expr, size_t nexpr, prox_vec3 x)
{
    if (!m || nexpr == 0) return 1; /* no terms: all space */
    if (expr > m->nterms || nexpr > m->nterms - expr) return 0;
    signed char local[STACK_LOCAL], *st = local;
    if (nexpr > STACK_LOCAL) {
        st = malloc(nexpr);
        if (!st) return 0;
    }
    size_t sp = 0;
    int ok = 1;
    for (size_t i = 0; i < nexpr && ok; ++i) {
        const prox_term *t = &m->terms[expr + i];
        switch (t->op) {
        case PROX_OP_LEAF: {
            if (t->surf >= m->nsurfs) {
                ok = 0;
                break;
            }
            double f = prox_surf_eval(&m->surfs[t->surf], x);
            st[sp++] = f == 0.0 || isnan(f) ? -1 : (t->sense < 0 ? f < 0 : f > 0);
            break;
        }
        case PROX_OP_ALL: st[sp++] = 1; break;
        case PROX_OP_NOT:
            if (sp < 1) ok = 0;
            else if (st[sp - 1] >= 0) st[sp - 1] = (signed char)!st[sp - 1];
            break;
        case PROX_OP_AND:
        case PROX_OP_OR: {
            if (sp < 2) {
                ok = 0;
                break;
            }
            int a = st[sp - 2], b = st[sp - 1], r;
            int dom = t->op == PROX_OP_AND ? 0 : 1; /* the value that decides the operation */
            r = (a == dom || b == dom) ? dom : (a < 0 || b < 0) ? -1 : !dom;
            st[--sp - 1] = (signed char)r;
            break;
        }
        default: ok = 0;
        }
    }
    int r = ok && sp == 1 ? st[0] : 0;
    if (st != local) free(st);
    return r;
}

PROX_API int prox_cell_contains(const prox_cell_model *m, size_t cell, prox_vec3 x)
{
    if (!m || cell >= m->ncells) return 0;
    const prox_cell *c = &m->cells[cell];
    return prox_region_contains(m, c->expr, c->nexpr, x);
}
