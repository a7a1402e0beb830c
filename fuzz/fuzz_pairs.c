/* libFuzzer harness for the text the CLI reads in `prox pairs` (src/cli/pairs.c): the bytes become
 * stdin of prox_cli_pairs (through a temporary file), in the mode chosen by the first byte modulo 3
 * (distance, --signed, --test) and with the method chosen by the first byte / 3 modulo 3 (--method
 * fast, closed-form, support); run.sh passes -close_fd_mask=3 to silence its output. Contract: no crash, no leak, exit status
 * 0 or 1 (2 only for usage errors, never for data). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "cli/cli.h"
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char path[64];
    if (!path[0]) snprintf(path, sizeof path, "/tmp/prox_fuzz_pairs_%ld.txt", (long)getpid());
    if (size < 1) return 0;
    FILE *f = fopen(path, "wb");
    if (!f) return 0;
    fwrite(data + 1, 1, size - 1, f);
    fclose(f);
    if (!freopen(path, "rb", stdin)) return 0;
    char a0[] = "pairs", a1[] = "--signed", a2[] = "--test", am[] = "--method";
    char m0[] = "fast", m1[] = "closed-form", m2[] = "support";
    char *methods[3] = {m0, m1, m2};
    char *argv[5] = {a0, am, methods[(data[0] / 3) % 3], data[0] % 3 == 1 ? a1 : a2, NULL};
    int argc = data[0] % 3 == 0 ? 3 : 4;
    int rc = prox_cli_pairs(argc, argv);
    if (rc != 0 && rc != 1) __builtin_trap();
    return 0;
}
