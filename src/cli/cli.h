/* Subcommands of the prox tool; each returns the process exit status. */
#ifndef PROX_CLI_H
#define PROX_CLI_H

#include <stdio.h>

#include "prox/status.h"

int prox_cli_pairs(int argc, char **argv);
int prox_cli_check(int argc, char **argv);

/* The report of `prox check` for the deck at `path` written to out (JSON when json != 0, else the
 * table); the Python package calls it for prox.check_deck. Returns the exit status of prox check
 * (0 no crossings, 1 crossings, 2 input errors); *st says why no report was written (PROX_OK when one
 * was). */
int prox_check_report(const char *path, double clearance, int all, int json, FILE *out, prox_status *st);

#endif
