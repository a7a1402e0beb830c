/* prox pairs: placeholder until the RCC-RCC query lands (issue 3). */
#include <stdio.h>
#include "cli/cli.h"

int prox_cli_pairs(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "prox pairs: not implemented yet\n");
    return 2;
}
