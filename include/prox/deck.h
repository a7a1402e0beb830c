/// @file deck.h
/// Reader for MCNP input decks: the solid bodies of the surface block (the ten macrobodies RCC, BOX,
/// RPP, SPH, TRC, REC, ELL, RHP/HEX, WED, ARB in every card form, and the sphere surfaces SO, S, SX,
/// SY, SZ) placed in the deck's global frame through the TRn / *TRn cards of the data block. Every
/// surface card ends up as a body, an error (malformed card, with line and reason) or an unsupported
/// entry (card mnemonic and line): none is dropped. docs/deck.md lists the rules and their sources.
/// Rules followed (MCNP6 manual, Ch. 3): case-insensitive; `c` comment cards (c in columns 1-5
/// followed by a blank, or alone); `$` end-of-line comments; continuation by five leading blanks or
/// a trailing `&`; columns 1-128 of a line (text beyond is listed as unsupported); an optional
/// `message:` block; blank-line block delimiters; numbers with E/D exponents; the shorthands nR, nI,
/// xM, nILOG (nJ is an error; a Fortran exponent without its letter, 1.5-3, is 1.5e-3); READ FILE=name cards with ECHO, NOECHO,
/// ENCODE (followed by prox_deck_read_file only; see there; DECODE is listed as unsupported).
/// The cell model of a deck (cells, all surface kinds, universes) is read by cells.h.
#ifndef PROX_DECK_H
#define PROX_DECK_H

#include <stddef.h>

#include "shapes.h"

/// Longest message or card text kept (longer text is cut).
#define PROX_DECK_TEXT 160

/// One body of the deck: a surface card turned into a solid in the global frame.
typedef struct prox_deck_body {
    long surface;      ///< surface number as written (without a * or + boundary prefix)
    int line;          ///< 1-based line of the card's first line
    char card[8];      ///< mnemonic, upper case as written ("RCC", ..., "RHP" or "HEX", "SO", "SX", ...)
    long tr;           ///< transformation number applied (0 for none)
    prox_shape shape;  ///< the solid in the global frame (an RPP under a rotation becomes a BOX)
} prox_deck_body;

/// An error or an unsupported card.
typedef struct prox_deck_note {
    int line;                   ///< 1-based line of the card (0 for the whole file)
    char text[PROX_DECK_TEXT];  ///< error: the reason; unsupported: the card, e.g. "12 PZ"
} prox_deck_note;

/// A parsed deck. Start from {0}; release with prox_deck_free.
typedef struct prox_deck {
    char title[PROX_DECK_TEXT];
    prox_deck_body *bodies;
    size_t nbodies;
    prox_deck_note *errors;       ///< malformed cards and file-level problems
    size_t nerrors;
    prox_deck_note *unsupported;  ///< surface cards (and cell placements) the reader does not model
    size_t nunsupported;
} prox_deck;

/// Parses the deck held in `text` (NUL-terminated). Returns PROX_OK when the text was read (the deck
/// may still hold errors: see deck->nerrors), PROX_EINVAL_ARG for null arguments, PROX_ENOMEM when
/// memory ran out. Any previous content of *deck is not freed: pass a zeroed deck. With no file
/// context, a READ card is listed as unsupported (no file is opened).
PROX_API prox_status prox_deck_parse(const char *text, prox_deck *deck);
/// Reads and parses the file at `path`; a file that cannot be read gives one error with line 0.
/// READ FILE=name cards are followed: the file (relative names resolved against the directory of
/// the file holding the card; nesting up to 8 levels) replaces the card. Bodies and notes that come
/// from an included file have `line` = the line of the READ card in the main deck, and a note's text
/// starts with "'<file>' line <n>: " (the file's own line). Missing files, cycles, deeper nesting
/// and READ cards without FILE= are errors on the READ card's line; the rest is still read.
PROX_API prox_status prox_deck_read_file(const char *path, prox_deck *deck);
/// Frees everything a deck holds and zeroes it.
PROX_API void prox_deck_free(prox_deck *deck);

#endif
