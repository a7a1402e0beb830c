/* Subcommands of the prox tool; each returns the process exit status. */
#ifndef PROX_CLI_H
#define PROX_CLI_H

int prox_cli_pairs(int argc, char **argv);
int prox_cli_check(int argc, char **argv);

#endif
