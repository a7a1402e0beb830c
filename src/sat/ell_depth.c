/* A lower bound of the depth of two overlapping ellipsoids by an ellipsoid inside their Minkowski
 * difference.
 *
 * An ellipsoid centred at the origin is {L u : |u| <= 1} with L symmetric positive definite (an ELL:
 * L = b I + (a - b) w w^T; a sphere: r I), its support function h(D) = |L D|. The depth of A and B,
 * centres differing by delta, is min over unit D of phi(D) = |L_A D| + |L_B D| - D.delta: the distance
 * from delta to the boundary of M = A - B (centred), delta inside M. For any orthogonal Q,
 *   |L_A D + Q L_B D| <= |L_A D| + |L_B D|,
 * so E_Q = {K u : |u| <= 1}, K = L_A + L_B Q^T (support function |K^T D| = |L_A D + Q L_B D|), lies in
 * M, and the distance from delta to the boundary of E_Q is a lower bound of the depth. With Q the
 * least rotation taking L_B n to the direction of L_A n, E_Q touches M along n (equality above); when
 * n is the deepest direction the bound is then the depth itself for nearly every pair (two random
 * ellipsoids of revolution, overlapping: 105 of 111 in a trial against a multistart search), where
 * the tangent balls (convex.c) prove shallow contacts only.
 *
 * The distance from an interior point y to the boundary of the ellipsoid with squared semi-axes s_i
 * (the eigenvalues of K K^T, cyclic Jacobi) along its axes: the closest boundary point is x_i = s_i y_i
 * / (s_i + t) for the root t in (-s_min, 0] of sum s_i y_i^2 / (s_i + t)^2 = 1 (the Lagrange
 * condition; the left side falls with t there), at distance |t| |(y_i / (s_i + t))|. */
#include "ell_depth.h"

#include <float.h>
#include <math.h>

int prox_ell_pair(const prox_body *a, const prox_body *b)
{
    return (a->kind == PROX_BODY_ELL || a->kind == PROX_BODY_SPH) &&
           (b->kind == PROX_BODY_ELL || b->kind == PROX_BODY_SPH);
}

/* The symmetric square root L of the body's shape matrix. */
static void ell_root(const prox_body *b, double L[3][3])
{
    int sph = b->kind == PROX_BODY_SPH;
    double e = sph ? b->r : b->x.ell.b, f = sph ? 0.0 : b->x.ell.a - b->x.ell.b;
    prox_vec3 w = sph ? prox_v3(0, 0, 1) : b->x.ell.w;
    double wv[3] = {w.x, w.y, w.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) L[i][j] = (i == j ? e : 0.0) + f * wv[i] * wv[j];
}

static prox_vec3 mat_vec(double M[3][3], prox_vec3 v)
{
    return prox_v3(M[0][0] * v.x + M[0][1] * v.y + M[0][2] * v.z, M[1][0] * v.x + M[1][1] * v.y + M[1][2] * v.z,
                   M[2][0] * v.x + M[2][1] * v.y + M[2][2] * v.z);
}

/* The least rotation Q with Q f = t (unit vectors, f.t > -1): Q = I + [v] + [v]^2 / (1 + c), v = f x t,
 * c = f.t. 0 when f and t are nearly opposite. */
static int rot_align(prox_vec3 f, prox_vec3 t, double Q[3][3])
{
    prox_vec3 v = prox_v3_cross(f, t);
    double c = prox_v3_dot(f, t);
    if (!(1.0 + c > 1e-8)) return 0;
    double k = 1.0 / (1.0 + c), X[3][3] = {{0.0, -v.z, v.y}, {v.z, 0.0, -v.x}, {-v.y, v.x, 0.0}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double x2 = X[i][0] * X[0][j] + X[i][1] * X[1][j] + X[i][2] * X[2][j];
            Q[i][j] = (i == j ? 1.0 : 0.0) + X[i][j] + k * x2;
        }
    return 1;
}

/* Eigenvalues ev and eigenvectors (the columns of V) of the symmetric A (overwritten): cyclic Jacobi
 * rotations until the off-diagonal part is rounding. */
