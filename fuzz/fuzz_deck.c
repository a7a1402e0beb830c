/* libFuzzer harness for MCNP deck text: any bytes, made NUL-terminated, are read by both readers of
 * a deck. prox_deck_parse (src/scene/deck.c): no crash, leak or hang, and every body produced is a
 * valid shape (errors are reported as notes, never as invalid bodies). prox_cells_parse
 * (src/cells/): the model is well formed (every term names an existing surface, every region and
 * window is a complete postfix expression within the term array; a cell that could not be built
 * claims no point) and membership can be asked of every cell and window. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "prox/cells.h"
#include "prox/deck.h"
#include "fuzz_common.h"

/* A region is a complete postfix expression: the stack never underflows and ends with one value. */
static void check_region(const prox_cell_model *m, size_t expr, size_t nexpr)
{
    if (expr > m->nterms || nexpr > m->nterms - expr) __builtin_trap();
    size_t depth = 0;
    for (size_t i = 0; i < nexpr; ++i) {
        const prox_term *t = &m->terms[expr + i];
        switch (t->op) {
        case PROX_OP_LEAF:
            if (t->surf >= m->nsurfs || (t->sense != 1 && t->sense != -1)) __builtin_trap();
            ++depth;
            break;
        case PROX_OP_ALL: ++depth; break;
        case PROX_OP_NOT:
            if (depth < 1) __builtin_trap();
            break;
        case PROX_OP_AND:
        case PROX_OP_OR:
            if (depth < 2) __builtin_trap();
            --depth;
            break;
        default: __builtin_trap();
        }
    }
    if (nexpr && depth != 1) __builtin_trap();
}

static void check_cells(const char *text)
{
    prox_cell_model m = {0};
    if (prox_cells_parse(text, &m) != PROX_OK) return;
    const prox_vec3 probes[2] = {{0, 0, 0}, {0.31, -1.7, 2.9}};
    for (size_t i = 0; i < m.ncells; ++i) {
        const prox_cell *c = &m.cells[i];
        if (!c->nexpr || !c->elem_nexpr) __builtin_trap(); /* a cell always has a region */
        check_region(&m, c->expr, c->nexpr);
        check_region(&m, c->elem_expr, c->elem_nexpr);
        if (c->unchecked && prox_cell_contains(&m, i, probes[0]) != 0) __builtin_trap(); /* empty */
        for (int k = 0; k < 2; ++k) {
            int r = prox_cell_contains(&m, i, probes[k]);
            if (r < -1 || r > 1) __builtin_trap();
        }
    }
    for (size_t i = 0; i < m.nwindows; ++i) {
        const prox_window *w = &m.windows[i];
        if (w->cell != (size_t)-1 && w->cell >= m.ncells) __builtin_trap();
        check_region(&m, w->expr, w->nexpr);
        (void)prox_region_contains(&m, w->expr, w->nexpr, probes[1]);
    }
    prox_cells_free(&m);
}

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
    check_cells(text);
    free(text);
    return 0;
}
