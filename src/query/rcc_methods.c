/* The three cylinder-pair distance methods behind one entry point (prox_rcc_distance_ex), and their
 * names. The methods share only the geometric core (src/core/): the fast method (src/distance/rcc_rcc.c)
 * and the closed-form method (src/distance/rcc_closed_form.c) live in the distance module, the support
 * method in src/sat; choosing between them composes the two modules, hence lives here. */
#include <string.h>

#include "distance/rcc_methods.h"
#include "prox/distance.h"
#include "prox/sat.h"

static const char *const method_names[PROX_METHOD_COUNT_] = {
    [PROX_METHOD_FAST] = "fast",
    [PROX_METHOD_CLOSED_FORM] = "closed-form",
    [PROX_METHOD_SUPPORT] = "support",
};

/* 1 for a value of the enumeration (the enum's type may be unsigned: compare as an int). */
static int method_valid(prox_method m) { return (int)m >= 0 && (int)m < PROX_METHOD_COUNT_; }

PROX_API prox_distance_result prox_rcc_distance_ex(const prox_rcc *a, const prox_rcc *b, prox_method method)
{
    prox_distance_result r = {0};
    switch (method) {
    case PROX_METHOD_FAST: return prox_rcc_distance(a, b); /* sets CLOSED_FORM when it fell back */
    case PROX_METHOD_CLOSED_FORM: r = prox_rcc_closed_form(a, b); break;
    case PROX_METHOD_SUPPORT: r = prox_rcc_distance_support(a, b); break;
    default: r.status = PROX_EINVAL_ARG; return r;
    }
    if (r.status == PROX_OK) r.method = method;
    return r;
}

PROX_API const char *prox_method_name(prox_method m) { return method_valid(m) ? method_names[m] : NULL; }

PROX_API int prox_method_parse(const char *s, prox_method *m)
{
    if (!s || !m) return 0;
    for (int i = 0; i < PROX_METHOD_COUNT_; ++i) {
        if (strcmp(s, method_names[i]) == 0) {
            *m = (prox_method)i;
            return 1;
        }
    }
    return 0;
}
