/* prox command-line tool: dispatches to the subcommands. */
#include <stdio.h>
#include <string.h>
#include <gsl/gsl_errno.h>

#include "cli/cli.h"
#include "prox/version.h"

static void usage(FILE *f)
{
    fprintf(f, "usage: prox <command> [options]\n"
               "commands:\n"
               "  pairs     cylinder pairs on stdin (14 numbers a line) -> distance and proximal points\n"
               "  check     MCNP deck -> overlapping cells, gaps (--bodies: crossing and nested bodies)\n"
               "            (prox check DECK --help)\n"
               "  plot      MCNP deck -> PNG of the cells on a slice, overlaps and gaps marked\n"
               "            (prox plot DECK --slice z=10 -o slice.png; prox plot --help)\n"
               "  help      this text\n"
               "  --version the version of prox\n");
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off(); /* the library checks every GSL status itself */
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (strcmp(argv[1], "--version") == 0 || strcmp(argv[1], "version") == 0) {
        printf("prox %s\n", prox_version());
        return 0;
    }
    if (strcmp(argv[1], "pairs") == 0) return prox_cli_pairs(argc - 1, argv + 1);
    if (strcmp(argv[1], "check") == 0) return prox_cli_check(argc - 1, argv + 1);
    if (strcmp(argv[1], "plot") == 0) return prox_cli_plot(argc - 1, argv + 1);
    if (strcmp(argv[1], "help") == 0 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        usage(stdout);
        return 0;
    }
    fprintf(stderr, "prox: unknown command '%s'\n", argv[1]);
    usage(stderr);
    return 2;
}
