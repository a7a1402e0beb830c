/* Shared prologue of the libFuzzer harnesses (fuzz_deck.c, fuzz_pairs.c, fuzz_queries.c): the libFuzzer
 * entry-point prototypes and the one-time initialisation. Included by exactly one translation unit per
 * harness binary (run.sh links each harness separately), so the non-static definition below is unique. */
#ifndef PROX_FUZZ_COMMON_H
#define PROX_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <gsl/gsl_errno.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

/* Like the prox tool, tests and bench: GSL's default handler aborts, prox reports statuses. */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    gsl_set_error_handler_off();
    return 0;
}

#endif
