/* Subcommands of the prox tool; each returns the process exit status. */
#ifndef PROX_CLI_H
#define PROX_CLI_H

#include <stdio.h>

#include "prox/status.h"

int prox_cli_pairs(int argc, char **argv);
int prox_cli_check(int argc, char **argv);
int prox_cli_plot(int argc, char **argv);

/* Everything `prox check` is asked (src/cli/check.c). */
typedef struct prox_check_args {
    const char *path;
    double clearance;  /* --clearance D (implies bodies) */
    int all;           /* --all (implies bodies) */
    int json;          /* --json */
    int bodies;        /* --bodies: the body-level report */
    int strict;        /* --strict: unchecked cards are an error */
    double resolution; /* --resolution R; 0: the default */
    int threads;       /* --threads N; 0: the default (2) */
    int progress;      /* a progress line on stderr (when it is a terminal) */
} prox_check_args;

/* The report of `prox check` with these arguments, written to out; returns the exit status; *st says
 * why no report was written (PROX_OK when one was). */
int prox_check_run(const prox_check_args *a, FILE *out, prox_status *st);

/* The report of `prox check DECK [--clearance D] [--all] [--json]` for the deck at `path` written to
 * out (JSON when json != 0, else the table): the cell report when the deck has cells and neither
 * clearance > 0 nor all is given, else the body-level report. The Python package calls it for
 * prox.check_deck. Returns the exit status of prox check (0 clean, 1 overlaps, gaps or crossings,
 * 2 input errors); *st says why no report was written (PROX_OK when one was). */
int prox_check_report(const char *path, double clearance, int all, int json, FILE *out, prox_status *st);

#endif
