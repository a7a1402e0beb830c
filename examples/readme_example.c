#include <stdio.h>
#include <gsl/gsl_errno.h>
#include <prox/prox.h>

int main(void)
{
    gsl_set_error_handler_off(); /* prox reports GSL failures as PROX_ENUMERIC */
    prox_rcc a = {prox_v3(0, 0, 0), prox_v3(0, 0, 12), 2.0};   /* RCC: base, axis (height), radius */
    prox_rcc b = {prox_v3(8, -8, 8), prox_v3(1.4782147081789352, 17.644185480676729, -3.24), 2.5};
    prox_distance_result r = prox_rcc_distance(&a, &b);
    if (r.status != PROX_OK) {
        fprintf(stderr, "prox: %s\n", prox_status_str(r.status));
        return 1;
    }
    printf("distance %.15g between (%g %g %g) and (%g %g %g)%s\n", r.distance, r.p1.x, r.p1.y, r.p1.z,
           r.p2.x, r.p2.y, r.p2.z, r.intersect ? " (overlap)" : "");
    return 0;
}
