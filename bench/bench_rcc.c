/* placeholder, replaced below */
#include "bench.h"
void bench_group_rcc(const bench_opts *o) { (void)o; }
void bench_group_peers(const bench_opts *o) { (void)o; }
void bench_group_stress(const bench_opts *o) { (void)o; }
