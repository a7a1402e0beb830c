/* placeholder: the peer group lands next */
#include "bench.h"
void bench_group_peers(const bench_opts *o) { (void)o; }
