/* libFuzzer harness for MCNP deck text (src/scene/deck.c, prox_deck_parse): any bytes, made
 * NUL-terminated, are parsed; no crash, leak or hang, and every body produced is a valid shape
 * (errors are reported as notes, never as invalid bodies). */
#include <stdlib.h>
#include <string.h>

#include "prox/deck.h"
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text) return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    prox_deck deck;
    memset(&deck, 0, sizeof deck);
    prox_status st = prox_deck_parse(text, &deck);
    if (st == PROX_OK)
        for (size_t k = 0; k < deck.nbodies; ++k)
            if (prox_shape_validate(&deck.bodies[k].shape) != PROX_OK) __builtin_trap();
    prox_deck_free(&deck);
    free(text);
    return 0;
}