static void jacobi3(double A[3][3], double ev[3], double V[3][3])
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) V[i][j] = i == j ? 1.0 : 0.0;
    static const int P[3] = {0, 0, 1}, R[3] = {1, 2, 2};
    for (int sweep = 0; sweep < 32; ++sweep) {
        double off = fabs(A[0][1]) + fabs(A[0][2]) + fabs(A[1][2]);
        double dia = fabs(A[0][0]) + fabs(A[1][1]) + fabs(A[2][2]);
        if (!(off > DBL_EPSILON * DBL_EPSILON * dia)) break;
        for (int k = 0; k < 3; ++k) {
            int p = P[k], q = R[k], r = 3 - p - q;
            double apq = A[p][q];
            if (apq == 0.0) continue;
            double th = (A[q][q] - A[p][p]) / (2.0 * apq);
            double t = (th >= 0.0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
            double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
            A[p][p] -= t * apq;
            A[q][q] += t * apq;
            A[p][q] = A[q][p] = 0.0;
            double arp = A[r][p], arq = A[r][q];
            A[r][p] = A[p][r] = c * arp - s * arq;
            A[r][q] = A[q][r] = s * arp + c * arq;
            for (int i = 0; i < 3; ++i) {
                double vp = V[i][p], vq = V[i][q];
                V[i][p] = c * vp - s * vq;
                V[i][q] = s * vp + c * vq;
            }
        }
    }
    for (int i = 0; i < 3; ++i) ev[i] = A[i][i];
}

/* Distance from y (components along the axes) to the boundary of the ellipsoid with squared semi-axes
 * s2, from inside; -1 when y is not inside or lies on the plane of the shortest axis (the root then
 * need not exist). The root by bisection in u = t + s_min in (0, s_min], where s_i + t = s_i - s_min
 * + u keeps its digits; the distance is taken at the upper end, which it does not exceed (it falls to
 * 0 as u rises to s_min, where x = y). */
static double inner_distance(const double s2[3], const double y[3])
{
    int m = 0;
    for (int i = 1; i < 3; ++i)
        if (s2[i] < s2[m]) m = i;
    if (!(s2[m] > 0.0) || y[m] == 0.0) return -1.0;
    double q = 0.0;
    for (int i = 0; i < 3; ++i) q += y[i] * y[i] / s2[i];
    if (!(q < 1.0)) return -1.0;
    double lo = 0.0, hi = s2[m];
    for (int it = 0; it < 80; ++it) {
        double u = 0.5 * (lo + hi), g = -1.0;
        if (!(u > lo && u < hi)) break;
        for (int i = 0; i < 3; ++i) {
            double den = i == m ? u : s2[i] - s2[m] + u;
            g += s2[i] * (y[i] / den) * (y[i] / den);
        }
        if (g > 0.0) lo = u;
        else hi = u;
    }
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        double z = y[i] / (i == m ? hi : s2[i] - s2[m] + hi);
        sum += z * z;
    }
    return (s2[m] - hi) * sqrt(sum);
}

double prox_ell_depth_lower(const prox_body *a, const prox_body *b, prox_vec3 delta, prox_vec3 n, double S)
{
    double La[3][3], Lb[3][3], Q[3][3];
    ell_root(a, La);
    ell_root(b, Lb);
    prox_vec3 ua = mat_vec(La, n), ub = mat_vec(Lb, n);
    double na = prox_v3_norm(ua), nb = prox_v3_norm(ub);
    if (!(na > 0.0 && nb > 0.0)) return -INFINITY;
    if (!rot_align(prox_v3_scale(ub, 1.0 / nb), prox_v3_scale(ua, 1.0 / na), Q)) return -INFINITY;
    /* K = L_A + L_B Q^T and C = K K^T */
    double K[3][3], C[3][3], s2[3], V[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            K[i][j] = La[i][j] + Lb[i][0] * Q[j][0] + Lb[i][1] * Q[j][1] + Lb[i][2] * Q[j][2];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) C[i][j] = K[i][0] * K[j][0] + K[i][1] * K[j][1] + K[i][2] * K[j][2];
    jacobi3(C, s2, V);
    double y[3], smin = INFINITY;
    for (int i = 0; i < 3; ++i) {
        y[i] = fabs(V[0][i] * delta.x + V[1][i] * delta.y + V[2][i] * delta.z);
        smin = fmin(smin, s2[i]);
    }
    double d = inner_distance(s2, y);
    if (!(d > 0.0)) return -INFINITY;
    /* rounding: K and delta carry eps S, C and its eigenvalues eps S^2, which moves the shortest
     * semi-axis, and with it the distance, by eps S^2 / s_min */
    return d - 64.0 * DBL_EPSILON * (S + S * S / sqrt(smin));
}
