/* The prox cylinder-pair methods behind the uniform bench_method interface (bench_pairs.h), shared by
 * the "rcc" and "stress" groups: the exact distance by each of the three methods (prox_rcc_distance =
 * fast, and prox_rcc_distance_ex with closed-form and support), the SAT verdict
 * (prox_rcc_sat) and the signed distance (prox_rcc_signed_distance), each compiled in when the library
 * defines it (PROX_BENCH_HAVE_*). */
#include "bench_pairs.h"
#include "prox/sat.h"

#ifdef PROX_BENCH_HAVE_RCC
static void run_distance(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    (void)cfg;
    prox_distance_result r = prox_rcc_distance(a, b);
    out->ok = r.status == PROX_OK;
    out->value = r.distance;
    out->intersect = r.intersect;
    out->p1 = r.p1, out->p2 = r.p2;
    out->has_points = 1;
}
const bench_method bench_prox_distance_method = {"prox-distance", BENCH_DIST, run_distance, NULL};

/* The other two methods; cfg points at the prox_method. */
static void run_distance_ex(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    prox_distance_result r = prox_rcc_distance_ex(a, b, *(const prox_method *)cfg);
    out->ok = r.status == PROX_OK;
    out->value = r.distance;
    out->intersect = r.intersect;
    out->p1 = r.p1, out->p2 = r.p2;
    out->has_points = 1;
}
static const prox_method method_closed_form = PROX_METHOD_CLOSED_FORM, method_support = PROX_METHOD_SUPPORT;
static const bench_method m_closed_form = {"prox-closed-form", BENCH_DIST, run_distance_ex, &method_closed_form};
static const bench_method m_support = {"prox-support", BENCH_DIST, run_distance_ex, &method_support};
#endif
#ifdef PROX_BENCH_HAVE_SAT
static void run_sat(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    (void)cfg;
    prox_test_result r = prox_rcc_sat(a, b);
    out->ok = r.status == PROX_OK;
    out->intersect = r.intersect;
    out->value = r.value;
    out->has_points = 0;
}
static const bench_method m_sat = {"prox-sat", BENCH_VERDICT, run_sat, NULL};
#endif
#ifdef PROX_BENCH_HAVE_SIGNED
static void run_signed(const void *cfg, const prox_rcc *a, const prox_rcc *b, bench_answer *out)
{
    (void)cfg;
    prox_signed_result r = prox_rcc_signed_distance(a, b);
    out->ok = r.status == PROX_OK;
    out->value = r.sd;
    out->intersect = r.sd <= 0;
    out->p1 = r.p1, out->p2 = r.p2;
    out->has_points = 1;
}
static const bench_method m_signed = {"prox-signed", BENCH_SIGNED, run_signed, NULL};
#endif

const bench_method *const bench_prox_methods[] = {
#ifdef PROX_BENCH_HAVE_RCC
    &bench_prox_distance_method,
    &m_closed_form,
    &m_support,
#endif
#ifdef PROX_BENCH_HAVE_SAT
    &m_sat,
#endif
#ifdef PROX_BENCH_HAVE_SIGNED
    &m_signed,
#endif
    NULL,
};
