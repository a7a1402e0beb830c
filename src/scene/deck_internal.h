/* Internal (scene): the card layer of the MCNP deck reader (src/scene/deck.c) shared with the cell
 * model reader (src/cells/cells_parse.c): the deck split into logical cards (message block, title,
 * comments, continuations, READ files and column limits already handled), the TRn cards, the entry
 * shorthands and the number syntax. One reader of the input format for both. */
#ifndef PROX_SCENE_DECK_INTERNAL_H
#define PROX_SCENE_DECK_INTERNAL_H

#include <stddef.h>

#include "prox/deck.h"

/* A TRn card (or an inline TRCL / fill transform) as the map r = o + R r'. */
typedef struct prox_deck_tr {
    long n;
    int line;
    double o[3];
    double R[3][3]; /* R[i][j]: main component i of auxiliary axis j */
    int identity;   /* R is exactly the identity */
} prox_deck_tr;

/* Block of a card. */
enum { PROX_CARD_CELL = 0, PROX_CARD_SURFACE = 1, PROX_CARD_DATA = 2 };

/* One logical card: continuation lines joined by blanks, `$` comments removed. */
typedef struct prox_deck_card {
    int block;  /* PROX_CARD_* */
    int line;   /* line of the main deck (the READ card's line for a card from an included file) */
    int fline;  /* line in the file that holds it (== line for the main deck) */
    int file;   /* index into prox_deck_raw.files (0: the main deck) */
    char *text;
} prox_deck_card;

/* The deck as cards. `deck` holds the title and the notes of the card layer (READ problems, stray
 * continuations, TRn card errors); surface cards are not turned into bodies. */
typedef struct prox_deck_raw {
    prox_deck deck;
    prox_deck_card *cards;
    size_t ncards;
    prox_deck_tr *trs;
    size_t ntrs;
    char **files;  /* files[0]: the main deck (or "" for text) */
    size_t nfiles;
} prox_deck_raw;

/* Reads the deck: from `path` when text is NULL (READ cards followed), else from text (READ cards
 * listed as unsupported). Returns PROX_OK, PROX_EINVAL_ARG or PROX_ENOMEM. Start from {0}. */
prox_status prox_deck_raw_read(const char *text, const char *path, prox_deck_raw *raw);
void prox_deck_raw_free(prox_deck_raw *raw);

/* Expands the entries tok[0..n) (numbers and the nR nI xM nILOG shorthands) into v (capacity max);
 * on failure writes the reason to err and returns -1. */
int prox_deck_entries(char **tok, size_t n, double *v, size_t *nv, size_t max, char *err, size_t errsz);
/* A whole token as a decimal integer / an MCNP number. 0 on success. */
int prox_deck_long(const char *s, long *out);
int prox_deck_number(const char *s, double *out);
/* Case-insensitive equality. */
int prox_deck_ieq(const char *a, const char *b);

/* Builds the map of a TRn / TRCL entry list (3, 9, 12 or 13 entries; angles in degrees when
 * `degrees`). 0 on success, else -1 with the reason in err. */
int prox_deck_make_tr(const double *v, size_t nv, int degrees, prox_deck_tr *t, char *err, size_t errsz);
/* The solid of a body card (RCC BOX RPP SPH TRC REC ELL RHP HEX WED ARB SO S SX SY SZ; mn upper
 * case) from its entries, validated in its own frame, then moved by t (NULL: none) and validated
 * again. 0 on success, 1 when mn is not a body card, -1 with the reason in err. */
int prox_deck_body_shape(const char *mn, const double *v, size_t nv, const prox_deck_tr *t, prox_shape *out,
                         char *err, size_t errsz);
/* r = o + R r' for a point, R v for a vector (t may be NULL: identity). */
prox_vec3 prox_deck_tr_point(const prox_deck_tr *t, prox_vec3 p);
prox_vec3 prox_deck_tr_vec(const prox_deck_tr *t, prox_vec3 v);

#endif
